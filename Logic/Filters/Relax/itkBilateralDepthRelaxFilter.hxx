// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef itkBilateralDepthRelaxFilter_hxx
#define itkBilateralDepthRelaxFilter_hxx

#include "itkBilateralDepthRelaxFilter.h"

#include "itkMultiThreaderBase.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace itk
{

template<typename TImage, typename TMaskImage>
BilateralDepthRelaxFilter<TImage, TMaskImage>::BilateralDepthRelaxFilter()
{
  this->SetNumberOfRequiredInputs(1);
  this->AddOptionalInputName("FixedMask");
}

template<typename TImage, typename TMaskImage>
void
BilateralDepthRelaxFilter<TImage, TMaskImage>::SetNumberOfWorkUnits(ThreadIdType workUnits)
{
  m_WorkUnitsWereSet = true;
  Superclass::SetNumberOfWorkUnits(workUnits);
}

template<typename TImage, typename TMaskImage>
void
BilateralDepthRelaxFilter<TImage, TMaskImage>::SetAnisotropy(double anisotropy)
{
  // An equal value changes nothing (reruns nothing); which parametrisation was set last only words the messages.
  const bool changed = !(m_Anisotropy == anisotropy); // NaN != NaN: a NaN always counts as a change
  m_JumpThresholdWasSet = false;
  m_Anisotropy = anisotropy;
  m_JumpThreshold = anisotropy > 0.0 ? 1.0 / std::sqrt(anisotropy) : std::numeric_limits<double>::infinity();
  if (changed)
  {
    this->Modified();
  }
}

template<typename TImage, typename TMaskImage>
void
BilateralDepthRelaxFilter<TImage, TMaskImage>::SetJumpThreshold(double jumpThreshold)
{
  const bool changed = !(m_JumpThreshold == jumpThreshold);
  m_JumpThresholdWasSet = true;
  m_JumpThreshold = jumpThreshold;
  m_Anisotropy = 1.0 / (jumpThreshold * jumpThreshold);
  if (changed)
  {
    this->Modified();
  }
}

template<typename TImage, typename TMaskImage>
void
BilateralDepthRelaxFilter<TImage, TMaskImage>::VerifyPreconditions() ITKv5_CONST
{
  Superclass::VerifyPreconditions();
  if (!(std::isfinite(m_Relaxation) && m_Relaxation >= 0.0 && m_Relaxation <= 1.0))
  {
    itkExceptionMacro(<< "Relaxation w = " << m_Relaxation << " is invalid: it must be a finite number in [0, 1]");
  }
  if (m_JumpThresholdWasSet && !(std::isfinite(m_JumpThreshold) && m_JumpThreshold > 0.0))
  {
    itkExceptionMacro(<< "JumpThreshold J = " << m_JumpThreshold << " mm is invalid: it must be finite and > 0");
  }
  if (!(std::isfinite(m_Anisotropy) && m_Anisotropy >= 0.0))
  {
    itkExceptionMacro(<< "Anisotropy a = " << m_Anisotropy << " mm^-2 is invalid: it must be finite and >= 0"
                      << (m_JumpThresholdWasSet ? " (from JumpThreshold J = " : "")
                      << (m_JumpThresholdWasSet ? std::to_string(m_JumpThreshold) + " mm)" : ""));
  }
  if (!(std::isfinite(m_SteadyTolerance) && m_SteadyTolerance > 0.0))
  {
    itkExceptionMacro(<< "SteadyTolerance = " << m_SteadyTolerance << " mm is invalid: it must be finite and > 0");
  }
}

template<typename TImage, typename TMaskImage>
void
BilateralDepthRelaxFilter<TImage, TMaskImage>::VerifyInputInformation() ITKv5_CONST
{
  const ImageType *     depth = this->GetInput();
  const MaskImageType * mask = this->GetFixedMask();
  if (depth != nullptr && mask != nullptr &&
      depth->GetLargestPossibleRegion().GetSize() != mask->GetLargestPossibleRegion().GetSize())
  {
    itkExceptionMacro(<< "FixedMask size " << mask->GetLargestPossibleRegion().GetSize()
                      << " differs from the depth image size " << depth->GetLargestPossibleRegion().GetSize());
  }
  Superclass::VerifyInputInformation();
}

template<typename TImage, typename TMaskImage>
void
BilateralDepthRelaxFilter<TImage, TMaskImage>::GenerateInputRequestedRegion()
{
  Superclass::GenerateInputRequestedRegion();
  for (auto & input : this->GetInputs())
  {
    if (auto * image = dynamic_cast<ImageBase<ImageType::ImageDimension> *>(input.GetPointer()))
    {
      image->SetRequestedRegionToLargestPossibleRegion();
    }
  }
}

template<typename TImage, typename TMaskImage>
void
BilateralDepthRelaxFilter<TImage, TMaskImage>::EnlargeOutputRequestedRegion(DataObject * output)
{
  Superclass::EnlargeOutputRequestedRegion(output);
  output->SetRequestedRegionToLargestPossibleRegion();
}

template<typename TImage, typename TMaskImage>
void
BilateralDepthRelaxFilter<TImage, TMaskImage>::GenerateOutputInformation()
{
  Superclass::GenerateOutputInformation();
  this->GetOutput()->SetMetaDataDictionary(this->GetInput()->GetMetaDataDictionary());
}

template<typename TImage, typename TMaskImage>
void
BilateralDepthRelaxFilter<TImage, TMaskImage>::VerifyDepthIsFinite() const
{
  const ImageType * depth = this->GetInput();
  const auto &      region = depth->GetBufferedRegion();
  const PixelType * values = depth->GetBufferPointer();
  const std::size_t count = region.GetNumberOfPixels();
  for (std::size_t k = 0; k < count; ++k)
  {
    if (!std::isfinite(values[k]))
    {
      const auto index = depth->ComputeIndex(static_cast<typename ImageType::OffsetValueType>(k));
      itkExceptionMacro(<< "Depth input holds the non-finite value " << values[k] << " at pixel " << index);
    }
  }
}

template<typename TImage, typename TMaskImage>
void
BilateralDepthRelaxFilter<TImage, TMaskImage>::GenerateData()
{
  this->AllocateOutputs();
  this->VerifyDepthIsFinite();
  this->RelaxOnHost();
}

template<typename TImage, typename TMaskImage>
unsigned int
BilateralDepthRelaxFilter<TImage, TMaskImage>::GetNumberOfHostThreads()
{
  // ITK's pool threader hands out several work units per thread; the kernels' teams need real threads, one per
  // core ITK uses, or their barriers would wait on threads that share a core.
  unsigned int threads = std::min(this->GetNumberOfWorkUnits(), this->GetMultiThreader()->GetMaximumNumberOfThreads());
  if (!m_WorkUnitsWereSet)
  {
    threads = std::min(threads, MultiThreaderBase::GetGlobalDefaultNumberOfThreads());
  }
  return std::max(1u, threads);
}

template<typename TImage, typename TMaskImage>
std::size_t
BilateralDepthRelaxFilter<TImage, TMaskImage>::GetWorkspaceBytes(const SizeType & size)
{
  const std::size_t  width = size[0];
  const std::size_t  height = size[1];
  const unsigned int threads = this->GetNumberOfHostThreads();
  if (m_Solver == BilateralDepthRelaxSolver::Steady)
  {
    return BilateralDepthRelaxSteadySolver::GetWorkspaceBytes(width, height, threads);
  }
  // RelaxOnHostFast(): the mask as bytes unless it is already, and the kernel's buffers (none when w = 0).
  std::size_t bytes = 0;
  if constexpr (!std::is_same<typename MaskImageType::PixelType, unsigned char>::value)
  {
    bytes += width * height * sizeof(unsigned char);
  }
  const unsigned int iterations = m_Relaxation == 0.0 ? 0 : m_NumberOfIterations;
  return bytes + BilateralDepthRelaxKernel::GetWorkspaceBytes(
                   width, height, iterations, threads, m_PassesBetweenSynchronizations);
}

template<typename TImage, typename TMaskImage>
void
BilateralDepthRelaxFilter<TImage, TMaskImage>::RelaxOnHost()
{
  m_SteadyReport = BilateralDepthRelaxSteadySolver::Report();
  if (m_Solver == BilateralDepthRelaxSolver::Steady)
  {
    this->RelaxOnHostSteady();
    return;
  }
  if constexpr (std::is_same<PixelType, float>::value)
  {
    const ImageType * depth = this->GetInput();
    if (BilateralDepthRelaxKernel::IsWithinRange(
          depth->GetBufferPointer(), depth->GetBufferedRegion().GetNumberOfPixels(), m_Anisotropy))
    {
      this->RelaxOnHostFast();
      return;
    }
  }
  this->RelaxOnHostGeneric();
}

template<typename TImage, typename TMaskImage>
void
BilateralDepthRelaxFilter<TImage, TMaskImage>::RelaxOnHostFast()
{
  const ImageType *     depth = this->GetInput();
  const MaskImageType * mask = this->GetFixedMask();
  ImageType *           output = this->GetOutput();
  const auto            size = depth->GetLargestPossibleRegion().GetSize();

  // The kernel reads the mask as bytes, non-zero = fixed.
  const unsigned char *      fixed = nullptr;
  std::vector<unsigned char> fixedBytes;
  if (mask)
  {
    if constexpr (std::is_same<typename MaskImageType::PixelType, unsigned char>::value)
    {
      fixed = mask->GetBufferPointer();
    }
    else
    {
      const auto * values = mask->GetBufferPointer();
      fixedBytes.resize(mask->GetBufferedRegion().GetNumberOfPixels());
      for (std::size_t k = 0; k < fixedBytes.size(); ++k)
      {
        fixedBytes[k] = values[k] != 0 ? 1 : 0;
      }
      fixed = fixedBytes.data();
    }
  }

  const unsigned int threads = this->GetNumberOfHostThreads();
  const unsigned int iterations = m_NumberOfIterations;
  BilateralDepthRelaxKernel::Relax(
    depth->GetBufferPointer(),
    fixed,
    output->GetBufferPointer(),
    size[0],
    size[1],
    m_Relaxation,
    m_Anisotropy,
    iterations,
    threads,
    [this, iterations](unsigned int done)
    {
      this->UpdateProgress(static_cast<float>(done) / iterations);
      this->ThrowIfAborted(done);
    },
    &m_KernelWorkspace,
    m_PassesBetweenSynchronizations);
}

template<typename TImage, typename TMaskImage>
void
BilateralDepthRelaxFilter<TImage, TMaskImage>::RelaxOnHostGeneric()
{
  const ImageType *     depth = this->GetInput();
  const MaskImageType * mask = this->GetFixedMask();
  ImageType *           output = this->GetOutput();

  const auto        size = depth->GetLargestPossibleRegion().GetSize();
  const std::size_t width = size[0];
  const std::size_t height = size[1];
  const std::size_t count = width * height;

  std::vector<PixelType> current(depth->GetBufferPointer(), depth->GetBufferPointer() + count);
  std::vector<PixelType> next(current);
  const auto *           fixed = mask ? mask->GetBufferPointer() : nullptr;

  const double w = m_Relaxation;
  const double a = m_Anisotropy;
  const double selfWeight = 1.0 - w;

  auto weight = [a](double difference)
  {
    const double exponent = a * difference * difference;
    return exponent > WeightUnderflowExponent ? 0.0 : std::exp(-exponent);
  };

  // Each row reads only `current` and writes only its own part of `next`, so any split gives the same bits.
  auto relaxRow = [&](SizeValueType row)
  {
    for (std::size_t column = 0; column < width; ++column)
    {
      const std::size_t k = row * width + column;
      const double      dp = current[k];
      if (fixed && fixed[k])
      {
        next[k] = current[k];
        continue;
      }
      double neighbours = 0.0;
      double weightSum = 0.0;
      double weightedDifference = 0.0;
      auto   accumulate = [&](std::size_t q)
      {
        const double difference = static_cast<double>(current[q]) - dp;
        const double r = weight(difference);
        neighbours += 1.0;
        weightSum += r;
        weightedDifference += r * difference;
      };
      if (column > 0)
      {
        accumulate(k - 1);
      }
      if (column + 1 < width)
      {
        accumulate(k + 1);
      }
      if (row > 0)
      {
        accumulate(k - width);
      }
      if (row + 1 < height)
      {
        accumulate(k + width);
      }
      // D' = D_p + w sum R (D_q - D_p) / ((1-w)|Omega| + w sum R): Eq. 1 rearranged, exact for w = 0.
      const double denominator = selfWeight * neighbours + w * weightSum;
      next[k] = denominator > 0.0 ? static_cast<PixelType>(dp + w * weightedDifference / denominator) : current[k];
    }
  };

  MultiThreaderBase * threader = this->GetMultiThreader();
  threader->SetNumberOfWorkUnits(this->GetNumberOfWorkUnits());
  for (unsigned int iteration = 0; iteration < m_NumberOfIterations; ++iteration)
  {
    threader->ParallelizeArray(0, height, relaxRow, nullptr);
    std::swap(current, next);
    this->UpdateProgress(static_cast<float>(iteration + 1) / m_NumberOfIterations);
    this->ThrowIfAborted(iteration + 1);
  }
  std::copy(current.begin(), current.end(), output->GetBufferPointer());
}

template<typename TImage, typename TMaskImage>
void
BilateralDepthRelaxFilter<TImage, TMaskImage>::RelaxOnHostSteady()
{
  const ImageType *     depth = this->GetInput();
  const MaskImageType * mask = this->GetFixedMask();
  ImageType *           output = this->GetOutput();
  const auto            size = depth->GetLargestPossibleRegion().GetSize();
  const std::size_t     count = depth->GetBufferedRegion().GetNumberOfPixels();

  std::vector<unsigned char> fixed;
  if (mask)
  {
    const auto * values = mask->GetBufferPointer();
    fixed.resize(count);
    for (std::size_t k = 0; k < count; ++k)
    {
      fixed[k] = values[k] != 0 ? 1 : 0;
    }
  }
  const PixelType *  in = depth->GetBufferPointer();
  PixelType *        out = output->GetBufferPointer();
  std::vector<float> copy;
  const float *      values = nullptr;
  std::vector<float> relaxed(count);
  if constexpr (std::is_same<PixelType, float>::value)
  {
    values = in;
  }
  else
  {
    copy.assign(in, in + count);
    values = copy.data();
  }
  auto progress = [this](double fraction)
  {
    this->UpdateProgress(static_cast<float>(fraction));
    if (this->GetAbortGenerateData())
    {
      ProcessAborted aborted(__FILE__, __LINE__);
      aborted.SetDescription(std::string(this->GetNameOfClass()) + ": aborted during the steady solve");
      throw aborted;
    }
  };
  BilateralDepthRelaxSteadySolver::Settings settings = BilateralDepthRelaxSteadySolver::DefaultSettings();
  settings.MaximumOuterIterations = m_SteadyMaximumOuterIterations;
  m_SteadyReport = BilateralDepthRelaxSteadySolver::Solve(values,
                                                          fixed.empty() ? nullptr : fixed.data(),
                                                          relaxed.data(),
                                                          size[0],
                                                          size[1],
                                                          m_Anisotropy,
                                                          m_SteadyTolerance,
                                                          this->GetNumberOfHostThreads(),
                                                          progress,
                                                          &m_SteadyWorkspace,
                                                          settings);
  // Fixed pixels come from the input itself, bit for bit, whatever the pixel type.
  for (std::size_t k = 0; k < count; ++k)
  {
    out[k] = !fixed.empty() && fixed[k] ? in[k] : static_cast<PixelType>(relaxed[k]);
  }
}

template<typename TImage, typename TMaskImage>
void
BilateralDepthRelaxFilter<TImage, TMaskImage>::ThrowIfAborted(unsigned int completedIterations) const
{
  if (this->GetAbortGenerateData())
  {
    ProcessAborted     aborted(__FILE__, __LINE__);
    std::ostringstream description;
    description << this->GetNameOfClass() << ": aborted after " << completedIterations << " of " << m_NumberOfIterations
                << " iterations";
    aborted.SetDescription(description.str());
    throw aborted;
  }
}

template<typename TImage, typename TMaskImage>
void
BilateralDepthRelaxFilter<TImage, TMaskImage>::PrintSelf(std::ostream & os, Indent indent) const
{
  Superclass::PrintSelf(os, indent);
  os << indent << "Relaxation (w): " << m_Relaxation << std::endl;
  os << indent << "JumpThreshold (J, mm): " << m_JumpThreshold << std::endl;
  os << indent << "Anisotropy (a = 1/J^2, mm^-2): " << m_Anisotropy << std::endl;
  os << indent << "JumpThresholdWasSet: " << (m_JumpThresholdWasSet ? "yes (J set last)" : "no (a set last)")
     << std::endl;
  os << indent << "NumberOfIterations (N): " << m_NumberOfIterations << std::endl;
  os << indent << "PassesBetweenSynchronizations: " << m_PassesBetweenSynchronizations
     << (m_PassesBetweenSynchronizations == 0 ? " (chosen by the kernel)" : "") << std::endl;
  os << indent << "Solver: " << m_Solver << std::endl;
  os << indent << "SteadyTolerance (mm): " << m_SteadyTolerance << std::endl;
  os << indent << "SteadyMaximumOuterIterations: " << m_SteadyMaximumOuterIterations << std::endl;
  os << indent << "SteadyReport: " << m_SteadyReport.OuterIterations << " outer iterations ("
     << m_SteadyReport.CoarseOuterIterations << " on coarser grids), " << m_SteadyReport.Cycles
     << " V-cycles, residual " << m_SteadyReport.Residual << " mm"
     << (m_SteadyReport.Converged ? "" : ", stopped short") << std::endl;
  os << indent << "KernelWorkspace, SteadyWorkspace: the fast paths' buffers, kept between updates" << std::endl;
}

} // namespace itk

#endif
