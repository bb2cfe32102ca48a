// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "itkThoraxPhantomImageSource.h"

#include "itkPhantomRendering.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace itk
{
namespace
{
using detail::MakeCapsule;
using detail::MakePhantomPoint;
using detail::PhantomPoint;

constexpr double LeftEdgeOfFieldOfView = -175.0;
constexpr double RightEdgeOfFieldOfView = 175.0;
constexpr double AnteriorEdgeOfFieldOfView = -125.0;
constexpr double PosteriorEdgeOfFieldOfView = 135.0;
constexpr double BottomOfFieldOfView = -235.0;
constexpr double TopOfFieldOfView = 115.0;

constexpr float AirHU = -1000.0f;
constexpr float LungHU = -850.0f;
constexpr float FatHU = -100.0f;
constexpr float MediastinalFatHU = -80.0f;
constexpr float MuscleHU = 50.0f;
constexpr float MyocardiumHU = 90.0f;
constexpr float LeftVentricleHU = 330.0f;
constexpr float RightHeartHU = 170.0f;
constexpr float LiverHU = 60.0f;
constexpr float CorticalBoneHU = 900.0f;
constexpr float CalcificationHU = 1000.0f;
constexpr float AortaHU = 360.0f;
constexpr float BranchHU = 350.0f;
constexpr float PulmonaryArteryHU = 240.0f;

/** A control point of an artery: position and lumen radius, mm. */
struct ControlPoint
{
  double x, y, z, radius;
};

struct ArteryDefinition
{
  int                       id;
  const char *              name;
  std::vector<ControlPoint> controls;
};

/** The arterial tree. Each branch starts at a control point of its parent (inside the parent's lumen). In the
 * anterior view (depth = y) the supra-aortic branches lie 3-10 mm apart in depth, the ascending and descending aorta
 * about 55 mm. */
const std::vector<ArteryDefinition> &
ArteryDefinitions()
{
  static const std::vector<ArteryDefinition> arteries = {
    { 1,
      "ascending aorta, arch and descending aorta",
      { { 6, -14, -95, 13.0 },
        { -4, -24, -65, 14.5 },
        { -10, -26, -35, 15.0 },
        { -9, -22, -12, 14.5 },
        { -3, -12, 4, 14.0 },
        { 10, 0, 12, 13.5 },
        { 24, 16, 6, 13.0 },
        { 28, 32, -12, 12.5 },
        { 26, 40, -40, 12.0 },
        { 21, 42, -90, 11.5 },
        { 15, 40, -140, 11.0 },
        { 9, 36, -190, 10.5 },
        { 5, 30, -230, 10.0 } } },
    { 2, "brachiocephalic trunk", { { -3, -12, 4, 7.0 }, { -9, -10, 25, 6.5 }, { -16, -8, 45, 6.0 } } },
    { 3,
      "right common carotid artery",
      { { -16, -8, 45, 4.2 }, { -22, -5, 70, 4.0 }, { -27, -2, 95, 3.8 }, { -29, 0, 115, 3.6 } } },
    { 4,
      "right subclavian artery",
      { { -16, -8, 45, 4.8 }, { -35, -6, 56, 4.6 }, { -65, -2, 60, 4.4 }, { -100, 2, 55, 4.2 } } },
    { 5,
      "left common carotid artery",
      { { 10, 0, 12, 4.4 }, { 13, -2, 35, 4.2 }, { 19, 1, 65, 4.0 }, { 25, 5, 95, 3.8 }, { 27, 7, 115, 3.6 } } },
    { 6,
      "left subclavian artery",
      { { 24, 16, 6, 5.2 }, { 31, 12, 30, 5.0 }, { 43, 10, 50, 4.8 }, { 70, 8, 58, 4.6 }, { 102, 10, 54, 4.4 } } },
  };
  return arteries;
}

/** The pulmonary trunk and arteries: enhanced, drawn, but not part of the centerline tree. */
const std::vector<std::vector<ControlPoint>> &
PulmonaryArteries()
{
  static const std::vector<std::vector<ControlPoint>> arteries = {
    { { 14, -50, -80, 12.0 }, { 16, -44, -55, 12.0 }, { 16, -22, -36, 11.0 } },
    { { 16, -22, -36, 10.0 }, { 34, -6, -40, 9.0 }, { 58, 6, -48, 8.0 } },
    { { 16, -22, -36, 10.0 }, { -4, 2, -42, 9.0 }, { -42, 8, -48, 8.0 } },
  };
  return arteries;
}

CenterlineBranch
SampleArtery(int id, const std::vector<ControlPoint> & controls)
{
  std::vector<PhantomPoint> knots;
  std::vector<double>       radii;
  for (const auto & c : controls)
  {
    knots.push_back(MakePhantomPoint(c.x, c.y, c.z));
    radii.push_back(c.radius);
  }
  return detail::SampleCatmullRomBranch(id, knots, radii, 2.0);
}

double
Interpolate(const std::vector<std::array<double, 4>> & table, double z, int column)
{
  if (z <= table.front()[0])
  {
    return table.front()[column];
  }
  for (std::size_t k = 1; k < table.size(); ++k)
  {
    if (z <= table[k][0])
    {
      const double f = (z - table[k - 1][0]) / (table[k][0] - table[k - 1][0]);
      return table[k - 1][column] + f * (table[k][column] - table[k - 1][column]);
    }
  }
  return table.back()[column];
}

/** The body outline at height z: half width, half depth and centre y of an ellipse, chest to neck. */
struct BodySection
{
  double halfWidth, halfDepth, centreY;
};

BodySection
BodyAt(double z)
{
  // z, half width, half depth, centre y.
  static const std::vector<std::array<double, 4>> body = { { -235, 150, 112, 8 }, { -120, 158, 115, 6 },
                                                           { 0, 165, 112, 6 },    { 35, 160, 105, 8 },
                                                           { 60, 110, 85, 12 },   { 80, 62, 58, 18 },
                                                           { 115, 58, 56, 20 } };
  return { Interpolate(body, z, 1), Interpolate(body, z, 2), Interpolate(body, z, 3) };
}

/** ((x - c) / a)^2 summed over the axes: <= 1 inside the ellipsoid. */
double
EllipsoidMeasure(double x, double y, double z, const std::array<double, 6> & e)
{
  const double dx = (x - e[0]) / e[3];
  const double dy = (y - e[1]) / e[4];
  const double dz = (z - e[2]) / e[5];
  return dx * dx + dy * dy + dz * dz;
}

// Centre and semi-axes (mm) of the organs drawn as ellipsoids.
constexpr std::array<double, 6> Heart{ 18, -28, -118, 58, 46, 50 };
constexpr std::array<double, 6> LeftVentricle{ 34, -18, -122, 26, 24, 30 };
constexpr std::array<double, 6> RightHeart{ -8, -42, -112, 24, 18, 30 };
constexpr std::array<double, 6> RightLung{ -78, 12, -62, 58, 82, 128 };
constexpr std::array<double, 6> LeftLung{ 82, 16, -58, 52, 78, 122 };

/** Distance from (x, y, z) to the airway axis (trachea down to the carina at z = -20, then the main bronchi). */
double
DistanceToAirway(double x, double y, double z, double & radius)
{
  const PhantomPoint p = MakePhantomPoint(x, y, z);
  double             t = 0.0;
  double best = detail::DistanceToSegment(p, MakePhantomPoint(-4, 18, 120), MakePhantomPoint(-2, 18, -20), t);
  radius = 9.0;
  const double right = detail::DistanceToSegment(p, MakePhantomPoint(-2, 18, -20), MakePhantomPoint(-38, 22, -45), t);
  if (right < best)
  {
    best = right;
    radius = 7.0;
  }
  const double left = detail::DistanceToSegment(p, MakePhantomPoint(-2, 18, -20), MakePhantomPoint(42, 26, -52), t);
  if (left < best)
  {
    best = left;
    radius = 6.5;
  }
  return best;
}

/** Soft tissue at (x, y, z): air, subcutaneous fat, chest-wall or neck muscle, and inside the thoracic cavity the
 * airways, spinal canal, oesophagus, heart, lungs, mediastinal fat, and below the diaphragm the liver. */
float
SoftTissue(const BodySection & body, double x, double y, double z)
{
  const double q = std::hypot(x / body.halfWidth, (y - body.centreY) / body.halfDepth);
  const double depthInside = (1.0 - q) * std::min(body.halfWidth, body.halfDepth);
  if (depthInside < 0.0)
  {
    return AirHU;
  }
  const double fat = 12.0 + 3.0 * std::sin(z / 40.0 + x / 55.0);
  if (depthInside < fat)
  {
    return FatHU;
  }
  const double texture = 8.0 * std::sin(x / 6.0 + 1.3 * std::sin(z / 21.0)) * std::sin(y / 8.0 + z / 27.0);
  double       airwayRadius = 0.0;
  const double airway = DistanceToAirway(x, y, z, airwayRadius);
  if (airway < airwayRadius - 1.5)
  {
    return AirHU;
  }
  if (airway < airwayRadius)
  {
    return 30.0f; // cartilage and mucosa
  }
  if (std::hypot(x, y - 84.0) < 8.0)
  {
    return 15.0f; // spinal canal
  }
  if (std::hypot(x - 2.0, y - 34.0) < 8.0 && z > -200.0)
  {
    return static_cast<float>(40.0 + texture); // oesophagus
  }
  if (z > 55.0 || depthInside < fat + 14.0)
  {
    // Muscles separated by thin fat planes, about 11 mm apart in depth and tilted, as the neck's and chest wall's
    // muscles are: where the cut surface steps in depth, the planes in the CPR step with it (the visible seam).
    const double plane = std::fmod(std::abs(y + 0.35 * x + 0.2 * z + 500.0), 11.0);
    if (plane < 1.8)
    {
      return static_cast<float>(FatHU + 0.5 * texture);
    }
    return static_cast<float>(MuscleHU + texture);
  }
  const double diaphragm = -150.0 - 0.004 * x * x - 0.1 * x;
  if (z < diaphragm)
  {
    return static_cast<float>((x < 40.0 ? LiverHU : 35.0) + texture);
  }
  const double heart = EllipsoidMeasure(x, y, z, Heart);
  if (heart <= 1.0)
  {
    if (EllipsoidMeasure(x, y, z, LeftVentricle) <= 1.0)
    {
      return LeftVentricleHU;
    }
    if (EllipsoidMeasure(x, y, z, RightHeart) <= 1.0)
    {
      return RightHeartHU;
    }
    return static_cast<float>(MyocardiumHU + texture);
  }
  if (heart <= 1.16)
  {
    return -60.0f; // pericardial fat
  }
  if (EllipsoidMeasure(x, y, z, RightLung) <= 1.0 || EllipsoidMeasure(x, y, z, LeftLung) <= 1.0)
  {
    return static_cast<float>(LungHU + 2.5 * texture);
  }
  return static_cast<float>(MediastinalFatHU + texture);
}

/** A rib at height z0 on side s (+1 left, -1 right): from the transverse process around the chest wall towards the
 * front, descending as it goes, as a chain of capsules. */
void
AddRib(std::vector<detail::Capsule> & bones, double side, double z0, double endAngle)
{
  const BodySection body = BodyAt(z0);
  const double      rx = body.halfWidth - 28.0;
  const double      ry = body.halfDepth - 24.0;
  PhantomPoint      previous = MakePhantomPoint(side * 30.0, 82.0, z0);
  const int         pieces = 12;
  const double      startAngle = 0.45;
  for (int k = 0; k <= pieces; ++k)
  {
    const double       angle = startAngle + (endAngle - startAngle) * k / pieces;
    const double       drop = 38.0 * (angle / Math::pi) * (angle / Math::pi);
    const PhantomPoint next =
      MakePhantomPoint(side * rx * std::sin(angle), body.centreY + ry * std::cos(angle), z0 - drop);
    bones.push_back(MakeCapsule(previous, next, 5.0, 4.5, 2.5, 2.2, 180.0f));
    previous = next;
  }
}

detail::PhantomLayers
BuildLayers(const CenterlineTree & tree)
{
  detail::PhantomLayers layers;
  layers.CorticalBoneHU = CorticalBoneHU;
  layers.CalcificationHU = CalcificationHU;
  layers.AirHU = AirHU;
  for (const auto & branch : tree.GetBranches())
  {
    for (std::size_t p = 0; p + 1 < branch.Points.size(); ++p)
    {
      layers.Vessels.push_back(
        MakeCapsule(branch.Points[p], branch.Points[p + 1], branch.Radii[p], branch.Radii[p + 1], 0.0, 0.0, 0.0f));
      layers.VesselHU.push_back(branch.Id == 1 ? AortaHU : BranchHU);
    }
  }
  for (const auto & controls : PulmonaryArteries())
  {
    const CenterlineBranch artery = SampleArtery(0, controls);
    for (std::size_t p = 0; p + 1 < artery.Points.size(); ++p)
    {
      layers.Vessels.push_back(
        MakeCapsule(artery.Points[p], artery.Points[p + 1], artery.Radii[p], artery.Radii[p + 1], 0.0, 0.0, 0.0f));
      layers.VesselHU.push_back(PulmonaryArteryHU);
    }
  }
  // Thoracic spine: vertebral bodies (cancellous bone in a cortical shell) with discs between, spinous and transverse
  // processes.
  for (int level = 0; level < 13; ++level)
  {
    const double z = 110.0 - 27.5 * level;
    layers.Bones.push_back(
      MakeCapsule(MakePhantomPoint(0, 60, z - 9), MakePhantomPoint(0, 60, z + 9), 16.0, 16.0, 13.5, 13.5, 230.0f));
    layers.Bones.push_back(
      MakeCapsule(MakePhantomPoint(0, 97, z - 4), MakePhantomPoint(0, 114, z - 14), 5.0, 4.0, 2.5, 2.0, 200.0f));
    for (const double side : { -1.0, 1.0 })
    {
      layers.Bones.push_back(MakeCapsule(
        MakePhantomPoint(side * 8, 70, z), MakePhantomPoint(side * 9, 95, z - 4), 4.5, 4.5, 2.2, 2.2, 200.0f));
      layers.Bones.push_back(MakeCapsule(
        MakePhantomPoint(side * 10, 80, z), MakePhantomPoint(side * 30, 82, z), 4.5, 4.0, 2.2, 2.0, 200.0f));
    }
  }
  // Eleven pairs of ribs, the lowest two short.
  for (int rib = 0; rib < 11; ++rib)
  {
    for (const double side : { -1.0, 1.0 })
    {
      AddRib(layers.Bones, side, 48.0 - 24.0 * rib, rib < 9 ? 2.35 : 1.9);
    }
  }
  // Sternum, just under the front of the chest wall, and the clavicles.
  PhantomPoint previous;
  for (int k = 0; k <= 8; ++k)
  {
    const double       z = 42.0 - 21.0 * k;
    const BodySection  body = BodyAt(z);
    const PhantomPoint point = MakePhantomPoint(0.0, body.centreY - body.halfDepth + 20.0, z);
    if (k > 0)
    {
      layers.Bones.push_back(MakeCapsule(previous, point, 9.0, 9.0, 6.0, 6.0, 200.0f));
    }
    previous = point;
  }
  for (const double side : { -1.0, 1.0 })
  {
    const BodySection  body = BodyAt(46.0);
    const PhantomPoint medial = MakePhantomPoint(side * 18.0, body.centreY - body.halfDepth + 22.0, 48.0);
    const PhantomPoint middle = MakePhantomPoint(side * 75.0, -50.0, 62.0);
    const PhantomPoint lateral = MakePhantomPoint(side * 125.0, -20.0, 58.0);
    layers.Bones.push_back(MakeCapsule(medial, middle, 7.0, 7.0, 4.0, 4.0, 250.0f));
    layers.Bones.push_back(MakeCapsule(middle, lateral, 7.0, 6.5, 4.0, 3.5, 250.0f));
  }
  // Calcified plaques in the wall of the arch (fraction of the aorta's length, side of the wall in degrees).
  const CenterlineBranch & aorta = tree.GetBranches().front();
  for (const auto & [fraction, angle] : { std::pair<double, double>{ 0.28, 60.0 }, { 0.36, 200.0 }, { 0.44, 320.0 } })
  {
    const std::size_t n = aorta.Points.size();
    const std::size_t p = std::min(n - 2, static_cast<std::size_t>(fraction * (n - 1)));
    Vector<double, 3> tangent = aorta.Points[p + 1] - aorta.Points[p];
    tangent.Normalize();
    Vector<double, 3> reference;
    reference[0] = 1.0;
    reference[1] = 0.0;
    reference[2] = 0.0;
    Vector<double, 3> across = CrossProduct(tangent, reference);
    across.Normalize();
    const Vector<double, 3> other = CrossProduct(tangent, across);
    const double            radians = angle * Math::pi / 180.0;
    const PhantomPoint      centre =
      aorta.Points[p] + (across * std::cos(radians) + other * std::sin(radians)) * (0.92 * aorta.Radii[p]);
    layers.Calcifications.push_back(MakeCapsule(centre, centre, 2.6, 2.6, 0.0, 0.0, 0.0f));
  }
  return layers;
}
} // namespace

ThoraxPhantomImageSource::ThoraxPhantomImageSource()
{
  this->SetNumberOfRequiredInputs(0);
}

CenterlineTree
ThoraxPhantomImageSource::GetCenterlineTree() const
{
  CenterlineTree tree;
  for (const auto & artery : ArteryDefinitions())
  {
    tree.AddBranch(SampleArtery(artery.id, artery.controls));
  }
  // The names travel with the branches, so that any later renumbering of ids keeps each vessel's name.
  for (auto & branch : tree.GetBranches())
  {
    branch.Name = GetBranchName(branch.Id);
  }
  return tree;
}

std::string
ThoraxPhantomImageSource::GetBranchName(int id)
{
  for (const auto & artery : ArteryDefinitions())
  {
    if (artery.id == id)
    {
      return artery.name;
    }
  }
  return "unknown";
}

void
ThoraxPhantomImageSource::VerifyPreconditions() ITKv5_CONST
{
  if (!(std::isfinite(m_Spacing) && m_Spacing > 0.0))
  {
    itkExceptionMacro(<< "Spacing = " << m_Spacing << " mm is invalid: it must be finite and > 0");
  }
  if (!(std::isfinite(m_NoiseStandardDeviation) && m_NoiseStandardDeviation >= 0.0))
  {
    itkExceptionMacro(<< "NoiseStandardDeviation = " << m_NoiseStandardDeviation
                      << " HU is invalid: it must be finite and >= 0");
  }
  const double voxels = ((RightEdgeOfFieldOfView - LeftEdgeOfFieldOfView) / m_Spacing) *
                        ((PosteriorEdgeOfFieldOfView - AnteriorEdgeOfFieldOfView) / m_Spacing) *
                        ((TopOfFieldOfView - BottomOfFieldOfView) / m_Spacing);
  if (voxels > 2.0e9)
  {
    itkExceptionMacro(<< "Spacing = " << m_Spacing << " mm would need " << voxels
                      << " voxels; choose a coarser spacing");
  }
}

void
ThoraxPhantomImageSource::GenerateOutputInformation()
{
  ImageType *            output = this->GetOutput();
  ImageType::SizeType    size;
  ImageType::PointType   origin;
  ImageType::SpacingType spacing;
  const double           low[3] = { LeftEdgeOfFieldOfView, AnteriorEdgeOfFieldOfView, BottomOfFieldOfView };
  const double           high[3] = { RightEdgeOfFieldOfView, PosteriorEdgeOfFieldOfView, TopOfFieldOfView };
  for (unsigned int axis = 0; axis < 3; ++axis)
  {
    size[axis] = static_cast<SizeValueType>(std::ceil((high[axis] - low[axis]) / m_Spacing));
    origin[axis] = low[axis] + 0.5 * m_Spacing;
    spacing[axis] = m_Spacing;
  }
  ImageType::RegionType region;
  region.SetSize(size);
  output->SetLargestPossibleRegion(region);
  output->SetSpacing(spacing);
  output->SetOrigin(origin);
  ImageType::DirectionType direction;
  direction.SetIdentity();
  output->SetDirection(direction);
}

void
ThoraxPhantomImageSource::DynamicThreadedGenerateData(const OutputImageRegionType & region)
{
  // Cheap to rebuild per work unit, and it keeps the source free of mutable caches.
  const detail::PhantomLayers layers = BuildLayers(this->GetCenterlineTree());
  auto                        tissueAtHeight = [](double z)
  {
    const BodySection body = BodyAt(z);
    return [body, z](double x, double y) { return SoftTissue(body, x, y, z); };
  };
  detail::RenderPhantomRegion(this->GetOutput(), region, layers, tissueAtHeight, m_NoiseStandardDeviation, m_Seed);
}

void
ThoraxPhantomImageSource::PrintSelf(std::ostream & os, Indent indent) const
{
  Superclass::PrintSelf(os, indent);
  os << indent << "Spacing (mm): " << m_Spacing << std::endl;
  os << indent << "NoiseStandardDeviation (HU): " << m_NoiseStandardDeviation << std::endl;
  os << indent << "Seed: " << m_Seed << std::endl;
}

} // namespace itk
