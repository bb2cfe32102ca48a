// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrPythonCenterlines.h"

#include "vrCenterlineIO.h"
#include "vrCoordinateFrames.h"
#include "vrPythonEngineRun.h"
#include "vrPythonErrors.h"
#include "vrPythonVolume.h"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <cmath>

namespace vr::python
{
namespace
{
CoordinateSpace
SpaceOf(const std::string & text)
{
  CoordinateSpace space = CoordinateSpace::LPS;
  OnArguments([&] { space = ParseCoordinateSpace(text, "space"); });
  if (space == CoordinateSpace::Auto)
  {
    RaiseValueError("space: give \"LPS\" (ITK, SimpleITK) or \"RAS\" (nibabel, 3D Slicer, VMTK) for points in a list");
  }
  return space;
}

/** One branch from a dict {"points", "radii", "name", "id"} or from an N x 3 array of points. */
itk::CenterlineBranch
BranchOf(const py::handle & item, std::size_t index, CoordinateSpace space)
{
  const std::string     where = "centerlines: branch " + std::to_string(index);
  py::object            points = py::reinterpret_borrow<py::object>(item);
  py::object            radii = py::none();
  itk::CenterlineBranch branch;
  branch.Id = static_cast<int>(index) + 1;
  if (py::isinstance<py::dict>(item))
  {
    const py::dict entry = py::reinterpret_borrow<py::dict>(item);
    if (!entry.contains("points"))
    {
      RaiseValueError(where + ": a branch given as a dict needs \"points\" (N x 3 mm)");
    }
    points = entry["points"];
    if (entry.contains("radii") && !entry["radii"].is_none())
    {
      radii = entry["radii"];
    }
    if (entry.contains("name") && !entry["name"].is_none())
    {
      branch.Name = py::str(entry["name"]).cast<std::string>();
    }
    if (entry.contains("id") && !entry["id"].is_none())
    {
      branch.Id = entry["id"].cast<int>();
    }
  }
  py::array_t<double, py::array::c_style | py::array::forcecast> array;
  try
  {
    array = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(points);
  }
  catch (const py::error_already_set &)
  {
  }
  if (!array || array.ndim() != 2 || array.shape(1) != 3 || array.shape(0) < 2)
  {
    RaiseValueError(where + ": points must be an N x 3 array of mm with N >= 2, got " +
                    (array ? "shape " + py::repr(py::getattr(array, "shape")).cast<std::string>()
                           : py::repr(py::type::of(points)).cast<std::string>()));
  }
  const auto cells = array.unchecked<2>();
  for (py::ssize_t n = 0; n < array.shape(0); ++n)
  {
    itk::Point<double, 3> point;
    for (py::ssize_t c = 0; c < 3; ++c)
    {
      point[c] = cells(n, c);
      if (!std::isfinite(point[c]))
      {
        RaiseValueError(where + ": point " + std::to_string(n) + " is not finite");
      }
    }
    branch.Points.push_back(space == CoordinateSpace::RAS ? RASToLPS(point) : point);
  }
  if (!radii.is_none())
  {
    const auto values = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(radii);
    if (!values || values.ndim() != 1 || values.shape(0) != array.shape(0))
    {
      RaiseValueError(where + ": radii must give one radius (mm) per point (" + std::to_string(array.shape(0)) + ")");
    }
    branch.Radii.assign(values.data(), values.data() + values.shape(0));
  }
  return branch;
}

py::list
BranchesOf(const itk::CenterlineTree & tree, CoordinateSpace space)
{
  py::list branches;
  for (const auto & branch : tree.GetBranches())
  {
    py::array_t<double> points({ static_cast<py::ssize_t>(branch.Points.size()), py::ssize_t{ 3 } });
    auto                cells = points.mutable_unchecked<2>();
    for (std::size_t n = 0; n < branch.Points.size(); ++n)
    {
      const auto point = space == CoordinateSpace::RAS ? LPSToRAS(branch.Points[n]) : branch.Points[n];
      for (py::ssize_t c = 0; c < 3; ++c)
      {
        cells(n, c) = point[c];
      }
    }
    py::dict entry;
    entry["id"] = branch.Id;
    entry["name"] = branch.Name;
    entry["points"] = points;
    entry["radii"] = branch.HasRadii() ? py::object(py::array_t<double>(branch.Radii.size(), branch.Radii.data()))
                                       : py::object(py::none());
    branches.append(entry);
  }
  return branches;
}

void
Validate(const itk::CenterlineTree & tree)
{
  try
  {
    tree.Validate();
  }
  catch (const itk::ExceptionObject & error)
  {
    RaiseValueError(std::string("centerlines: ") + error.GetDescription());
  }
}
} // namespace

itk::CenterlineTree
TreeOf(const py::object & value, const std::string & space)
{
  if (py::isinstance<Centerlines>(value))
  {
    return value.cast<const Centerlines &>().Tree;
  }
  if (value.is_none() || py::isinstance<py::str>(value) || !py::isinstance<py::sequence>(value))
  {
    RaiseValueError("centerlines: give a Centerlines (read_centerlines, extract_centerlines) or a list of branches, "
                    "each an N x 3 array of points or a dict with \"points\" and optional \"radii\", \"name\"; got " +
                    py::repr(py::type::of(value)).cast<std::string>());
  }
  const py::sequence  items = value.cast<py::sequence>();
  const auto          frame = SpaceOf(space);
  itk::CenterlineTree tree;
  if (items.size() == 0)
  {
    RaiseValueError("centerlines: the list is empty; give at least one branch of N x 3 points (mm)");
  }
  for (std::size_t k = 0; k < items.size(); ++k)
  {
    tree.AddBranch(BranchOf(items[k], k, frame));
  }
  Validate(tree);
  return tree;
}

void
RegisterCenterlines(py::module_ & module)
{
  py::class_<Centerlines>(module, "Centerlines", R"doc(
The centerlines of a vessel tree: branches of points (mm) with optional lumen radii (mm) and names.

Centerlines(branches, space="LPS")
    branches  a list; each branch an N x 3 array of points, or a dict {"points": N x 3, "radii": N (optional),
              "name": str (optional), "id": int >= 1 (optional; default its position + 1)}.
    space     "LPS" (ITK, SimpleITK, DICOM) or "RAS" (nibabel, 3D Slicer, VMTK): the frame of the points given.

Branches may overlap (VMTK's source-to-target paths): the reformation merges them. Radii let the reformation keep the
lumen fixed and give vessel_path its lumen when no segmentation is given.
)doc")
    .def(py::init(
           [](const py::object & branches, const std::string & space)
           {
             Centerlines centerlines;
             centerlines.Tree = TreeOf(branches, space);
             return centerlines;
           }),
         py::arg("branches"),
         py::arg("space") = "LPS")
    .def(
      "branches",
      [](const Centerlines & c, const std::string & space) { return BranchesOf(c.Tree, SpaceOf(space)); },
      py::arg("space") = "LPS",
      "The branches as dicts {id, name, points (N x 3, in `space`), radii (N, or None)}.")
    .def("__len__", [](const Centerlines & c) { return c.Tree.GetNumberOfBranches(); })
    .def_property_readonly("number_of_points", [](const Centerlines & c) { return c.Tree.GetNumberOfPoints(); })
    .def_property_readonly("has_radii", [](const Centerlines & c) { return c.Tree.HasRadii(); })
    .def_property_readonly("source", [](const Centerlines & c) { return c.Source; })
    .def_property_readonly("warnings", [](const Centerlines & c) { return c.Warnings; })
    .def(
      "write",
      [](const Centerlines & c, const py::object & path, const std::string & space)
      {
        const std::string file = py::str(py::module_::import("os").attr("fspath")(path)).cast<std::string>();
        CoordinateSpace   frame = CoordinateSpace::Auto;
        OnArguments([&] { frame = ParseCoordinateSpace(space, "space"); });
        OnFiles(file, [&] { WriteCenterlines(c.Tree, file, frame); });
      },
      py::arg("path"),
      py::arg("space") = "auto",
      "Writes .vtp, .vtk, .mrk.json, .tre or .csv (space \"auto\": each format's usual one), whole or not at all.")
    .def("__repr__",
         [](const Centerlines & c)
         {
           return "<Centerlines " + std::to_string(c.Tree.GetNumberOfBranches()) + " branches, " +
                  std::to_string(c.Tree.GetNumberOfPoints()) + " points, " + c.Source + ">";
         });

  module.def(
    "read_centerlines",
    [](const py::object & path, const std::string & space)
    {
      const std::string file = py::str(py::module_::import("os").attr("fspath")(path)).cast<std::string>();
      CoordinateSpace   frame = CoordinateSpace::Auto;
      OnArguments([&] { frame = ParseCoordinateSpace(space, "space"); });
      Centerlines          centerlines;
      CenterlineReadReport report;
      OnFiles(file,
              [&]
              {
                const py::gil_scoped_release release;
                centerlines.Tree = ReadCenterlines(file, frame, &report);
              });
      centerlines.Source = report.Format + ", " + ToString(report.FileSpace);
      return centerlines;
    },
    py::arg("path"),
    py::arg("space") = "auto",
    R"doc(Reads centerlines as the command-line modules do: VMTK .vtp/.vtk (radius from MaximumInscribedSphereRadius
or Radius), 3D Slicer .mrk.json curves, TubeTK .tre, CSV. space overrides the file's own frame ("RAS", "LPS").
Raises OSError naming the file and the field.)doc");

  module.def(
    "extract_centerlines",
    [](const py::object &                       segmentation,
       const std::vector<std::vector<double>> & rootPoints,
       double                                   minimumBranchLength,
       double                                   rootPointTolerance,
       const py::object &                       progress)
    {
      const Segmentation &           input = SegmentationOf(segmentation, "segmentation");
      CenterlineExtractionParameters parameters;
      for (const auto & point : rootPoints)
      {
        if (point.size() != 3)
        {
          RaiseValueError("root_points: each root point is 3 numbers (RAS mm)");
        }
        parameters.RootPointsRAS.emplace_back(point.data());
      }
      parameters.MinimumBranchLength = minimumBranchLength;
      parameters.RootPointTolerance = rootPointTolerance;
      OnArguments([&] { parameters.Validate(); });
      Centerlines centerlines;
      OnArguments(
        [&]
        {
          RunEngine(
            progress,
            [&](ProgressSink & sink)
            {
              centerlines.Tree = ExtractCenterlineTree(
                input.Mask,
                "segmentation " + input.Name,
                parameters,
                [&sink](double fraction, const std::string & stage)
                {
                  if (sink.StopRequested())
                  {
                    throw Cancelled("centerline extraction: cancelled");
                  }
                  sink.Report(fraction, stage);
                },
                centerlines.Warnings);
              NameBranchesByRegion(centerlines.Tree, input.Regions.GetPointer(), RegionNamesOf(input));
            },
            [] {});
        });
      centerlines.Source = "extracted from segmentation " + input.Name;
      return centerlines;
    },
    py::arg("segmentation"),
    py::arg("root_points") = std::vector<std::vector<double>>(),
    py::arg("minimum_branch_length") = 0.0,
    py::arg("root_point_tolerance") = 10.0,
    py::arg("progress") = py::none(),
    R"doc(Centerlines with radii from a vessel segmentation (a Segmentation from read_segmentation() or
Segmentation.from_volume()), with the filter the ExtractCenterlines module runs. root_points: RAS mm, at most one per
connected component; minimum_branch_length: shorter end branches are dropped (mm). Branches are named after the file
(TotalSegmentator: one per vessel) their voxels came from. progress: a callable (fraction, stage); returning False
cancels (Cancelled). Raises ValueError when the segmentation holds no elongated vessel.)doc");
}
} // namespace vr::python
