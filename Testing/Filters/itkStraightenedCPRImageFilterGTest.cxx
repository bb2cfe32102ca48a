// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// StraightenedCPRImageFilter and CrossSectionStackImageFilter against analytic tubes (docs/vessel-path.md,
// "Straightened CPR" to "Folds"): a straight tube with a stenosis in a rotated, anisotropic volume, a helix and an
// S-curve, a tight U-turn that folds.

#include "itkCrossSectionStackImageFilter.h"
#include "itkLinearInterpolateImageFunction.h"
#include "itkStraightenedCPRImageFilter.h"

#include "vrTestImages.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>

namespace
{
using VolumeType = itk::Image<float, 3>;
using CPRType = itk::Image<float, 2>;
using CPRFilter = itk::StraightenedCPRImageFilter<VolumeType, CPRType>;
using StackFilter = itk::CrossSectionStackImageFilter<VolumeType, VolumeType>;
using PointType = itk::Point<double, 3>;
using VectorType = itk::Vector<double, 3>;
using vr::test::P;

constexpr double Bright = 1000.0;
/** Width of the tubes' soft wall (mm): smooth enough for linear interpolation to find its half-maximum. */
constexpr double Wall = 0.4;

VectorType
V(double x, double y, double z)
{
  VectorType v;
  v[0] = x;
  v[1] = y;
  v[2] = z;
  return v;
}

/** A tube's intensity at distance d from its axis where its radius is r: Bright inside, 0 outside, half at d = r. */
double
Tube(double d, double r)
{
  return Bright / (1.0 + std::exp((d - r) / Wall));
}

VolumeType::Pointer
MakeVolume(const itk::Size<3> &                             size,
           const VectorType &                               spacing,
           const PointType &                                origin,
           const VolumeType::DirectionType &                direction,
           const std::function<double(const PointType &)> & f)
{
  auto volume = VolumeType::New();
  volume->SetRegions(size);
  volume->SetSpacing(spacing);
  volume->SetOrigin(origin);
  volume->SetDirection(direction);
  volume->Allocate();
  float *     voxels = volume->GetBufferPointer();
  std::size_t n = 0;
  for (itk::IndexValueType k = 0; k < static_cast<itk::IndexValueType>(size[2]); ++k)
  {
    for (itk::IndexValueType j = 0; j < static_cast<itk::IndexValueType>(size[1]); ++j)
    {
      for (itk::IndexValueType i = 0; i < static_cast<itk::IndexValueType>(size[0]); ++i)
      {
        PointType point;
        volume->TransformIndexToPhysicalPoint({ { i, j, k } }, point);
        voxels[n++] = static_cast<float>(f(point));
      }
    }
  }
  return volume;
}

VolumeType::DirectionType
Identity()
{
  VolumeType::DirectionType direction;
  direction.SetIdentity();
  return direction;
}

/** A rotation by 30 degrees about (1, 2, 2)/3. */
VolumeType::DirectionType
Rotated()
{
  const VectorType          axis = V(1.0, 2.0, 2.0) / 3.0;
  const double              angle = M_PI / 6.0;
  const double              c = std::cos(angle);
  const double              s = std::sin(angle);
  VolumeType::DirectionType r;
  for (unsigned int i = 0; i < 3; ++i)
  {
    for (unsigned int j = 0; j < 3; ++j)
    {
      r(i, j) = (i == j ? c : 0.0) + (1.0 - c) * axis[i] * axis[j];
    }
  }
  r(0, 1) -= s * axis[2];
  r(1, 0) += s * axis[2];
  r(0, 2) += s * axis[1];
  r(2, 0) -= s * axis[1];
  r(1, 2) -= s * axis[0];
  r(2, 1) += s * axis[0];
  return r;
}

/** A branch through curve(t), t in [0, 1], at count + 1 points, with radius(t) when given. */
itk::VesselPath
PathThrough(const std::function<PointType(double)> & curve,
            int                                      count,
            const std::function<double(double)> &    radius = nullptr)
{
  itk::CenterlineBranch branch;
  branch.Id = 1;
  for (int k = 0; k <= count; ++k)
  {
    const double t = static_cast<double>(k) / count;
    branch.Points.push_back(curve(t));
    if (radius)
    {
      branch.Radii.push_back(radius(t));
    }
  }
  itk::CenterlineTree tree;
  tree.AddBranch(branch);
  return itk::VesselPath::FromTree(tree);
}

/** The half-maximum crossings of a row's profile on each side of the middle column, in columns (linear between
 * columns); false when the profile does not fall below half on both sides. */
bool
HalfMaximumEdges(const CPRType * image, itk::IndexValueType row, double & left, double & right)
{
  const auto   width = static_cast<itk::IndexValueType>(image->GetLargestPossibleRegion().GetSize()[0]);
  const auto   middle = (width - 1) / 2;
  const auto   at = [&](itk::IndexValueType i) { return static_cast<double>(image->GetPixel({ { i, row } })); };
  const double half = 0.5 * Bright;
  if (at(middle) < half)
  {
    return false;
  }
  itk::IndexValueType i = middle;
  while (i + 1 < width && at(i + 1) >= half)
  {
    ++i;
  }
  if (i + 1 >= width)
  {
    return false;
  }
  right = i + (at(i) - half) / (at(i) - at(i + 1));
  i = middle;
  while (i > 0 && at(i - 1) >= half)
  {
    --i;
  }
  if (i == 0)
  {
    return false;
  }
  left = i - (at(i) - half) / (at(i) - at(i - 1));
  return true;
}

template<typename F>
std::string
MessageOf(F && f)
{
  try
  {
    f();
  }
  catch (const itk::ExceptionObject & error)
  {
    return error.GetDescription();
  }
  return "(nothing thrown)";
}

/** The straight tube of must-show 1: axis through the volume's centre, radius 4 mm narrowing to 2 mm over 10 mm. */
struct StenosisScene
{
  VolumeType::Pointer Volume;
  PointType           Start;
  VectorType          Axis;
  double              Length{ 80.0 };
  static double
  Radius(double s)
  {
    const double centre = 40.0;
    return std::abs(s - centre) < 5.0 ? 4.0 - 2.0 * 0.5 * (1.0 + std::cos(M_PI * (s - centre) / 5.0)) : 4.0;
  }
  itk::VesselPath
  Path() const
  {
    return PathThrough(
      [&](double t) { return Start + Axis * (Length * t); }, 80, [&](double t) { return Radius(Length * t); });
  }
};

StenosisScene
MakeStenosisScene()
{
  StenosisScene      scene;
  const itk::Size<3> size{ { 60, 70, 130 } };
  const VectorType   spacing = V(0.6, 0.5, 0.8);
  const auto         direction = Rotated();
  const PointType    origin = P(-12.0, 7.0, 3.0);
  // The axis runs along the volume's third index axis, tilted, through the volume's centre.
  VectorType indexAxis = V(0.15, 0.1, 1.0);
  indexAxis.Normalize();
  VectorType centreOffset;
  for (unsigned int k = 0; k < 3; ++k)
  {
    centreOffset[k] = 0.5 * (size[k] - 1.0) * spacing[k];
  }
  const PointType centre = origin + direction * centreOffset;
  scene.Axis = direction * indexAxis;
  scene.Start = centre - scene.Axis * (0.5 * scene.Length);
  const PointType  start = scene.Start;
  const VectorType axis = scene.Axis;
  const double     length = scene.Length;
  scene.Volume = MakeVolume(size,
                            spacing,
                            origin,
                            direction,
                            [=](const PointType & p)
                            {
                              const double s = (p - start) * axis;
                              const double d = (p - (start + axis * s)).GetNorm();
                              return Tube(d, StenosisScene::Radius(std::clamp(s, 0.0, length)));
                            });
  return scene;
}

/** A helix (R cos t, R sin t, c t), t in [0, 3 pi], and a tube of radius 3 mm around it. */
struct HelixScene
{
  static constexpr double R = 15.0;
  static constexpr double C = 6.0;
  static constexpr double Turn = 3.0 * M_PI;
  static PointType
  At(double t)
  {
    return P(R * std::cos(t), R * std::sin(t), C * t);
  }
  /** Distance from p to the helix, by Newton's method from the turn nearest in height. */
  static double
  Distance(const PointType & p)
  {
    const double rho = std::hypot(p[0], p[1]);
    if (std::abs(rho - R) > 8.0)
    {
      return 8.0;
    }
    const double phi = std::atan2(p[1], p[0]);
    double       t = phi + 2.0 * M_PI * std::round((p[2] / C - phi) / (2.0 * M_PI));
    for (int k = 0; k < 12; ++k)
    {
      const VectorType d = p - At(t);
      const VectorType d1 = V(-R * std::sin(t), R * std::cos(t), C);
      const VectorType d2 = V(-R * std::cos(t), -R * std::sin(t), 0.0);
      t -= -(d * d1) / (d1 * d1 - d * d2);
    }
    t = std::clamp(t, 0.0, Turn);
    return p.EuclideanDistanceTo(At(t));
  }
};

VolumeType::Pointer
MakeHelixVolume()
{
  return MakeVolume({ { 92, 92, 132 } },
                    V(0.5, 0.5, 0.5),
                    P(-23, -23, -4),
                    Identity(),
                    [](const PointType & p) { return Tube(HelixScene::Distance(p), 3.0); });
}

itk::VesselPath
HelixPath()
{
  return PathThrough([](double t) { return HelixScene::At(HelixScene::Turn * t); }, 20000);
}

/** x = 15 sin(2 pi z / 120), z from 0 down to -120: one inflection, at z = -60. */
struct SCurveScene
{
  static constexpr double A = 15.0;
  static constexpr double K = 2.0 * M_PI / 120.0;
  static PointType
  At(double z)
  {
    return P(A * std::sin(K * z), 0.0, z);
  }
  static double
  Distance(const PointType & p)
  {
    double z = p[2];
    for (int k = 0; k < 12; ++k)
    {
      const double dx = p[0] - A * std::sin(K * z);
      const double first = -dx * A * K * std::cos(K * z) - (p[2] - z);
      const double second = A * A * K * K * std::cos(K * z) * std::cos(K * z) + dx * A * K * K * std::sin(K * z) + 1.0;
      z -= first / second;
    }
    z = std::clamp(z, -120.0, 0.0);
    return p.EuclideanDistanceTo(At(z));
  }
};

/** Widths at half maximum (mm) of the rows of \a cpr whose arc length lies in [from, to]; fails when a row has no
 * edge. */
std::vector<double>
RowWidths(const CPRFilter * filter, double from, double to)
{
  const CPRType *     cpr = filter->GetOutput();
  std::vector<double> widths;
  for (std::size_t j = 0; j < filter->GetSections().size(); ++j)
  {
    const double s = filter->GetSections()[j].ArcLength;
    if (s < from || s > to)
    {
      continue;
    }
    double left;
    double right;
    EXPECT_TRUE(HalfMaximumEdges(cpr, static_cast<itk::IndexValueType>(j), left, right)) << "row " << j;
    widths.push_back((right - left) * filter->GetPixelSpacing());
  }
  return widths;
}

void
ExpectConstantWidth(const CPRFilter * filter, double from, double to, double expected, double spread)
{
  const std::vector<double> widths = RowWidths(filter, from, to);
  ASSERT_FALSE(widths.empty());
  const auto [smallest, largest] = std::minmax_element(widths.begin(), widths.end());
  std::cout << widths.size() << " rows: width " << *smallest << " to " << *largest << " mm" << std::endl;
  EXPECT_LE(*largest - *smallest, spread);
  EXPECT_NEAR(0.5 * (*largest + *smallest), expected, 0.1);
}
} // namespace

TEST(StraightenedCPRImageFilter, StenosedTubeLiesInTheMiddleColumnOfARotatedAnisotropicVolume)
{
  const auto scene = MakeStenosisScene();
  auto       filter = CPRFilter::New();
  filter->SetVolume(scene.Volume);
  filter->SetPath(scene.Path());
  filter->SetWidth(24.0);
  filter->SetPixelSpacing(0.25);
  filter->Update();
  const CPRType * cpr = filter->GetOutput();
  const auto      size = cpr->GetLargestPossibleRegion().GetSize();
  ASSERT_EQ(size[0], 97u);
  ASSERT_EQ(size[1], 321u);
  EXPECT_NEAR(cpr->GetOrigin()[0], -12.0, 1e-12);
  EXPECT_NEAR(cpr->GetSpacing()[1], 0.25, 0.0);
  const double middle = 48.0;
  double       largestOffset = 0.0;
  double       largestDiameterError = 0.0;
  for (itk::IndexValueType j = 0; j < static_cast<itk::IndexValueType>(size[1]); ++j)
  {
    const double s = filter->GetSections()[j].ArcLength;
    EXPECT_NEAR(s, 0.25 * j, 1e-9);
    if (s < 5.0 || s > scene.Length - 5.0)
    {
      continue;
    }
    double left;
    double right;
    ASSERT_TRUE(HalfMaximumEdges(cpr, j, left, right)) << "row " << j;
    largestOffset = std::max(largestOffset, std::abs(0.5 * (left + right) - middle));
    largestDiameterError =
      std::max(largestDiameterError, std::abs((right - left) * 0.25 - 2.0 * StenosisScene::Radius(s)));
  }
  std::cout << "stenosis: tube centre at most " << largestOffset << " columns off the middle, diameter within "
            << largestDiameterError << " mm" << std::endl;
  EXPECT_LT(largestOffset, 0.1);
  EXPECT_LT(largestDiameterError, 0.25);
  EXPECT_EQ(filter->GetNumberOfFoldedPixels(), 0u);
  EXPECT_GT(filter->GetFoldFreeHalfWidth(), 1e6) << "a straight path has no curvature, but for rounding";
  EXPECT_TRUE(filter->GetFoldWarning().empty());
}

TEST(StraightenedCPRImageFilter, EveryPixelsPointGivesItsValue)
{
  const auto scene = MakeStenosisScene();
  auto       filter = CPRFilter::New();
  filter->SetVolume(scene.Volume);
  filter->SetPath(scene.Path());
  filter->SetWidth(30.0);
  filter->SetPixelSpacing(0.5);
  filter->SetRollAngle(35.0);
  filter->ComputePointImageOn();
  filter->Update();
  const CPRType *                   cpr = filter->GetOutput();
  const CPRFilter::PointImageType * points = filter->GetPointImage();
  ASSERT_EQ(points->GetLargestPossibleRegion(), cpr->GetLargestPossibleRegion());
  auto interpolator = itk::LinearInterpolateImageFunction<VolumeType, double>::New();
  interpolator->SetInputImage(scene.Volume);
  const auto  size = cpr->GetLargestPossibleRegion().GetSize();
  std::size_t compared = 0;
  double      largest = 0.0;
  double      largestPointError = 0.0;
  for (itk::IndexValueType j = 0; j < static_cast<itk::IndexValueType>(size[1]); ++j)
  {
    for (itk::IndexValueType i = 0; i < static_cast<itk::IndexValueType>(size[0]); ++i)
    {
      const auto & stored = points->GetPixel({ { i, j } });
      PointType    point;
      for (unsigned int k = 0; k < 3; ++k)
      {
        point[k] = stored[k];
      }
      largestPointError = std::max(largestPointError, point.EuclideanDistanceTo(filter->ComputePoint(i, j)));
      if (!interpolator->IsInsideBuffer(point))
      {
        continue;
      }
      ++compared;
      largest = std::max(largest, std::abs(interpolator->Evaluate(point) - cpr->GetPixel({ { i, j } })));
    }
  }
  std::cout << compared << " pixels: value at the stored point within " << largest << ", points within "
            << largestPointError << " mm of ComputePoint" << std::endl;
  EXPECT_GT(compared, size[0] * size[1] / 2);
  EXPECT_LT(largest, 0.05);
  EXPECT_LT(largestPointError, 1e-4);
}

TEST(StraightenedCPRImageFilter, HelixHasConstantWidthAndItsCenterlineMapsToTheMiddleColumn)
{
  auto filter = CPRFilter::New();
  filter->SetVolume(MakeHelixVolume());
  const auto path = HelixPath();
  filter->SetPath(path);
  filter->SetWidth(20.0);
  filter->SetPixelSpacing(0.2);
  filter->Update();
  // 0.1 voxel of 0.5 mm; away from the ends, where the tube stops.
  ExpectConstantWidth(filter, 5.0, path.GetLength() - 5.0, 6.0, 0.05);
  // A point on the centerline, between rows, maps to the middle column.
  const double middle = 0.5 * (filter->GetOutput()->GetLargestPossibleRegion().GetSize()[0] - 1.0);
  for (const double s : { 3.3, 17.77, 60.05, 123.456 })
  {
    const PointType onPath = path.PointAt(s);
    const double    row = filter->RowOfArcLength(path.ProjectPoint(onPath));
    EXPECT_NEAR(row, s / 0.2, 1e-6);
    EXPECT_LT(filter->ComputePoint(middle, row).EuclideanDistanceTo(onPath), 1e-3) << "at s = " << s;
  }
  // The helix's radius of curvature (R^2 + c^2) / R is below no fold at 10 mm half-width.
  const double rho = (HelixScene::R * HelixScene::R + HelixScene::C * HelixScene::C) / HelixScene::R;
  EXPECT_NEAR(filter->GetFoldFreeHalfWidth(), rho, 0.01 * rho);
  EXPECT_EQ(filter->GetNumberOfFoldedPixels(), 0u);
}

TEST(StraightenedCPRImageFilter, SCurveHasConstantWidthThroughItsInflection)
{
  auto volume = MakeVolume({ { 80, 24, 262 } },
                           V(0.5, 0.5, 0.5),
                           P(-20, -6, -125),
                           Identity(),
                           [](const PointType & p) { return Tube(SCurveScene::Distance(p), 3.0); });
  auto filter = CPRFilter::New();
  filter->SetVolume(volume);
  const auto path = PathThrough([](double t) { return SCurveScene::At(-120.0 * t); }, 12000);
  filter->SetPath(path);
  filter->SetWidth(20.0);
  filter->SetPixelSpacing(0.2);
  filter->Update();
  ExpectConstantWidth(filter, 5.0, path.GetLength() - 5.0, 6.0, 0.05);
}

TEST(StraightenedCPRImageFilter, StretchedKeepsDistancesAlongTheProjectedPath)
{
  auto filter = CPRFilter::New();
  filter->SetVolume(MakeHelixVolume());
  const auto path = HelixPath();
  filter->SetPath(path);
  filter->SetMode(itk::VesselPathCPRMode::Stretched);
  filter->SetWidth(50.0);
  filter->SetPixelSpacing(0.25);
  filter->Update();
  // The default direction is the default view's screen-right, LPS +x: the path projects on the y-z plane, where its
  // arc length is the integral of sqrt(R^2 cos^2 t + c^2) dt (Simpson's rule here).
  const auto sigma = [](double t)
  {
    const int    n = 2000;
    const double h = t / n;
    double       sum = 0.0;
    for (int k = 0; k <= n; ++k)
    {
      const double u = k * h;
      const double f = std::hypot(HelixScene::R * std::cos(u), HelixScene::C);
      sum += (k == 0 || k == n ? 1.0 : (k % 2 ? 4.0 : 2.0)) * f;
    }
    return sum * h / 3.0;
  };
  const double speed = std::hypot(HelixScene::R, HelixScene::C);
  const auto & sections = filter->GetSections();
  const double middle = 0.5 * (filter->GetOutput()->GetLargestPossibleRegion().GetSize()[0] - 1.0);
  double       measured = 0.0;
  double       largestError = 0.0;
  for (std::size_t j = 0; j < sections.size(); ++j)
  {
    EXPECT_NEAR((sections[j].Lateral - V(1, 0, 0)).GetNorm(), 0.0, 1e-12);
    const PointType centre = filter->ComputePoint(middle, static_cast<double>(j));
    EXPECT_LT(centre.EuclideanDistanceTo(path.PointAt(sections[j].ArcLength)), 1e-9);
    if (j > 0)
    {
      const PointType before = filter->ComputePoint(middle, static_cast<double>(j - 1));
      measured += std::hypot(centre[1] - before[1], centre[2] - before[2]);
    }
    const double image = 0.25 * static_cast<double>(j);
    if (image >= 10.0)
    {
      largestError = std::max(largestError, std::abs(measured - image) / image);
      largestError = std::max(largestError, std::abs(sigma(sections[j].ArcLength / speed) - image) / image);
    }
  }
  std::cout << "stretched: " << sections.size() << " rows, largest relative error of distances " << largestError
            << std::endl;
  EXPECT_LT(largestError, 0.005);
  EXPECT_NEAR(sections.size(), std::floor(sigma(HelixScene::Turn) / 0.25) + 1.0, 1.0);
}

TEST(StraightenedCPRImageFilter, TightUTurnFoldsAndTheMaskMarksTheOverlap)
{
  // Down 40 mm, a half circle of radius R = 32/pi mm (about 10.19) about (R, 0, 0) in the frontal plane, up 40 mm;
  // points every 0.01 mm, so the tangent is the curve's. The half circle starts and ends on rows (s = 40, 72 mm).
  const double R = 32.0 / M_PI;
  const double arcLength = M_PI * R;
  const auto   curve = [&](double t)
  {
    const double s = t * (80.0 + arcLength);
    if (s <= 40.0)
    {
      return P(0, 0, 40.0 - s);
    }
    if (s <= 40.0 + arcLength)
    {
      const double angle = (s - 40.0) / R;
      return P(R - R * std::cos(angle), 0, -R * std::sin(angle));
    }
    return P(2.0 * R, 0, s - 40.0 - arcLength);
  };
  const auto tangent = [&](double s)
  {
    if (s <= 40.0)
    {
      return V(0, 0, -1);
    }
    if (s <= 40.0 + arcLength)
    {
      const double angle = (s - 40.0) / R;
      return V(std::sin(angle), 0, -std::cos(angle));
    }
    return V(0, 0, 1);
  };
  auto path = PathThrough(curve, 11200);
  path.SetTangentHalfWindow(0.01); // the curve's own tangent, up to where the half circle begins and ends
  auto filter = CPRFilter::New();
  filter->SetVolume(
    MakeVolume({ { 4, 4, 4 } }, V(1, 1, 1), P(0, 0, 0), Identity(), [](const PointType &) { return 0.0; }));
  filter->SetPath(path);
  filter->SetWidth(30.0);
  filter->SetPixelSpacing(0.5);
  filter->ComputePointImageOn();
  filter->Update();

  // Independently: a pixel is folded where its row's points move backwards along the curve's own tangent, the
  // points of the rows before and after it.
  const auto * points = filter->GetPointImage();
  const auto   size = points->GetLargestPossibleRegion().GetSize();
  const auto   point = [&](itk::IndexValueType i, itk::IndexValueType j)
  {
    const auto & p = points->GetPixel({ { i, j } });
    return V(p[0], p[1], p[2]);
  };
  const auto * mask = filter->GetFoldMask();
  std::size_t  backwards = 0;
  std::size_t  agree = 0;
  for (itk::IndexValueType j = 1; j + 1 < static_cast<itk::IndexValueType>(size[1]); ++j)
  {
    const VectorType t = tangent(filter->GetSections()[j].ArcLength);
    for (itk::IndexValueType i = 0; i < static_cast<itk::IndexValueType>(size[0]); ++i)
    {
      const bool folded = (point(i, j + 1) - point(i, j - 1)) * t <= 0.0;
      backwards += folded ? 1 : 0;
      agree += folded == (mask->GetPixel({ { i, j } }) != 0) ? 1 : 0;
    }
  }
  // Analytically: the rows strictly inside the half circle (s in (40, 72) mm, 63 rows at 0.5 mm) and the columns on
  // the inner side beyond the centre of curvature (x >= 10.5 mm: 10 columns). The rows where it begins and ends see
  // half the turn between their neighbours, and fold only beyond 2R, outside the image.
  EXPECT_EQ(size[0], 61u);
  EXPECT_EQ(filter->GetNumberOfFoldedPixels(), 630u);
  EXPECT_EQ(backwards, 630u);
  EXPECT_EQ(agree, (size[0]) * (size[1] - 2));
  EXPECT_NEAR(filter->GetFoldFreeHalfWidth(), R, 0.005 * R);
  const std::string warning = filter->GetFoldWarning();
  EXPECT_NE(warning.find("630 pixels"), std::string::npos) << warning;
  EXPECT_NE(warning.find("Width of at most 20.3"), std::string::npos) << warning;

  // Half as wide: no fold.
  filter->SetWidth(20.0);
  filter->Update();
  EXPECT_EQ(filter->GetNumberOfFoldedPixels(), 0u);
  EXPECT_TRUE(filter->GetFoldWarning().empty());
}

TEST(StraightenedCPRImageFilter, SlabModesCombineAlongUp)
{
  // A bright bead 1.5 mm off the plane along Up, beside a straight path down the volume.
  const auto volume =
    MakeVolume({ { 40, 40, 40 } },
               V(0.5, 0.5, 0.5),
               P(-10, -10, -10),
               Identity(),
               [](const PointType & p) { return p.EuclideanDistanceTo(P(2, -1.5, 0)) < 1.0 ? 100.0 : 10.0; });
  const auto path = PathThrough([](double t) { return P(0, 0, 8.0 - 16.0 * t); }, 16);
  auto       filter = CPRFilter::New();
  filter->SetVolume(volume);
  filter->SetPath(path);
  filter->SetWidth(8.0);
  filter->SetPixelSpacing(0.5);
  filter->SetInterpolation(itk::CPRInterpolationMode::Nearest);
  // Up is anterior, -y: the bead lies 1.5 mm along Up at lateral x = 2 mm, arc length 8 mm.
  const itk::Index<2> bead{ { 12, 16 } };
  filter->Update();
  EXPECT_EQ(filter->GetOutput()->GetPixel(bead), 10.0f);
  filter->SetSlabThickness(4.0);
  filter->SetSlabMode(itk::CPRSlabMode::MIP);
  filter->Update();
  EXPECT_EQ(filter->GetOutput()->GetPixel(bead), 100.0f);
  filter->SetSlabMode(itk::CPRSlabMode::MinIP);
  filter->Update();
  EXPECT_EQ(filter->GetOutput()->GetPixel(bead), 10.0f);
  filter->SetSlabMode(itk::CPRSlabMode::Mean);
  filter->Update();
  EXPECT_GT(filter->GetOutput()->GetPixel(bead), 10.0f);
  EXPECT_LT(filter->GetOutput()->GetPixel(bead), 100.0f);
  filter->SetSlabThickness(0.0);
  filter->SetInterpolation(itk::CPRInterpolationMode::Cubic);
  filter->Update();
  EXPECT_NEAR(filter->GetOutput()->GetPixel({ { 0, 4 } }), 10.0f, 1e-3);
}

TEST(StraightenedCPRImageFilter, BadParametersThrowNamingThem)
{
  const auto volume =
    MakeVolume({ { 4, 4, 4 } }, V(1, 1, 1), P(0, 0, 0), Identity(), [](const PointType &) { return 0.0; });
  const auto path = PathThrough([](double t) { return P(0, 0, -10.0 * t); }, 10);
  const auto update = [&](const std::function<void(CPRFilter *)> & configure)
  {
    auto filter = CPRFilter::New();
    filter->SetVolume(volume);
    filter->SetPath(path);
    configure(filter);
    return MessageOf([&] { filter->Update(); });
  };
  EXPECT_NE(update([](CPRFilter * f) { f->SetWidth(0.0); }).find("Width = 0 mm"), std::string::npos);
  EXPECT_NE(update([](CPRFilter * f) { f->SetWidth(-3.0); }).find("Width = -3 mm"), std::string::npos);
  EXPECT_NE(update([](CPRFilter * f) { f->SetWidth(std::nan("")); }).find("Width = nan mm"), std::string::npos);
  EXPECT_NE(update([](CPRFilter * f) { f->SetPixelSpacing(0.0); }).find("PixelSpacing = 0 mm"), std::string::npos);
  EXPECT_NE(update([](CPRFilter * f) { f->SetPixelSpacing(std::nan("")); }).find("PixelSpacing = nan mm"),
            std::string::npos);
  EXPECT_NE(update([](CPRFilter * f) { f->SetRollAngle(INFINITY); }).find("RollAngle = inf"), std::string::npos);
  EXPECT_NE(update([](CPRFilter * f) { f->SetSlabThickness(-1.0); }).find("SlabThickness = -1 mm"), std::string::npos);
  const std::string shortPath = update([](CPRFilter * f) { f->SetPixelSpacing(12.0); });
  EXPECT_NE(shortPath.find("10 mm long, shorter than one row of PixelSpacing = 12 mm"), std::string::npos) << shortPath;
  auto noPath = CPRFilter::New();
  noPath->SetVolume(volume);
  EXPECT_NE(MessageOf([&] { noPath->Update(); }).find("no path"), std::string::npos);

  const auto stack = [&](const std::function<void(StackFilter *)> & configure)
  {
    auto filter = StackFilter::New();
    filter->SetVolume(volume);
    filter->SetPath(path);
    configure(filter);
    return MessageOf([&] { filter->Update(); });
  };
  EXPECT_NE(stack([](StackFilter * f) { f->SetSectionStep(0.0); }).find("SectionStep = 0 mm"), std::string::npos);
  EXPECT_NE(stack([](StackFilter * f) { f->SetSectionStep(std::nan("")); }).find("SectionStep = nan mm"),
            std::string::npos);
  EXPECT_NE(stack([](StackFilter * f) { f->SetSectionSpacing(itk::Vector<double, 2>(0.0)); }).find("SectionSpacing"),
            std::string::npos);
  EXPECT_NE(stack([](StackFilter * f) { f->SetSectionSize({ { 0, 8 } }); }).find("SectionSize"), std::string::npos);
  EXPECT_NE(stack([](StackFilter * f) { f->SetSectionStep(11.0); }).find("shorter than one section"),
            std::string::npos);
}

TEST(CrossSectionStackImageFilter, PlanesShowTheTubesDiscAndMatchTheStraightenedRows)
{
  const auto scene = MakeStenosisScene();
  auto       stack = StackFilter::New();
  stack->SetVolume(scene.Volume);
  stack->SetPath(scene.Path());
  stack->SetSectionStep(0.5);
  stack->SetSectionSize({ { 49, 49 } });
  stack->SetSectionSpacing(itk::Vector<double, 2>(0.25));
  stack->SetRollAngle(20.0);
  stack->Update();
  const VolumeType * planes = stack->GetOutput();
  const auto         size = planes->GetLargestPossibleRegion().GetSize();
  ASSERT_EQ(size[2], 161u);
  EXPECT_NEAR(planes->GetSpacing()[2], 0.5, 0.0);
  EXPECT_NEAR(planes->GetOrigin()[0], -6.0, 1e-12);
  double largestCentre = 0.0;
  double largestDiameter = 0.0;
  for (itk::IndexValueType k = 0; k < static_cast<itk::IndexValueType>(size[2]); ++k)
  {
    const double s = stack->GetSections()[k].ArcLength;
    if (s < 5.0 || s > scene.Length - 5.0)
    {
      continue;
    }
    // The region above half maximum: its area gives the equivalent diameter, its centroid the centre.
    double area = 0.0;
    double ci = 0.0;
    double cj = 0.0;
    for (itk::IndexValueType j = 0; j < 49; ++j)
    {
      for (itk::IndexValueType i = 0; i < 49; ++i)
      {
        if (planes->GetPixel({ { i, j, k } }) >= 0.5 * Bright)
        {
          area += 1.0;
          ci += i;
          cj += j;
        }
      }
    }
    largestCentre = std::max(largestCentre, std::hypot(ci / area - 24.0, cj / area - 24.0));
    largestDiameter =
      std::max(largestDiameter, std::abs(2.0 * std::sqrt(area * 0.0625 / M_PI) - 2.0 * StenosisScene::Radius(s)));
  }
  std::cout << "stack: disc centre within " << largestCentre << " pixels, equivalent diameter within "
            << largestDiameter << " mm" << std::endl;
  EXPECT_LT(largestCentre, 0.1);
  EXPECT_LT(largestDiameter, 0.25);

  // Plane k's middle row is the straightened CPR's row k at the same roll and spacing.
  auto cpr = CPRFilter::New();
  cpr->SetVolume(scene.Volume);
  cpr->SetPath(scene.Path());
  cpr->SetPixelSpacing(0.25);
  cpr->SetWidth(12.0);
  cpr->SetRollAngle(20.0);
  cpr->Update();
  auto sameStep = StackFilter::New();
  sameStep->SetVolume(scene.Volume);
  sameStep->SetPath(scene.Path());
  sameStep->SetSectionStep(0.25);
  sameStep->SetSectionSize({ { 49, 5 } });
  sameStep->SetSectionSpacing(itk::Vector<double, 2>(0.25));
  sameStep->SetRollAngle(20.0);
  sameStep->Update();
  ASSERT_EQ(cpr->GetOutput()->GetLargestPossibleRegion().GetSize()[1],
            sameStep->GetOutput()->GetLargestPossibleRegion().GetSize()[2]);
  for (itk::IndexValueType k = 0; k < 321; k += 7)
  {
    for (itk::IndexValueType i = 0; i < 49; ++i)
    {
      ASSERT_EQ(cpr->GetOutput()->GetPixel({ { i, k } }), sameStep->GetOutput()->GetPixel({ { i, 2, k } }))
        << "column " << i << ", row " << k;
    }
  }
  EXPECT_LT(sameStep->ComputePoint(24, 2, 40).EuclideanDistanceTo(scene.Path().PointAt(10.0)), 1e-9);
}
