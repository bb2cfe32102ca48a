// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrSlicerMemoryImageIO_h
#define vrSlicerMemoryImageIO_h

#include "itkImage.h"
#include "itkImageIOBase.h"
#include "itkMetaDataDictionary.h"
#include "itkObjectFactoryBase.h"

#include <cstring>
#include <map>
#include <string>
#include <vector>

namespace vr::test
{
/** \class MemoryScene
 * \brief Stands in for a 3D Slicer MRML scene as Slicer's in-memory ImageIO sees it: images kept by node id, named
 * to a shared-library module as "slicer:<scene address>#<node id>"
 * (vtkSlicerCLIModuleLogic::ConstructTemporaryFileName; read and written by Slicer's itk::MRMLIDImageIO, which finds
 * the scene with sscanf("%p") and the node by its id).
 *
 * A node holds an image as ITK hands it over: dimension, size, spacing, origin and direction (LPS), pixel component
 * type and the raw pixels, and the metadata dictionary. Only scenes alive in this process are found by name.
 * \ingroup VesselReformation
 */
class MemoryScene
{
public:
  struct Node
  {
    unsigned int                    Dimension{ 0 };
    std::vector<itk::SizeValueType> Size;
    std::vector<double>             Spacing;
    std::vector<double>             Origin;
    /** Direction()[axis] is the direction of image axis \a axis (a column of ITK's direction matrix). */
    std::vector<std::vector<double>> Direction;
    itk::IOComponentEnum             ComponentType{ itk::IOComponentEnum::UNKNOWNCOMPONENTTYPE };
    std::vector<char>                Pixels;
    itk::MetaDataDictionary          Dictionary;
    unsigned int                     Reads{ 0 };
    unsigned int                     Writes{ 0 };
  };

  MemoryScene();
  ~MemoryScene();
  MemoryScene(const MemoryScene &) = delete;
  MemoryScene &
  operator=(const MemoryScene &) = delete;

  /** \return "slicer:<this scene's address, as %p prints it>#<node id>". */
  std::string
  NameOf(const std::string & nodeId) const;

  /** Puts a copy of \a image in the node \a nodeId (scalar pixels). */
  template<typename TImage>
  void
  SetImage(const std::string & nodeId, const TImage * image)
  {
    Node &             node = m_Nodes[nodeId];
    const unsigned int dimension = TImage::ImageDimension;
    node.Dimension = dimension;
    node.Size.assign(dimension, 0);
    node.Spacing.assign(dimension, 0.0);
    node.Origin.assign(dimension, 0.0);
    node.Direction.assign(dimension, std::vector<double>(dimension, 0.0));
    for (unsigned int axis = 0; axis < dimension; ++axis)
    {
      node.Size[axis] = image->GetLargestPossibleRegion().GetSize()[axis];
      node.Spacing[axis] = image->GetSpacing()[axis];
      node.Origin[axis] = image->GetOrigin()[axis];
      for (unsigned int row = 0; row < dimension; ++row)
      {
        node.Direction[axis][row] = image->GetDirection()[row][axis];
      }
    }
    node.ComponentType = itk::ImageIOBase::MapPixelType<typename TImage::PixelType>::CType;
    const std::size_t bytes =
      image->GetLargestPossibleRegion().GetNumberOfPixels() * sizeof(typename TImage::PixelType);
    node.Pixels.resize(bytes);
    std::memcpy(node.Pixels.data(), image->GetBufferPointer(), bytes);
    node.Dictionary = image->GetMetaDataDictionary();
  }

  /** \return an image made from the node \a nodeId, or null when the node is missing or holds another pixel type
   * or dimension. */
  template<typename TImage>
  typename TImage::Pointer
  GetImage(const std::string & nodeId) const
  {
    const Node * node = FindNode(nodeId);
    if (node == nullptr || node->Dimension != TImage::ImageDimension ||
        node->ComponentType != itk::ImageIOBase::MapPixelType<typename TImage::PixelType>::CType)
    {
      return nullptr;
    }
    auto                           image = TImage::New();
    typename TImage::SizeType      size;
    typename TImage::SpacingType   spacing;
    typename TImage::PointType     origin;
    typename TImage::DirectionType direction;
    for (unsigned int axis = 0; axis < TImage::ImageDimension; ++axis)
    {
      size[axis] = node->Size[axis];
      spacing[axis] = node->Spacing[axis];
      origin[axis] = node->Origin[axis];
      for (unsigned int row = 0; row < TImage::ImageDimension; ++row)
      {
        direction[row][axis] = node->Direction[axis][row];
      }
    }
    image->SetRegions(size);
    image->SetSpacing(spacing);
    image->SetOrigin(origin);
    image->SetDirection(direction);
    image->Allocate();
    if (node->Pixels.size() !=
        image->GetLargestPossibleRegion().GetNumberOfPixels() * sizeof(typename TImage::PixelType))
    {
      return nullptr;
    }
    std::memcpy(image->GetBufferPointer(), node->Pixels.data(), node->Pixels.size());
    image->SetMetaDataDictionary(node->Dictionary);
    return image;
  }

  /** \return the node, or null. */
  const Node *
  FindNode(const std::string & nodeId) const;
  Node *
  FindNode(const std::string & nodeId);
  /** \return the node, made empty when missing. */
  Node *
  FindNodeOrCreate(const std::string & nodeId)
  {
    return &m_Nodes[nodeId];
  }
  /** \return the node ids, sorted. */
  std::vector<std::string>
  NodeIds() const;

  /** \param name a name as NameOf() makes it.
   * \param nodeId receives the node id.
   * \return the live scene the name points at, or null (not "slicer:", not a live scene's address, no '#'). */
  static MemoryScene *
  FromName(const std::string & name, std::string & nodeId);

private:
  std::map<std::string, Node> m_Nodes;
};

/** \class SlicerMemoryImageIO
 * \brief A small ITK ImageIO for MemoryScene names ("slicer:0x...#node"), the part of 3D Slicer's MRMLIDImageIO
 * that a shared-library module meets: it reads a node's image and writes an image into a node, with geometry and
 * metadata, without touching a file.
 * \ingroup VesselReformation
 */
class SlicerMemoryImageIO : public itk::ImageIOBase
{
public:
  ITK_DISALLOW_COPY_AND_MOVE(SlicerMemoryImageIO);
  using Self = SlicerMemoryImageIO;
  using Superclass = itk::ImageIOBase;
  using Pointer = itk::SmartPointer<Self>;
  itkNewMacro(Self);
  itkTypeMacro(SlicerMemoryImageIO, ImageIOBase);

  bool
  SupportsDimension(unsigned long dimension) override
  {
    return dimension >= 2 && dimension <= 3;
  }
  bool
  CanReadFile(const char * name) override;
  void
  ReadImageInformation() override;
  void
  Read(void * buffer) override;
  bool
  CanWriteFile(const char * name) override;
  void
  WriteImageInformation() override
  {
  }
  void
  Write(const void * buffer) override;

protected:
  SlicerMemoryImageIO() = default;
  ~SlicerMemoryImageIO() override = default;
  void
  PrintSelf(std::ostream & os, itk::Indent indent) const override;
};

/** \class SlicerMemoryImageIOFactory
 * \brief Registers SlicerMemoryImageIO with ITK's object factory, in front of the file formats, as 3D Slicer's
 * itkMRMLIDIOPlugin does in its process.
 * \ingroup VesselReformation
 */
class SlicerMemoryImageIOFactory : public itk::ObjectFactoryBase
{
public:
  ITK_DISALLOW_COPY_AND_MOVE(SlicerMemoryImageIOFactory);
  using Self = SlicerMemoryImageIOFactory;
  using Superclass = itk::ObjectFactoryBase;
  using Pointer = itk::SmartPointer<Self>;
  itkFactorylessNewMacro(Self);
  itkTypeMacro(SlicerMemoryImageIOFactory, ObjectFactoryBase);

  const char *
  GetITKSourceVersion() const override;
  const char *
  GetDescription() const override;

  /** Registers one factory for the process (once). */
  static void
  RegisterOneFactory();

protected:
  SlicerMemoryImageIOFactory();
  ~SlicerMemoryImageIOFactory() override = default;
};
} // namespace vr::test

#endif
