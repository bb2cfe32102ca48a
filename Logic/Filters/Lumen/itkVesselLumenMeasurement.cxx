// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "itkVesselLumenMeasurement.h"

#include "itkMacro.h"
#include "itkMultiThreaderBase.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <sstream>
#include <utility>

namespace itk
{

const char *
ToString(VesselLumenSource source)
{
  return source == VesselLumenSource::Segmentation ? "segmentation" : "centerline radius";
}

namespace
{
constexpr double Pi = 3.14159265358979323846;
constexpr double Threshold = 0.5;
constexpr long   MaximumSamplesPerSide = 4096;

struct PlanePoint
{
  double X;
  double Y;
};

double
Cross(const PlanePoint & o, const PlanePoint & a, const PlanePoint & b)
{
  return (a.X - o.X) * (b.Y - o.Y) - (a.Y - o.Y) * (b.X - o.X);
}

double
Distance(const PlanePoint & a, const PlanePoint & b)
{
  return std::hypot(a.X - b.X, a.Y - b.Y);
}

/** Andrew's monotone chain: the convex hull, counter-clockwise, without collinear points. Sorts \a points. */
std::vector<PlanePoint>
ConvexHull(std::vector<PlanePoint> & points)
{
  std::sort(points.begin(),
            points.end(),
            [](const PlanePoint & a, const PlanePoint & b) { return a.X < b.X || (a.X == b.X && a.Y < b.Y); });
  const std::size_t n = points.size();
  if (n < 3)
  {
    return points;
  }
  std::vector<PlanePoint> hull(2 * n);
  std::size_t             k = 0;
  for (std::size_t i = 0; i < n; ++i)
  {
    while (k >= 2 && Cross(hull[k - 2], hull[k - 1], points[i]) <= 0.0)
    {
      --k;
    }
    hull[k++] = points[i];
  }
  for (std::size_t i = n - 1, lower = k + 1; i > 0; --i)
  {
    while (k >= lower && Cross(hull[k - 2], hull[k - 1], points[i - 1]) <= 0.0)
    {
      --k;
    }
    hull[k++] = points[i - 1];
  }
  hull.resize(k - 1);
  return hull;
}

/** Smallest width and largest diameter of a convex polygon (counter-clockwise) by rotating calipers. */
void
FeretDiameters(const std::vector<PlanePoint> & hull, double & minimum, double & maximum)
{
  const std::size_t n = hull.size();
  minimum = 0.0;
  maximum = 0.0;
  if (n < 3)
  {
    for (std::size_t i = 0; i < n; ++i)
    {
      for (std::size_t j = i + 1; j < n; ++j)
      {
        maximum = std::max(maximum, Distance(hull[i], hull[j]));
      }
    }
    return;
  }
  minimum = std::numeric_limits<double>::infinity();
  std::size_t j = 1;
  for (std::size_t i = 0; i < n; ++i)
  {
    const std::size_t next = (i + 1) % n;
    // The antipodal vertex of edge (i, next): farthest from its line.
    while (Cross(hull[i], hull[next], hull[(j + 1) % n]) > Cross(hull[i], hull[next], hull[j]))
    {
      j = (j + 1) % n;
    }
    const double edge = Distance(hull[i], hull[next]);
    if (edge > 0.0)
    {
      minimum = std::min(minimum, Cross(hull[i], hull[next], hull[j]) / edge);
    }
    maximum = std::max({ maximum, Distance(hull[i], hull[j]), Distance(hull[next], hull[j]) });
  }
}

/** The mask as the sampler reads it: its buffer, size and the map from LPS to continuous index. */
struct MaskAccess
{
  const unsigned char * Buffer{ nullptr };
  long                  Size[3]{ 0, 0, 0 };
  long                  Stride[3]{ 0, 0, 0 };
  double                Matrix[3][3]{};
  double                Origin[3]{};

  explicit MaskAccess(const VesselLumenMaskType * mask)
  {
    const auto region = mask->GetBufferedRegion();
    Buffer = mask->GetBufferPointer();
    for (unsigned int d = 0; d < 3; ++d)
    {
      Size[d] = static_cast<long>(region.GetSize(d));
      Origin[d] = mask->GetOrigin()[d];
    }
    Stride[0] = 1;
    Stride[1] = Size[0];
    Stride[2] = Size[0] * Size[1];
    // The buffered region may start anywhere: continuous index relative to its start.
    // index = diag(1 / spacing) direction^-1 (point - origin), as ITK's TransformPhysicalPointToContinuousIndex.
    const auto & inverse = mask->GetInverseDirection();
    for (unsigned int r = 0; r < 3; ++r)
    {
      for (unsigned int c = 0; c < 3; ++c)
      {
        Matrix[r][c] = inverse[r][c] / mask->GetSpacing()[r];
      }
    }
    for (unsigned int d = 0; d < 3; ++d)
    {
      Offset[d] = static_cast<double>(region.GetIndex(d));
    }
  }

  void
  ToIndex(const double physical[3], double index[3], bool isVector) const
  {
    for (unsigned int r = 0; r < 3; ++r)
    {
      double sum = 0.0;
      for (unsigned int c = 0; c < 3; ++c)
      {
        sum += Matrix[r][c] * (physical[c] - (isVector ? 0.0 : Origin[c]));
      }
      index[r] = sum - (isVector ? 0.0 : Offset[r]);
    }
  }

  double
  Voxel(long x, long y, long z) const
  {
    if (x < 0 || y < 0 || z < 0 || x >= Size[0] || y >= Size[1] || z >= Size[2])
    {
      return 0.0;
    }
    return Buffer[x + y * Stride[1] + z * Stride[2]] != 0 ? 1.0 : 0.0;
  }

  /** Trilinear interpolation of the 0/1 mask at a continuous index; outside the buffer is background. */
  double
  Sample(double x, double y, double z) const
  {

    // Far outside (and NaN): background, before any conversion to an integer.
    if (!(x >= -1.0 && y >= -1.0 && z >= -1.0 && x < static_cast<double>(Size[0]) && y < static_cast<double>(Size[1]) &&
          z < static_cast<double>(Size[2])))
    {
      return 0.0;
    }
    // floor() of a number >= -1 by truncation, without a call.
    const long   x0 = static_cast<long>(x + 1.0) - 1;
    const long   y0 = static_cast<long>(y + 1.0) - 1;
    const long   z0 = static_cast<long>(z + 1.0) - 1;
    const double tx = x - static_cast<double>(x0);
    const double ty = y - static_cast<double>(y0);
    const double tz = z - static_cast<double>(z0);
    double       v[8];
    if (x0 >= 0 && y0 >= 0 && z0 >= 0 && x0 + 1 < Size[0] && y0 + 1 < Size[1] && z0 + 1 < Size[2])
    {
      const unsigned char * p = Buffer + x0 + y0 * Stride[1] + z0 * Stride[2];
      v[0] = p[0] != 0;
      v[1] = p[1] != 0;
      v[2] = p[Stride[1]] != 0;
      v[3] = p[Stride[1] + 1] != 0;
      v[4] = p[Stride[2]] != 0;
      v[5] = p[Stride[2] + 1] != 0;
      v[6] = p[Stride[2] + Stride[1]] != 0;
      v[7] = p[Stride[2] + Stride[1] + 1] != 0;
    }
    else
    {
      v[0] = Voxel(x0, y0, z0);
      v[1] = Voxel(x0 + 1, y0, z0);
      v[2] = Voxel(x0, y0 + 1, z0);
      v[3] = Voxel(x0 + 1, y0 + 1, z0);
      v[4] = Voxel(x0, y0, z0 + 1);
      v[5] = Voxel(x0 + 1, y0, z0 + 1);
      v[6] = Voxel(x0, y0 + 1, z0 + 1);
      v[7] = Voxel(x0 + 1, y0 + 1, z0 + 1);
    }
    const double a = v[0] + tx * (v[1] - v[0]);
    const double b = v[2] + tx * (v[3] - v[2]);
    const double c = v[4] + tx * (v[5] - v[4]);
    const double d = v[6] + tx * (v[7] - v[6]);
    const double e = a + ty * (b - a);
    const double f = c + ty * (d - c);
    return e + tz * (f - e);
  }

  double Offset[3]{};
};

/** The in-plane grid of one thread, reused from section to section: which samples this section has evaluated
 * (a generation stamp, so nothing is cleared between sections) and their values. */
class PlaneSampler
{
public:
  PlaneSampler(const MaskAccess & mask, double step, long halfSide)
    : m_Mask(mask)
    , m_Step(step)
    , m_HalfSide(halfSide)
    , m_Side(2 * halfSide + 1)
    , m_Stamp(static_cast<std::size_t>(m_Side * m_Side), 0)
    , m_Value(static_cast<std::size_t>(m_Side * m_Side), 0.0f)
  {
  }

  VesselLumenSection
  Measure(const VesselPathSection & section)
  {
    VesselLumenSection result = Describe(section);
    ++m_Generation;
    if (m_Generation == 0) // wrapped: clear once every 2^32 sections
    {
      std::fill(m_Stamp.begin(), m_Stamp.end(), 0u);
      m_Generation = 1;
    }
    double center[3];
    double lateral[3];
    double up[3];
    for (unsigned int d = 0; d < 3; ++d)
    {
      center[d] = section.Center[d];
      lateral[d] = section.Lateral[d] * m_Step;
      up[d] = section.Up[d] * m_Step;
    }
    m_Mask.ToIndex(center, m_Origin, false);
    m_Mask.ToIndex(lateral, m_DU, true);
    m_Mask.ToIndex(up, m_DV, true);

    if (Evaluate(m_HalfSide, m_HalfSide) < Threshold)
    {
      return result;
    }
    result.CenterInSegmentation = true;

    m_Stack.clear();
    m_Boundary.clear();
    m_Stack.push_back({ m_HalfSide, m_HalfSide });
    std::size_t count = 0;
    bool        clipped = false;
    const long  offsets[4] = { 1, -1, m_Side, -m_Side };
    while (!m_Stack.empty())
    {
      const long column = m_Stack.back().first;
      const long row = m_Stack.back().second;
      m_Stack.pop_back();
      ++count;
      const long   pixel = row * m_Side + column;
      const double value = m_Value[pixel];
      for (unsigned int k = 0; k < 4; ++k)
      {
        const long neighbourColumn = column + (k == 0 ? 1 : k == 1 ? -1 : 0);
        const long neighbourRow = row + (k == 2 ? 1 : k == 3 ? -1 : 0);
        if (neighbourColumn < 0 || neighbourRow < 0 || neighbourColumn >= m_Side || neighbourRow >= m_Side)
        {
          clipped = true;
          m_Boundary.push_back({ static_cast<double>(column), static_cast<double>(row) });
          continue;
        }
        const long neighbour = pixel + offsets[k];
        if (m_Stamp[neighbour] == m_Generation)
        {
          // Evaluated already: in the region (queued when first seen) or background.
          if (m_Value[neighbour] < Threshold)
          {
            AddCrossing(column, row, value, neighbourColumn, neighbourRow, m_Value[neighbour]);
          }
          continue;
        }
        const double neighbourValue = Evaluate(neighbourColumn, neighbourRow);
        if (neighbourValue >= Threshold)
        {
          m_Stack.push_back({ neighbourColumn, neighbourRow });
        }
        else
        {
          AddCrossing(column, row, value, neighbourColumn, neighbourRow, neighbourValue);
        }
      }
    }
    const double area = static_cast<double>(count) * m_Step * m_Step;
    result.RegionClipped = clipped;
    result.Area = area;
    result.EquivalentDiameter = 2.0 * std::sqrt(area / Pi);
    const std::vector<PlanePoint> hull = ConvexHull(m_Boundary);
    double                        minimum = 0.0;
    double                        maximum = 0.0;
    FeretDiameters(hull, minimum, maximum);
    result.MinimumDiameter = minimum * m_Step;
    result.MaximumDiameter = maximum * m_Step;
    result.Diameter = result.EquivalentDiameter;
    return result;
  }

  static VesselLumenSection
  Describe(const VesselPathSection & section)
  {
    VesselLumenSection result;
    result.ArcLength = section.ArcLength;
    result.Center = section.Center;
    result.BranchId = section.BranchId;
    if (std::isfinite(section.Radius) && section.Radius >= 0.0)
    {
      result.InscribedDiameter = 2.0 * section.Radius;
    }
    return result;
  }

private:
  double
  Evaluate(long column, long row)
  {
    const long   pixel = row * m_Side + column;
    const double i = static_cast<double>(column - m_HalfSide);
    const double j = static_cast<double>(row - m_HalfSide);
    const double value = m_Mask.Sample(m_Origin[0] + i * m_DU[0] + j * m_DV[0],
                                       m_Origin[1] + i * m_DU[1] + j * m_DV[1],
                                       m_Origin[2] + i * m_DU[2] + j * m_DV[2]);
    m_Stamp[pixel] = m_Generation;
    m_Value[pixel] = static_cast<float>(value);
    return value;
  }

  /** Where the interpolated mask crosses the threshold between an inside sample and an outside neighbour. */
  void
  AddCrossing(long column, long row, double inside, long outsideColumn, long outsideRow, double outside)
  {
    const double t = inside > outside ? (inside - Threshold) / (inside - outside) : 0.5;
    m_Boundary.push_back({ static_cast<double>(column) + t * static_cast<double>(outsideColumn - column),
                           static_cast<double>(row) + t * static_cast<double>(outsideRow - row) });
  }

  const MaskAccess &                 m_Mask;
  double                             m_Step;
  long                               m_HalfSide;
  long                               m_Side;
  std::vector<uint32_t>              m_Stamp;
  std::vector<float>                 m_Value;
  uint32_t                           m_Generation{ 0 };
  std::vector<std::pair<long, long>> m_Stack;
  std::vector<PlanePoint>            m_Boundary;
  double                             m_Origin[3]{};
  double                             m_DU[3]{};
  double                             m_DV[3]{};
};

bool
IsFinite(const Vector<double, 3> & vector)
{
  return std::isfinite(vector[0]) && std::isfinite(vector[1]) && std::isfinite(vector[2]);
}

void
CheckSection(const VesselPathSection & section, std::size_t index)
{
  const bool finite = std::isfinite(section.Center[0]) && std::isfinite(section.Center[1]) &&
                      std::isfinite(section.Center[2]) && IsFinite(section.Lateral) && IsFinite(section.Up) &&
                      std::isfinite(section.ArcLength);
  if (!finite || section.Lateral.GetNorm() < 0.5 || section.Up.GetNorm() < 0.5)
  {
    std::ostringstream message;
    message << "lumen measurement: path section " << index << " (arc length " << section.ArcLength
            << " mm) has a non-finite centre or arc length, or no unit in-plane axes";
    itkGenericExceptionMacro(<< message.str());
  }
}

/** The step and the half side (in samples) the options ask for on \a mask. */
void
ResolveSampling(const VesselLumenMaskType *           mask,
                const VesselLumenMeasurementOptions & options,
                double &                              step,
                long &                                halfSide)
{
  if (mask == nullptr || mask->GetBufferedRegion().GetNumberOfPixels() == 0 || mask->GetBufferPointer() == nullptr)
  {
    itkGenericExceptionMacro(<< "lumen measurement: no segmentation mask (null or empty)");
  }
  const auto & spacing = mask->GetSpacing();
  step = options.SamplingStep;
  if (step == 0.0)
  {
    step = 0.25 * std::min({ spacing[0], spacing[1], spacing[2] });
  }
  if (!(step > 0.0) || !std::isfinite(step))
  {
    itkGenericExceptionMacro(<< "lumen measurement: the sampling step " << options.SamplingStep
                             << " mm is not a positive finite number");
  }
  const double halfWidth = options.MaximumHalfWidth;
  if (!(halfWidth > 0.0) || !std::isfinite(halfWidth))
  {
    itkGenericExceptionMacro(<< "lumen measurement: the half-width " << halfWidth
                             << " mm is not a positive finite number");
  }
  const double samples = std::ceil(halfWidth / step);
  if (samples > static_cast<double>(MaximumSamplesPerSide / 2))
  {
    itkGenericExceptionMacro(<< "lumen measurement: a half-width of " << halfWidth << " mm at a step of " << step
                             << " mm needs more than " << MaximumSamplesPerSide << " samples per side");
  }
  halfSide = std::max(1L, static_cast<long>(samples));
}
} // namespace

VesselLumenProfile
MeasureVesselLumen(const VesselLumenMaskType *           mask,
                   const VesselPathSectionList &         sections,
                   const VesselLumenMeasurementOptions & options)
{
  double step = 0.0;
  long   halfSide = 0;
  ResolveSampling(mask, options, step, halfSide);
  for (std::size_t k = 0; k < sections.size(); ++k)
  {
    CheckSection(sections[k], k);
  }

  VesselLumenProfile profile;
  profile.Source = VesselLumenSource::Segmentation;
  profile.SamplingStep = step;
  profile.Sections.resize(sections.size());
  const MaskAccess access(mask);

  // Contiguous chunks, one per work unit, one sampler (and its grid) each.
  auto threader = MultiThreaderBase::New();
  if (options.NumberOfWorkUnits > 0)
  {
    threader->SetMaximumNumberOfThreads(options.NumberOfWorkUnits);
    threader->SetNumberOfWorkUnits(options.NumberOfWorkUnits);
  }
  const std::size_t chunks =
    std::max<std::size_t>(1, std::min<std::size_t>(sections.size(), threader->GetNumberOfWorkUnits()));
  threader->ParallelizeArray(
    0,
    chunks,
    [&](SizeValueType chunk)
    {
      const std::size_t first = chunk * sections.size() / chunks;
      const std::size_t last = (chunk + 1) * sections.size() / chunks;
      if (first == last)
      {
        return;
      }
      PlaneSampler sampler(access, step, halfSide);
      for (std::size_t k = first; k < last; ++k)
      {
        profile.Sections[k] = sampler.Measure(sections[k]);
      }
    },
    nullptr);

  for (const auto & section : profile.Sections)
  {
    profile.SectionsOutsideSegmentation += section.CenterInSegmentation ? 0 : 1;
    profile.ClippedSections += section.RegionClipped ? 1 : 0;
    profile.SectionsWithoutRadius += section.InscribedDiameter == section.InscribedDiameter ? 0 : 1;
  }
  return profile;
}

VesselLumenSection
MeasureVesselLumenSection(const VesselLumenMaskType *           mask,
                          const VesselPathSection &             section,
                          const VesselLumenMeasurementOptions & options)
{
  double step = 0.0;
  long   halfSide = 0;
  ResolveSampling(mask, options, step, halfSide);
  CheckSection(section, 0);
  const MaskAccess access(mask);
  PlaneSampler     sampler(access, step, halfSide);
  return sampler.Measure(section);
}

VesselLumenProfile
VesselLumenFromRadii(const VesselPathSectionList & sections)
{
  VesselLumenProfile profile;
  profile.Source = VesselLumenSource::CenterlineRadius;
  profile.Sections.reserve(sections.size());
  for (const auto & section : sections)
  {
    VesselLumenSection result = PlaneSampler::Describe(section);
    result.Diameter = result.InscribedDiameter;
    profile.SectionsWithoutRadius += result.IsMeasured() ? 0 : 1;
    profile.Sections.push_back(result);
  }
  return profile;
}

} // namespace itk
