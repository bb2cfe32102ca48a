// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef itkCPRVolumeSampler_h
#define itkCPRVolumeSampler_h

#include "itkBSplineInterpolateImageFunction.h"
#include "itkCPRSamplingModes.h"
#include "itkContinuousIndex.h"
#include "itkLinearInterpolateImageFunction.h"
#include "itkNearestNeighborInterpolateImageFunction.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace itk::detail
{

/** \class CPRVolumeSampler
 * \brief The sampling every reformation filter shares (docs/design.md 3.6, docs/vessel-path.md 6): a volume read at
 * continuous indices, linearly (straight from the buffer), nearest or by cubic B-spline, and the samples of a slab
 * combined by MIP, MinIP or mean, samples outside the volume left out.
 *
 * Prepare() once per update (not thread-safe); then Sample() and Evaluate() from any thread.
 */
template<typename TVolume>
class CPRVolumeSampler
{
public:
  using VolumeType = TVolume;
  using ContinuousIndexType = ContinuousIndex<double, 3>;
  using IndexVectorType = Vector<double, 3>;
  using InterpolatorType = InterpolateImageFunction<VolumeType, double>;

  /** Builds the interpolator for \a mode on \a volume and the linear path's buffer tables. */
  void
  Prepare(const VolumeType * volume, CPRInterpolationMode mode)
  {
    switch (mode)
    {
      case CPRInterpolationMode::Nearest:
        m_Interpolator = NearestNeighborInterpolateImageFunction<VolumeType, double>::New();
        break;
      case CPRInterpolationMode::Cubic:
      {
        auto bspline = BSplineInterpolateImageFunction<VolumeType, double, float>::New();
        bspline->SetSplineOrder(3);
        m_Interpolator = bspline;
        break;
      }
      default:
        m_Interpolator = LinearInterpolateImageFunction<VolumeType, double>::New();
    }
    m_Interpolator->SetInputImage(volume);
    m_Linear = mode == CPRInterpolationMode::Linear;

    const auto & buffered = volume->GetBufferedRegion();
    m_Buffer = volume->GetBufferPointer();
    m_BufferStart = buffered.GetIndex();
    for (unsigned int k = 0; k < 3; ++k)
    {
      m_BufferEnd[k] = m_BufferStart[k] + static_cast<IndexValueType>(buffered.GetSize()[k]) - 1;
    }
    m_OffsetTable[0] = 1;
    m_OffsetTable[1] = static_cast<OffsetValueType>(buffered.GetSize()[0]);
    m_OffsetTable[2] = m_OffsetTable[1] * static_cast<OffsetValueType>(buffered.GetSize()[1]);
  }

  const InterpolatorType *
  GetInterpolator() const
  {
    return m_Interpolator.GetPointer();
  }

  /** True where the interpolator reads: within half a voxel of the buffer (ITK's IsInsideBuffer). */
  bool
  IsInside(const ContinuousIndexType & index) const
  {
    return m_Interpolator->IsInsideBuffer(index);
  }

  /** The interpolated value at \a index, which must be inside. */
  double
  Evaluate(const ContinuousIndexType & index) const
  {
    return m_Linear ? InterpolateLinearly(index) : m_Interpolator->EvaluateAtContinuousIndex(index);
  }

  /** The samples at base + offset * normalPerMillimetre for each of \a offsets (mm) combined by \a mode; false
   * when none lies inside the volume. */
  bool
  Sample(const IndexVectorType &     base,
         const IndexVectorType &     normalPerMillimetre,
         const std::vector<double> & offsets,
         CPRSlabMode                 mode,
         double &                    value) const
  {
    double sum = 0.0;
    double extreme = 0.0;
    int    inside = 0;
    for (const double offset : offsets)
    {
      ContinuousIndexType sample;
      for (unsigned int k = 0; k < 3; ++k)
      {
        sample[k] = base[k] + normalPerMillimetre[k] * offset;
      }
      if (!IsInside(sample))
      {
        continue;
      }
      const double v = Evaluate(sample);
      if (inside == 0)
      {
        extreme = v;
      }
      else if (mode == CPRSlabMode::MIP)
      {
        extreme = std::max(extreme, v);
      }
      else if (mode == CPRSlabMode::MinIP)
      {
        extreme = std::min(extreme, v);
      }
      sum += v;
      ++inside;
    }
    if (inside == 0)
    {
      return false;
    }
    value = mode == CPRSlabMode::Mean && offsets.size() > 1 ? sum / inside : extreme;
    return true;
  }

  /** The offsets (mm) of a slab of \a thickness across \a volume: {0} for no slab, else samples spaced at most half
   * the volume's smallest spacing over [-thickness/2, thickness/2]. */
  static std::vector<double>
  SlabOffsets(const VolumeType * volume, double thickness)
  {
    std::vector<double> offsets(1, 0.0);
    if (thickness > 0.0)
    {
      const auto & spacing = volume->GetSpacing();
      const double step = 0.5 * std::min({ spacing[0], spacing[1], spacing[2] });
      const auto   intervals = static_cast<std::size_t>(std::ceil(thickness / step - 1e-9));
      offsets.resize(intervals + 1);
      for (std::size_t k = 0; k <= intervals; ++k)
      {
        offsets[k] = -0.5 * thickness + thickness * static_cast<double>(k) / intervals;
      }
    }
    return offsets;
  }

private:
  /** Trilinear interpolation straight from the volume's buffer: the same arithmetic, in the same order, as
   * itk::LinearInterpolateImageFunction (3D), which costs most of a CPR's time through its general interface.
   * \a index must pass IsInside. */
  double
  InterpolateLinearly(const ContinuousIndexType & index) const
  {
    // Base voxel clamped to the buffer's start; a negative fraction (within half a voxel before the start) and a
    // neighbour past the end both leave that axis uninterpolated, exactly where the ITK interpolator skips it.
    OffsetValueType offset = 0;
    OffsetValueType step[3];
    double          fraction[3];
    for (unsigned int k = 0; k < 3; ++k)
    {
      IndexValueType base = Math::Floor<IndexValueType>(index[k]);
      base = std::max(base, m_BufferStart[k]);
      fraction[k] = std::max(0.0, index[k] - static_cast<double>(base));
      offset += (base - m_BufferStart[k]) * m_OffsetTable[k];
      step[k] = base < m_BufferEnd[k] ? m_OffsetTable[k] : 0;
    }
    const auto * v = m_Buffer + offset;
    const double v000 = static_cast<double>(v[0]);
    const double v100 = static_cast<double>(v[step[0]]);
    const double v010 = static_cast<double>(v[step[1]]);
    const double v110 = static_cast<double>(v[step[0] + step[1]]);
    const double v001 = static_cast<double>(v[step[2]]);
    const double v101 = static_cast<double>(v[step[0] + step[2]]);
    const double v011 = static_cast<double>(v[step[1] + step[2]]);
    const double v111 = static_cast<double>(v[step[0] + step[1] + step[2]]);
    const double vx00 = v000 + (v100 - v000) * fraction[0];
    const double vx10 = v010 + (v110 - v010) * fraction[0];
    const double vx01 = v001 + (v101 - v001) * fraction[0];
    const double vx11 = v011 + (v111 - v011) * fraction[0];
    const double vxx0 = vx00 + (vx10 - vx00) * fraction[1];
    const double vxx1 = vx01 + (vx11 - vx01) * fraction[1];
    return vxx0 + (vxx1 - vxx0) * fraction[2];
  }

  typename InterpolatorType::Pointer     m_Interpolator;
  bool                                   m_Linear{ true };
  const typename VolumeType::PixelType * m_Buffer{ nullptr };
  typename VolumeType::IndexType         m_BufferStart;
  typename VolumeType::IndexType         m_BufferEnd;
  OffsetValueType                        m_OffsetTable[3]{};
};

/** \class CPRVolumeMinimum
 * \brief The smallest voxel value of a volume, computed again only when the volume (object, buffer or modification
 * time) changes: a new view or roll does not change it. NaN voxels are passed over, as MinimumMaximumImageCalculator
 * does over the buffered region.
 */
template<typename TVolume>
class CPRVolumeMinimum
{
public:
  using PixelType = typename TVolume::PixelType;

  PixelType
  Get(const TVolume * volume)
  {
    if (volume != m_Volume || volume->GetBufferPointer() != m_Buffer || volume->GetMTime() != m_Time)
    {
      const PixelType * values = volume->GetBufferPointer();
      const std::size_t count = volume->GetBufferedRegion().GetNumberOfPixels();
      PixelType         minimum = NumericTraits<PixelType>::max();
      for (std::size_t k = 0; k < count; ++k)
      {
        minimum = values[k] < minimum ? values[k] : minimum;
      }
      m_Minimum = minimum;
      m_Volume = volume;
      m_Buffer = values;
      m_Time = volume->GetMTime();
    }
    return m_Minimum;
  }

  void
  Print(std::ostream & os) const
  {
    os << static_cast<double>(m_Minimum) << " (volume " << m_Volume << ", modified time " << m_Time << ")";
  }

private:
  const TVolume *   m_Volume{ nullptr };
  const PixelType * m_Buffer{ nullptr };
  ModifiedTimeType  m_Time{ 0 };
  PixelType         m_Minimum{};
};

} // namespace itk::detail

#endif
