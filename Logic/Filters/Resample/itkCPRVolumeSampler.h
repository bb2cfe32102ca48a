// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef itkCPRVolumeSampler_h
#define itkCPRVolumeSampler_h

#include "itkBSplineInterpolateImageFunction.h"
#include "itkCPRIntensityRescale.h"
#include "itkCPRSamplingModes.h"
#include "itkContinuousIndex.h"
#include "itkLinearInterpolateImageFunction.h"
#include "itkNearestNeighborInterpolateImageFunction.h"

#include <algorithm>
#include <cmath>
#include <type_traits>
#include <variant>
#include <vector>

namespace itk
{

/** The pixel types a volume may keep from its file and the reformation filters sample at run time (docs/design.md
 * "Volumes in their stored type"): signed and unsigned 8- and 16-bit integers, float and double. */
inline constexpr const char * CPRStoredPixelTypes = "signed or unsigned char, short or unsigned short, float or double";

/** Calls \a function with \a volume cast to the itk::Image<T, 3> it is, T one of CPRStoredPixelTypes (const kept), and
 * returns what it returns. Throws itk::ExceptionObject when the volume is an image of another pixel type. */
template<typename TImageBase, typename TFunction>
decltype(auto)
VisitStoredVolume(TImageBase * volume, TFunction && function)
{
  static_assert(std::is_same_v<std::remove_const_t<TImageBase>, ImageBase<3>>, "a 3D volume");
  auto as = [volume](auto pixel)
  {
    using ImageType = Image<decltype(pixel), 3>;
    return dynamic_cast<std::conditional_t<std::is_const_v<TImageBase>, const ImageType, ImageType> *>(volume);
  };
  if (auto * image = as(short{}))
  {
    return function(image);
  }
  if (auto * image = as(float{}))
  {
    return function(image);
  }
  if (auto * image = as(static_cast<unsigned short>(0)))
  {
    return function(image);
  }
  if (auto * image = as(static_cast<unsigned char>(0)))
  {
    return function(image);
  }
  if (auto * image = as(static_cast<signed char>(0)))
  {
    return function(image);
  }
  if (auto * image = as(double{}))
  {
    return function(image);
  }
  itkGenericExceptionMacro(<< "the volume (" << (volume ? volume->GetNameOfClass() : "none")
                           << ") is not a 3D image of a pixel type the reformation samples (" << CPRStoredPixelTypes
                           << ")");
}

/** \class CPRVolumeSampler
 * \brief The sampling every reformation filter shares (docs/design.md "Resampling", docs/vessel-path.md "Sampling"): a
 * volume read at continuous indices, linearly (straight from the buffer), nearest or by cubic B-spline, and the samples
 * of a slab combined by MIP, MinIP or mean, samples outside the volume left out.
 *
 * The volume is read in its stored pixel type; an intensity rescale other than the identity (CPRIntensityRescale) is
 * applied to every value read: to each of the eight voxels of a linear sample before they are combined, to the voxel
 * of a nearest sample, and to the value of a cubic sample (the B-spline is linear in the voxel values, so that is the
 * spline of the rescaled values up to rounding). Linear and nearest samples are thus exactly those of a volume whose
 * voxels were rescaled to double first, without that volume.
 *
 * For TVolume = itk::ImageBase<3> the sampler takes any of CPRStoredPixelTypes at run time (the specialisation
 * below). Prepare() once per update (not thread-safe); then Sample() and Evaluate() from any thread.
 */
template<typename TVolume>
class CPRVolumeSampler
{
public:
  using VolumeType = TVolume;
  using PixelType = typename VolumeType::PixelType;
  using ContinuousIndexType = ContinuousIndex<double, 3>;
  using IndexVectorType = Vector<double, 3>;
  using InterpolatorType = InterpolateImageFunction<VolumeType, double>;

  /** Builds the interpolator for \a mode on \a volume and the linear path's buffer tables. */
  void
  Prepare(const VolumeType * volume, CPRInterpolationMode mode, const CPRIntensityRescale & rescale = {});

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

  /** The interpolated intensity at \a index, which must be inside. */
  double
  Evaluate(const ContinuousIndexType & index) const
  {
    if (m_Linear)
    {
      return m_Rescaled ? InterpolateLinearly<true>(index) : InterpolateLinearly<false>(index);
    }
    const double value = m_Interpolator->EvaluateAtContinuousIndex(index);
    return m_Rescaled ? m_Rescale.Apply(value) : value;
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
  SlabOffsets(const ImageBase<3> * volume, double thickness)
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
  /** A stored value as an intensity. */
  template<bool TRescaled>
  double
  Intensity(PixelType stored) const
  {
    if constexpr (TRescaled)
    {
      return m_Rescale.Apply(static_cast<double>(stored));
    }
    else
    {
      return static_cast<double>(stored);
    }
  }

  /** Trilinear interpolation straight from the volume's buffer: the same arithmetic, in the same order, as
   * itk::LinearInterpolateImageFunction (3D), which costs most of a CPR's time through its general interface.
   * \a index must pass IsInside. The offsets are 64-bit: a volume may hold more than 2^31 bytes. */
  template<bool TRescaled>
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
    const PixelType * v = m_Buffer + offset;
    const double      v000 = Intensity<TRescaled>(v[0]);
    const double      v100 = Intensity<TRescaled>(v[step[0]]);
    const double      v010 = Intensity<TRescaled>(v[step[1]]);
    const double      v110 = Intensity<TRescaled>(v[step[0] + step[1]]);
    const double      v001 = Intensity<TRescaled>(v[step[2]]);
    const double      v101 = Intensity<TRescaled>(v[step[0] + step[2]]);
    const double      v011 = Intensity<TRescaled>(v[step[1] + step[2]]);
    const double      v111 = Intensity<TRescaled>(v[step[0] + step[1] + step[2]]);
    const double      vx00 = v000 + (v100 - v000) * fraction[0];
    const double      vx10 = v010 + (v110 - v010) * fraction[0];
    const double      vx01 = v001 + (v101 - v001) * fraction[0];
    const double      vx11 = v011 + (v111 - v011) * fraction[0];
    const double      vxx0 = vx00 + (vx10 - vx00) * fraction[1];
    const double      vxx1 = vx01 + (vx11 - vx01) * fraction[1];
    return vxx0 + (vxx1 - vxx0) * fraction[2];
  }

  typename InterpolatorType::Pointer m_Interpolator;
  CPRInterpolationMode               m_Mode{ CPRInterpolationMode::Linear };
  const VolumeType *                 m_Volume{ nullptr };
  ModifiedTimeType                   m_VolumeTime{ 0 };
  typename VolumeType::RegionType    m_BufferedRegion;
  bool                               m_Linear{ true };
  bool                               m_Rescaled{ false };
  CPRIntensityRescale                m_Rescale;
  const PixelType *                  m_Buffer{ nullptr };
  typename VolumeType::IndexType     m_BufferStart;
  typename VolumeType::IndexType     m_BufferEnd;
  OffsetValueType                    m_OffsetTable[3]{};
};

template<typename TVolume>
void
CPRVolumeSampler<TVolume>::Prepare(const VolumeType *          volume,
                                   CPRInterpolationMode        mode,
                                   const CPRIntensityRescale & rescale)
{
  if (!rescale.IsValid())
  {
    itkGenericExceptionMacro(<< "IntensityRescale = " << rescale
                             << " is invalid: both must be finite and the slope must not be 0");
  }
  m_Rescale = rescale;
  m_Rescaled = !rescale.IsIdentity();
  // The interpolator of the same volume, unchanged, is kept: a cubic one holds the B-spline coefficients of the whole
  // volume, computed again only when the volume changes (a new view does not change them).
  if (m_Interpolator && mode == m_Mode && volume == m_Volume && volume->GetMTime() == m_VolumeTime &&
      volume->GetBufferPointer() == m_Buffer && volume->GetBufferedRegion() == m_BufferedRegion)
  {
    return;
  }
  m_Interpolator = nullptr; // before the next one is made: a cubic one's coefficients are as large as the volume
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
  m_Mode = mode;
  m_Volume = volume;
  m_VolumeTime = volume->GetMTime();

  const auto & buffered = volume->GetBufferedRegion();
  m_BufferedRegion = buffered;
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

/** \class CPRVolumeSampler<ImageBase<3>>
 * \brief The sampler of a volume whose pixel type is known at run time only: one of CPRStoredPixelTypes, as the
 * module's logic holds a volume in the type of its file. Prepare() picks the typed sampler of the volume's pixel type;
 * each call then goes to it (one well-predicted branch per sample). The same results, bit for bit, as the typed
 * sampler of that pixel type.
 */
template<>
class CPRVolumeSampler<ImageBase<3>>
{
public:
  using VolumeType = ImageBase<3>;
  using ContinuousIndexType = ContinuousIndex<double, 3>;
  using IndexVectorType = Vector<double, 3>;

private:
  /** Calls \a function with the prepared typed sampler (Prepare() must have succeeded). */
  template<typename TFunction>
  decltype(auto)
  Visit(TFunction && function) const
  {
    switch (m_Typed.index())
    {
      case 1:
        return function(*std::get_if<1>(&m_Typed));
      case 2:
        return function(*std::get_if<2>(&m_Typed));
      case 3:
        return function(*std::get_if<3>(&m_Typed));
      case 4:
        return function(*std::get_if<4>(&m_Typed));
      case 5:
        return function(*std::get_if<5>(&m_Typed));
      default:
        return function(*std::get_if<6>(&m_Typed));
    }
  }

public:
  /** Picks the typed sampler of \a volume's pixel type and prepares it. Throws itk::ExceptionObject for another
   * pixel type. */
  void
  Prepare(const VolumeType * volume, CPRInterpolationMode mode, const CPRIntensityRescale & rescale = {})
  {
    VisitStoredVolume(volume,
                      [this, mode, &rescale](const auto * image)
                      {
                        using ImageType = std::remove_const_t<std::remove_pointer_t<decltype(image)>>;
                        using TypedSampler = CPRVolumeSampler<ImageType>;
                        // The typed sampler of the same pixel type is kept, with its interpolator.
                        auto * typed = std::get_if<TypedSampler>(&m_Typed);
                        if (typed == nullptr)
                        {
                          typed = &m_Typed.template emplace<TypedSampler>();
                        }
                        typed->Prepare(image, mode, rescale);
                      });
  }

  /** The typed sampler's interpolator (null before Prepare()). */
  const Object *
  GetInterpolator() const
  {
    return std::visit(
      [](const auto & typed) -> const Object *
      {
        if constexpr (std::is_same_v<std::decay_t<decltype(typed)>, std::monostate>)
        {
          return nullptr;
        }
        else
        {
          return typed.GetInterpolator();
        }
      },
      m_Typed);
  }

  bool
  IsInside(const ContinuousIndexType & index) const
  {
    return Visit([&index](const auto & typed) { return typed.IsInside(index); });
  }

  double
  Evaluate(const ContinuousIndexType & index) const
  {
    return Visit([&index](const auto & typed) { return typed.Evaluate(index); });
  }

  bool
  Sample(const IndexVectorType &     base,
         const IndexVectorType &     normalPerMillimetre,
         const std::vector<double> & offsets,
         CPRSlabMode                 mode,
         double &                    value) const
  {
    return Visit([&](const auto & typed) { return typed.Sample(base, normalPerMillimetre, offsets, mode, value); });
  }

  static std::vector<double>
  SlabOffsets(const ImageBase<3> * volume, double thickness)
  {
    return CPRVolumeSampler<Image<float, 3>>::SlabOffsets(volume, thickness);
  }

private:
  std::variant<std::monostate,
               CPRVolumeSampler<Image<short, 3>>,
               CPRVolumeSampler<Image<float, 3>>,
               CPRVolumeSampler<Image<unsigned short, 3>>,
               CPRVolumeSampler<Image<unsigned char, 3>>,
               CPRVolumeSampler<Image<signed char, 3>>,
               CPRVolumeSampler<Image<double, 3>>>
    m_Typed;
};

/** \class CPRVolumeMinimum
 * \brief The smallest intensity of a volume (its stored values through the rescale), computed again only when the
 * volume (object, buffer or modification time) or the rescale changes: a new view or roll does not change it. NaN
 * voxels are passed over, as MinimumMaximumImageCalculator does over the buffered region. TVolume may be
 * itk::ImageBase<3>, for a volume of any of CPRStoredPixelTypes.
 */
template<typename TVolume>
class CPRVolumeMinimum
{
public:
  double
  Get(const TVolume * volume, const CPRIntensityRescale & rescale = {})
  {
    if (volume != m_Volume || BufferOf(volume) != m_Buffer || volume->GetMTime() != m_Time)
    {
      m_Lowest = 0.0;
      m_Highest = 0.0;
      VisitVolume(volume,
                  [this](const auto * image)
                  {
                    using PixelType = typename std::remove_pointer_t<decltype(image)>::PixelType;
                    const PixelType * values = image->GetBufferPointer();
                    const std::size_t count = image->GetBufferedRegion().GetNumberOfPixels();
                    PixelType         lowest = NumericTraits<PixelType>::max();
                    PixelType         highest = NumericTraits<PixelType>::NonpositiveMin();
                    for (std::size_t k = 0; k < count; ++k)
                    {
                      lowest = values[k] < lowest ? values[k] : lowest;
                      highest = values[k] > highest ? values[k] : highest;
                    }
                    m_Lowest = static_cast<double>(lowest);
                    m_Highest = static_cast<double>(highest);
                  });
      m_Volume = volume;
      m_Buffer = BufferOf(volume);
      m_Time = volume->GetMTime();
    }
    if (rescale.IsIdentity())
    {
      return m_Lowest;
    }
    return std::min(rescale.Apply(m_Lowest), rescale.Apply(m_Highest));
  }

  void
  Print(std::ostream & os) const
  {
    os << m_Lowest << " to " << m_Highest << " stored (volume " << m_Volume << ", modified time " << m_Time << ")";
  }

private:
  template<typename TFunction>
  static void
  VisitVolume(const TVolume * volume, TFunction && function)
  {
    if constexpr (std::is_same_v<TVolume, ImageBase<3>>)
    {
      VisitStoredVolume(volume, function);
    }
    else
    {
      function(volume);
    }
  }
  static const void *
  BufferOf(const TVolume * volume)
  {
    const void * buffer = nullptr;
    VisitVolume(volume, [&buffer](const auto * image) { buffer = image->GetBufferPointer(); });
    return buffer;
  }

  const TVolume *  m_Volume{ nullptr };
  const void *     m_Buffer{ nullptr };
  ModifiedTimeType m_Time{ 0 };
  double           m_Lowest{ 0.0 };
  double           m_Highest{ 0.0 };
};

// Compiled once, in the VesselReformationFilters library, for every stored pixel type.
extern template class CPRVolumeSampler<Image<short, 3>>;
extern template class CPRVolumeSampler<Image<float, 3>>;
extern template class CPRVolumeSampler<Image<unsigned short, 3>>;
extern template class CPRVolumeSampler<Image<unsigned char, 3>>;
extern template class CPRVolumeSampler<Image<signed char, 3>>;
extern template class CPRVolumeSampler<Image<double, 3>>;

} // namespace itk

#endif
