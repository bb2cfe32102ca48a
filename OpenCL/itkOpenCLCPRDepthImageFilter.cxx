// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "itkOpenCLCPRDepthImageFilter.h"

#include "itkCPRCenterlineRasterizer.h"
#include "vrCPRDepthKernelSource.h"
#include "vrInputError.h"
#include "vrOpenCLRuntime.h"
#include "vrOpenCLSessionState.h"

#include <algorithm>
#include <array>
#include <climits>
#include <cmath>
#include <cstring>
#include <sstream>
#include <vector>

namespace itk
{
namespace
{
constexpr int None = -1;

/** A key whose unsigned order is the order of the doubles (for finite values and infinities; -0 counts as +0, as
 * the CPU's comparisons count it). */
cl_ulong
OrderedKey(double value)
{
  if (value == 0.0)
  {
    value = 0.0;
  }
  std::uint64_t bits = 0;
  std::memcpy(&bits, &value, sizeof bits);
  constexpr std::uint64_t sign = std::uint64_t{ 1 } << 63;
  return (bits & sign) != 0 ? ~bits : bits | sign;
}

/** The most whole columns n (at most \a limit) with n * spacing <= radius, as the CPU measures the distance to
 * the owner along a row (|column - chosen| * spacing); -1 when no distance qualifies (no lumen fixing, no radius). */
cl_int
LumenReach(double radius, double spacing, bool fixLumen, long limit)
{
  if (!fixLumen || std::isnan(radius) || !(radius >= 0.0))
  {
    return None;
  }
  long reach = static_cast<long>(std::min(std::floor(radius / spacing), static_cast<double>(limit)));
  while (reach < limit && static_cast<double>(reach + 1) * spacing <= radius)
  {
    ++reach;
  }
  while (reach > 0 && static_cast<double>(reach) * spacing > radius)
  {
    --reach;
  }
  return static_cast<cl_int>(reach);
}

std::size_t
RoundUp(std::size_t value, std::size_t multiple)
{
  return (value + multiple - 1) / multiple * multiple;
}

/** Sections of the per-view upload, each at a multiple of \a alignment bytes (a sub-buffer's origin must be). */
struct ListLayout
{
  std::size_t Index, Owner, Depth, Reach, Key, Radius, FilledRows, Bytes;

  ListLayout(std::size_t count, std::size_t rows, std::size_t alignment)
  {
    std::size_t at = 0;
    const auto  section = [&](std::size_t bytes)
    {
      const std::size_t start = at;
      at = RoundUp(at + std::max<std::size_t>(bytes, 1), alignment);
      return start;
    };
    Index = section(count * sizeof(cl_int));
    Owner = section(count * sizeof(cl_uint));
    Depth = section(count * sizeof(cl_float));
    Reach = section(count * sizeof(cl_int));
    Key = section(count * sizeof(cl_ulong));
    Radius = section(count * sizeof(cl_double));
    FilledRows = section(rows * sizeof(cl_int));
    Bytes = at;
  }
};
} // namespace

struct OpenCLCPRDepthImageFilter::DeviceState
{
  std::shared_ptr<vr::OpenCLSession> Session;
  cl::Program                        Program;
  cl::Kernel                         Scatter, NearestAlongLines, AssignScanline, CopyEmptyRows;
  cl::Kernel                         NearestColumnWinners, AssignNearest; // with double precision only
  std::size_t                        LineGroup{ 1 };
  cl::NDRange                        Local2D;
  std::size_t                        BaseAlignment{ 128 };

  /** Per image size. */
  std::size_t Width{ 0 };
  std::size_t Height{ 0 };
  cl::Buffer  Slots, Before, After, Winner, ColumnDistance, Depth, Fixed, Owner;

  /** The per-view upload and its sections, grown as needed. */
  std::vector<unsigned char>              Upload;
  std::size_t                             ListCapacity{ 0 };
  std::size_t                             ListRows{ 0 };
  cl::Buffer                              List;
  cl::Buffer                              Index, ListOwner, ListDepth, Reach, Key, Radius, FilledRows;
  std::vector<detail::CPRCenterlinePixel> Pixels;

  vr::OpenCLSessionState &
  Device()
  {
    return Session->GetInternals();
  }
};

OpenCLCPRDepthImageFilter::OpenCLCPRDepthImageFilter() = default;

OpenCLCPRDepthImageFilter::~OpenCLCPRDepthImageFilter()
{
  this->WithdrawOutputs();
}

void
OpenCLCPRDepthImageFilter::WithdrawOutputs()
{
  if (m_DeviceState)
  {
    m_DeviceState->Device().WithdrawAll(this);
  }
}

void
OpenCLCPRDepthImageFilter::SetSession(std::shared_ptr<vr::OpenCLSession> session)
{
  if (session != m_Session)
  {
    m_Session = std::move(session);
    this->Modified();
  }
}

std::shared_ptr<vr::OpenCLSession>
OpenCLCPRDepthImageFilter::GetSession() const
{
  return m_Session ? m_Session : (m_DeviceState ? m_DeviceState->Session : nullptr);
}

std::string
OpenCLCPRDepthImageFilter::GetDeviceLabel() const
{
  const auto session = this->GetSession();
  return session ? session->GetDeviceInfo().Label() : std::string();
}

std::string
OpenCLCPRDepthImageFilter::GetKernelSource()
{
  return vr::opencl_sources::CPRDepth;
}

void
OpenCLCPRDepthImageFilter::PrepareDevice()
{
  std::shared_ptr<vr::OpenCLSession> session = m_Session;
  if (!session)
  {
    if (m_DeviceState)
    {
      return; // the filter's own session, opened before
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
  this->WithdrawOutputs();
  m_DeviceState.reset();
  auto state = std::make_unique<DeviceState>();
  state->Session = session;
  vr::OpenCLSessionState & device = state->Device();
  try
  {
    const std::size_t maximumGroup = device.Device.getInfo<CL_DEVICE_MAX_WORK_GROUP_SIZE>();
    while (state->LineGroup * 2 <= std::min<std::size_t>(maximumGroup, 128))
    {
      state->LineGroup *= 2;
    }
    std::size_t localWidth = 16;
    std::size_t localHeight = 8;
    while (localWidth * localHeight > maximumGroup)
    {
      (localWidth >= localHeight ? localWidth : localHeight) /= 2;
    }
    state->Local2D = cl::NDRange(localWidth, localHeight);
    state->BaseAlignment = std::max<std::size_t>(device.Device.getInfo<CL_DEVICE_MEM_BASE_ADDR_ALIGN>() / 8, 8);

    std::ostringstream options;
    options << "-D LINE_GROUP_SIZE=" << state->LineGroup << " -D HAS_DOUBLE=" << (device.DoublePrecision ? 1 : 0);
    try
    {
      state->Program = device.Program(vr::opencl_sources::CPRDepthFileName, GetKernelSource(), options.str());
    }
    catch (const vr::OpenCLBuildFailure & failure)
    {
      itkExceptionMacro(<< failure.what() << "; the compiler's log:\n" << failure.Log());
    }
    state->Scatter = cl::Kernel(state->Program, "ScatterSlots");
    state->NearestAlongLines = cl::Kernel(state->Program, "NearestAlongLines");
    state->AssignScanline = cl::Kernel(state->Program, "AssignScanline");
    state->CopyEmptyRows = cl::Kernel(state->Program, "CopyEmptyRows");
    if (device.DoublePrecision)
    {
      state->NearestColumnWinners = cl::Kernel(state->Program, "NearestColumnWinners");
      state->AssignNearest = cl::Kernel(state->Program, "AssignNearest");
    }
  }
  catch (const cl::Error & error)
  {
    itkExceptionMacro(<< "preparing OpenCL device " << device.Info.Label() << ": " << vr::DescribeOpenCLError(error));
  }
  m_DeviceState = std::move(state);
}

std::string
OpenCLCPRDepthImageFilter::WhyHost(CPRDepthMode mode) const
{
  std::ostringstream why;
  switch (mode)
  {
    case CPRDepthMode::Scanline:
      return std::string();
    case CPRDepthMode::Nearest:
      if (m_DeviceState->Session->HasDoublePrecision())
      {
        return std::string();
      }
      why << "the depth mode Nearest needs double precision on the device (cl_khr_fp64), which "
          << m_DeviceState->Session->GetDeviceInfo().Label() << " lacks: the CPU computes the depth map";
      return why.str();
    default:
      why << "the depth mode " << mode << " has no OpenCL kernel: the CPU computes the depth map";
      return why.str();
  }
}

void
OpenCLCPRDepthImageFilter::GenerateData()
{
  this->WithdrawOutputs();
  this->PrepareDevice();
  m_HostReason = this->WhyHost(this->GetMode());
  if (!m_HostReason.empty())
  {
    Superclass::GenerateData();
    return;
  }
  this->ComputeOnDevice();
}

void
OpenCLCPRDepthImageFilter::ComputeOnDevice()
{
  DepthImageType * depth = this->GetDepthOutput();
  MaskImageType *  mask = this->GetFixedMaskOutput();
  LabelImageType * labels = this->GetOwnerLabelOutput();
  LabelImageType * hidden = this->GetHiddenLabelOutput();
  for (ImageBase<2> * output : std::initializer_list<ImageBase<2> *>{ depth, mask, labels, hidden })
  {
    output->SetBufferedRegion(output->GetRequestedRegion());
  }
  depth->Allocate();
  mask->Allocate();
  labels->Allocate();
  // Only Visibility mode hides a vessel, and it runs on the CPU (WhyHost): here no pixel has one behind it.
  hidden->Allocate();
  hidden->FillBuffer(0);

  DeviceState &            state = *m_DeviceState;
  vr::OpenCLSessionState & device = state.Device();
  const CPRViewGeometry &  view = this->GetView();
  const std::size_t        width = view.GetSize()[0];
  const std::size_t        height = view.GetSize()[1];
  if (width * height > static_cast<std::size_t>(INT_MAX))
  {
    itkExceptionMacro(<< "the view of " << width << " x " << height
                      << " pixels is too large for the OpenCL depth kernels (at most " << INT_MAX << " pixels)");
  }
  const bool nearest = this->GetMode() == CPRDepthMode::Nearest;
  const bool fixLumen = this->GetFixLumen() && this->GetCenterlineTree().HasRadii();

  detail::RasterizeCenterlines(this->GetCenterlineTree(), view, state.Pixels);
  this->UpdateProgress(0.3f);
  const std::size_t count = state.Pixels.size();
  if (count == 0)
  {
    itkExceptionMacro(<< "CPRDepthImageFilter: no centerline point projects into the " << width << " x " << height
                      << " image; check the view centre, size and spacing");
  }

  // Scanline: each row's nearest row with a centerline pixel (the upper one on a tie), as the CPU copies rows.
  std::vector<cl_int> filledRows(height, None);
  if (!nearest)
  {
    std::vector<unsigned char> filled(height, 0);
    for (const auto & pixel : state.Pixels)
    {
      filled[pixel.Index / width] = 1;
    }
    long previous = None;
    for (std::size_t row = 0; row < height; ++row)
    {
      previous = filled[row] ? static_cast<long>(row) : previous;
      filledRows[row] = static_cast<cl_int>(previous);
    }
    long next = None;
    for (long row = static_cast<long>(height) - 1; row >= 0; --row)
    {
      next = filled[row] ? row : next;
      const long above = filledRows[row];
      if (above == None || (next != None && next - row < row - above))
      {
        filledRows[row] = static_cast<cl_int>(next);
      }
    }
  }

  try
  {
    if (state.Width != width || state.Height != height)
    {
      state.Width = state.Height = 0;
      const std::size_t pixels = width * height;
      state.Slots = cl::Buffer(device.Context, CL_MEM_READ_WRITE, pixels * sizeof(cl_int));
      state.Before = cl::Buffer(device.Context, CL_MEM_READ_WRITE, pixels * sizeof(cl_int));
      state.After = cl::Buffer(device.Context, CL_MEM_READ_WRITE, pixels * sizeof(cl_int));
      state.Depth = cl::Buffer(device.Context, CL_MEM_READ_WRITE, pixels * sizeof(cl_float));
      state.Fixed = cl::Buffer(device.Context, CL_MEM_READ_WRITE, pixels);
      state.Owner = cl::Buffer(device.Context, CL_MEM_READ_WRITE, pixels * sizeof(cl_uint));
      state.Winner = cl::Buffer();
      state.ColumnDistance = cl::Buffer();
      state.Width = width;
      state.Height = height;
    }
    if (nearest && state.Winner() == nullptr)
    {
      state.Winner = cl::Buffer(device.Context, CL_MEM_READ_WRITE, width * height * sizeof(cl_int));
      state.ColumnDistance = cl::Buffer(device.Context, CL_MEM_READ_WRITE, width * height * sizeof(cl_double));
    }

    // The list, one upload: sub-buffers of one buffer, grown to the next power of two of entries when too small.
    if (count > state.ListCapacity || height != state.ListRows)
    {
      std::size_t capacity = std::max<std::size_t>(state.ListCapacity, 1024);
      while (capacity < count)
      {
        capacity *= 2;
      }
      const ListLayout layout(capacity, height, state.BaseAlignment);
      state.List = cl::Buffer(device.Context, CL_MEM_READ_ONLY, layout.Bytes);
      const auto section = [&](std::size_t origin, std::size_t bytes)
      {
        cl_buffer_region region{ origin, std::max<std::size_t>(bytes, 1) };
        return state.List.createSubBuffer(CL_MEM_READ_ONLY, CL_BUFFER_CREATE_TYPE_REGION, &region);
      };
      state.Index = section(layout.Index, capacity * sizeof(cl_int));
      state.ListOwner = section(layout.Owner, capacity * sizeof(cl_uint));
      state.ListDepth = section(layout.Depth, capacity * sizeof(cl_float));
      state.Reach = section(layout.Reach, capacity * sizeof(cl_int));
      state.Key = section(layout.Key, capacity * sizeof(cl_ulong));
      state.Radius = section(layout.Radius, capacity * sizeof(cl_double));
      state.FilledRows = section(layout.FilledRows, height * sizeof(cl_int));
      state.Upload.assign(layout.Bytes, 0);
      state.ListCapacity = capacity;
      state.ListRows = height;
    }
    const ListLayout layout(state.ListCapacity, height, state.BaseAlignment);
    unsigned char *  upload = state.Upload.data();
    const double     columnSpacing = view.GetSpacing()[0];
    for (std::size_t entry = 0; entry < count; ++entry)
    {
      const auto &   pixel = state.Pixels[entry];
      const cl_int   index = static_cast<cl_int>(pixel.Index);
      const cl_uint  owner = pixel.Owner;
      const cl_float depthValue = static_cast<float>(pixel.Depth);
      const cl_int   reach = LumenReach(pixel.Radius, columnSpacing, fixLumen, static_cast<long>(width));
      const cl_ulong key = OrderedKey(pixel.Depth);
      const double   radius = pixel.Radius;
      std::memcpy(upload + layout.Index + entry * sizeof index, &index, sizeof index);
      std::memcpy(upload + layout.Owner + entry * sizeof owner, &owner, sizeof owner);
      std::memcpy(upload + layout.Depth + entry * sizeof depthValue, &depthValue, sizeof depthValue);
      std::memcpy(upload + layout.Reach + entry * sizeof reach, &reach, sizeof reach);
      std::memcpy(upload + layout.Key + entry * sizeof key, &key, sizeof key);
      std::memcpy(upload + layout.Radius + entry * sizeof radius, &radius, sizeof radius);
    }
    std::memcpy(upload + layout.FilledRows, filledRows.data(), height * sizeof(cl_int));
    cl::CommandQueue & queue = device.Queue;
    queue.enqueueWriteBuffer(state.List, CL_FALSE, 0, layout.Bytes, upload);
    queue.enqueueFillBuffer(state.Slots, static_cast<cl_int>(None), 0, width * height * sizeof(cl_int));

    const cl::NDRange local = state.Local2D;
    const cl::NDRange global(RoundUp(width, local[0]), RoundUp(height, local[1]));
    state.Scatter.setArg(0, state.Index);
    state.Scatter.setArg(1, state.Slots);
    state.Scatter.setArg(2, static_cast<cl_int>(count));
    queue.enqueueNDRangeKernel(state.Scatter, cl::NullRange, cl::NDRange(RoundUp(count, 64)), cl::NDRange(64));

    // Rows (Scanline) or columns (Nearest): element p of line l at l * lineStride + p * elementStride.
    const std::size_t lines = nearest ? width : height;
    state.NearestAlongLines.setArg(0, state.Slots);
    state.NearestAlongLines.setArg(1, state.Before);
    state.NearestAlongLines.setArg(2, state.After);
    state.NearestAlongLines.setArg(3, static_cast<cl_int>(nearest ? height : width));
    state.NearestAlongLines.setArg(4, static_cast<cl_int>(nearest ? 1 : width));
    state.NearestAlongLines.setArg(5, static_cast<cl_int>(nearest ? width : 1));
    queue.enqueueNDRangeKernel(
      state.NearestAlongLines, cl::NullRange, cl::NDRange(lines * state.LineGroup), cl::NDRange(state.LineGroup));
    if (nearest)
    {
      cl::Kernel & winners = state.NearestColumnWinners;
      winners.setArg(0, state.Slots);
      winners.setArg(1, state.Before);
      winners.setArg(2, state.After);
      winners.setArg(3, state.Key);
      winners.setArg(4, state.ListOwner);
      winners.setArg(5, state.Winner);
      winners.setArg(6, state.ColumnDistance);
      winners.setArg(7, static_cast<cl_int>(width));
      winners.setArg(8, static_cast<cl_int>(height));
      winners.setArg(9, static_cast<cl_double>(view.GetSpacing()[1]));
      queue.enqueueNDRangeKernel(winners, cl::NullRange, global, local);
      cl::Kernel & assign = state.AssignNearest;
      assign.setArg(0, state.Slots);
      assign.setArg(1, state.Winner);
      assign.setArg(2, state.ColumnDistance);
      assign.setArg(3, state.Key);
      assign.setArg(4, state.ListOwner);
      assign.setArg(5, state.ListDepth);
      assign.setArg(6, state.Radius);
      assign.setArg(7, state.Depth);
      assign.setArg(8, state.Fixed);
      assign.setArg(9, state.Owner);
      assign.setArg(10, static_cast<cl_int>(width));
      assign.setArg(11, static_cast<cl_int>(height));
      assign.setArg(12, static_cast<cl_double>(columnSpacing));
      assign.setArg(13, static_cast<cl_int>(fixLumen ? 1 : 0));
      queue.enqueueNDRangeKernel(assign, cl::NullRange, global, local);
    }
    else
    {
      cl::Kernel & assign = state.AssignScanline;
      assign.setArg(0, state.Slots);
      assign.setArg(1, state.Before);
      assign.setArg(2, state.After);
      assign.setArg(3, state.FilledRows);
      assign.setArg(4, state.Key);
      assign.setArg(5, state.ListOwner);
      assign.setArg(6, state.ListDepth);
      assign.setArg(7, state.Reach);
      assign.setArg(8, state.Depth);
      assign.setArg(9, state.Fixed);
      assign.setArg(10, state.Owner);
      assign.setArg(11, static_cast<cl_int>(width));
      assign.setArg(12, static_cast<cl_int>(height));
      queue.enqueueNDRangeKernel(assign, cl::NullRange, global, local);
      cl::Kernel & copy = state.CopyEmptyRows;
      copy.setArg(0, state.FilledRows);
      copy.setArg(1, state.Depth);
      copy.setArg(2, state.Fixed);
      copy.setArg(3, state.Owner);
      copy.setArg(4, static_cast<cl_int>(width));
      copy.setArg(5, static_cast<cl_int>(height));
      queue.enqueueNDRangeKernel(copy, cl::NullRange, global, local);
    }

    // One download of each output; the depth and the mask stay on the device for the session's other filters.
    queue.enqueueReadBuffer(state.Depth, CL_FALSE, 0, width * height * sizeof(float), depth->GetBufferPointer());
    queue.enqueueReadBuffer(state.Fixed, CL_FALSE, 0, width * height, mask->GetBufferPointer());
    queue.enqueueReadBuffer(
      state.Owner, CL_TRUE, 0, width * height * sizeof(LabelPixelType), labels->GetBufferPointer());
    vr::OpenCLDeviceImage published;
    published.Buffer = state.Depth;
    published.RowPitch = width * sizeof(float);
    published.Width = width;
    published.Height = height;
    published.PixelBytes = sizeof(float);
    device.Publish(this, depth, depth->GetBufferPointer(), published);
    published.Buffer = state.Fixed;
    published.RowPitch = width;
    published.PixelBytes = 1;
    device.Publish(this, mask, mask->GetBufferPointer(), published);
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
    itkExceptionMacro(<< "computing the depth map on OpenCL device " << label << ": "
                      << vr::DescribeOpenCLError(error));
  }
  this->UpdateProgress(1.0f);
}

void
OpenCLCPRDepthImageFilter::PrintSelf(std::ostream & os, Indent indent) const
{
  Superclass::PrintSelf(os, indent);
  os << indent << "DeviceRequest: \"" << m_DeviceRequest << "\"" << std::endl;
  os << indent << "Session: " << (m_Session ? "shared, set by the caller" : "the filter's own") << std::endl;
  os << indent << "Device: " << (m_DeviceState ? this->GetDeviceLabel() : std::string("(not chosen yet)")) << std::endl;
  os << indent << "HostReason: \"" << m_HostReason << "\"" << std::endl;
}

} // namespace itk
