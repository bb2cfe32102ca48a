// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrSharedVoxelContainer_h
#define vrSharedVoxelContainer_h

#include "itkImportImageContainer.h"

#include <memory>
#include <utility>

/** Not installed: an implementation detail of the libraries that hand voxels to ITK without a copy (the node
 * conversion, the DICOM reader's mapping). */
namespace vr::detail
{
/** An ITK pixel container that reads voxels in place and holds what owns them (a VTK array, another image's container,
 * a mapping of the DICOM reader's hand-over): the voxels live as long as the last image that reads them, and ITK never
 * frees them itself (its own container would with delete[]). */
template<typename TPixel>
class SharedVoxelContainer : public itk::ImportImageContainer<itk::SizeValueType, TPixel>
{
public:
  ITK_DISALLOW_COPY_AND_MOVE(SharedVoxelContainer);
  using Self = SharedVoxelContainer;
  using Superclass = itk::ImportImageContainer<itk::SizeValueType, TPixel>;
  using Pointer = itk::SmartPointer<Self>;
  itkNewMacro(Self);
  itkTypeMacro(SharedVoxelContainer, ImportImageContainer);

  /** Reads the \a count voxels at \a voxels, holding \a owner until this container goes. */
  void
  Share(TPixel * voxels, itk::SizeValueType count, std::shared_ptr<const void> owner)
  {
    this->SetImportPointer(voxels, count, false);
    m_Owner = std::move(owner);
  }

protected:
  SharedVoxelContainer() = default;
  ~SharedVoxelContainer() override = default;

private:
  std::shared_ptr<const void> m_Owner;
};
} // namespace vr::detail

#endif
