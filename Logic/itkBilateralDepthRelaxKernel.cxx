#include "itkBilateralDepthRelaxKernel.h"

#include "itkBilateralDepthRelaxRows.h"
#include "itkThreadTeamBarrier.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <exception>
#include <future>
#include <limits>
#include <memory>
#include <new>
#include <stdexcept>
#include <string>
#include <system_error>
#include <thread>
#include <vector>

namespace itk
{
namespace
{
using BilateralDepthRelaxRows::RelaxGrid;
using BilateralDepthRelaxRows::RowAlignment;
using BilateralDepthRelaxRows::RowScratch;
using BilateralDepthRelaxRows::SweepFunction;

/** The row sweep for one instruction set, and its name. */
struct RowSweep
{
  SweepFunction Sweep;
  const char *  InstructionSet;
};

#if defined(VR_RELAX_RUNTIME_DISPATCH)
/** The instruction sets this processor runs (CPUID), widest first. */
std::vector<RowSweep>
FindRowSweeps()
{
  std::vector<RowSweep> sweeps;
  __builtin_cpu_init();
  if (__builtin_cpu_supports("x86-64-v4"))
  {
    sweeps.push_back({ BilateralDepthRelaxRows::SweepAVX512, "AVX-512" });
  }
  if (__builtin_cpu_supports("x86-64-v3"))
  {
    sweeps.push_back({ BilateralDepthRelaxRows::SweepAVX2, "AVX2+FMA" });
  }
  sweeps.push_back({ BilateralDepthRelaxRows::SweepBaseline, BilateralDepthRelaxRows::BaselineInstructionSet });
  return sweeps;
}
#else
/** Without runtime dispatch the compiler's target flags (e.g. -march=native) decide the vector width. */
std::vector<RowSweep>
FindRowSweeps()
{
  return { { BilateralDepthRelaxRows::SweepBaseline, BilateralDepthRelaxRows::BaselineInstructionSet } };
}
#endif

const std::vector<RowSweep> &
RowSweeps()
{
  static const std::vector<RowSweep> sweeps = FindRowSweeps();
  return sweeps;
}

/** Index into RowSweeps() of the one Relax() uses: the widest unless SetInstructionSet() said otherwise. */
std::atomic<std::size_t> ChosenRowSweep{ 0 };

const RowSweep &
TheRowSweep()
{
  return RowSweeps()[ChosenRowSweep.load(std::memory_order_relaxed)];
}

/** sqrt(a log2(e)) for a > 0, 1 for a = 0: the factor the kernel holds depths multiplied by. */
double
DepthScale(double anisotropy)
{
  return anisotropy > 0.0 ? std::sqrt(anisotropy / std::log(2.0)) : 1.0;
}

/** Values aligned to a cache line, zero-filled. */
template <typename TValue>
class AlignedBuffer
{
public:
  explicit AlignedBuffer(std::size_t count)
    : m_Data(Allocate(count))
  {
  }
  TValue *
  Get() const
  {
    return m_Data.get();
  }

private:
  static constexpr std::align_val_t Alignment{ 64 };
  static TValue *
  Allocate(std::size_t count)
  {
    if (count > std::numeric_limits<std::size_t>::max() / sizeof(TValue) - RowAlignment)
    {
      throw std::bad_alloc();
    }
    const std::size_t rounded = (count + RowAlignment - 1) / RowAlignment * RowAlignment;
    auto *            data = static_cast<TValue *>(::operator new[](rounded * sizeof(TValue), Alignment));
    std::fill_n(data, rounded, TValue{});
    return data;
  }
  struct Deleter
  {
    void
    operator()(TValue * data) const
    {
      ::operator delete[](data, Alignment);
    }
  };
  std::unique_ptr<TValue[], Deleter> m_Data;
};

/** A thread's row buffers, in two allocations. */
class ThreadScratch
{
public:
  explicit ThreadScratch(std::size_t stride)
    : m_Edges(4 * stride)
    , m_DiscardedRow(2 * stride)
  {
    m_Rows.UpWeight = m_Edges.Get();
    m_Rows.UpFlux = m_Edges.Get() + stride;
    m_Rows.DownWeight = m_Edges.Get() + 2 * stride;
    m_Rows.DownFlux = m_Edges.Get() + 3 * stride;
    m_Rows.DiscardedRow = m_DiscardedRow.Get();
  }
  RowScratch &
  Rows()
  {
    return m_Rows;
  }

private:
  AlignedBuffer<float> m_Edges;
  AlignedBuffer<float> m_DiscardedRow;
  RowScratch           m_Rows{};
};
} // namespace

void
BilateralDepthRelaxKernel::Relax(const float *            depth,
                                 const unsigned char *    fixed,
                                 float *                  relaxed,
                                 std::size_t              width,
                                 std::size_t              height,
                                 double                   relaxation,
                                 double                   anisotropy,
                                 unsigned int             iterations,
                                 unsigned int             threads,
                                 const ProgressCallback & progress)
{
  const std::size_t count = width * height;
  if (count == 0)
  {
    return;
  }
  if (iterations == 0 || relaxation == 0.0)
  {
    // w = 0 gives every pixel all the weight: nothing moves.
    std::memmove(relaxed, depth, count * sizeof(float));
    if (progress && iterations > 0)
    {
      progress(iterations);
    }
    return;
  }

  RelaxGrid grid{};
  grid.Width = width;
  grid.Height = height;
  grid.Stride = (width + RowAlignment - 1) / RowAlignment * RowAlignment;
  grid.Isotropic = anisotropy == 0.0;
  const double      scale = DepthScale(anisotropy);
  const std::size_t paddedCount = height * grid.Stride;

  // The right neighbour of the last vector of the last row reads one vector past the image.
  AlignedBuffer<float> first(2 * paddedCount + RowAlignment);
  AlignedBuffer<float> second(2 * paddedCount + RowAlignment);
  // Eq. 1 divided by w: the pixel's own weight becomes ((1 - w) / w) |Omega|.
  AlignedBuffer<float> selfWeight(paddedCount);
  const double         selfPerNeighbour = (1.0 - relaxation) / relaxation;
  const float          immovable = std::numeric_limits<float>::infinity();
  for (std::size_t y = 0; y < height; ++y)
  {
    // Padding columns repeat the last column.
    float * high = first.Get() + 2 * y * grid.Stride;
    float * low = high + grid.Stride;
    for (std::size_t x = 0; x < grid.Stride; ++x)
    {
      const double scaled = scale * depth[y * width + std::min(x, width - 1)];
      high[x] = static_cast<float>(scaled);
      low[x] = static_cast<float>(scaled - high[x]);
    }
    float *           self = selfWeight.Get() + y * grid.Stride;
    const std::size_t verticalNeighbours = (y > 0) + (y + 1 < height);
    for (std::size_t x = 0; x < width; ++x)
    {
      const std::size_t neighbours = verticalNeighbours + (x > 0) + (x + 1 < width);
      self[x] = (fixed && fixed[y * width + x])
                  ? immovable
                  : static_cast<float>(selfPerNeighbour * static_cast<double>(neighbours));
    }
    std::fill(self + width, self + grid.Stride, immovable);
  }
  std::copy_n(first.Get(), 2 * paddedCount + RowAlignment, second.Get());
  grid.SelfWeight = selfWeight.Get();

  const unsigned int team = static_cast<unsigned int>(std::max<std::size_t>(1, std::min<std::size_t>(threads, height)));
  std::vector<ThreadScratch> scratch;
  scratch.reserve(team);
  for (unsigned int member = 0; member < team; ++member)
  {
    scratch.emplace_back(grid.Stride);
  }

  // Each member sweeps a fixed band of rows; after the barrier every member sees the whole new image. Member 0
  // is the calling thread and reports progress; a progress callback that throws stops every member after the
  // same barrier. The iteration after whose barrier the team stops is set by member 0 while others may still
  // be leaving the previous barrier, so each member compares it with the iteration it has just finished.
  ThreadTeamBarrier         barrier(team);
  std::atomic<unsigned int> stopAfterIteration{ iterations };
  std::exception_ptr        failure;
  auto                      work = [&](unsigned int member)
  {
    const std::size_t   rowBegin = height * member / team;
    const std::size_t   rowEnd = height * (member + 1) / team;
    const SweepFunction sweep = TheRowSweep().Sweep;
    float *             current = first.Get();
    float *             next = second.Get();
    for (unsigned int iteration = 0; iteration < iterations; ++iteration)
    {
      sweep(grid, current, next, rowBegin, rowEnd, scratch[member].Rows());
      if (member == 0 && progress && iteration > 0)
      {
        try
        {
          progress(iteration);
        }
        catch (...)
        {
          failure = std::current_exception();
          stopAfterIteration.store(iteration, std::memory_order_relaxed);
        }
      }
      barrier.Wait();
      if (stopAfterIteration.load(std::memory_order_relaxed) <= iteration)
      {
        return;
      }
      std::swap(current, next);
    }
  };

  // Helpers wait for the word to start, so that a helper the system refuses to create leaves nobody waiting.
  std::promise<bool>       start;
  std::shared_future<bool> started = start.get_future().share();
  std::vector<std::thread> helpers;
  helpers.reserve(team - 1);
  try
  {
    for (unsigned int member = 1; member < team; ++member)
    {
      helpers.emplace_back(
        [&work, started, member]
        {
          if (started.get())
          {
            work(member);
          }
        });
    }
  }
  catch (const std::system_error &)
  {
    start.set_value(false);
    for (auto & helper : helpers)
    {
      helper.join();
    }
    // The result does not depend on the team size: do it all on this thread.
    Relax(depth, fixed, relaxed, width, height, relaxation, anisotropy, iterations, 1, progress);
    return;
  }
  start.set_value(true);
  work(0);
  for (auto & helper : helpers)
  {
    helper.join();
  }
  if (failure)
  {
    std::rethrow_exception(failure);
  }
  if (progress)
  {
    progress(iterations);
  }

  const float * result = (iterations % 2 == 0) ? first.Get() : second.Get();
  for (std::size_t y = 0; y < height; ++y)
  {
    // Exact for fixed pixels: (x scale) / scale comes within 1e-14 of the float x, which rounding gives back.
    const float * high = result + 2 * y * grid.Stride;
    const float * low = high + grid.Stride;
    for (std::size_t x = 0; x < width; ++x)
    {
      relaxed[y * width + x] = static_cast<float>((static_cast<double>(high[x]) + low[x]) / scale);
    }
  }
}

bool
BilateralDepthRelaxKernel::IsWithinRange(const float * depth, std::size_t count, double anisotropy)
{
  const double limit = MaximumDepthMagnitude / std::max(1.0, DepthScale(anisotropy));
  return std::all_of(depth, depth + count, [limit](float value) { return std::abs(value) <= limit; });
}

std::string
BilateralDepthRelaxKernel::GetInstructionSet()
{
  return TheRowSweep().InstructionSet;
}

std::vector<std::string>
BilateralDepthRelaxKernel::GetSupportedInstructionSets()
{
  std::vector<std::string> names;
  for (const auto & sweep : RowSweeps())
  {
    names.emplace_back(sweep.InstructionSet);
  }
  return names;
}

void
BilateralDepthRelaxKernel::SetInstructionSet(const std::string & name)
{
  const auto & sweeps = RowSweeps();
  if (name.empty())
  {
    ChosenRowSweep.store(0);
    return;
  }
  for (std::size_t k = 0; k < sweeps.size(); ++k)
  {
    if (name == sweeps[k].InstructionSet)
    {
      ChosenRowSweep.store(k);
      return;
    }
  }
  std::string supported;
  for (const auto & sweep : sweeps)
  {
    supported += std::string(supported.empty() ? "" : ", ") + sweep.InstructionSet;
  }
  throw std::invalid_argument("BilateralDepthRelaxKernel: instruction set \"" + name +
                              "\" is not supported here; supported: " + supported);
}

} // namespace itk
