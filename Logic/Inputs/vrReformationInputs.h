// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrReformationInputs_h
#define vrReformationInputs_h

#include "itkCenterlineTree.h"
#include "vrCenterlineNode.h"
#include "vrIntensityWindow.h"
#include "vrVolumeIO.h"
#include "vrVolumeNode.h"

#include <vtkSmartPointer.h>

#include <string>
#include <vector>

namespace vr
{
/** \class ReformationInputs
 * \brief What a host of the module widgets (the viewer) reforms: a volume node and a centerline node as a platform
 * hands them to the logic, or a volume node and a vessel segmentation node whose centerlines the logic extracts; and
 * what the views show of them (the tree the logic converts the centerlines to, branch names, a description). No Qt:
 * the state a host keeps, in the logic's layer.
 *
 * Made once per opened file or phantom, on the controller's worker thread, and never changed afterwards: results
 * share it, so the overlays of an image always belong to the data it was computed from.
 *
 * \sa ReformationController
 * \ingroup VesselReformation
 */
struct ReformationInputs
{
  vtkSmartPointer<VolumeNode> Volume;
  /** The centerlines: the node given, or for a segmentation the logic's extracted centerlines (null until the
   * controller has had the logic extract them). */
  vtkSmartPointer<CenterlineNode> Centerlines;
  /** A vessel segmentation (mask, label map or level set, several files combined; vr::ReadSegmentation) whose
   * centerlines the logic extracts (VesselReformationLogic::SetSegmentationNode); null with a centerline node. */
  vtkSmartPointer<VolumeNode> Segmentation;
  /** What reading the inputs warned about (a DICOM series' gap filled by interpolation, a duplicate file left out; a
   * segmentation on another grid, resampled; most centerline points outside the volume), each in full. */
  std::vector<std::string> Warnings;
  /** What reading them skipped and changes nothing (the entries of a DICOM folder that are no DICOM images). */
  std::vector<std::string> Notes;
  /** The centerline node as the logic converts it (vr::ConvertCenterlineNodeToTree), LPS mm: the ids are the
   * owner labels' values, and each branch carries its name when the source gave one (the one source of names). */
  itk::CenterlineTree Tree;
  /** Where the volume and the centerlines came from: file paths, or the phantom's name. */
  std::string VolumeSource;
  std::string CenterlineSource;
  /** True for a built-in phantom (intensities in HU, so the CTA window suits it), and its name ("thorax"). */
  bool        IsPhantom{ false };
  std::string PhantomName;
  /** The unit the views give the volume's intensities: "HU" for a CT (IntensityUnitOf), empty for other data (an MR
   * angiography's intensities have no unit). */
  std::string IntensityUnit;
  /** The window and level spanning the volume's 1st to 99th intensity percentile (vr::PercentileWindowOf,
   * vrIntensityWindow.h): the first view of a volume without HU. */
  double PercentileWindow{ 0.0 };
  double PercentileLevel{ 0.0 };

  /** \return the name of the branch of Tree with id \a id, or "branch <id>" when it has none. */
  std::string
  BranchName(int id) const;
};

/** The names of the built-in phantoms the viewer offers (itk::GetCTAPhantomNames(): "runoff", "thorax"). */
std::vector<std::string>
PhantomNames();

/** Makes a built-in phantom's volume and exact centerlines as nodes (RAS, as a platform holds them), with the
 * phantom factory (itk::MakeCTAPhantom).
 * \param name one of PhantomNames().
 * \param spacing the phantom's voxel spacing in mm (> 0).
 * \return the inputs. Throws vr::InputError naming the phantom or the spacing. */
ReformationInputs
MakePhantomInputs(const std::string & name, double spacing);

/** Reads a volume (NRRD, NIfTI, MetaImage, or a DICOM series folder) into a volume node, in the pixel type of its
 * file (vr::ReadStoredVolume): the node holds the one copy of the voxels that the logic then samples.
 * \param path the file or folder.
 * \param options which DICOM series of a folder that holds several (vr::VolumeReadOptions).
 * \param report receives the reader's warnings and notes, when given (vr::VolumeReadReport; see AddVolumeReport).
 * \return the node. Throws vr::InputError naming the file (vr::ReadStoredVolume's messages), and
 * vr::DICOMSeriesChoiceRequired, listing the series, for a folder of several without a choice. */
vtkSmartPointer<VolumeNode>
ReadVolumeNode(const std::string &       path,
               const VolumeReadOptions & options = VolumeReadOptions(),
               VolumeReadReport *        report = nullptr);

/** Puts what reading the volume reported into \a inputs: its warnings before theirs, its notes. */
void
AddVolumeReport(ReformationInputs & inputs, const VolumeReadReport & report);

/** Reads centerlines in any format the logic reads (.vtp, .vtk, .mrk.json, .tre, .csv) into a centerline node.
 * \param path the file.
 * \return the node. Throws vr::InputError naming the file and the field (vr::ReadCenterlines' messages). */
vtkSmartPointer<CenterlineNode>
ReadCenterlineNode(const std::string & path);

/** Reads one or more vessel segmentation files (label map, mask, VMTK level set; vr::ReadSegmentation combines
 * several) into a segmentation node, as a platform's label map node.
 * \param paths the files.
 * \param warnings receives vr::ReadSegmentation's warnings.
 * \param descriptions receives a line per file: what it held.
 * \return the node, named by the files. Throws vr::InputError naming the file (vr::ReadSegmentation's messages). */
vtkSmartPointer<VolumeNode>
ReadSegmentationNode(const std::vector<std::string> & paths,
                     std::vector<std::string> &       warnings,
                     std::vector<std::string> &       descriptions);

/** Puts a volume node and a segmentation node together; the centerlines come from the logic's extraction (see
 * ReformationController::LoadInputs).
 * \param volume the volume node.
 * \param segmentation the segmentation node.
 * \return the inputs, without centerlines yet. */
ReformationInputs
MakeSegmentationInputs(vtkSmartPointer<VolumeNode> volume, vtkSmartPointer<VolumeNode> segmentation);

/** \return \a inputs with the centerlines the logic extracted from their segmentation, converted for the overlays.
 * \param inputs segmentation inputs.
 * \param extracted VesselReformationLogic's ReformationOutputs::ExtractedCenterlines. */
ReformationInputs
WithExtractedCenterlines(const ReformationInputs & inputs, vtkSmartPointer<CenterlineNode> extracted);

/** Puts a volume node and a centerline node together, converting the centerlines once for the overlays.
 * \param volume the volume node.
 * \param centerlines the centerline node.
 * \return the inputs; when most centerline points lie outside the volume, Warnings says so in full.
 * Throws vr::InputError when the centerline node does not convert, or when none of its points lies in the volume
 * (vr::CheckCenterlineVolumeFit: the message names both). */
ReformationInputs
MakeInputs(vtkSmartPointer<VolumeNode> volume, vtkSmartPointer<CenterlineNode> centerlines);
} // namespace vr

#endif
