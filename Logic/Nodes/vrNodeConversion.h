// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrNodeConversion_h
#define vrNodeConversion_h

#include "itkCenterlineTree.h"
#include "vrCenterlineNode.h"
#include "vrImageTypes.h"
#include "vrStoredVolume.h"
#include "vrVolumeNode.h"

#include <array>
#include <memory>
#include <string>

/** \file vrNodeConversion.h
 * \brief The one place where platform nodes (RAS, VTK) and the ITK side (LPS) meet, as SlicerRT's
 * ConvertVolumeNodeToItkImage. Points and directions go through vrCoordinateFrames.h.
 *
 * Every function throws vr::InputError naming the node and what is wrong with it.
 */
namespace vr
{
/** A volume node as an ITK volume in LPS in the node's own pixel type, sharing the node's voxels: no copy is made
 * (docs/design.md "Volumes in their stored type"). Spacing and direction come from the IJK->RAS matrix's columns,
 * origin from its translation, the start index from the image extent; the rescale from the node. The image keeps the
 * node's voxel array alive, so it stays valid whatever later happens to the node; voxels changed in place through
 * either are changed in both, as in 3D Slicer, where node and filter share one buffer.
 *
 * Shared: signed and unsigned char, short and unsigned short, float and double voxels (the stored pixel types). A node
 * of another scalar type (32- or 64-bit integers, VTK's plain char) or of an unusual memory layout becomes a float copy
 * with the rescale applied, as every node did before.
 * \param node a node with image data; the image data's own origin must be 0 and spacing 1 (Slicer's rule).
 * \return the volume. Throws vr::InputError naming the node and what is wrong with it. */
StoredVolume
ConvertVolumeNodeToStoredVolume(VolumeNode * node);

/** A stored volume as a volume node sharing its voxels (no copy): the node's voxel array keeps the image's buffer
 * alive. The IJK->RAS matrix from the image's geometry, the rescale from the volume, the "DICOM.*" entries of the
 * image's metadata dictionary as attributes (ConvertItkImageToVolumeNode).
 * \param volume a volume of a stored pixel type.
 * \param name the node's name.
 * \return a new node. Throws vr::InputError when the volume is null or of another pixel type. */
vtkSmartPointer<VolumeNode>
ConvertStoredVolumeToVolumeNode(const StoredVolume & volume, const std::string & name);

/** Makes a volume node of voxels that someone else owns, without a copy: the entry point for a host that holds a
 * volume's voxels itself, such as a NumPy array handed over from Python or a platform's own buffer. The node (and
 * every ITK image ConvertVolumeNodeToStoredVolume makes of it) reads \a voxels in place and holds \a owner until the
 * last of them is gone; \a owner is released on whichever thread lets go of the last one.
 *
 * The voxels are a contiguous block of dimensions[0] x dimensions[1] x dimensions[2] values of \a pixelType, i
 * varying fastest, then j, then k: a C-ordered NumPy array of shape (k, j, i), as ITK and VTK lay out an image.
 * \param voxels the first voxel (not null).
 * \param pixelType UCHAR, CHAR (signed), USHORT, SHORT, FLOAT or DOUBLE.
 * \param dimensions the voxels along i, j and k, each at least 1.
 * \param ijkToRAS the voxel index to RAS matrix (mm), copied; null for the identity.
 * \param owner what keeps the voxels alive (e.g. a reference to the NumPy array); may be null when the caller
 * guarantees it otherwise.
 * \param name the node's name.
 * \param rescale stored values to intensities.
 * \return the node. Throws vr::InputError naming what is wrong (a null pointer, an empty axis, another pixel type). */
vtkSmartPointer<VolumeNode>
WrapVoxelBuffer(void *                           voxels,
                itk::IOComponentEnum             pixelType,
                const std::array<int, 3> &       dimensions,
                vtkMatrix4x4 *                   ijkToRAS,
                std::shared_ptr<const void>      owner,
                const std::string &              name,
                const itk::CPRIntensityRescale & rescale = {});

/** The IJK->RAS matrix (mm) of an ITK grid in LPS: its spacing, direction and origin (the voxel index, not the region's
 * start, is I, J, K), as the nodes made here carry it; for a reader that wraps voxels of its own with WrapVoxelBuffer
 * (a DICOM series in a shared mapping, say) from the LPS geometry it knows. */
vtkSmartPointer<vtkMatrix4x4>
IJKToRASMatrixOf(const itk::ImageBase<3> & image);

/** A volume node as a float ITK volume in LPS (the node's rescale applied), with the geometry of
 * ConvertVolumeNodeToStoredVolume().
 * \param node a node with image data; the image data's own origin must be 0 and spacing 1 (Slicer's rule).
 * \return a new image that owns a copy of the voxels, as float: for what needs float values (a segmentation, tests);
 * the reformation samples the stored volume. */
VolumeImageType::Pointer
ConvertVolumeNodeToItkImage(VolumeNode * node);

/** The inverse of ConvertVolumeNodeToItkImage.
 * \param image a float volume in LPS.
 * \param name the node's name.
 * \return a new node with a copy of the voxels (float) and the IJK->RAS matrix (ConvertStoredVolumeToVolumeNode
 * shares them instead). */
vtkSmartPointer<VolumeNode>
ConvertItkImageToVolumeNode(const VolumeImageType * image, const std::string & name);
/** The same for a label map or vessel mask: a node of unsigned char voxels, as 3D Slicer's label map volume node
 * holds them. */
vtkSmartPointer<VolumeNode>
ConvertItkImageToVolumeNode(const LabelMapVolumeType * image, const std::string & name);

/** A 2D output of the reformation as a one-slice volume node placed on the view plane: voxel (i, j, 0) lies at
 * B(i, j) in RAS, the third axis along the view direction. The view (and the rest of the image's metadata
 * dictionary) becomes the node's attributes.
 * \param image a 2D image whose metadata holds a CPR view (CPRViewGeometry::WriteToDictionary).
 * \param name the node's name.
 * \return a new node with a copy of the pixels, of the image's pixel type. */
vtkSmartPointer<VolumeNode>
ConvertItkImageToVolumeNode(const DepthImageType * image, const std::string & name);
vtkSmartPointer<VolumeNode>
ConvertItkImageToVolumeNode(const MaskImageType * image, const std::string & name);
vtkSmartPointer<VolumeNode>
ConvertItkImageToVolumeNode(const LabelImageType * image, const std::string & name);

/** A one-slice volume node holding a reformation output back as the 2D ITK image on its view grid (spacing,
 * origin and metadata from the view in the node's attributes); pixels are cast to the image's type.
 * \param node a node made by ConvertItkImageToVolumeNode(2D) or alike: one slice, CPR_* attributes.
 * \return a new image. */
DepthImageType::Pointer
ConvertVolumeNodeToDepthImage(VolumeNode * node);
MaskImageType::Pointer
ConvertVolumeNodeToMaskImage(VolumeNode * node);
LabelImageType::Pointer
ConvertVolumeNodeToLabelImage(VolumeNode * node);

/** A centerline node's polylines as a tree in LPS, through vr::CenterlineTreeFromPolyData (vrCenterlinePolyData.h,
 * the one polydata -> tree conversion, shared with the .vtp/.vtk reader): VMTK's overlapping paths are merged,
 * radii come from "MaximumInscribedSphereRadius" or "Radius", ids from the "BranchIds" cell array when present.
 * \param node a node with polydata (RAS).
 * \return the tree, validated (itk::CenterlineTree::Validate). */
itk::CenterlineTree
ConvertCenterlineNodeToTree(CenterlineNode * node);

/** The inverse, through vr::PolyDataFromCenterlineTree: one polyline per branch in RAS, the "Radius" point array
 * when the tree has radii and the ids in the "BranchIds" cell array.
 * \param tree a tree in LPS.
 * \param name the node's name.
 * \return a new node. */
vtkSmartPointer<CenterlineNode>
ConvertTreeToCenterlineNode(const itk::CenterlineTree & tree, const std::string & name);
} // namespace vr

#endif
