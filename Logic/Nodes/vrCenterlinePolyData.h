// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrCenterlinePolyData_h
#define vrCenterlinePolyData_h

#include "itkCenterlineTree.h"
#include "vrCenterlineReport.h"
#include "vrCoordinateFrames.h"

#include <vtkSmartPointer.h>

#include <string>

class vtkPolyData;

namespace vr
{
/** Radius arrays recognised on centerline polydata, in order of preference: VMTK's, then 3D Slicer's. */
constexpr const char * VMTKRadiusArrayName = "MaximumInscribedSphereRadius";
constexpr const char * SlicerRadiusArrayName = "Radius";
/** The cell array that carries branch ids through the .vtp/.vtk writer and back. */
constexpr const char * BranchIdsArrayName = "BranchIds";
/** The string cell array that carries branch names (itk::CenterlineBranch::Name) through nodes and files. */
constexpr const char * BranchNamesArrayName = "BranchNames";

/** How CenterlineTreeFromPolyData treats points that several polylines share.
 * \ingroup VesselReformation
 */
struct CenterlinePolyDataOptions
{
  /** Points of different polylines closer than this (mm) are the same point: VMTK and 3D Slicer copy the
   * shared trunk exactly, so 1 um is far above round-off and far below any vessel detail. */
  double SharedPointTolerance{ 1e-3 };
};

/** Turns centerline polylines (a VMTK centerline file, a 3D Slicer centerline model or curve node) into a tree
 * in LPS mm: the one implementation behind the .vtp/.vtk reader and the logic's centerline node.
 *
 * \param polyData  polylines (line cells); a radius per point from the point array
 *                  "MaximumInscribedSphereRadius" (VMTK) or "Radius" (3D Slicer), when present.
 * \param space     the system of the points: RAS (3D Slicer nodes, VMTK), LPS, or Auto (the 3D Slicer "SPACE"
 *                  field-data string array when present, else RAS).
 * \param sourceName names the input in error messages (a file name, a node name).
 * \param report    receives what was found; may be null.
 *
 * This function only converts: it reads the polylines, radii and cell arrays, and leaves the topology to the tree's
 * side (itkCenterlinePolylineMerge.h). Without branch arrays, VMTK's overlapping source-to-target paths are merged
 * (itk::MergeOverlappingPaths: two paths sharing a trunk give three branches); with the vmtkbranchextractor cell
 * arrays GroupIds, Blanking, CenterlineIds and TractIds, each non-blanked group becomes one branch
 * (itk::MergeBranchGroups, as vmtkcenterlinemerge does).
 *
 * Branch ids are 1, 2, ... in order of appearance, or the cell array "BranchIds" when each polyline became
 * exactly one branch (what WriteCenterlines writes). Branch names come from a string cell array ("BranchNames", as
 * written by PolyDataFromCenterlineTree, or "BranchName", "Name", "Names", "GroupNames"): each branch takes the
 * name of the polyline it came from (a trunk cut where a child leaves keeps its name in each part; a merged group
 * takes its first tract's).
 *
 * Throws vr::InputError naming \a sourceName and the point, cell or array on: no polyline, a non-finite
 * coordinate, a radius array with the wrong number of values or components, a radius that is negative or not
 * finite.
 */
itk::CenterlineTree
CenterlineTreeFromPolyData(vtkPolyData *                     polyData,
                           CoordinateSpace                   space = CoordinateSpace::RAS,
                           const std::string &               sourceName = "centerline polydata",
                           CenterlineReadReport *            report = nullptr,
                           const CenterlinePolyDataOptions & options = CenterlinePolyDataOptions());

/** One polyline per branch, in \a space (RAS for a 3D Slicer node; Auto means RAS), with the point array
 * "Radius" when the tree has radii, the cell array "BranchIds", the string cell array "BranchNames" when any branch
 * has a name, and the 3D Slicer "SPACE" field-data entry. */
vtkSmartPointer<vtkPolyData>
PolyDataFromCenterlineTree(const itk::CenterlineTree & tree, CoordinateSpace space = CoordinateSpace::RAS);
} // namespace vr

#endif
