// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "itkOpenCLCPRResampleImageFilter.h"

#include "vrCPRResampleKernelSource.h"
#include "vrInputError.h"
#include "vrOpenCLRuntime.h"
#include "vrOpenCLSessionState.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <type_traits>
#include <vector>

namespace itk
{
namespace
{
/** The OpenCL C name of a voxel type. */
template<typename TPixel>
const char *
VoxelTypeName()
{
  if constexpr (std::is_same_v<TPixel, short>)
  {
    return "short";
  }
  else if constexpr (std::is_same_v<TPixel, unsigned short>)
  {
    return "ushort";
  }
  else if constexpr (std::is_same_v<TPixel, signed char>)
  {
    return "char";
  }
  else if constexpr (std::is_same_v<TPixel, unsigned char>)
  {
    return "uchar";
  }
  else if constexpr (std::is_same_v<TPixel, float>)
  {
    return "float";
  }
  else
  {
    static_assert(std::is_same_v<TPixel, double>, "volumes of short, ushort, char, uchar, float or double");
    return "double";
  }
}

/** A volume's voxels as the device takes them: where they are, the bytes of one, and the OpenCL C type. */
struct VolumeVoxels
{
  const void * Pointer;
  std::size_t  VoxelBytes;
  const char * TypeName;
};

/** The voxels of \a volume: of its pixel type, or, for an itk::ImageBase<3> (the logic's stored volume), of the type
 * it holds at run time (itk::VisitStoredVolume). */
template<typename TVolumeImage>
VolumeVoxels
VoxelsOf(const TVolumeImage * volume)
{
  const auto describe = [](auto * image)
  {
    using PixelType = typename std::remove_const_t<std::remove_pointer_t<decltype(image)>>::PixelType;
    return VolumeVoxels{ image->GetBufferPointer(), sizeof(PixelType), VoxelTypeName<PixelType>() };
  };
  if constexpr (std::is_same_v<TVolumeImage, ImageBase<3>>)
  {
    return VisitStoredVolume(volume, describe);
  }
  else
  {
    return describe(volume);
  }
}

std::size_t
RoundUp(std::size_t value, std::size_t multiple)
{
  return (value + multiple - 1) / multiple * multiple;
}

/** Whether an OpenCL failure means the device has no room (for the volume): then the CPU samples instead. */
bool
IsOutOfDeviceMemory(const cl::Error & error)
{
  return error.err() == CL_MEM_OBJECT_ALLOCATION_FAILURE || error.err() == CL_OUT_OF_RESOURCES ||
         error.err() == CL_INVALID_BUFFER_SIZE || error.err() == CL_OUT_OF_HOST_MEMORY;
}
} // namespace

template<typename TVolumeImage>
struct OpenCLCPRResampleImageFilter<TVolumeImage>::DeviceState
{
  std::shared_ptr<vr::OpenCLSession> Session;
  /** The kernel is built for one voxel type (VOXEL_TYPE); a volume of another type builds it again. */
  std::string                        KernelVoxelType;
  cl::Program                        Program;
  cl::Kernel                         Kernel;
  cl::NDRange                        Local;
  /** The depth uploaded when no filter of the session holds it, and the output; grown as needed. */
  cl::Buffer          Depth;
  std::size_t         DepthBytes{ 0 };
  cl::Buffer          Output;
  std::size_t         OutputBytes{ 0 };
  cl::Buffer          SlabOffsets;
  std::vector<double> UploadedSlabOffsets;

  vr::OpenCLSessionState &
  Device()
  {
    return Session->GetInternals();
  }
};

template<typename TVolumeImage>
OpenCLCPRResampleImageFilter<TVolumeImage>::OpenCLCPRResampleImageFilter() = default;

template<typename TVolumeImage>
OpenCLCPRResampleImageFilter<TVolumeImage>::~OpenCLCPRResampleImageFilter() = default;

template<typename TVolumeImage>
void
OpenCLCPRResampleImageFilter<TVolumeImage>::SetSession(std::shared_ptr<vr::OpenCLSession> session)
{
  if (session != m_Session)
  {
    m_Session = std::move(session);
    this->Modified();
  }
}

template<typename TVolumeImage>
std::shared_ptr<vr::OpenCLSession>
OpenCLCPRResampleImageFilter<TVolumeImage>::GetSession() const
{
  return m_Session ? m_Session : (m_DeviceState ? m_DeviceState->Session : nullptr);
}

template<typename TVolumeImage>
std::string
OpenCLCPRResampleImageFilter<TVolumeImage>::GetDeviceLabel() const
{
  const auto session = this->GetSession();
  return session ? session->GetDeviceInfo().Label() : std::string();
}

template<typename TVolumeImage>
std::string
OpenCLCPRResampleImageFilter<TVolumeImage>::GetKernelSource()
{
  return vr::opencl_sources::CPRResample;
}

template<typename TVolumeImage>
void
OpenCLCPRResampleImageFilter<TVolumeImage>::BuildKernel(const char * voxelType)
{
  DeviceState & state = *m_DeviceState;
  if (state.KernelVoxelType == voxelType)
  {
    return;
  }
  vr::OpenCLSessionState & device = state.Device();
  try
  {
    const std::string options = std::string("-D VOXEL_TYPE=") + voxelType;
    try
    {
      state.Program = device.Program(vr::opencl_sources::CPRResampleFileName, GetKernelSource(), options);
    }
    catch (const vr::OpenCLBuildFailure & failure)
    {
      itkExceptionMacro(<< failure.what() << "; the compiler's log:\n" << failure.Log());
    }
    state.Kernel = cl::Kernel(state.Program, "ResampleAlongDepth");
    state.KernelVoxelType = voxelType;
  }
  catch (const cl::Error & error)
  {
    itkExceptionMacro(<< "preparing OpenCL device " << device.Info.Label() << ": " << vr::DescribeOpenCLError(error));
  }
}

template<typename TVolumeImage>
void
OpenCLCPRResampleImageFilter<TVolumeImage>::PrepareDevice()
{
  std::shared_ptr<vr::OpenCLSession> session = m_Session;
  if (!session)
  {
    if (m_DeviceState)
    {
      return;
    }
    try
    {
      session = vr::OpenCLSession::Create(m_DeviceRequest, "DeviceRequest");
    }
    catch (const vr::InputError & error)
    {
      itkExceptionMacro(<< error.what());
    }
  }
  if (m_DeviceState && m_DeviceState->Session == session)
  {
    return;
  }
  m_DeviceState.reset();
  auto state = std::make_unique<DeviceState>();
  state->Session = session;
  vr::OpenCLSessionState & device = state->Device();
  if (device.DoublePrecision)
  {
    try
    {
      const std::size_t maximumGroup = device.Device.getInfo<CL_DEVICE_MAX_WORK_GROUP_SIZE>();
      std::size_t       localWidth = 32;
      std::size_t       localHeight = 4;
      while (localWidth * localHeight > maximumGroup)
      {
        (localWidth >= localHeight ? localWidth : localHeight) /= 2;
      }
      state->Local = cl::NDRange(localWidth, localHeight);
    }
    catch (const cl::Error & error)
    {
      itkExceptionMacro(<< "preparing OpenCL device " << device.Info.Label() << ": " << vr::DescribeOpenCLError(error));
    }
  }
  m_DeviceState = std::move(state);
  if (device.DoublePrecision)
  {
    // The kernel for the volume's voxel type now (float before a volume is set), so that a build failure shows here.
    const TVolumeImage * volume = this->GetVolume();
    this->BuildKernel(volume != nullptr ? VoxelsOf(volume).TypeName : "float");
  }
}

template<typename TVolumeImage>
std::string
OpenCLCPRResampleImageFilter<TVolumeImage>::WhyHost() const
{
  const vr::OpenCLSessionState & device = m_DeviceState->Session->GetInternals();
  if (this->GetInterpolation() == CPRInterpolationMode::Cubic)
  {
    return "cubic interpolation has no OpenCL kernel: the CPU samples the volume";
  }
  if (!device.DoublePrecision)
  {
    return "the resampling needs double precision on the device (cl_khr_fp64), which " + device.Info.Label() +
           " lacks: the CPU samples the volume";
  }
  const TVolumeImage * volume = this->GetVolume();
  const std::size_t    bytes = volume->GetBufferedRegion().GetNumberOfPixels() * VoxelsOf(volume).VoxelBytes;
  if (!device.Info.IsCPU && bytes > device.MaximumAllocationBytes)
  {
    std::ostringstream why;
    why << "the volume's " << bytes << " bytes exceed the largest buffer of " << device.Info.Label() << " ("
        << device.MaximumAllocationBytes << " bytes): the CPU samples the volume";
    return why.str();
  }
  return std::string();
}

template<typename TVolumeImage>
void
OpenCLCPRResampleImageFilter<TVolumeImage>::GenerateData()
{
  this->PrepareDevice();
  m_DepthWasOnDevice = false;
  m_HostReason = this->WhyHost();
  if (m_HostReason.empty())
  {
    this->AllocateOutputs();
    m_HostReason = this->SampleOnDevice();
    if (m_HostReason.empty())
    {
      return;
    }
  }
  Superclass::GenerateData(); // the CPU applies the same rescale

}

template<typename TVolumeImage>
std::string
OpenCLCPRResampleImageFilter<TVolumeImage>::SampleOnDevice()
{
  const TVolumeImage *     volume = this->GetVolume();
  const VolumeVoxels       voxels = VoxelsOf(volume);
  const DepthImageType *   depth = this->GetDepth();
  OutputImageType *        output = this->GetOutput();
  DeviceState &            state = *m_DeviceState;
  vr::OpenCLSessionState & device = state.Device();
  this->PrepareIndexMapping(); // the outside value too: the volume's smallest intensity (rescaled) or the default
  this->BuildKernel(voxels.TypeName);
  const double                outside = static_cast<double>(this->GetOutsideValue());
  const CPRIntensityRescale & rescale = this->GetIntensityRescale();

  const auto &      volumeRegion = volume->GetBufferedRegion();
  const std::size_t voxelSize[3] = { volumeRegion.GetSize()[0], volumeRegion.GetSize()[1], volumeRegion.GetSize()[2] };
  const std::size_t volumeBytes = volumeRegion.GetNumberOfPixels() * voxels.VoxelBytes;
  const auto &      region = output->GetBufferedRegion();
  const std::size_t columns = region.GetSize()[0];
  const std::size_t rows = region.GetSize()[1];
  const auto &      viewSize = this->GetView().GetSize();
  const auto &      depthRegion = depth->GetBufferedRegion();

  const vr::OpenCLDeviceVolume * onDevice = nullptr;
  try
  {
    onDevice = &device.Volume(volume,
                              voxels.Pointer,
                              std::max(volume->GetMTime(), volume->GetUpdateMTime()),
                              voxels.TypeName,
                              voxelSize,
                              volumeBytes);
  }
  catch (const cl::Error & error)
  {
    if (!IsOutOfDeviceMemory(error))
    {
      itkExceptionMacro(<< "uploading the volume to OpenCL device " << device.Info.Label() << ": "
                        << vr::DescribeOpenCLError(error));
    }
    device.ReleaseVolume();
    std::ostringstream why;
    why << "the volume's " << volumeBytes << " bytes do not fit on " << device.Info.Label() << " ("
        << vr::DescribeOpenCLError(error) << "): the CPU samples the volume";
    return why.str();
  }

  try
  {
    cl::CommandQueue & queue = device.Queue;
    // The depth: the device copy another filter of the session left there, else an upload of the buffered part.
    vr::OpenCLDeviceImage depthOnDevice;
    cl::Buffer            depthBuffer;
    std::size_t           depthRowLength = depthRegion.GetSize()[0];
    if (depthRegion == depth->GetLargestPossibleRegion() &&
        device.Find(depth,
                    depth->GetBufferPointer(),
                    depthRegion.GetSize()[0],
                    depthRegion.GetSize()[1],
                    sizeof(float),
                    depthOnDevice) &&
        depthOnDevice.Offset == 0 && depthOnDevice.RowPitch == depthRowLength * sizeof(float))
    {
      depthBuffer = depthOnDevice.Buffer;
      m_DepthWasOnDevice = true;
    }
    else
    {
      const std::size_t bytes = depthRegion.GetNumberOfPixels() * sizeof(float);
      if (bytes > state.DepthBytes)
      {
        state.Depth = cl::Buffer(device.Context, CL_MEM_READ_ONLY, bytes);
        state.DepthBytes = bytes;
      }
      queue.enqueueWriteBuffer(state.Depth, CL_FALSE, 0, bytes, depth->GetBufferPointer());
      depthBuffer = state.Depth;
    }
    const std::size_t outputBytes = std::max<std::size_t>(columns * rows * sizeof(float), sizeof(float));
    if (outputBytes > state.OutputBytes)
    {
      state.Output = cl::Buffer(device.Context, CL_MEM_WRITE_ONLY, outputBytes);
      state.OutputBytes = outputBytes;
    }
    if (state.UploadedSlabOffsets != this->GetSlabOffsets())
    {
      state.UploadedSlabOffsets = this->GetSlabOffsets();
      state.SlabOffsets = cl::Buffer(device.Context,
                                     CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR,
                                     state.UploadedSlabOffsets.size() * sizeof(double),
                                     state.UploadedSlabOffsets.data());
    }

    const auto & atCentre = this->GetIndexAtCenter();
    const auto & column = this->GetIndexStepPerColumn();
    const auto & row = this->GetIndexStepPerRow();
    const auto & along = this->GetIndexStepPerMillimetreDepth();
    const auto   start = volumeRegion.GetIndex();
    cl::Kernel & kernel = state.Kernel;
    cl_uint      argument = 0;
    kernel.setArg(argument++, onDevice->Buffer);
    kernel.setArg(argument++, depthBuffer);
    kernel.setArg(argument++, state.Output);
    kernel.setArg(argument++, state.SlabOffsets);
    kernel.setArg(argument++, static_cast<cl_int>(state.UploadedSlabOffsets.size()));
    kernel.setArg(argument++,
                  static_cast<cl_int>(this->GetSlabMode() == CPRSlabMode::MIP     ? 0
                                      : this->GetSlabMode() == CPRSlabMode::MinIP ? 1
                                                                                  : 2));
    kernel.setArg(argument++, static_cast<cl_int>(this->GetInterpolation() == CPRInterpolationMode::Nearest ? 1 : 0));
    kernel.setArg(argument++, static_cast<cl_float>(outside));
    kernel.setArg(argument++, static_cast<cl_int>(region.GetIndex()[0]));
    kernel.setArg(argument++, static_cast<cl_int>(region.GetIndex()[1]));
    kernel.setArg(argument++, static_cast<cl_int>(columns));
    kernel.setArg(argument++, static_cast<cl_int>(rows));
    kernel.setArg(argument++, static_cast<cl_int>(depthRegion.GetIndex()[0]));
    kernel.setArg(argument++, static_cast<cl_int>(depthRegion.GetIndex()[1]));
    kernel.setArg(argument++, static_cast<cl_int>(depthRowLength));
    kernel.setArg(argument++, static_cast<cl_double>(0.5 * (viewSize[0] - 1.0)));
    kernel.setArg(argument++, static_cast<cl_double>(0.5 * (viewSize[1] - 1.0)));
    const Vector<double, 3> centre = atCentre.GetVectorFromOrigin();
    for (const Vector<double, 3> * vector : { &centre, &column, &row, &along })
    {
      for (unsigned int k = 0; k < 3; ++k)
      {
        kernel.setArg(argument++, static_cast<cl_double>((*vector)[k]));
      }
    }
    for (unsigned int k = 0; k < 3; ++k)
    {
      kernel.setArg(argument++, static_cast<cl_long>(voxelSize[k]));
    }
    for (unsigned int k = 0; k < 3; ++k)
    {
      kernel.setArg(argument++, static_cast<cl_long>(start[k]));
    }
    kernel.setArg(argument++, static_cast<cl_double>(rescale.Slope));
    kernel.setArg(argument++, static_cast<cl_double>(rescale.Intercept));
    if (columns > 0 && rows > 0)
    {
      const cl::NDRange global(RoundUp(columns, state.Local[0]), RoundUp(rows, state.Local[1]));
      queue.enqueueNDRangeKernel(kernel, cl::NullRange, global, state.Local);
      queue.enqueueReadBuffer(state.Output, CL_TRUE, 0, columns * rows * sizeof(float), output->GetBufferPointer());
    }
  }
  catch (const cl::Error & error)
  {
    try
    {
      device.Queue.finish();
    }
    catch (const cl::Error &)
    {
    }
    const std::string label = device.Info.Label();
    m_DeviceState.reset();
    itkExceptionMacro(<< "resampling on OpenCL device " << label << ": " << vr::DescribeOpenCLError(error));
  }
  this->UpdateProgress(1.0f);
  return std::string();
}

template<typename TVolumeImage>
void
OpenCLCPRResampleImageFilter<TVolumeImage>::PrintSelf(std::ostream & os, Indent indent) const
{
  Superclass::PrintSelf(os, indent);
  os << indent << "DeviceRequest: \"" << m_DeviceRequest << "\"" << std::endl;
  os << indent << "Session: " << (m_Session ? "shared, set by the caller" : "the filter's own") << std::endl;
  os << indent << "Device: " << (m_DeviceState ? this->GetDeviceLabel() : std::string("(not chosen yet)")) << std::endl;
  os << indent << "HostReason: \"" << m_HostReason << "\"" << std::endl;
}

template class OpenCLCPRResampleImageFilter<Image<short, 3>>;
template class OpenCLCPRResampleImageFilter<Image<unsigned short, 3>>;
template class OpenCLCPRResampleImageFilter<Image<signed char, 3>>;
template class OpenCLCPRResampleImageFilter<Image<unsigned char, 3>>;
template class OpenCLCPRResampleImageFilter<Image<float, 3>>;
template class OpenCLCPRResampleImageFilter<Image<double, 3>>;
template class OpenCLCPRResampleImageFilter<ImageBase<3>>;
} // namespace itk
