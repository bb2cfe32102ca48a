// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrPythonCenterlines_h
#define vrPythonCenterlines_h

#include "itkCenterlineTree.h"
#include "vrCenterlineExtraction.h"

#include <pybind11/pybind11.h>

#include <string>
#include <vector>

namespace vr::python
{
namespace py = pybind11;

/** \class Centerlines
 * \brief vesselreformation.Centerlines: a centerline tree (branches of points with optional radii and names), held
 * in LPS mm as the engine takes it.
 */
struct Centerlines
{
  itk::CenterlineTree Tree;
  /** Where it came from: a file's format and space, "extracted from ...", or "given". */
  std::string              Source{ "given" };
  std::vector<std::string> Warnings;
};

/** \return \a value as the engine's tree: a Centerlines, or a list of branches (see the class's doc) in \a space
 * (a Centerlines keeps its own). Throws ValueError naming "centerlines". */
itk::CenterlineTree
TreeOf(const py::object & value, const std::string & space = "LPS");

/** Defines Centerlines, read_centerlines and extract_centerlines. */
void
RegisterCenterlines(py::module_ & module);
} // namespace vr::python

#endif
