// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "itkOpenCLBilateralDepthRelaxFilter.h"

#include "vrBilateralDepthRelaxKernelSource.h"
#include "vrInputError.h"
#include "vrOpenCLDevices.h"
#include "vrOpenCLRuntime.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <climits>
#include <cmath>
#include <locale>
#include <mutex>
#include <sstream>
#include <stdexcept>
#include <system_error>
#include <vector>

namespace itk
{
namespace
{
constexpr const char * KernelName = "RelaxIteration";
constexpr unsigned int ProgressReports = 10;

std::mutex &
KernelSourceMutex()
{
  static std::mutex mutex;
  return mutex;
}

std::string &
KernelSourceForTesting()
{
  static std::string source;
  return source;
}

std::string
CurrentKernelSource()
{
  const std::lock_guard<std::mutex> lock(KernelSourceMutex());
  return KernelSourceForTesting().empty() ? std::string(vr::opencl_sources::BilateralDepthRelax)
                                          : KernelSourceForTesting();
}

/** How the kernel covers the image: each work-item relaxes VectorsPerItem vectors of VectorWidth lanes side by
 * side, in RowsPerItem rows; work-groups are LocalWidth x LocalHeight work-items. */
struct KernelShape
{
  int         VectorWidth{ 1 };
  int         VectorsPerItem{ 1 };
  int         RowsPerItem{ 1 };
  std::size_t LocalWidth{ 1 };
  std::size_t LocalHeight{ 1 };
};

// CPU devices get wide vectors and large blocks per work-item, which share most edge weights through registers;
// GPUs get one pixel column per work-item, so that neighbouring work-items read neighbouring pixels. A forced
// vector width (not 0) and layout replace the device's (the test hook).
KernelShape
ChooseKernelShape(const cl::Device & device, unsigned int forcedVectorWidth, bool forcedGPULayout)
{
  KernelShape   shape;
  const cl_uint preferred =
    forcedVectorWidth > 0 ? forcedVectorWidth : device.getInfo<CL_DEVICE_PREFERRED_VECTOR_WIDTH_FLOAT>();
  while (shape.VectorWidth * 2 <= static_cast<int>(std::min<cl_uint>(preferred, 16)))
  {
    shape.VectorWidth *= 2;
  }
  const bool cpuDevice = (device.getInfo<CL_DEVICE_TYPE>() & CL_DEVICE_TYPE_GPU) == 0 &&
                         (device.getInfo<CL_DEVICE_TYPE>() & CL_DEVICE_TYPE_CPU) != 0;
  if (forcedVectorWidth > 0 ? !forcedGPULayout : cpuDevice)
  {
    shape.VectorsPerItem = 8;
    shape.RowsPerItem = 16;
    shape.LocalWidth = 1;
    shape.LocalHeight = 4;
  }
  else
  {
    shape.VectorsPerItem = 1;
    shape.RowsPerItem = 4;
    shape.LocalWidth = 32;
    shape.LocalHeight = 4;
  }
  const std::size_t              maximumGroup = device.getInfo<CL_DEVICE_MAX_WORK_GROUP_SIZE>();
  const std::vector<std::size_t> maximumItems = device.getInfo<CL_DEVICE_MAX_WORK_ITEM_SIZES>();
  while (shape.LocalWidth * shape.LocalHeight > maximumGroup ||
         (maximumItems.size() >= 2 && (shape.LocalWidth > maximumItems[0] || shape.LocalHeight > maximumItems[1])))
  {
    (shape.LocalWidth >= shape.LocalHeight ? shape.LocalWidth : shape.LocalHeight) /= 2;
  }
  shape.LocalWidth = std::max<std::size_t>(shape.LocalWidth, 1);
  shape.LocalHeight = std::max<std::size_t>(shape.LocalHeight, 1);
  return shape;
}

// The underflow rule a x^2 > -ln(FLT_MIN) in powers of two: a log2(e) x^2 > -log2(FLT_MIN), exactly 126.
constexpr double WeightUnderflowPower = 126.0;
static_assert(OpenCLBilateralDepthRelaxFilter::WeightUnderflowExponent > 126.0 * 0.6931471805599452 &&
                OpenCLBilateralDepthRelaxFilter::WeightUnderflowExponent < 126.0 * 0.6931471805599454,
              "the underflow exponent is -ln(FLT_MIN) = 126 ln 2");

// A float as an OpenCL C literal that denotes exactly \a value: the shortest decimal that reads back as the same
// float (std::to_chars ignores the locale), with a point or exponent so that it is not an integer, and the f suffix.
std::string
FloatLiteral(float value)
{
  if (!std::isfinite(value))
  {
    throw std::invalid_argument("an OpenCL float literal must be finite");
  }
  std::array<char, 32> digits{};
  const auto [end, error] = std::to_chars(digits.data(), digits.data() + digits.size(), value);
  if (error != std::errc())
  {
    throw std::invalid_argument("an OpenCL float literal could not be formatted");
  }
  std::string literal(digits.data(), end);
  if (literal.find_first_of(".e") == std::string::npos)
  {
    literal += ".0";
  }
  return literal + 'f';
}

// The definitions the kernel expects, as -D options of clBuildProgram: the source stays exactly the .cl file, so
// every vendor's compiler counts its lines (NVIDIA's ignores #line, so definitions put before the source shifted
// its messages). Integers and the float literal are written without the locale's help.
std::string
BuildOptionsFor(const KernelShape & shape)
{
  std::ostringstream options;
  options.imbue(std::locale::classic());
  options << "-D VECTOR_WIDTH=" << shape.VectorWidth << " -D VECTORS_PER_ITEM=" << shape.VectorsPerItem
          << " -D ROWS_PER_ITEM=" << shape.RowsPerItem << " -D LOCAL_WIDTH=" << shape.LocalWidth
          << " -D LOCAL_HEIGHT=" << shape.LocalHeight
          << " -D WEIGHT_UNDERFLOW_POWER=" << FloatLiteral(static_cast<float>(WeightUnderflowPower));
  return options.str();
}

std::size_t
RoundUp(std::size_t value, std::size_t multiple)
{
  return (value + multiple - 1) / multiple * multiple;
}
} // namespace

struct OpenCLBilateralDepthRelaxFilter::DeviceState
{
  vr::OpenCLDeviceInfo Info;
  /** The source the program was built from (the test hook may change it). */
  std::string Source;
  /** The layout the test hook forced when the program was built (0: none). */
  unsigned int ForcedVectorWidth{ 0 };
  bool         ForcedGPULayout{ false };
  KernelShape  Shape;
  /** The -D options the program was built with (BuildOptionsFor(Shape)). */
  std::string      BuildOptions;
  cl::Device       Device;
  cl::Context      Context;
  cl::CommandQueue Queue;
  cl::Program      Program;
  /** Iteration k reads Depth[k % 2] and writes Depth[(k + 1) % 2]: Kernels[k % 2] has those arguments. */
  std::array<cl::Kernel, 2> Kernels;

  /** Buffers for images of Width x Height pixels, rows Pitch floats apart (see BilateralDepthRelax.cl). */
  std::size_t               Width{ 0 };
  std::size_t               Height{ 0 };
  std::size_t               Pitch{ 0 };
  std::array<cl::Buffer, 2> Depth;
  cl::Buffer                Mask;
};

OpenCLBilateralDepthRelaxFilter::OpenCLBilateralDepthRelaxFilter() = default;
OpenCLBilateralDepthRelaxFilter::~OpenCLBilateralDepthRelaxFilter() = default;

void
OpenCLBilateralDepthRelaxFilter::SetKernelSourceForTesting(const std::string & source)
{
  const std::lock_guard<std::mutex> lock(KernelSourceMutex());
  KernelSourceForTesting() = source;
}

void
OpenCLBilateralDepthRelaxFilter::SetKernelLayoutForTesting(unsigned int vectorWidth, bool gpuLayout)
{
  if (vectorWidth != 0 && vectorWidth != 1 && vectorWidth != 2 && vectorWidth != 4 && vectorWidth != 8 &&
      vectorWidth != 16)
  {
    itkExceptionMacro(<< "SetKernelLayoutForTesting: the vector width must be 0, 1, 2, 4, 8 or 16, not "
                      << vectorWidth);
  }
  m_ForcedVectorWidth = vectorWidth;
  m_ForcedGPULayout = vectorWidth != 0 && gpuLayout;
  this->Modified();
}

std::string
OpenCLBilateralDepthRelaxFilter::GetKernelSource()
{
  return CurrentKernelSource();
}

std::string
OpenCLBilateralDepthRelaxFilter::GetBuildOptions() const
{
  return m_DeviceState ? m_DeviceState->BuildOptions : std::string();
}

std::string
OpenCLBilateralDepthRelaxFilter::GetProgramSource() const
{
  if (!m_DeviceState)
  {
    return std::string();
  }
  try
  {
    return m_DeviceState->Program.getInfo<CL_PROGRAM_SOURCE>();
  }
  catch (const cl::Error & error)
  {
    itkExceptionMacro(<< "reading the program source back: " << vr::DescribeOpenCLError(error));
  }
}

std::string
OpenCLBilateralDepthRelaxFilter::GetDeviceLabel() const
{
  return m_DeviceState ? m_DeviceState->Info.Label() : std::string();
}

void
OpenCLBilateralDepthRelaxFilter::PrepareDevice()
{
  vr::OpenCLDeviceInfo chosen;
  try
  {
    chosen = vr::FindOpenCLDevice(m_DeviceRequest, "DeviceRequest");
  }
  catch (const vr::InputError & error)
  {
    itkExceptionMacro(<< error.what());
  }
  const std::string source = CurrentKernelSource();
  if (m_DeviceState && m_DeviceState->Info.PlatformIndex == chosen.PlatformIndex &&
      m_DeviceState->Info.DeviceIndex == chosen.DeviceIndex && m_DeviceState->Info.DeviceName == chosen.DeviceName &&
      m_DeviceState->Source == source && m_DeviceState->ForcedVectorWidth == m_ForcedVectorWidth &&
      m_DeviceState->ForcedGPULayout == m_ForcedGPULayout)
  {
    return;
  }

  m_DeviceState.reset();
  auto state = std::make_unique<DeviceState>();
  state->Info = chosen;
  state->Source = source;
  state->ForcedVectorWidth = m_ForcedVectorWidth;
  state->ForcedGPULayout = m_ForcedGPULayout;
  try
  {
    state->Device = vr::GetOpenCLDevice(chosen.PlatformIndex, chosen.DeviceIndex);
    state->Context = cl::Context(state->Device);
    state->Queue = cl::CommandQueue(state->Context, state->Device);
    state->Shape = ChooseKernelShape(state->Device, m_ForcedVectorWidth, m_ForcedGPULayout);
    state->BuildOptions = BuildOptionsFor(state->Shape);
    state->Program = cl::Program(state->Context, source);
    try
    {
      state->Program.build(std::vector<cl::Device>{ state->Device }, state->BuildOptions.c_str());
    }
    catch (const cl::Error & error)
    {
      if (error.err() != CL_BUILD_PROGRAM_FAILURE)
      {
        throw;
      }
      const std::string log = state->Program.getBuildInfo<CL_PROGRAM_BUILD_LOG>(state->Device);
      itkExceptionMacro(<< "the OpenCL program " << vr::opencl_sources::BilateralDepthRelaxFileName
                        << " failed to build for " << chosen.Label() << "; the compiler's log:\n"
                        << log);
    }
    for (auto & kernel : state->Kernels)
    {
      kernel = cl::Kernel(state->Program, KernelName);
    }
  }
  catch (const cl::Error & error)
  {
    itkExceptionMacro(<< "preparing OpenCL device " << chosen.Label() << ": " << vr::DescribeOpenCLError(error));
  }
  m_DeviceState = std::move(state);
}

std::size_t
OpenCLBilateralDepthRelaxFilter::GetWorkspaceBytes(const SizeType & size)
{
  if (this->GetSolver() == BilateralDepthRelaxSolver::Steady)
  {
    return Superclass::GetWorkspaceBytes(size);
  }
  if (!m_DeviceState || !m_DeviceState->Info.IsCPU)
  {
    return 0; // a GPU's buffers are in its own memory
  }
  // RelaxOnDevice()'s two buffers of high and low planes and the mask, on rows of the layout's pitch.
  const KernelShape & shape = m_DeviceState->Shape;
  const std::size_t   vectorWidth = shape.VectorWidth;
  const std::size_t   pitch = vectorWidth + RoundUp(size[0], vectorWidth * shape.VectorsPerItem) + vectorWidth;
  return 2 * 2 * pitch * size[1] * sizeof(float) + pitch * size[1];
}

void
OpenCLBilateralDepthRelaxFilter::GenerateData()
{
  this->AllocateOutputs();
  this->VerifyDepthIsFinite();
  if (this->GetSolver() == BilateralDepthRelaxSolver::Steady)
  {
    // The steady solver (a multigrid) has no OpenCL kernel: it runs on the CPU, explicitly and whatever the device.
    this->RelaxOnHost();
    return;
  }
  this->PrepareDevice();
  this->RelaxOnDevice();
}

void
OpenCLBilateralDepthRelaxFilter::RelaxOnDevice()
{
  const ImageType *     depth = this->GetInput();
  const MaskImageType * mask = this->GetFixedMask();
  ImageType *           output = this->GetOutput();
  DeviceState &         state = *m_DeviceState;
  const KernelShape &   shape = state.Shape;

  const auto        size = depth->GetLargestPossibleRegion().GetSize();
  const std::size_t width = size[0];
  const std::size_t height = size[1];
  const std::size_t vectorWidth = shape.VectorWidth;
  const std::size_t blockWidth = vectorWidth * shape.VectorsPerItem;
  const std::size_t pitch = vectorWidth + RoundUp(width, blockWidth) + vectorWidth;
  // Each buffer holds the high and the low plane of the depth pairs. The kernel indexes floats with int.
  const std::size_t plane = pitch * height;
  if (2 * plane > static_cast<std::size_t>(INT_MAX))
  {
    itkExceptionMacro(<< "the depth image of " << width << " x " << height
                      << " pixels is too large for the OpenCL kernel (at most " << INT_MAX << " padded pixels)");
  }
  const std::size_t blocksPerRow = RoundUp(width, blockWidth) / blockWidth;
  const std::size_t itemRows = RoundUp(height, shape.RowsPerItem) / shape.RowsPerItem;
  const cl::NDRange global(RoundUp(blocksPerRow, shape.LocalWidth), RoundUp(itemRows, shape.LocalHeight));
  const cl::NDRange local(shape.LocalWidth, shape.LocalHeight);

  // The pixels of a row start after a vector of padding; padding stays 0 (finite) for ever.
  const std::array<std::size_t, 3> depthOrigin{ vectorWidth * sizeof(float), 0, 0 };
  const std::array<std::size_t, 3> maskOrigin{ vectorWidth, 0, 0 };
  const std::array<std::size_t, 3> hostOrigin{ 0, 0, 0 };
  const std::array<std::size_t, 3> depthRegion{ width * sizeof(float), height, 1 };
  const std::array<std::size_t, 3> maskRegion{ width, height, 1 };

  try
  {
    if (state.Width != width || state.Height != height || state.Pitch != pitch)
    {
      state.Width = state.Height = state.Pitch = 0;
      for (auto & buffer : state.Depth)
      {
        buffer = cl::Buffer(state.Context, CL_MEM_READ_WRITE, 2 * plane * sizeof(float));
        state.Queue.enqueueFillBuffer(buffer, 0.0f, 0, 2 * plane * sizeof(float));
      }
      state.Mask = cl::Buffer(state.Context, CL_MEM_READ_ONLY, pitch * height);
      state.Width = width;
      state.Height = height;
      state.Pitch = pitch;
    }

    state.Queue.enqueueWriteBufferRect(state.Depth[0],
                                       CL_FALSE,
                                       depthOrigin,
                                       hostOrigin,
                                       depthRegion,
                                       pitch * sizeof(float),
                                       0,
                                       width * sizeof(float),
                                       0,
                                       depth->GetBufferPointer());
    state.Queue.enqueueFillBuffer(state.Depth[0], 0.0f, plane * sizeof(float), plane * sizeof(float)); // low = 0
    if (mask)
    {
      state.Queue.enqueueWriteBufferRect(
        state.Mask, CL_FALSE, maskOrigin, hostOrigin, maskRegion, pitch, 0, width, 0, mask->GetBufferPointer());
    }
    else
    {
      state.Queue.enqueueFillBuffer(state.Mask, static_cast<cl_uchar>(0), 0, pitch * height);
    }

    for (int parity = 0; parity < 2; ++parity)
    {
      cl::Kernel & kernel = state.Kernels[parity];
      kernel.setArg(0, state.Depth[parity]);
      kernel.setArg(1, state.Depth[1 - parity]);
      kernel.setArg(2, state.Mask);
      kernel.setArg(3, static_cast<cl_int>(width));
      kernel.setArg(4, static_cast<cl_int>(height));
      kernel.setArg(5, static_cast<cl_int>(pitch));
      kernel.setArg(6, static_cast<cl_int>(blocksPerRow));
      kernel.setArg(7, static_cast<cl_float>(this->GetRelaxation()));
      kernel.setArg(8, static_cast<cl_float>(this->GetAnisotropy() / std::log(2.0))); // a log2(e): R = 2^(-. x^2)
      kernel.setArg(9, static_cast<cl_int>(plane));
    }
    // Progress, and a chance to abort, about ProgressReports times per update: the host waits for the queue once
    // per chunk of iterations, never once per iteration.
    const unsigned int iterations = this->GetNumberOfIterations();
    const unsigned int chunk = std::max(1u, (iterations + ProgressReports - 1) / ProgressReports);
    for (unsigned int iteration = 0; iteration < iterations;)
    {
      for (const unsigned int end = std::min(iterations, iteration + chunk); iteration < end; ++iteration)
      {
        state.Queue.enqueueNDRangeKernel(state.Kernels[iteration % 2], cl::NullRange, global, local);
      }
      state.Queue.finish();
      this->UpdateProgress(static_cast<float>(iteration) / static_cast<float>(iterations));
      this->ThrowIfAborted(iteration);
    }
    // One download of both planes; the depth is high + low.
    std::vector<float>               lowPlane(width * height);
    const std::array<std::size_t, 3> lowOrigin{ vectorWidth * sizeof(float), height, 0 };
    state.Queue.enqueueReadBufferRect(state.Depth[iterations % 2],
                                      CL_FALSE,
                                      depthOrigin,
                                      hostOrigin,
                                      depthRegion,
                                      pitch * sizeof(float),
                                      0,
                                      width * sizeof(float),
                                      0,
                                      output->GetBufferPointer());
    state.Queue.enqueueReadBufferRect(state.Depth[iterations % 2],
                                      CL_TRUE,
                                      lowOrigin,
                                      hostOrigin,
                                      depthRegion,
                                      pitch * sizeof(float),
                                      0,
                                      width * sizeof(float),
                                      0,
                                      lowPlane.data());
    float * relaxed = output->GetBufferPointer();
    for (std::size_t k = 0; k < lowPlane.size(); ++k)
    {
      relaxed[k] += lowPlane[k];
    }
  }
  catch (const cl::Error & error)
  {
    // The queue may still read the input or write the output: let it drain before the images can go away.
    try
    {
      state.Queue.finish();
    }
    catch (const cl::Error &)
    {
    }
    const std::string device = state.Info.Label();
    m_DeviceState.reset(); // start afresh next time rather than trust a queue that failed
    itkExceptionMacro(<< "relaxing on OpenCL device " << device << ": " << vr::DescribeOpenCLError(error));
  }
}

void
OpenCLBilateralDepthRelaxFilter::PrintSelf(std::ostream & os, Indent indent) const
{
  Superclass::PrintSelf(os, indent);
  os << indent << "DeviceRequest: \"" << m_DeviceRequest << "\"" << std::endl;
  os << indent << "ForcedVectorWidth: " << m_ForcedVectorWidth << " (0 = the device's preferred width)" << std::endl;
  os << indent << "ForcedGPULayout: " << (m_ForcedGPULayout ? "On" : "Off") << std::endl;
  if (m_DeviceState)
  {
    const KernelShape & shape = m_DeviceState->Shape;
    os << indent << "Device: " << m_DeviceState->Info.Label() << std::endl;
    os << indent << "Kernel shape: " << shape.VectorWidth << "-lane vectors, " << shape.VectorsPerItem << " vectors x "
       << shape.RowsPerItem << " rows per work-item, work-groups of " << shape.LocalWidth << " x " << shape.LocalHeight
       << std::endl;
    os << indent << "Build options: " << m_DeviceState->BuildOptions << std::endl;
  }
  else
  {
    os << indent << "Device: (not chosen yet)" << std::endl;
  }
}

} // namespace itk
