// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef itkOpenCLCPRResampleImageFilter_h
#define itkOpenCLCPRResampleImageFilter_h

#include "itkCPRResampleImageFilter.h"
#include "vrOpenCLSession.h"

#include <memory>
#include <string>

namespace itk
{

/** \class OpenCLCPRResampleImageFilter
 * \brief CPRResampleImageFilter on an OpenCL device: the volume sampled along the cut surface with the CPU's
 * arithmetic.
 *
 * Samples the volume at X = B(i, j) + d(i, j) v as CPRResampleImageFilter documents it (docs/design.md
 * "Resampling"), with the kernel of OpenCL/CPRResample.cl: the same continuous indices, the same trilinear
 * arithmetic in double (or ITK's nearest voxel), the same slabs (MIP, MinIP, mean), the same outside value. The
 * volume is uploaded once per vr::OpenCLSession and kept on the device in its stored pixel type (TVolumeImage's:
 * short, unsigned short, signed or unsigned char, float or double), each voxel read converted to double there; the
 * depth image is read from the device when a filter of the same session produced it (the relaxation, the depth
 * map), else uploaded; the image is downloaded once per update.
 *
 * The base class's IntensityRescale turns stored values into intensities per voxel read (slope x stored +
 * intercept, in double: DICOM's rescale, for a volume held in its stored type), on the device as on the CPU. The
 * outside value, when it is the volume's minimum, is the minimum's rescaled value.
 *
 * Cubic interpolation has no kernel, a device without double precision (cl_khr_fp64) cannot reproduce the CPU's
 * sampling, and a volume larger than the device's largest buffer (or its free memory) does not fit: then the CPU
 * filter samples (Superclass's data generation, with the same rescale), and GetHostReason() says why. Only
 * GenerateData() differs from the CPU filter.
 *
 * Instantiated for volumes of short, unsigned short, signed char, unsigned char, float and double voxels, and for
 * itk::ImageBase<3>, the logic's volume in whichever of those types its file stored (the kernel is built for the
 * type the volume holds at run time).
 *
 * \sa CPRResampleImageFilter, OpenCLCPRDepthImageFilter, OpenCLBilateralDepthRelaxFilter, vr::OpenCLSession
 * \ingroup VesselReformation
 */
template<typename TVolumeImage>
class OpenCLCPRResampleImageFilter : public CPRResampleImageFilter<TVolumeImage, Image<float, 2>, Image<float, 2>>
{
public:
  ITK_DISALLOW_COPY_AND_MOVE(OpenCLCPRResampleImageFilter);

  using Self = OpenCLCPRResampleImageFilter;
  using Superclass = CPRResampleImageFilter<TVolumeImage, Image<float, 2>, Image<float, 2>>;
  using Pointer = SmartPointer<Self>;
  using ConstPointer = SmartPointer<const Self>;
  using VolumeImageType = TVolumeImage;
  using DepthImageType = Image<float, 2>;
  using OutputImageType = Image<float, 2>;

  itkNewMacro(Self);
  itkTypeMacro(OpenCLCPRResampleImageFilter, CPRResampleImageFilter);

  /** The device to open when no session is set ("" = VR_OPENCL_DEVICE, else the first GPU, else the first CPU
   * device). */
  itkSetStringMacro(DeviceRequest);
  itkGetStringMacro(DeviceRequest);

  /** The session to run in, shared with the view's other OpenCL filters; null opens one for the DeviceRequest. */
  void
  SetSession(std::shared_ptr<vr::OpenCLSession> session);
  std::shared_ptr<vr::OpenCLSession>
  GetSession() const;

  /** Opens the device and builds the kernel now rather than in the next Update(). */
  void
  PrepareDevice();


  /** "" when the last update sampled on the device; otherwise why the CPU sampled. */
  const std::string &
  GetHostReason() const
  {
    return m_HostReason;
  }
  /** Whether the last update read its depth image from another filter's device buffer (no upload). */
  bool
  GetDepthWasOnDevice() const
  {
    return m_DepthWasOnDevice;
  }

  /** The device the filter runs on ("" before it is prepared). */
  std::string
  GetDeviceLabel() const;

  /** The OpenCL C source the filter builds: OpenCL/CPRResample.cl as embedded at build time. */
  static std::string
  GetKernelSource();

protected:
  OpenCLCPRResampleImageFilter();
  ~OpenCLCPRResampleImageFilter() override;


  void
  GenerateData() override;

  void
  PrintSelf(std::ostream & os, Indent indent) const override;

private:
  /** The program, kernel and buffers (defined in the .cxx, which includes OpenCL's headers). */
  struct DeviceState;

  /** Builds the kernel for volumes of \a voxelType (OpenCL C) unless it is built for that type already. */
  void
  BuildKernel(const char * voxelType);
  /** Why this update cannot sample on the device, or "". */
  std::string
  WhyHost() const;

  /** Samples on the device; returns why not (a volume the device could not hold) or "". */
  std::string
  SampleOnDevice();

  std::string                        m_DeviceRequest;
  std::shared_ptr<vr::OpenCLSession> m_Session;
  std::string                        m_HostReason;
  bool                               m_DepthWasOnDevice{ false };
  std::unique_ptr<DeviceState>       m_DeviceState;
};

// Instantiated in the VesselReformationOpenCL library for the stored pixel types of CT and MR volumes.
extern template class OpenCLCPRResampleImageFilter<Image<short, 3>>;
extern template class OpenCLCPRResampleImageFilter<Image<unsigned short, 3>>;
extern template class OpenCLCPRResampleImageFilter<Image<signed char, 3>>;
extern template class OpenCLCPRResampleImageFilter<Image<unsigned char, 3>>;
extern template class OpenCLCPRResampleImageFilter<Image<float, 3>>;
extern template class OpenCLCPRResampleImageFilter<Image<double, 3>>;
extern template class OpenCLCPRResampleImageFilter<ImageBase<3>>;

} // namespace itk

#endif
