// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrSlicerMemoryImageIO.h"

#include "itkVersion.h"

#include <algorithm>
#include <cstdio>
#include <mutex>
#include <set>

namespace vr::test
{
namespace
{
std::mutex &
ScenesMutex()
{
  static std::mutex mutex;
  return mutex;
}

std::set<const MemoryScene *> &
LiveScenes()
{
  static std::set<const MemoryScene *> scenes;
  return scenes;
}
} // namespace

MemoryScene::MemoryScene()
{
  const std::lock_guard<std::mutex> lock(ScenesMutex());
  LiveScenes().insert(this);
}

MemoryScene::~MemoryScene()
{
  const std::lock_guard<std::mutex> lock(ScenesMutex());
  LiveScenes().erase(this);
}

std::string
MemoryScene::NameOf(const std::string & nodeId) const
{
  // As vtkSlicerCLIModuleLogic: sprintf(tname, "slicer:%p#%s", this->GetMRMLScene(), name.c_str()).
  char name[512];
  std::snprintf(name, sizeof(name), "slicer:%p#%s", static_cast<const void *>(this), nodeId.c_str());
  return name;
}

const MemoryScene::Node *
MemoryScene::FindNode(const std::string & nodeId) const
{
  const auto found = m_Nodes.find(nodeId);
  return found == m_Nodes.end() ? nullptr : &found->second;
}

MemoryScene::Node *
MemoryScene::FindNode(const std::string & nodeId)
{
  const auto found = m_Nodes.find(nodeId);
  return found == m_Nodes.end() ? nullptr : &found->second;
}

std::vector<std::string>
MemoryScene::NodeIds() const
{
  std::vector<std::string> ids;
  for (const auto & entry : m_Nodes)
  {
    ids.push_back(entry.first);
  }
  return ids;
}

MemoryScene *
MemoryScene::FromName(const std::string & name, std::string & nodeId)
{
  // As MRMLIDImageIO::FileNameToVolumeNodePtr: "slicer:" then the scene's address, '#', the node id.
  const std::string scheme = "slicer:";
  const auto        hash = name.find('#');
  if (name.compare(0, scheme.size(), scheme) != 0 || hash == std::string::npos || hash + 1 == name.size())
  {
    return nullptr;
  }
  const std::string address = name.substr(scheme.size(), hash - scheme.size());
  void *            pointer = nullptr;
  if (std::sscanf(address.c_str(), "%p", &pointer) != 1)
  {
    return nullptr;
  }
  const std::lock_guard<std::mutex> lock(ScenesMutex());
  const auto                        found = LiveScenes().find(static_cast<const MemoryScene *>(pointer));
  if (found == LiveScenes().end())
  {
    return nullptr;
  }
  nodeId = name.substr(hash + 1);
  return const_cast<MemoryScene *>(*found);
}

bool
SlicerMemoryImageIO::CanReadFile(const char * name)
{
  std::string         nodeId;
  const MemoryScene * scene = name ? MemoryScene::FromName(name, nodeId) : nullptr;
  return scene != nullptr && scene->FindNode(nodeId) != nullptr;
}

bool
SlicerMemoryImageIO::CanWriteFile(const char * name)
{
  std::string nodeId;
  return name != nullptr && MemoryScene::FromName(name, nodeId) != nullptr;
}

void
SlicerMemoryImageIO::ReadImageInformation()
{
  std::string               nodeId;
  MemoryScene *             scene = MemoryScene::FromName(this->GetFileName(), nodeId);
  const MemoryScene::Node * node = scene ? scene->FindNode(nodeId) : nullptr;
  if (node == nullptr)
  {
    itkExceptionMacro("no image node for " << this->GetFileName());
  }
  this->SetNumberOfDimensions(node->Dimension);
  for (unsigned int axis = 0; axis < node->Dimension; ++axis)
  {
    this->SetDimensions(axis, node->Size[axis]);
    this->SetSpacing(axis, node->Spacing[axis]);
    this->SetOrigin(axis, node->Origin[axis]);
    this->SetDirection(axis, node->Direction[axis]);
  }
  this->SetPixelType(itk::IOPixelEnum::SCALAR);
  this->SetNumberOfComponents(1);
  this->SetComponentType(node->ComponentType);
  this->SetMetaDataDictionary(node->Dictionary);
}

void
SlicerMemoryImageIO::Read(void * buffer)
{
  std::string         nodeId;
  MemoryScene *       scene = MemoryScene::FromName(this->GetFileName(), nodeId);
  MemoryScene::Node * node = scene ? scene->FindNode(nodeId) : nullptr;
  if (node == nullptr || node->Pixels.size() != this->GetImageSizeInBytes())
  {
    itkExceptionMacro("cannot read the pixels of " << this->GetFileName());
  }
  std::memcpy(buffer, node->Pixels.data(), node->Pixels.size());
  ++node->Reads;
}

void
SlicerMemoryImageIO::Write(const void * buffer)
{
  std::string   nodeId;
  MemoryScene * scene = MemoryScene::FromName(this->GetFileName(), nodeId);
  if (scene == nullptr)
  {
    itkExceptionMacro("no scene for " << this->GetFileName());
  }
  MemoryScene::Node node;
  if (const MemoryScene::Node * previous = scene->FindNode(nodeId))
  {
    node.Reads = previous->Reads;
    node.Writes = previous->Writes;
  }
  node.Dimension = this->GetNumberOfDimensions();
  for (unsigned int axis = 0; axis < node.Dimension; ++axis)
  {
    node.Size.push_back(this->GetDimensions(axis));
    node.Spacing.push_back(this->GetSpacing(axis));
    node.Origin.push_back(this->GetOrigin(axis));
    node.Direction.push_back(this->GetDirection(axis));
  }
  if (this->GetNumberOfComponents() != 1)
  {
    itkExceptionMacro("only scalar images go into a node here, not " << this->GetNumberOfComponents() << " components");
  }
  node.ComponentType = this->GetComponentType();
  const auto * bytes = static_cast<const char *>(buffer);
  node.Pixels.assign(bytes, bytes + this->GetImageSizeInBytes());
  node.Dictionary = this->GetMetaDataDictionary();
  ++node.Writes;
  // SetImage() is templated on a C++ image; here the node is filled from the IO's description instead.
  *scene->FindNodeOrCreate(nodeId) = std::move(node);
}

void
SlicerMemoryImageIO::PrintSelf(std::ostream & os, itk::Indent indent) const
{
  Superclass::PrintSelf(os, indent);
  os << indent << "Scheme: slicer:<scene address>#<node id>" << std::endl;
}

SlicerMemoryImageIOFactory::SlicerMemoryImageIOFactory()
{
  this->RegisterOverride("itkImageIOBase",
                         "itkSlicerMemoryImageIO",
                         "In-memory images of a test scene, named as 3D Slicer names its nodes",
                         true,
                         itk::CreateObjectFunction<SlicerMemoryImageIO>::New());
}

const char *
SlicerMemoryImageIOFactory::GetITKSourceVersion() const
{
  return ITK_SOURCE_VERSION;
}

const char *
SlicerMemoryImageIOFactory::GetDescription() const
{
  return "SlicerMemoryImageIO: slicer:<scene>#<node> names of a test scene";
}

void
SlicerMemoryImageIOFactory::RegisterOneFactory()
{
  static const bool registered = []
  {
    itk::ObjectFactoryBase::RegisterFactory(SlicerMemoryImageIOFactory::New().GetPointer(),
                                            itk::ObjectFactoryBase::INSERT_AT_FRONT);
    return true;
  }();
  (void)registered;
}
} // namespace vr::test
