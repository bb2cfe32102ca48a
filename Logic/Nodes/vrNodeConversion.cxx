// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrNodeConversion.h"

#include "itkCPRViewGeometry.h"
#include "itkCPRVolumeSampler.h"
#include "itkMetaDataObject.h"
#include "vrCenterlinePolyData.h"
#include "vrCoordinateFrames.h"
#include "vrAvailableMemory.h"
#include "vrInputError.h"
#include "vrSharedVoxelContainer.h"

#include <vtkDataArray.h>
#include <vtkImageData.h>
#include <vtkInformation.h>
#include <vtkInformationObjectBaseKey.h>
#include <vtkObjectFactory.h>
#include <vtkMatrix3x3.h>
#include <vtkMatrix4x4.h>
#include <vtkPointData.h>
#include <vtkSetGet.h>

#include <cmath>
#include <cstdint>
#include <type_traits>
#include <sstream>

namespace vr
{
namespace
{
using Point3 = itk::Point<double, 3>;

std::string
Describe(const char * kind, const std::string & name)
{
  return std::string(kind) + (name.empty() ? std::string() : " \"" + name + "\"");
}

/** A direction or offset taken through the point conversion, so that RAS <-> LPS stays in vrCoordinateFrames. */
Point3
AsPoint(double x, double y, double z)
{
  Point3 point;
  point[0] = x;
  point[1] = y;
  point[2] = z;
  return point;
}

template<typename TSource>
void
CopyAsFloat(const TSource * source, std::size_t count, const itk::CPRIntensityRescale & rescale, float * target)
{
  if (rescale.IsIdentity())
  {
    for (std::size_t k = 0; k < count; ++k)
    {
      target[k] = static_cast<float>(source[k]);
    }
    return;
  }
  for (std::size_t k = 0; k < count; ++k)
  {
    target[k] = static_cast<float>(rescale.Apply(static_cast<double>(source[k])));
  }
}

/** Keeps what owns shared voxels alive for as long as a VTK array reads them: held in the array's information, so it
 * goes with the array (a plain free function, all VTK offers for a foreign buffer, cannot carry it). */
class VoxelOwner : public vtkObject
{
public:
  static VoxelOwner *
  New();
  vtkTypeMacro(VoxelOwner, vtkObject);
  std::shared_ptr<const void> Owner;

protected:
  VoxelOwner() = default;
  ~VoxelOwner() override = default;

private:
  VoxelOwner(const VoxelOwner &) = delete;
  void
  operator=(const VoxelOwner &) = delete;
};
vtkStandardNewMacro(VoxelOwner);

vtkInformationObjectBaseKey *
VoxelOwnerKey()
{
  // Deleted at exit by VTK's key manager, as every information key.
  static auto * key = new vtkInformationObjectBaseKey("VoxelOwner", "vr::VolumeNode");
  return key;
}

/** A VTK array of \a count values of \a vtkType read in place at \a voxels, holding \a owner. */
vtkSmartPointer<vtkDataArray>
WrapVoxels(void * voxels, int vtkType, vtkIdType count, std::shared_ptr<const void> owner)
{
  auto array = vtkSmartPointer<vtkDataArray>::Take(vtkDataArray::CreateDataArray(vtkType));
  array->SetNumberOfComponents(1);
  array->SetVoidArray(voxels, count, 1); // 1: VTK never frees these voxels; the owner does
  auto holder = vtkSmartPointer<VoxelOwner>::New();
  holder->Owner = std::move(owner);
  array->GetInformation()->Set(VoxelOwnerKey(), holder);
  return array;
}

/** The VTK scalar type of a stored pixel type; -1 for another type. */
int
VTKTypeOf(itk::IOComponentEnum pixelType)
{
  switch (pixelType)
  {
    case itk::IOComponentEnum::CHAR:
      return VTK_SIGNED_CHAR;
    case itk::IOComponentEnum::UCHAR:
      return VTK_UNSIGNED_CHAR;
    case itk::IOComponentEnum::SHORT:
      return VTK_SHORT;
    case itk::IOComponentEnum::USHORT:
      return VTK_UNSIGNED_SHORT;
    case itk::IOComponentEnum::FLOAT:
      return VTK_FLOAT;
    case itk::IOComponentEnum::DOUBLE:
      return VTK_DOUBLE;
    default:
      return -1;
  }
}

/** Copies with a cast; for an unsigned target (mask, labels) a negative value becomes 0 rather than wrapping. */
template<typename TSource, typename TTarget>
void
CopyCast(const TSource * source, std::size_t count, TTarget * target)
{
  for (std::size_t k = 0; k < count; ++k)
  {
    if constexpr (std::is_unsigned_v<TTarget> && std::is_signed_v<TSource>)
    {
      target[k] = source[k] < 0 ? TTarget{ 0 } : static_cast<TTarget>(source[k]);
    }
    else
    {
      target[k] = static_cast<TTarget>(source[k]);
    }
  }
}

/** Checks what every node conversion needs: image data, one component, Slicer's origin 0 and spacing 1. */
vtkImageData *
CheckedImageData(VolumeNode * node, const std::string & what)
{
  if (node == nullptr)
  {
    throw InputError(what + ": no node given");
  }
  vtkImageData * data = node->GetImageData();
  if (data == nullptr || data->GetPointData()->GetScalars() == nullptr)
  {
    throw InputError(what + ": has no voxel data");
  }
  if (data->GetNumberOfScalarComponents() != 1)
  {
    throw InputError(what + ": has " + std::to_string(data->GetNumberOfScalarComponents()) +
                     " components per voxel; a scalar volume has one");
  }
  const double * origin = data->GetOrigin();
  const double * spacing = data->GetSpacing();
  vtkMatrix3x3 * direction = data->GetDirectionMatrix();
  bool           identityDirection = true;
  for (int r = 0; r < 3; ++r)
  {
    for (int c = 0; c < 3; ++c)
    {
      identityDirection = identityDirection && direction->GetElement(r, c) == (r == c ? 1.0 : 0.0);
    }
  }
  if (origin[0] != 0.0 || origin[1] != 0.0 || origin[2] != 0.0 || spacing[0] != 1.0 || spacing[1] != 1.0 ||
      spacing[2] != 1.0 || !identityDirection)
  {
    throw InputError(what + ": the image data has its own origin, spacing or direction; as in 3D Slicer it must "
                            "have origin 0, spacing 1 and identity direction, the geometry belonging in IJKToRAS");
  }
  int extent[6];
  data->GetExtent(extent);
  if (extent[1] < extent[0] || extent[3] < extent[2] || extent[5] < extent[4])
  {
    throw InputError(what + ": the image data is empty");
  }
  return data;
}

/** Makes a one-slice node on the view plane for a 2D output. */
template<typename TImage>
vtkSmartPointer<VolumeNode>
Convert2DImageToNode(const TImage * image, int vtkScalarType, const std::string & name)
{
  const std::string what = Describe("output image", name);
  if (image == nullptr)
  {
    throw InputError(what + ": no image given");
  }
  itk::CPRViewGeometry view;
  try
  {
    view = itk::CPRViewGeometry::ReadFromDictionary(image->GetMetaDataDictionary());
  }
  catch (const itk::ExceptionObject & error)
  {
    throw InputError(what + ": " + error.GetDescription());
  }
  const auto size = image->GetBufferedRegion().GetSize();
  if (size != view.GetSize())
  {
    std::ostringstream message;
    message << what << ": its size " << size << " differs from its view's " << view.GetSize();
    throw InputError(message.str());
  }
  auto data = vtkSmartPointer<vtkImageData>::New();
  data->SetExtent(0, static_cast<int>(size[0]) - 1, 0, static_cast<int>(size[1]) - 1, 0, 0);
  data->AllocateScalars(vtkScalarType, 1);
  const std::size_t count = size[0] * size[1];
  std::copy(image->GetBufferPointer(),
            image->GetBufferPointer() + count,
            static_cast<typename TImage::PixelType *>(data->GetScalarPointer()));

  // IJK -> LPS: B(i, j) = B(0, 0) + i sx u - j sy up; the third axis steps 1 mm along v.
  const auto   u = view.GetU() * view.GetSpacing()[0];
  const auto   down = view.GetUp() * -view.GetSpacing()[1];
  const auto & v = view.GetV();
  const Point3 columns[3] = { LPSToRAS(AsPoint(u[0], u[1], u[2])),
                              LPSToRAS(AsPoint(down[0], down[1], down[2])),
                              LPSToRAS(AsPoint(v[0], v[1], v[2])) };
  const Point3 corner = LPSToRAS(view.PlanePoint(0.0, 0.0));
  auto         matrix = vtkSmartPointer<vtkMatrix4x4>::New();
  for (int r = 0; r < 3; ++r)
  {
    for (int c = 0; c < 3; ++c)
    {
      matrix->SetElement(r, c, columns[c][r]);
    }
    matrix->SetElement(r, 3, corner[r]);
  }

  auto node = vtkSmartPointer<VolumeNode>::New();
  node->SetName(name);
  node->SetImageData(data);
  node->SetIJKToRASMatrix(matrix);
  const itk::MetaDataDictionary & dictionary = image->GetMetaDataDictionary();
  for (const auto & key : dictionary.GetKeys())
  {
    std::string value;
    if (itk::ExposeMetaData<std::string>(dictionary, key, value))
    {
      node->SetAttribute(key, value);
    }
  }
  return node;
}

/** Reads a one-slice node back onto its view grid. */
template<typename TImage>
typename TImage::Pointer
ConvertNodeTo2DImage(VolumeNode * node)
{
  const std::string what = Describe("image node", node ? node->GetName() : std::string());
  vtkImageData *    data = CheckedImageData(node, what);
  int               dimensions[3];
  data->GetDimensions(dimensions);
  if (dimensions[2] != 1)
  {
    throw InputError(what + ": has " + std::to_string(dimensions[2]) + " slices; a reformation output has one");
  }
  itk::MetaDataDictionary dictionary;
  for (const auto & attribute : node->GetAttributes())
  {
    itk::EncapsulateMetaData<std::string>(dictionary, attribute.first, attribute.second);
  }
  itk::CPRViewGeometry view;
  try
  {
    view = itk::CPRViewGeometry::ReadFromDictionary(dictionary);
  }
  catch (const itk::ExceptionObject & error)
  {
    throw InputError(what + ": " + error.GetDescription());
  }
  if (view.GetSize()[0] != static_cast<itk::SizeValueType>(dimensions[0]) ||
      view.GetSize()[1] != static_cast<itk::SizeValueType>(dimensions[1]))
  {
    throw InputError(what + ": its " + std::to_string(dimensions[0]) + " x " + std::to_string(dimensions[1]) +
                     " pixels differ from the size of the view in its attributes");
  }
  auto image = TImage::New();
  view.ConfigureImage(image.GetPointer());
  for (const auto & key : dictionary.GetKeys())
  {
    std::string value;
    itk::ExposeMetaData<std::string>(dictionary, key, value);
    itk::EncapsulateMetaData<std::string>(image->GetMetaDataDictionary(), key, value);
  }
  image->Allocate();
  const std::size_t count = static_cast<std::size_t>(dimensions[0]) * dimensions[1];
  using PixelType = typename TImage::PixelType;
  PixelType * target = image->GetBufferPointer();
  switch (data->GetScalarType())
  {
    vtkTemplateMacro(CopyCast(static_cast<const VTK_TT *>(data->GetScalarPointer()), count, target));
    default:
      throw InputError(what + ": voxel type " + std::string(data->GetScalarTypeAsString()) + " is not supported");
  }
  return image;
}
} // namespace

namespace
{
/** A volume node's grid in LPS, from its IJK->RAS matrix and its image data's extent. */
struct NodeGrid
{
  itk::ImageBase<3>::SpacingType   Spacing;
  itk::ImageBase<3>::DirectionType Direction;
  itk::ImageBase<3>::PointType     Origin;
  itk::ImageBase<3>::RegionType    Region;

  void
  ConfigureImage(itk::ImageBase<3> & image) const
  {
    image.SetRegions(Region);
    image.SetSpacing(Spacing);
    image.SetDirection(Direction);
    image.SetOrigin(Origin);
  }
};

NodeGrid
GridOfNode(VolumeNode * node, vtkImageData * data, const std::string & what)
{
  vtkMatrix4x4 * ijkToRAS = node->GetIJKToRASMatrix();
  bool           finite = true;
  for (int r = 0; r < 4; ++r)
  {
    for (int c = 0; c < 4; ++c)
    {
      finite = finite && std::isfinite(ijkToRAS->GetElement(r, c));
    }
  }
  if (!finite || ijkToRAS->GetElement(3, 0) != 0.0 || ijkToRAS->GetElement(3, 1) != 0.0 ||
      ijkToRAS->GetElement(3, 2) != 0.0 || ijkToRAS->GetElement(3, 3) != 1.0)
  {
    throw InputError(what + ": IJKToRAS is not a finite affine matrix (last row must be 0 0 0 1)");
  }

  NodeGrid grid;
  for (unsigned int axis = 0; axis < 3; ++axis)
  {
    const Point3 column =
      RASToLPS(AsPoint(ijkToRAS->GetElement(0, axis), ijkToRAS->GetElement(1, axis), ijkToRAS->GetElement(2, axis)));
    const double length = column.GetVectorFromOrigin().GetNorm();
    if (!(length > 0.0))
    {
      throw InputError(what + ": IJKToRAS column " + std::to_string(axis) + " is zero, so the voxel spacing is 0");
    }
    grid.Spacing[axis] = length;
    for (unsigned int row = 0; row < 3; ++row)
    {
      grid.Direction[row][axis] = column[row] / length;
    }
  }
  if (std::abs(vnl_determinant(grid.Direction.GetVnlMatrix())) < 1e-6)
  {
    throw InputError(what + ": IJKToRAS is singular (its axes are parallel)");
  }
  const Point3 origin =
    RASToLPS(AsPoint(ijkToRAS->GetElement(0, 3), ijkToRAS->GetElement(1, 3), ijkToRAS->GetElement(2, 3)));
  grid.Origin = origin;

  int extent[6];
  data->GetExtent(extent);
  for (unsigned int axis = 0; axis < 3; ++axis)
  {
    grid.Region.SetIndex(axis, extent[2 * axis]);
    grid.Region.SetSize(axis,
                        static_cast<itk::SizeValueType>(extent[2 * axis + 1]) -
                          static_cast<itk::SizeValueType>(extent[2 * axis]) + 1);
  }
  const auto scalars = data->GetPointData()->GetScalars();
  if (static_cast<std::uint64_t>(scalars->GetNumberOfTuples()) != grid.Region.GetNumberOfPixels())
  {
    throw InputError(what + ": its voxel array holds " + std::to_string(scalars->GetNumberOfTuples()) + " values for " +
                     std::to_string(grid.Region.GetNumberOfPixels()) + " voxels");
  }
  return grid;
}

/** The node's voxels as an ITK image of their own type, sharing them. */
template<typename TPixel>
StoredVolume
ShareNodeVoxels(const NodeGrid & grid, vtkDataArray * scalars, const itk::CPRIntensityRescale & rescale)
{
  auto image = itk::Image<TPixel, 3>::New();
  grid.ConfigureImage(*image);
  auto container = detail::SharedVoxelContainer<TPixel>::New();
  container->Share(static_cast<TPixel *>(scalars->GetVoidPointer(0)),
                   grid.Region.GetNumberOfPixels(),
                   std::make_shared<vtkSmartPointer<vtkDataArray>>(scalars));
  image->SetPixelContainer(container);
  return StoredVolume{ image.GetPointer(), rescale };
}

VolumeImageType::Pointer
CopyNodeVoxelsAsFloat(const NodeGrid & grid, vtkImageData * data, VolumeNode * node, const std::string & what)
{
  // Refused before it is allocated, naming the bytes, as a reader refuses a volume that does not fit.
  const double needed = static_cast<double>(grid.Region.GetNumberOfPixels()) * sizeof(float);
  const double available = AvailableMemoryInBytes();
  if (needed > available)
  {
    throw InputError(what + ": its voxels as float (a copy, for voxels of type " +
                     std::string(data->GetScalarTypeAsString()) + ") need " + DescribeBytes(needed) +
                     " of memory, more than the " + DescribeBytes(available) + " available");
  }
  auto image = VolumeImageType::New();
  grid.ConfigureImage(*image);
  image->Allocate();
  const std::size_t                count = grid.Region.GetNumberOfPixels();
  float *                          target = image->GetBufferPointer();
  const itk::CPRIntensityRescale & rescale = node->GetIntensityRescale();
  switch (data->GetScalarType())
  {
    vtkTemplateMacro(CopyAsFloat(static_cast<const VTK_TT *>(data->GetScalarPointer()), count, rescale, target));
    default:
      throw InputError(what + ": voxel type " + std::string(data->GetScalarTypeAsString()) + " is not supported");
  }
  return image;
}

void
CheckRescale(const itk::CPRIntensityRescale & rescale, const std::string & what)
{
  if (!rescale.IsValid())
  {
    std::ostringstream message;
    message << what << ": its intensity rescale (" << rescale
            << ") is invalid: both must be finite and the slope must not be 0";
    throw InputError(message.str());
  }
}
} // namespace

StoredVolume
ConvertVolumeNodeToStoredVolume(VolumeNode * node)
{
  const std::string what = Describe("volume node", node ? node->GetName() : std::string());
  vtkImageData *    data = CheckedImageData(node, what);
  const NodeGrid    grid = GridOfNode(node, data, what);
  const auto &      rescale = node->GetIntensityRescale();
  CheckRescale(rescale, what);
  vtkDataArray * scalars = data->GetPointData()->GetScalars();
  if (scalars->HasStandardMemoryLayout())
  {
    switch (scalars->GetDataType())
    {
      case VTK_SHORT:
        return ShareNodeVoxels<short>(grid, scalars, rescale);
      case VTK_UNSIGNED_SHORT:
        return ShareNodeVoxels<unsigned short>(grid, scalars, rescale);
      case VTK_FLOAT:
        return ShareNodeVoxels<float>(grid, scalars, rescale);
      case VTK_DOUBLE:
        return ShareNodeVoxels<double>(grid, scalars, rescale);
      case VTK_UNSIGNED_CHAR:
        return ShareNodeVoxels<unsigned char>(grid, scalars, rescale);
      case VTK_SIGNED_CHAR:
        return ShareNodeVoxels<signed char>(grid, scalars, rescale);
      default:
        break;
    }
  }
  return StoredVolume{ CopyNodeVoxelsAsFloat(grid, data, node, what).GetPointer(), itk::CPRIntensityRescale() };
}

VolumeImageType::Pointer
ConvertVolumeNodeToItkImage(VolumeNode * node)
{
  const std::string what = Describe("volume node", node ? node->GetName() : std::string());
  vtkImageData *    data = CheckedImageData(node, what);
  const NodeGrid    grid = GridOfNode(node, data, what);
  CheckRescale(node->GetIntensityRescale(), what);
  return CopyNodeVoxelsAsFloat(grid, data, node, what);
}

namespace
{
/** The image data of a 3D image's grid: the extent from its buffered region, no scalars yet. */
vtkSmartPointer<vtkImageData>
ImageDataOfGrid(const itk::ImageBase<3> & image)
{
  const auto & region = image.GetBufferedRegion();
  auto         data = vtkSmartPointer<vtkImageData>::New();
  int          extent[6];
  for (unsigned int axis = 0; axis < 3; ++axis)
  {
    extent[2 * axis] = static_cast<int>(region.GetIndex(axis));
    extent[2 * axis + 1] = static_cast<int>(region.GetIndex(axis) + region.GetSize(axis)) - 1;
  }
  data->SetExtent(extent);
  return data;
}

/** A node of \a data placed by the geometry of \a image (IJK->RAS), with the image's DICOM attributes. */
vtkSmartPointer<VolumeNode>
MakeNodeOfImage(const itk::ImageBase<3> & image, vtkImageData * data, const std::string & name)
{
  auto node = vtkSmartPointer<VolumeNode>::New();
  node->SetName(name);
  node->SetImageData(data);
  node->SetIJKToRASMatrix(IJKToRASMatrixOf(image));
  // What a reader knew of the patient and study (DICOM's, vr::DICOMAttribute) becomes the node's attributes.
  const auto & dictionary = image.GetMetaDataDictionary();
  for (const auto & key : dictionary.GetKeys())
  {
    std::string value;
    if (key.rfind("DICOM.", 0) == 0 && itk::ExposeMetaData<std::string>(dictionary, key, value))
    {
      node->SetAttribute(key, value);
    }
  }
  return node;
}

/** A 3D ITK image in LPS as a volume node of voxels of \a vtkType (the image's pixel type), copied. */
template<typename TImage>
vtkSmartPointer<VolumeNode>
Convert3DImageToNode(const TImage * image, int vtkType, const std::string & name)
{
  if (image == nullptr)
  {
    throw InputError(Describe("volume", name) + ": no image given");
  }
  auto data = ImageDataOfGrid(*image);
  data->AllocateScalars(vtkType, 1);
  std::copy(image->GetBufferPointer(),
            image->GetBufferPointer() + image->GetBufferedRegion().GetNumberOfPixels(),
            static_cast<typename TImage::PixelType *>(data->GetScalarPointer()));
  return MakeNodeOfImage(*image, data, name);
}
} // namespace

vtkSmartPointer<vtkMatrix4x4>
IJKToRASMatrixOf(const itk::ImageBase<3> & image)
{
  const auto & direction = image.GetDirection();
  const auto & spacing = image.GetSpacing();
  auto         matrix = vtkSmartPointer<vtkMatrix4x4>::New();
  for (unsigned int axis = 0; axis < 3; ++axis)
  {
    const Point3 column = LPSToRAS(AsPoint(
      direction[0][axis] * spacing[axis], direction[1][axis] * spacing[axis], direction[2][axis] * spacing[axis]));
    for (unsigned int row = 0; row < 3; ++row)
    {
      matrix->SetElement(row, axis, column[row]);
    }
  }
  const Point3 origin = LPSToRAS(image.GetOrigin());
  for (unsigned int row = 0; row < 3; ++row)
  {
    matrix->SetElement(row, 3, origin[row]);
  }
  return matrix;
}

vtkSmartPointer<VolumeNode>
ConvertStoredVolumeToVolumeNode(const StoredVolume & volume, const std::string & name)
{
  const std::string what = Describe("volume", name);
  if (!volume.Image)
  {
    throw InputError(what + ": no image given");
  }
  CheckRescale(volume.Rescale, what);
  const int vtkType = VTKTypeOf(volume.GetPixelType());
  if (vtkType < 0)
  {
    throw InputError(what + ": its pixel type is not one a volume is kept in (" +
                     std::string(itk::CPRStoredPixelTypes) + ")");
  }
  auto data = ImageDataOfGrid(*volume.Image);
  // The node's array reads the image's buffer and holds its pixel container (the buffer's owner).
  itk::VisitStoredVolume(volume.Image.GetPointer(),
                         [&data, vtkType](auto * image)
                         {
                           auto owner = std::make_shared<itk::Object::Pointer>(image->GetPixelContainer());
                           data->GetPointData()->SetScalars(
                             WrapVoxels(image->GetBufferPointer(),
                                        vtkType,
                                        static_cast<vtkIdType>(image->GetBufferedRegion().GetNumberOfPixels()),
                                        std::move(owner)));
                         });
  auto node = MakeNodeOfImage(*volume.Image, data, name);
  node->SetIntensityRescale(volume.Rescale);
  return node;
}

vtkSmartPointer<VolumeNode>
WrapVoxelBuffer(void *                           voxels,
                itk::IOComponentEnum             pixelType,
                const std::array<int, 3> &       dimensions,
                vtkMatrix4x4 *                   ijkToRAS,
                std::shared_ptr<const void>      owner,
                const std::string &              name,
                const itk::CPRIntensityRescale & rescale)
{
  const std::string what = Describe("voxel buffer", name);
  if (voxels == nullptr)
  {
    throw InputError(what + ": no voxels given (a null pointer)");
  }
  const int vtkType = VTKTypeOf(pixelType);
  if (vtkType < 0)
  {
    std::ostringstream message;
    message << what << ": pixel type " << pixelType << " is not one a volume is kept in (" << itk::CPRStoredPixelTypes
            << ")";
    throw InputError(message.str());
  }
  if (dimensions[0] < 1 || dimensions[1] < 1 || dimensions[2] < 1)
  {
    throw InputError(what + ": its dimensions " + std::to_string(dimensions[0]) + " x " +
                     std::to_string(dimensions[1]) + " x " + std::to_string(dimensions[2]) +
                     " leave an axis empty; each must be at least 1");
  }
  CheckRescale(rescale, what);
  auto data = vtkSmartPointer<vtkImageData>::New();
  data->SetExtent(0, dimensions[0] - 1, 0, dimensions[1] - 1, 0, dimensions[2] - 1);
  const vtkIdType count = static_cast<vtkIdType>(dimensions[0]) * dimensions[1] * dimensions[2];
  data->GetPointData()->SetScalars(WrapVoxels(voxels, vtkType, count, std::move(owner)));
  auto node = vtkSmartPointer<VolumeNode>::New();
  node->SetName(name);
  node->SetImageData(data);
  node->SetIJKToRASMatrix(ijkToRAS);
  node->SetIntensityRescale(rescale);
  return node;
}

vtkSmartPointer<VolumeNode>
ConvertItkImageToVolumeNode(const VolumeImageType * image, const std::string & name)
{
  return Convert3DImageToNode(image, VTK_FLOAT, name);
}

vtkSmartPointer<VolumeNode>
ConvertItkImageToVolumeNode(const LabelMapVolumeType * image, const std::string & name)
{
  return Convert3DImageToNode(image, VTK_UNSIGNED_CHAR, name);
}

vtkSmartPointer<VolumeNode>
ConvertItkImageToVolumeNode(const DepthImageType * image, const std::string & name)
{
  return Convert2DImageToNode(image, VTK_FLOAT, name);
}

vtkSmartPointer<VolumeNode>
ConvertItkImageToVolumeNode(const MaskImageType * image, const std::string & name)
{
  return Convert2DImageToNode(image, VTK_UNSIGNED_CHAR, name);
}

vtkSmartPointer<VolumeNode>
ConvertItkImageToVolumeNode(const LabelImageType * image, const std::string & name)
{
  return Convert2DImageToNode(image, VTK_UNSIGNED_INT, name);
}

DepthImageType::Pointer
ConvertVolumeNodeToDepthImage(VolumeNode * node)
{
  return ConvertNodeTo2DImage<DepthImageType>(node);
}

MaskImageType::Pointer
ConvertVolumeNodeToMaskImage(VolumeNode * node)
{
  return ConvertNodeTo2DImage<MaskImageType>(node);
}

LabelImageType::Pointer
ConvertVolumeNodeToLabelImage(VolumeNode * node)
{
  return ConvertNodeTo2DImage<LabelImageType>(node);
}

itk::CenterlineTree
ConvertCenterlineNodeToTree(CenterlineNode * node)
{
  const std::string what = Describe("centerline node", node ? node->GetName() : std::string());
  vtkPolyData *     polyData = node ? node->GetPolyData() : nullptr;
  if (polyData == nullptr)
  {
    throw InputError(what + ": has no polydata");
  }
  itk::CenterlineTree tree = CenterlineTreeFromPolyData(polyData, CoordinateSpace::RAS, what);
  try
  {
    tree.Validate();
  }
  catch (const itk::ExceptionObject & error)
  {
    throw InputError(what + ": " + error.GetDescription());
  }
  return tree;
}

vtkSmartPointer<CenterlineNode>
ConvertTreeToCenterlineNode(const itk::CenterlineTree & tree, const std::string & name)
{
  auto node = vtkSmartPointer<CenterlineNode>::New();
  node->SetName(name);
  node->SetPolyData(PolyDataFromCenterlineTree(tree, CoordinateSpace::RAS));
  return node;
}
} // namespace vr
