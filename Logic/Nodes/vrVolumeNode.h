// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrVolumeNode_h
#define vrVolumeNode_h

#include "itkCPRIntensityRescale.h"

#include <vtkImageData.h>
#include <vtkMatrix4x4.h>
#include <vtkObject.h>
#include <vtkSmartPointer.h>

#include <map>
#include <string>

namespace vr
{
/** \class VolumeNode
 * \brief A scalar image as a platform hands it over, shaped like 3D Slicer's vtkMRMLScalarVolumeNode.
 *
 * The voxels live in a single-component vtkImageData whose own origin is 0 and spacing 1 (as in Slicer: the
 * geometry is the node's, not the image data's); the IJK->RAS 4x4 matrix maps a voxel index (i, j, k) to RAS
 * millimetres. String attributes travel with the node, as MRML node attributes do; the 2D outputs of the
 * reformation keep their view there ("CPR_*" entries, LPS, see itk::CPRViewGeometry).
 *
 * The voxels keep the pixel type of their file (docs/design.md "Volumes in their stored type"): a CT of 16-bit integers
 * stays one, its intensity rescale (DICOM's rescale slope and intercept, NIfTI's scl_slope and scl_inter) held beside
 * it and applied by the filters to each value they read. 3D Slicer's node applies the rescale when it loads a series;
 * a platform that hands over voxels already rescaled leaves the node's at the identity.
 *
 * The logic converts nodes to ITK images in one place, vrNodeConversion.h; the ITK image of a node shares its voxels
 * (ConvertVolumeNodeToStoredVolume). WrapVoxelBuffer() makes a node of voxels someone else owns, without a copy.
 *
 * \sa CenterlineNode, VesselReformationLogic
 * \ingroup VesselReformation
 */
class VolumeNode : public vtkObject
{
public:
  static VolumeNode *
  New();
  vtkTypeMacro(VolumeNode, vtkObject);
  void
  PrintSelf(ostream & os, vtkIndent indent) override;

  /** \param imageData the voxels (single component, origin 0, spacing 1); the node keeps a reference. */
  void
  SetImageData(vtkImageData * imageData);
  /** \return the voxels, or null. */
  vtkImageData *
  GetImageData() const
  {
    return m_ImageData;
  }

  /** \param matrix the IJK->RAS matrix (mm), copied; null resets it to identity (the default). */
  void
  SetIJKToRASMatrix(vtkMatrix4x4 * matrix);
  /** \return the node's own matrix; modify it through SetIJKToRASMatrix so the node notices. */
  vtkMatrix4x4 *
  GetIJKToRASMatrix() const
  {
    return m_IJKToRAS;
  }

  /** \param rescale how the stored voxel values map to intensities (slope and intercept); identity by default. */
  void
  SetIntensityRescale(const itk::CPRIntensityRescale & rescale);
  /** \return how the stored voxel values map to intensities. */
  const itk::CPRIntensityRescale &
  GetIntensityRescale() const
  {
    return m_IntensityRescale;
  }

  /** \param name a name for messages ("aorta.mha"). */
  void
  SetName(const std::string & name);
  /** \return the name. */
  const std::string &
  GetName() const
  {
    return m_Name;
  }

  /** Sets a string attribute, as vtkMRMLNode::SetAttribute does.
   * \param key the attribute's name.
   * \param value its value. */
  void
  SetAttribute(const std::string & key, const std::string & value);
  /** \param key the attribute's name.
   * \return the attribute's value, or nullptr when the node has none of that name. */
  const char *
  GetAttribute(const std::string & key) const;
  /** \return every attribute, by name. */
  const std::map<std::string, std::string> &
  GetAttributes() const
  {
    return m_Attributes;
  }

  /** \return the latest modification time of the node, its image data and its matrix. */
  vtkMTimeType
  GetMTime() override;

protected:
  VolumeNode();
  ~VolumeNode() override;

private:
  VolumeNode(const VolumeNode &) = delete;
  void
  operator=(const VolumeNode &) = delete;

  vtkSmartPointer<vtkImageData>      m_ImageData;
  vtkSmartPointer<vtkMatrix4x4>      m_IJKToRAS;
  itk::CPRIntensityRescale           m_IntensityRescale;
  std::string                        m_Name;
  std::map<std::string, std::string> m_Attributes;
};
} // namespace vr

#endif
