// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrCenterlineFormats_h
#define vrCenterlineFormats_h

#include "itkCenterlineTree.h"
#include "vrCenterlineReport.h"
#include "vrCoordinateFrames.h"

#include <string>

/** The readers and writers behind vr::ReadCenterlines / vr::WriteCenterlines, one file per format. Readers get
 * an existing, non-empty file and return the tree in LPS; \a space is the caller's override (Auto: the file's
 * own system). Writers write to \a temporaryPath (vr::AtomicOutput renames it) and name \a finalPath in errors.
 * All throw vr::InputError naming the file. Not installed: an implementation detail of the IO library. */
namespace vr::detail
{
itk::CenterlineTree
ReadVTKCenterlines(const std::string & path, CoordinateSpace space, CenterlineReadReport & report);
void
WriteVTKCenterlines(const itk::CenterlineTree & tree,
                    const std::string &         finalPath,
                    const std::string &         temporaryPath,
                    CoordinateSpace             space);

itk::CenterlineTree
ReadMarkupsCurves(const std::string & path, CoordinateSpace space, CenterlineReadReport & report);
void
WriteMarkupsCurves(const itk::CenterlineTree & tree,
                   const std::string &         finalPath,
                   const std::string &         temporaryPath,
                   CoordinateSpace             space);

itk::CenterlineTree
ReadTubeTree(const std::string & path, CoordinateSpace space, CenterlineReadReport & report);
void
WriteTubeTree(const itk::CenterlineTree & tree,
              const std::string &         finalPath,
              const std::string &         temporaryPath,
              CoordinateSpace             space);

itk::CenterlineTree
ReadCenterlineCSV(const std::string & path, CoordinateSpace space, CenterlineReadReport & report);
void
WriteCenterlineCSV(const itk::CenterlineTree & tree,
                   const std::string &         finalPath,
                   const std::string &         temporaryPath,
                   CoordinateSpace             space);

/** \a tree with every point mapped RAS <-> LPS (the map is its own inverse). */
itk::CenterlineTree
FlipRASLPS(const itk::CenterlineTree & tree);
} // namespace vr::detail

#endif
