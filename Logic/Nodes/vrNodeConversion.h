// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrNodeConversion_h
#define vrNodeConversion_h

#include "itkCenterlineTree.h"
#include "vrCenterlineNode.h"
#include "vrImageTypes.h"
#include "vrVolumeNode.h"

#include <string>

/** \file vrNodeConversion.h
 * \brief The one place where platform nodes (RAS, VTK) and the ITK side (LPS) meet, as SlicerRT's
 * ConvertVolumeNodeToItkImage. Points and directions go through vrCoordinateFrames.h.
 *
 * Every function throws vr::InputError naming the node and what is wrong with it.
 */
namespace vr
{
/** A volume node (any single-component scalar type) as a float ITK volume in LPS: spacing and direction from
 * the IJK->RAS matrix's columns, origin from its translation, the start index from the image extent.
 * \param node a node with image data; the image data's own origin must be 0 and spacing 1 (Slicer's rule).
 * \return a new image that owns a copy of the voxels. */
VolumeImageType::Pointer
ConvertVolumeNodeToItkImage(VolumeNode * node);

/** The IJK->RAS matrix of a 3D image's grid in LPS (voxel index -> RAS mm), as ConvertItkImageToVolumeNode gives its
 * nodes: for a host that makes a node over voxels it holds already (the Python package's volumes).
 * \param image any 3D image in LPS.
 * \return a new matrix. */
vtkSmartPointer<vtkMatrix4x4>
IJKToRASMatrixOf(const itk::ImageBase<3> * image);

/** The inverse of ConvertVolumeNodeToItkImage.
 * \param image a float volume in LPS.
 * \param name the node's name.
 * \return a new node with a copy of the voxels (float) and the IJK->RAS matrix. */
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
