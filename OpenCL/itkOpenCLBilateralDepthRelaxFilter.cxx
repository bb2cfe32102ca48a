// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "itkOpenCLBilateralDepthRelaxFilter.h"

#include "vrBilateralDepthRelaxKernelSource.h"
#include "vrInputError.h"
#include "vrOpenCLDevices.h"
#include "vrOpenCLRuntime.h"
#include "vrOpenCLSessionState.h"

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
constexpr const char * MultiPassKernelName = "RelaxPasses";
constexpr const char * CombineKernelName = "CombinePlanes";
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
 * side, in RowsPerItem rows; work-groups are LocalWidth x LocalHeight work-items. With PassesPerLaunch > 1 the
 * multi-pass kernel runs instead: scalar, one work-group per tile of TileWidth x TileHeight pixels. */
struct KernelShape
{
  int         VectorWidth{ 1 };
  int         VectorsPerItem{ 1 };
  int         RowsPerItem{ 1 };
  std::size_t LocalWidth{ 1 };
  std::size_t LocalHeight{ 1 };
  int         PassesPerLaunch{ 1 };
  int         TileWidth{ 0 };
  int         TileHeight{ 0 };
};

// The bordered tile of the multi-pass kernel, in work-groups' widths and heights: 96 x 48 pixels for work-groups
// of 32 x 8, two floats and a byte a pixel (41.5 KB of the 48 KB of local memory NVIDIA's OpenCL gives a
// work-group). A tile keeps (96 - 2k) x (48 - 2k) pixels of its own for k passes a launch.
constexpr std::size_t MultiPassLocalWidth = 32;
constexpr std::size_t MultiPassLocalHeight = 8;
constexpr int         MultiPassSlotsX = 3;
constexpr int         MultiPassSlotsY = 6;
constexpr std::size_t MultiPassBytesPerPixel = 2 * sizeof(float) + 1;

bool
IsCPUDevice(const cl::Device & device)
{
  const auto type = device.getInfo<CL_DEVICE_TYPE>();
  return (type & CL_DEVICE_TYPE_GPU) == 0 && (type & CL_DEVICE_TYPE_CPU) != 0;
}

// CPU devices get wide vectors and large blocks per work-item, which share most edge weights through registers;
// GPUs get one pixel column per work-item, so that neighbouring work-items read neighbouring pixels, and several
// passes a launch on tiles in local memory. A forced vector width (not 0) and layout replace the device's (the test
// hook). \a passesPerLaunch is the filter's parameter (0: the device's choice).
KernelShape
ChooseKernelShape(const cl::Device & device,
                  std::size_t        localMemoryBytes,
                  unsigned int       forcedVectorWidth,
                  bool               forcedGPULayout,
                  unsigned int       passesPerLaunch)
{
  KernelShape   shape;
  const cl_uint preferred =
    forcedVectorWidth > 0 ? forcedVectorWidth : device.getInfo<CL_DEVICE_PREFERRED_VECTOR_WIDTH_FLOAT>();
  while (shape.VectorWidth * 2 <= static_cast<int>(std::min<cl_uint>(preferred, 16)))
  {
    shape.VectorWidth *= 2;
  }
  const bool cpuLayout = forcedVectorWidth > 0 ? !forcedGPULayout : IsCPUDevice(device);
  if (cpuLayout)
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
  const auto                     fits = [&](std::size_t width, std::size_t height)
  {
    return width * height <= maximumGroup &&
           (maximumItems.size() < 2 || (width <= maximumItems[0] && height <= maximumItems[1]));
  };
  while (!fits(shape.LocalWidth, shape.LocalHeight))
  {
    (shape.LocalWidth >= shape.LocalHeight ? shape.LocalWidth : shape.LocalHeight) /= 2;
  }
  shape.LocalWidth = std::max<std::size_t>(shape.LocalWidth, 1);
  shape.LocalHeight = std::max<std::size_t>(shape.LocalHeight, 1);

  int passes = static_cast<int>(passesPerLaunch);
  if (passes == 0)
  {
    passes = cpuLayout ? 1 : static_cast<int>(OpenCLBilateralDepthRelaxFilter::DefaultPassesPerLaunchOnGPUs);
  }
  const int extendedWidth = MultiPassSlotsX * static_cast<int>(MultiPassLocalWidth);
  const int extendedHeight = MultiPassSlotsY * static_cast<int>(MultiPassLocalHeight);
  // The multi-pass kernel needs its work-group and its tile's local memory; without them, one pass a launch.
  if (passes > 1 && (!fits(MultiPassLocalWidth, MultiPassLocalHeight) ||
                     extendedWidth * extendedHeight * MultiPassBytesPerPixel > localMemoryBytes))
  {
    passes = 1;
  }
  shape.PassesPerLaunch = passes;
  if (passes > 1)
  {
    shape.VectorWidth = 1;
    shape.VectorsPerItem = 1;
    shape.RowsPerItem = 1;
    shape.LocalWidth = MultiPassLocalWidth;
    shape.LocalHeight = MultiPassLocalHeight;
    shape.TileWidth = extendedWidth - 2 * passes;
    shape.TileHeight = extendedHeight - 2 * passes;
  }
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
  if (shape.PassesPerLaunch > 1)
  {
    options << " -D PASSES_PER_LAUNCH=" << shape.PassesPerLaunch << " -D TILE_WIDTH=" << shape.TileWidth
            << " -D TILE_HEIGHT=" << shape.TileHeight;
  }
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
  /** The device, context and queue (shared with the other filters of a view, or the filter's own). */
  std::shared_ptr<vr::OpenCLSession> Session;
  /** The source the program was built from (the test hook may change it). */
  std::string Source;
  /** The layout the test hook forced, and the passes per launch asked for, when the program was built. */
  unsigned int ForcedVectorWidth{ 0 };
  bool         ForcedGPULayout{ false };
  unsigned int RequestedPassesPerLaunch{ 0 };
  KernelShape  Shape;
  /** The -D options the program was built with (BuildOptionsFor(Shape)). */
  std::string BuildOptions;
  cl::Program Program;
  /** Launch k reads Depth[k % 2] and writes Depth[(k + 1) % 2]: Kernels[k % 2] has those arguments (RelaxIteration,
   * or RelaxPasses with several passes a launch). */
  std::array<cl::Kernel, 2> Kernels;
  cl::Kernel                Combine;

  /** Buffers for images of Width x Height pixels, rows Pitch floats apart (see BilateralDepthRelax.cl). */
  std::size_t               Width{ 0 };
  std::size_t               Height{ 0 };
  std::size_t               Pitch{ 0 };
  std::array<cl::Buffer, 2> Depth;
  cl::Buffer                Mask;
  /** The relaxed depth, one float a pixel, W x H: downloaded, and published for the session's resampling. */
  cl::Buffer Packed;

  vr::OpenCLSessionState &
  Device()
  {
    return Session->GetInternals();
  }
};

OpenCLBilateralDepthRelaxFilter::OpenCLBilateralDepthRelaxFilter() = default;

OpenCLBilateralDepthRelaxFilter::~OpenCLBilateralDepthRelaxFilter()
{
  if (m_DeviceState)
  {
    m_DeviceState->Device().WithdrawAll(this);
  }
}

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

void
OpenCLBilateralDepthRelaxFilter::SetSession(std::shared_ptr<vr::OpenCLSession> session)
{
  if (session != m_Session)
  {
    m_Session = std::move(session);
    this->Modified();
  }
}

std::shared_ptr<vr::OpenCLSession>
OpenCLBilateralDepthRelaxFilter::GetSession() const
{
  if (m_Session)
  {
    return m_Session;
  }
  return m_DeviceState ? m_DeviceState->Session : nullptr;
}

unsigned int
OpenCLBilateralDepthRelaxFilter::GetEffectivePassesPerLaunch() const
{
  return m_DeviceState ? static_cast<unsigned int>(m_DeviceState->Shape.PassesPerLaunch) : 0;
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
  return m_DeviceState ? m_DeviceState->Session->GetDeviceInfo().Label() : std::string();
}

void
OpenCLBilateralDepthRelaxFilter::VerifyPreconditions() ITKv5_CONST
{
  Superclass::VerifyPreconditions();
  if (m_PassesPerLaunch > MaximumPassesPerLaunch)
  {
    itkExceptionMacro(<< "PassesPerLaunch = " << m_PassesPerLaunch << " is invalid: it must be 0 (the device's "
                      << "choice) or 1 to " << MaximumPassesPerLaunch);
  }
}

void
OpenCLBilateralDepthRelaxFilter::PrepareDevice()
{
  std::shared_ptr<vr::OpenCLSession> session = m_Session;
  if (!session)
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
    const auto same = [&chosen](const vr::OpenCLDeviceInfo & info)
    {
      return info.PlatformIndex == chosen.PlatformIndex && info.DeviceIndex == chosen.DeviceIndex &&
             info.DeviceName == chosen.DeviceName;
    };
    session = m_DeviceState && same(m_DeviceState->Session->GetDeviceInfo()) ? m_DeviceState->Session
                                                                             : vr::OpenCLSession::Create(chosen);
  }
  const std::string source = CurrentKernelSource();
  if (m_DeviceState && m_DeviceState->Session == session && m_DeviceState->Source == source &&
      m_DeviceState->ForcedVectorWidth == m_ForcedVectorWidth && m_DeviceState->ForcedGPULayout == m_ForcedGPULayout &&
      m_DeviceState->RequestedPassesPerLaunch == m_PassesPerLaunch)
  {
    return;
  }

  if (m_DeviceState)
  {
    m_DeviceState->Device().WithdrawAll(this);
  }
  m_DeviceState.reset();
  auto state = std::make_unique<DeviceState>();
  state->Session = session;
  state->Source = source;
  state->ForcedVectorWidth = m_ForcedVectorWidth;
  state->ForcedGPULayout = m_ForcedGPULayout;
  state->RequestedPassesPerLaunch = m_PassesPerLaunch;
  vr::OpenCLSessionState & device = state->Device();
  try
  {
    state->Shape = ChooseKernelShape(
      device.Device, device.LocalMemoryBytes, m_ForcedVectorWidth, m_ForcedGPULayout, m_PassesPerLaunch);
    state->BuildOptions = BuildOptionsFor(state->Shape);
    try
    {
      state->Program = device.Program(vr::opencl_sources::BilateralDepthRelaxFileName, source, state->BuildOptions);
    }
    catch (const vr::OpenCLBuildFailure & failure)
    {
      itkExceptionMacro(<< failure.what() << "; the compiler's log:\n" << failure.Log());
    }
    for (auto & kernel : state->Kernels)
    {
      kernel = cl::Kernel(state->Program, state->Shape.PassesPerLaunch > 1 ? MultiPassKernelName : KernelName);
    }
    state->Combine = cl::Kernel(state->Program, CombineKernelName);
  }
  catch (const cl::Error & error)
  {
    itkExceptionMacro(<< "preparing OpenCL device " << device.Info.Label() << ": " << vr::DescribeOpenCLError(error));
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
  if (!m_DeviceState || !m_DeviceState->Session->GetDeviceInfo().IsCPU)
  {
    return 0; // a GPU's buffers are in its own memory
  }
  // RelaxOnDevice()'s two buffers of high and low planes and the mask on rows of the layout's pitch, and the packed
  // result.
  const KernelShape & shape = m_DeviceState->Shape;
  const std::size_t   vectorWidth = shape.VectorWidth;
  const std::size_t   pitch = vectorWidth + RoundUp(size[0], vectorWidth * shape.VectorsPerItem) + vectorWidth;
  return 2 * 2 * pitch * size[1] * sizeof(float) + pitch * size[1] + size[0] * size[1] * sizeof(float);
}

void
OpenCLBilateralDepthRelaxFilter::GenerateData()
{
  // The output is about to change: no filter of the session may read the device's copy of what it held.
  if (m_DeviceState)
  {
    m_DeviceState->Device().WithdrawAll(this);
  }
  m_NumberOfLaunches = 0;
  m_InputsWereOnDevice = false;
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
OpenCLBilateralDepthRelaxFilter::LoadInputs(std::size_t width, std::size_t height, std::size_t pitch, std::size_t plane)
{
  DeviceState &                    state = *m_DeviceState;
  vr::OpenCLSessionState &         device = state.Device();
  const ImageType *                depth = this->GetInput();
  const MaskImageType *            mask = this->GetFixedMask();
  const std::size_t                vectorWidth = state.Shape.VectorWidth;
  const std::array<std::size_t, 3> depthOrigin{ vectorWidth * sizeof(float), 0, 0 };
  const std::array<std::size_t, 3> maskOrigin{ vectorWidth, 0, 0 };
  const std::array<std::size_t, 3> zero{ 0, 0, 0 };
  const std::array<std::size_t, 3> depthRegion{ width * sizeof(float), height, 1 };
  const std::array<std::size_t, 3> maskRegion{ width, height, 1 };

  // Only a whole image can have been published: the depth filter's outputs are never cropped.
  vr::OpenCLDeviceImage onDevice;
  const bool            depthOnDevice = depth->GetBufferedRegion() == depth->GetLargestPossibleRegion() &&
                             device.Find(depth, depth->GetBufferPointer(), width, height, sizeof(float), onDevice);
  if (depthOnDevice)
  {
    const std::array<std::size_t, 3> sourceOrigin{ onDevice.Offset, 0, 0 };
    device.Queue.enqueueCopyBufferRect(onDevice.Buffer,
                                       state.Depth[0],
                                       sourceOrigin,
                                       depthOrigin,
                                       depthRegion,
                                       onDevice.RowPitch,
                                       0,
                                       pitch * sizeof(float),
                                       0);
  }
  else
  {
    device.Queue.enqueueWriteBufferRect(state.Depth[0],
                                        CL_FALSE,
                                        depthOrigin,
                                        zero,
                                        depthRegion,
                                        pitch * sizeof(float),
                                        0,
                                        width * sizeof(float),
                                        0,
                                        depth->GetBufferPointer());
  }
  device.Queue.enqueueFillBuffer(state.Depth[0], 0.0f, plane * sizeof(float), plane * sizeof(float)); // low = 0

  bool maskOnDevice = false;
  if (mask)
  {
    maskOnDevice = mask->GetBufferedRegion() == mask->GetLargestPossibleRegion() &&
                   device.Find(mask, mask->GetBufferPointer(), width, height, 1, onDevice);
    if (maskOnDevice)
    {
      const std::array<std::size_t, 3> sourceOrigin{ onDevice.Offset, 0, 0 };
      device.Queue.enqueueCopyBufferRect(
        onDevice.Buffer, state.Mask, sourceOrigin, maskOrigin, maskRegion, onDevice.RowPitch, 0, pitch, 0);
    }
    else
    {
      device.Queue.enqueueWriteBufferRect(
        state.Mask, CL_FALSE, maskOrigin, zero, maskRegion, pitch, 0, width, 0, mask->GetBufferPointer());
    }
  }
  else
  {
    device.Queue.enqueueFillBuffer(state.Mask, static_cast<cl_uchar>(0), 0, pitch * height);
  }
  m_InputsWereOnDevice = depthOnDevice && (mask == nullptr || maskOnDevice);
}

void
OpenCLBilateralDepthRelaxFilter::RelaxOnDevice()
{
  const ImageType *        depth = this->GetInput();
  ImageType *              output = this->GetOutput();
  DeviceState &            state = *m_DeviceState;
  vr::OpenCLSessionState & device = state.Device();
  const KernelShape &      shape = state.Shape;

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
  const bool        multiPass = shape.PassesPerLaunch > 1;
  const std::size_t blocksPerRow = RoundUp(width, blockWidth) / blockWidth;
  const std::size_t itemRows = RoundUp(height, shape.RowsPerItem) / shape.RowsPerItem;
  const cl::NDRange global =
    multiPass ? cl::NDRange(RoundUp(width, shape.TileWidth) / shape.TileWidth * shape.LocalWidth,
                            RoundUp(height, shape.TileHeight) / shape.TileHeight * shape.LocalHeight)
              : cl::NDRange(RoundUp(blocksPerRow, shape.LocalWidth), RoundUp(itemRows, shape.LocalHeight));
  const cl::NDRange local(shape.LocalWidth, shape.LocalHeight);
  const cl::NDRange combineLocal(std::min<std::size_t>(shape.LocalWidth * shape.LocalHeight, 64), 1);
  const cl::NDRange combineGlobal(RoundUp(width, combineLocal[0]), height);

  try
  {
    if (state.Width != width || state.Height != height || state.Pitch != pitch)
    {
      state.Width = state.Height = state.Pitch = 0;
      for (auto & buffer : state.Depth)
      {
        buffer = cl::Buffer(device.Context, CL_MEM_READ_WRITE, 2 * plane * sizeof(float));
        device.Queue.enqueueFillBuffer(buffer, 0.0f, 0, 2 * plane * sizeof(float));
      }
      state.Mask = cl::Buffer(device.Context, CL_MEM_READ_ONLY, pitch * height);
      state.Packed = cl::Buffer(device.Context, CL_MEM_READ_WRITE, width * height * sizeof(float));
      state.Width = width;
      state.Height = height;
      state.Pitch = pitch;
    }
    this->LoadInputs(width, height, pitch, plane);

    const float weightPower = static_cast<float>(this->GetAnisotropy() / std::log(2.0)); // a log2(e): R = 2^(-. x^2)
    for (int parity = 0; parity < 2; ++parity)
    {
      cl::Kernel & kernel = state.Kernels[parity];
      kernel.setArg(0, state.Depth[parity]);
      kernel.setArg(1, state.Depth[1 - parity]);
      kernel.setArg(2, state.Mask);
      kernel.setArg(3, static_cast<cl_int>(width));
      kernel.setArg(4, static_cast<cl_int>(height));
      kernel.setArg(5, static_cast<cl_int>(pitch));
      if (multiPass)
      {
        kernel.setArg(6, static_cast<cl_float>(this->GetRelaxation()));
        kernel.setArg(7, static_cast<cl_float>(weightPower));
        kernel.setArg(8, static_cast<cl_int>(plane));
      }
      else
      {
        kernel.setArg(6, static_cast<cl_int>(blocksPerRow));
        kernel.setArg(7, static_cast<cl_float>(this->GetRelaxation()));
        kernel.setArg(8, static_cast<cl_float>(weightPower));
        kernel.setArg(9, static_cast<cl_int>(plane));
      }
    }
    // Progress, and a chance to abort, about ProgressReports times per update: the host waits for the queue once
    // per chunk of launches, never once per launch.
    const unsigned int iterations = this->GetNumberOfIterations();
    const unsigned int passesPerLaunch = static_cast<unsigned int>(shape.PassesPerLaunch);
    const unsigned int launches = (iterations + passesPerLaunch - 1) / passesPerLaunch;
    const unsigned int chunk = std::max(1u, (launches + ProgressReports - 1) / ProgressReports);
    unsigned int       iteration = 0;
    for (unsigned int launch = 0; launch < launches;)
    {
      for (const unsigned int end = std::min(launches, launch + chunk); launch < end; ++launch)
      {
        cl::Kernel & kernel = state.Kernels[launch % 2];
        if (multiPass)
        {
          kernel.setArg(9, static_cast<cl_int>(std::min(passesPerLaunch, iterations - iteration)));
        }
        iteration = std::min(iterations, iteration + passesPerLaunch);
        device.Queue.enqueueNDRangeKernel(kernel, cl::NullRange, global, local);
        ++m_NumberOfLaunches;
      }
      device.Queue.finish();
      this->UpdateProgress(static_cast<float>(iteration) / static_cast<float>(iterations));
      this->ThrowIfAborted(iteration);
    }
    // The depth is high + low: joined on the device, downloaded once, and left there for the session's resampling.
    state.Combine.setArg(0, state.Depth[launches % 2]);
    state.Combine.setArg(1, state.Packed);
    state.Combine.setArg(2, static_cast<cl_int>(width));
    state.Combine.setArg(3, static_cast<cl_int>(height));
    state.Combine.setArg(4, static_cast<cl_int>(pitch));
    state.Combine.setArg(5, static_cast<cl_int>(plane));
    device.Queue.enqueueNDRangeKernel(state.Combine, cl::NullRange, combineGlobal, combineLocal);
    ++m_NumberOfLaunches;
    device.Queue.enqueueReadBuffer(
      state.Packed, CL_TRUE, 0, width * height * sizeof(float), output->GetBufferPointer());
    vr::OpenCLDeviceImage published;
    published.Buffer = state.Packed;
    published.RowPitch = width * sizeof(float);
    published.Width = width;
    published.Height = height;
    published.PixelBytes = sizeof(float);
    device.Publish(this, output, output->GetBufferPointer(), published);
  }
  catch (const cl::Error & error)
  {
    // The queue may still read the input or write the output: let it drain before the images can go away.
    try
    {
      device.Queue.finish();
    }
    catch (const cl::Error &)
    {
    }
    const std::string label = device.Info.Label();
    m_DeviceState.reset(); // start afresh next time rather than trust buffers that failed
    itkExceptionMacro(<< "relaxing on OpenCL device " << label << ": " << vr::DescribeOpenCLError(error));
  }
}

void
OpenCLBilateralDepthRelaxFilter::PrintSelf(std::ostream & os, Indent indent) const
{
  Superclass::PrintSelf(os, indent);
  os << indent << "DeviceRequest: \"" << m_DeviceRequest << "\"" << std::endl;
  os << indent << "Session: " << (m_Session ? "shared, set by the caller" : "the filter's own") << std::endl;
  os << indent << "PassesPerLaunch: " << m_PassesPerLaunch << " (0 = the device's choice)" << std::endl;
  os << indent << "ForcedVectorWidth: " << m_ForcedVectorWidth << " (0 = the device's preferred width)" << std::endl;
  os << indent << "ForcedGPULayout: " << (m_ForcedGPULayout ? "On" : "Off") << std::endl;
  os << indent << "NumberOfLaunches (last update): " << m_NumberOfLaunches << std::endl;
  if (m_DeviceState)
  {
    const KernelShape & shape = m_DeviceState->Shape;
    os << indent << "Device: " << m_DeviceState->Session->GetDeviceInfo().Label() << std::endl;
    if (shape.PassesPerLaunch > 1)
    {
      os << indent << "Kernel shape: " << shape.PassesPerLaunch << " passes a launch on tiles of " << shape.TileWidth
         << " x " << shape.TileHeight << " pixels, work-groups of " << shape.LocalWidth << " x " << shape.LocalHeight
         << std::endl;
    }
    else
    {
      os << indent << "Kernel shape: " << shape.VectorWidth << "-lane vectors, " << shape.VectorsPerItem
         << " vectors x " << shape.RowsPerItem << " rows per work-item, work-groups of " << shape.LocalWidth << " x "
         << shape.LocalHeight << ", one pass a launch" << std::endl;
    }
    os << indent << "Build options: " << m_DeviceState->BuildOptions << std::endl;
  }
  else
  {
    os << indent << "Device: (not chosen yet)" << std::endl;
  }
}

} // namespace itk
