// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "itkBilateralDepthRelaxKernel.h"

#include "itkBilateralDepthRelaxArrays.h"
#include "itkBilateralDepthRelaxInstructionSets.h"
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
using detail::BilateralDepthRelaxRows::RelaxGrid;
using detail::BilateralDepthRelaxRows::RowAlignment;
using detail::BilateralDepthRelaxRows::RowKernels;
using detail::BilateralDepthRelaxRows::RowScratch;
using detail::BilateralDepthRelaxRows::SweepFunction;

/** The row kernels for one instruction set, and its name. */
struct RowSweep
{
  const RowKernels * Kernels;
  const char *       InstructionSet;
};

/** The instruction sets this processor runs (CPUID, shared with the steady solver), widest first. */
std::vector<RowSweep>
FindRowSweeps()
{
  std::vector<RowSweep> sweeps;
  for (const detail::InstructionSet set : detail::RunnableInstructionSets())
  {
    switch (set)
    {
#if defined(VR_RELAX_RUNTIME_DISPATCH)
      case detail::InstructionSet::AVX512:
        sweeps.push_back({ &detail::BilateralDepthRelaxRows::KernelsAVX512, "AVX-512" });
        break;
      case detail::InstructionSet::AVX2:
        sweeps.push_back({ &detail::BilateralDepthRelaxRows::KernelsAVX2, "AVX2+FMA" });
        break;
#endif
      default:
        // Without runtime dispatch the compiler's target flags (e.g. -march=native) decide the vector width.
        sweeps.push_back({ &detail::BilateralDepthRelaxRows::KernelsBaseline,
                           detail::BilateralDepthRelaxRows::BaselineInstructionSet });
    }
  }
  return sweeps;
}

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

/** A thread's row buffers, in two allocations. */
class ThreadScratch
{
public:
  explicit ThreadScratch(std::size_t stride)
  {
    float * const edges = m_Edges.Reserve(4 * stride);
    m_Rows.UpWeight = edges;
    m_Rows.UpFlux = edges + stride;
    m_Rows.DownWeight = edges + 2 * stride;
    m_Rows.DownFlux = edges + 3 * stride;
    m_Rows.DiscardedRow = m_DiscardedRow.Reserve(2 * stride);
  }
  RowScratch &
  Rows()
  {
    return m_Rows;
  }

private:
  detail::ReusableArray<float> m_Edges;
  detail::ReusableArray<float> m_DiscardedRow;
  RowScratch                   m_Rows{};
};

/** Input rows a pass of a block keeps for the next: rows y and y + 1 are read while row y + 2 is written. */
constexpr std::size_t RingRows = 3;

/** One team member's buffers for blocks of passes (temporal blocking): for each pass of a block its row edges,
 * and for each pass but the last a ring of the rows it has relaxed, which the next pass reads. */
class MemberScratch
{
public:
  explicit MemberScratch(std::size_t stride)
    : m_Stride(stride)
  {
  }

  /** Buffers for blocks of up to \a passes passes. */
  void
  Reserve(unsigned int passes)
  {
    while (m_Passes.size() < passes)
    {
      m_Passes.push_back(std::make_unique<ThreadScratch>(m_Stride));
    }
    if (passes > 1 && passes - 1 > m_RingPasses)
    {
      // The right neighbour of the last vector of the last ring row reads one vector past it.
      m_RingRows = m_Ring.Reserve((passes - 1) * RingRows * 2 * m_Stride + RowAlignment);
      m_RingPasses = passes - 1;
    }
    NextRow.resize(std::max<std::size_t>(NextRow.size(), passes));
    Started.resize(std::max<std::size_t>(Started.size(), passes));
  }

  /** The edges of pass \a pass (0-based) of a block. */
  RowScratch &
  Rows(unsigned int pass)
  {
    return m_Passes[pass]->Rows();
  }

  /** Where pass \a pass (0-based, not a block's last) keeps row \a y for the next pass. */
  float *
  RingRow(unsigned int pass, std::size_t y)
  {
    return m_RingRows + (pass * RingRows + y % RingRows) * 2 * m_Stride;
  }

  /** Per pass of the block being run: the next row to relax, and whether its edges above were set up. */
  std::vector<std::size_t> NextRow;
  std::vector<char>        Started;

private:
  std::size_t                                 m_Stride;
  std::vector<std::unique_ptr<ThreadScratch>> m_Passes;
  detail::ReusableArray<float>                m_Ring;
  float *                                     m_RingRows{ nullptr };
  std::size_t                                 m_RingPasses{ 0 };
};

/** Runs \a passes Jacobi passes (>= 2) of one team member without meeting the others (temporal blocking): from
 * \a current (the whole image, all rows valid) into rows [rowBegin, rowEnd) of \a next. Pass j (1-based) of the
 * block relaxes the band widened by passes - j rows on each side (clipped to the image), so the last pass has
 * every input it reads; the rows shared with the neighbours' bands are computed again here rather than
 * exchanged. The passes run as a wavefront down the band: pass j relaxes row y as soon as pass j - 1 has row
 * y + 1, so the rows between passes stay in small rings in the cache. Every row is relaxed by the same row kernel
 * from the same input values as in a pass over the whole image, so every bit is the same. Calls \a passDone(j)
 * when pass j has relaxed its last row; returns early, leaving \a next unfinished, once \a stopped() is true. */
template<typename TPassDone, typename TStopped>
void
RelaxBlock(const RowKernels & kernels,
           const RelaxGrid &  grid,
           const float *      current,
           float *            next,
           std::size_t        rowBegin,
           std::size_t        rowEnd,
           unsigned int       passes,
           MemberScratch &    scratch,
           TPassDone &&       passDone,
           TStopped &&        stopped)
{
  const std::size_t height = grid.Height;
  const std::size_t stride = grid.Stride;
  // Pass p (0-based) relaxes rows [first(p), end(p)).
  auto first = [&](unsigned int p) { return rowBegin - std::min<std::size_t>(rowBegin, passes - 1 - p); };
  auto end = [&](unsigned int p) { return std::min(height, rowEnd + (passes - 1 - p)); };
  auto input = [&](unsigned int p, std::size_t y) -> const float *
  { return p == 0 ? current + 2 * y * stride : scratch.RingRow(p - 1, y); };
  auto output = [&](unsigned int p, std::size_t y) -> float *
  { return p + 1 == passes ? next + 2 * y * stride : scratch.RingRow(p, y); };
  // The first row of its ring that pass p still reads (the row above its first, to set up its edges).
  auto oldestNeeded = [&](unsigned int p)
  {
    const std::size_t y = scratch.NextRow[p];
    return scratch.Started[p] || y == 0 ? y : y - 1;
  };
  for (unsigned int p = 0; p < passes; ++p)
  {
    scratch.NextRow[p] = first(p);
    scratch.Started[p] = 0;
  }
  while (scratch.NextRow[passes - 1] < rowEnd)
  {
    if (stopped())
    {
      return;
    }
    // Each round relaxes a row of at least one pass (the rings are wide enough); one that could not would hang.
    bool relaxedARow = false;
    for (unsigned int p = 0; p < passes; ++p)
    {
      const std::size_t y = scratch.NextRow[p];
      if (y == end(p))
      {
        continue;
      }
      // Its input: the previous pass must have relaxed rows y and y + 1.
      if (p > 0 && scratch.NextRow[p - 1] <= std::min(y + 1, height - 1))
      {
        continue;
      }
      // Its ring: row y replaces row y - RingRows, which the next pass must no longer need.
      if (p + 1 < passes && scratch.NextRow[p + 1] < end(p + 1) && y >= oldestNeeded(p + 1) + RingRows)
      {
        continue;
      }
      RowScratch & rows = scratch.Rows(p);
      if (!scratch.Started[p])
      {
        kernels.Start(grid, y > 0 ? input(p, y - 1) : nullptr, input(p, y), y, rows);
        scratch.Started[p] = 1;
      }
      kernels.Row(grid, input(p, y), y + 1 < height ? input(p, y + 1) : nullptr, y, output(p, y), rows);
      scratch.NextRow[p] = y + 1;
      relaxedARow = true;
      if (y + 1 == end(p))
      {
        passDone(p + 1);
      }
    }
    if (!relaxedARow)
    {
      throw std::logic_error("BilateralDepthRelaxKernel: a block of passes stalled (a row's input was never made)");
    }
  }
}
} // namespace

/** The depth pairs (ping-pong), the self weights and each team member's row buffers. */
struct BilateralDepthRelaxKernel::Workspace::Buffers
{
  detail::ReusableArray<float>                First;
  detail::ReusableArray<float>                Second;
  detail::ReusableArray<float>                SelfWeight;
  std::vector<std::unique_ptr<MemberScratch>> Scratch;
  std::size_t                                 ScratchStride{ 0 };

  /** Row buffers for \a team members on rows of \a stride floats, for blocks of up to \a passes passes. */
  std::vector<std::unique_ptr<MemberScratch>> &
  ReserveScratch(unsigned int team, std::size_t stride, unsigned int passes)
  {
    if (stride != ScratchStride)
    {
      Scratch.clear();
      ScratchStride = stride;
    }
    while (Scratch.size() < team)
    {
      Scratch.push_back(std::make_unique<MemberScratch>(stride));
    }
    for (unsigned int member = 0; member < team; ++member)
    {
      Scratch[member]->Reserve(passes);
    }
    return Scratch;
  }
};

BilateralDepthRelaxKernel::Workspace::Workspace()
  : m_Buffers(std::make_unique<Buffers>())
{
}

BilateralDepthRelaxKernel::Workspace::~Workspace() = default;

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
                                 const ProgressCallback & progress,
                                 Workspace *              workspace,
                                 unsigned int             passesBetweenSynchronizations)
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

  Workspace            ownWorkspace;
  Workspace::Buffers & buffers = *(workspace ? workspace : &ownWorkspace)->m_Buffers;
  // The right neighbour of the last vector of the last row reads one vector past the image.
  float * const first = buffers.First.Reserve(2 * paddedCount + RowAlignment);
  float * const second = buffers.Second.Reserve(2 * paddedCount + RowAlignment);
  float * const selfWeight = buffers.SelfWeight.Reserve(paddedCount);
  grid.SelfWeight = selfWeight;
  // Eq. 1 divided by w: the pixel's own weight becomes ((1 - w) / w) |Omega|.
  const double selfPerNeighbour = (1.0 - relaxation) / relaxation;
  const float  immovable = std::numeric_limits<float>::infinity();
  auto         initialiseRows = [&](std::size_t rowBegin, std::size_t rowEnd)
  {
    for (std::size_t y = rowBegin; y < rowEnd; ++y)
    {
      const float * in = depth + y * width;
      float *       high = first + 2 * y * grid.Stride;
      float *       low = high + grid.Stride;
      for (std::size_t x = 0; x < width; ++x)
      {
        const double scaled = scale * in[x];
        high[x] = static_cast<float>(scaled);
        low[x] = static_cast<float>(scaled - high[x]);
      }
      // Padding columns repeat the last column.
      std::fill(high + width, high + grid.Stride, high[width - 1]);
      std::fill(low + width, low + grid.Stride, low[width - 1]);
      float *           self = selfWeight + y * grid.Stride;
      const std::size_t verticalNeighbours = (y > 0) + (y + 1 < height);
      for (std::size_t x = 0; x < width; ++x)
      {
        const std::size_t neighbours = verticalNeighbours + (x > 0) + (x + 1 < width);
        self[x] = static_cast<float>(selfPerNeighbour * static_cast<double>(neighbours));
      }
      if (fixed)
      {
        const unsigned char * isFixed = fixed + y * width;
        for (std::size_t x = 0; x < width; ++x)
        {
          self[x] = isFixed[x] ? immovable : self[x];
        }
      }
      std::fill(self + width, self + grid.Stride, immovable);
    }
  };
  auto writeRows = [&](const float * result, std::size_t rowBegin, std::size_t rowEnd)
  {
    for (std::size_t y = rowBegin; y < rowEnd; ++y)
    {
      // Exact for fixed pixels: (x scale) / scale comes within 1e-14 of the float x, which rounding gives back.
      const float * high = result + 2 * y * grid.Stride;
      const float * low = high + grid.Stride;
      float *       out = relaxed + y * width;
      for (std::size_t x = 0; x < width; ++x)
      {
        out[x] = static_cast<float>((static_cast<double>(high[x]) + low[x]) / scale);
      }
    }
  };

  const unsigned int team = static_cast<unsigned int>(std::max<std::size_t>(1, std::min<std::size_t>(threads, height)));
  const unsigned int blockPasses =
    std::min(iterations,
             passesBetweenSynchronizations > 0 ? passesBetweenSynchronizations
                                               : ChoosePassesBetweenSynchronizations(height, team));
  auto & scratch = buffers.ReserveScratch(team, grid.Stride, blockPasses);

  detail::ThreadTeamBarrier barrier(team);
  std::exception_ptr        failure;
  // The pass (one pass a block) or the first pass of the block (blocks) after whose barrier the team stops; set by
  // member 0 while others may still be leaving the previous barrier, so each member compares it with its own.
  std::atomic<unsigned int> stopAfter{ iterations };

  // One pass a block: each member sweeps a fixed band of rows; after the barrier every member sees the whole new
  // image. Member 0 is the calling thread and reports progress; a progress callback that throws stops every
  // member after the same barrier. The code of the kernel before blocks, kept as it was for small teams (2 cores:
  // the blocked path's row-by-row wavefront costs more per row than it saves in barriers, docs/design.md "Relaxation").
  auto sweepEveryPass = [&](unsigned int member)
  {
    const std::size_t   rowBegin = height * member / team;
    const std::size_t   rowEnd = height * (member + 1) / team;
    const SweepFunction sweep = TheRowSweep().Kernels->Sweep;
    float *             current = first;
    float *             next = second;
    // Every member prepares its own rows; the first sweep reads its neighbours' too.
    initialiseRows(rowBegin, rowEnd);
    barrier.Wait();
    for (unsigned int iteration = 0; iteration < iterations; ++iteration)
    {
      sweep(grid, current, next, rowBegin, rowEnd, scratch[member]->Rows(0));
      if (member == 0 && progress && iteration > 0)
      {
        try
        {
          progress(iteration);
        }
        catch (...)
        {
          failure = std::current_exception();
          stopAfter.store(iteration, std::memory_order_relaxed);
        }
      }
      barrier.Wait();
      if (stopAfter.load(std::memory_order_relaxed) <= iteration)
      {
        return;
      }
      std::swap(current, next);
    }
    // After the last barrier nobody reads the input any more, so \a relaxed may be \a depth.
    writeRows(current, rowBegin, rowEnd);
  };

  // Blocks of blockPasses passes (temporal blocking, RelaxBlock()): after the barrier that ends a block every
  // member sees the whole image those passes made. Member 0 reports progress after each of its passes; a progress
  // callback that throws stops every member at the barrier ending the same block, within about one pass of work.
  auto relaxInBlocks = [&](unsigned int member)
  {
    const std::size_t  rowBegin = height * member / team;
    const std::size_t  rowEnd = height * (member + 1) / team;
    const RowKernels & kernels = *TheRowSweep().Kernels;
    MemberScratch &    mine = *scratch[member];
    float *            current = first;
    float *            next = second;
    // Every member prepares its own rows; the first pass reads its neighbours' too.
    initialiseRows(rowBegin, rowEnd);
    barrier.Wait();
    for (unsigned int done = 0; done < iterations;)
    {
      const unsigned int passes = std::min(blockPasses, iterations - done);
      auto               stopped = [&] { return stopAfter.load(std::memory_order_relaxed) <= done; };
      // As with one pass a block: pass k (0-based) done by member 0 reports k, the passes the whole team has done.
      auto passDone = [&](unsigned int pass)
      {
        const unsigned int reported = done + pass - 1;
        if (member != 0 || !progress || reported == 0 || stopped())
        {
          return;
        }
        try
        {
          progress(reported);
        }
        catch (...)
        {
          failure = std::current_exception();
          stopAfter.store(done, std::memory_order_relaxed);
        }
      };
      if (passes == 1)
      {
        kernels.Sweep(grid, current, next, rowBegin, rowEnd, mine.Rows(0));
        passDone(1);
      }
      else
      {
        RelaxBlock(kernels, grid, current, next, rowBegin, rowEnd, passes, mine, passDone, stopped);
      }
      barrier.Wait();
      if (stopped())
      {
        return;
      }
      std::swap(current, next);
      done += passes;
    }
    writeRows(current, rowBegin, rowEnd);
  };

  auto work = [&](unsigned int member)
  {
    if (blockPasses == 1)
    {
      sweepEveryPass(member);
    }
    else
    {
      relaxInBlocks(member);
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
    Relax(depth,
          fixed,
          relaxed,
          width,
          height,
          relaxation,
          anisotropy,
          iterations,
          1,
          progress,
          workspace,
          passesBetweenSynchronizations);
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
}

std::size_t
BilateralDepthRelaxKernel::GetWorkspaceBytes(std::size_t  width,
                                             std::size_t  height,
                                             unsigned int iterations,
                                             unsigned int threads,
                                             unsigned int passesBetweenSynchronizations)
{
  if (width == 0 || height == 0 || iterations == 0)
  {
    return 0;
  }
  // As Relax() and the buffers above allocate them: ReusableArray rounds every count up to RowAlignment floats.
  static_assert(detail::ReusableArray<float>::Granule == RowAlignment);
  auto aligned = [](std::size_t count) { return (count + RowAlignment - 1) / RowAlignment * RowAlignment; };
  const std::size_t  stride = aligned(width);
  const std::size_t  paddedCount = height * stride;
  std::size_t        floats = 2 * aligned(2 * paddedCount + RowAlignment) + aligned(paddedCount);
  const auto         team = static_cast<unsigned int>(std::max<std::size_t>(1, std::min<std::size_t>(threads, height)));
  const unsigned int passes =
    std::min(iterations,
             passesBetweenSynchronizations > 0 ? passesBetweenSynchronizations
                                               : ChoosePassesBetweenSynchronizations(height, team));
  std::size_t memberFloats = passes * (aligned(4 * stride) + aligned(2 * stride));
  if (passes > 1)
  {
    memberFloats += aligned((passes - 1) * RingRows * 2 * stride + RowAlignment);
  }
  floats += team * memberFloats;
  return floats * sizeof(float);
}

unsigned int
BilateralDepthRelaxKernel::ChoosePassesBetweenSynchronizations(std::size_t height, unsigned int team)
{
  if (team <= LargestTeamWithoutBlocks)
  {
    return 1;
  }
  // A block of k passes relaxes about k + 1 rows per pass more than the band (the widened rows and the row above
  // each pass's first), so k = band / 16 keeps that below about 7 %, while cutting the barriers (and the passes over
  // the whole image in memory) k-fold; at most 16.
  const std::size_t band = height / team;
  return static_cast<unsigned int>(std::clamp<std::size_t>(band / 16, 1, 16));
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
