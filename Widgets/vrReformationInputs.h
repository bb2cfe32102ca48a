// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrReformationInputs_h
#define vrReformationInputs_h

#include "itkCenterlineTree.h"
#include "vrCenterlineNode.h"
#include "vrVolumeNode.h"

#include <vtkSmartPointer.h>

#include <map>
#include <string>
#include <vector>

namespace vr
{
/** \class ReformationInputs
 * \brief What the viewer reforms: a volume node and a centerline node as a platform hands them to the logic, and
 * what the views show of them (the tree the logic converts the centerline node to, branch names, a description).
 *
 * Made once per opened file or phantom, on the controller's worker thread, and never changed afterwards: results
 * share it, so the overlays of an image always belong to the data it was computed from.
 *
 * \sa ReformationController
 * \ingroup VesselReformation
 */
struct ReformationInputs
{
  vtkSmartPointer<VolumeNode>     Volume;
  vtkSmartPointer<CenterlineNode> Centerlines;
  /** The centerline node as the logic converts it (vr::ConvertCenterlineNodeToTree), LPS mm: the ids are the
   * owner labels' values. */
  itk::CenterlineTree Tree;
  /** Anatomical names of branch ids when known (the phantoms'); empty otherwise. */
  std::map<int, std::string> BranchNames;
  /** Where the volume and the centerlines came from: file paths, or the phantom's name. */
  std::string VolumeSource;
  std::string CenterlineSource;
  /** True for a built-in phantom (intensities in HU, so the CTA window suits it). */
  bool IsPhantom{ false };

  /** \return "name" of a branch id, or "branch <id>". */
  std::string
  BranchName(int id) const;
};

/** The names of the built-in phantoms the viewer offers ("runoff", ...). */
std::vector<std::string>
PhantomNames();

/** Makes a built-in phantom's volume and exact centerlines as nodes (RAS, as a platform holds them).
 * \param name one of PhantomNames().
 * \param spacing the phantom's voxel spacing in mm (> 0).
 * \return the inputs. Throws vr::InputError naming the phantom or the spacing. */
ReformationInputs
MakePhantomInputs(const std::string & name, double spacing);

/** Reads a volume (NRRD, NIfTI, MetaImage, or a DICOM series folder) into a volume node.
 * \param path the file or folder.
 * \return the node. Throws vr::InputError naming the file (vr::ReadVolume's messages). */
vtkSmartPointer<VolumeNode>
ReadVolumeNode(const std::string & path);

/** Reads centerlines in any format the logic reads (.vtp, .vtk, .mrk.json, .tre, .csv) into a centerline node.
 * \param path the file.
 * \return the node. Throws vr::InputError naming the file and the field (vr::ReadCenterlines' messages). */
vtkSmartPointer<CenterlineNode>
ReadCenterlineNode(const std::string & path);

/** Puts a volume node and a centerline node together, converting the centerlines once for the overlays.
 * \param volume the volume node.
 * \param centerlines the centerline node.
 * \return the inputs. Throws vr::InputError when the centerline node does not convert. */
ReformationInputs
MakeInputs(vtkSmartPointer<VolumeNode> volume, vtkSmartPointer<CenterlineNode> centerlines);
} // namespace vr

#endif
