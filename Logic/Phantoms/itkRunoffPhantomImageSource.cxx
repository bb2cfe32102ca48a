// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "itkRunoffPhantomImageSource.h"

#include "itkCPRVectorHelpers.h"
#include "itkPhantomRendering.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace itk
{
namespace
{
using PointType = Point<double, 3>;
using detail::Capsule;
using detail::MakeCapsule;

constexpr double TopOfFieldOfView = 10.0;
constexpr double BottomOfFieldOfView = -1010.0;
constexpr double HalfWidthOfFieldOfView = 190.0;
constexpr double AnteriorEdgeOfFieldOfView = -110.0;
constexpr double PosteriorEdgeOfFieldOfView = 130.0;

constexpr float AirHU = -1000.0f;
constexpr float FatHU = -100.0f;
constexpr float MuscleHU = 50.0f;
constexpr float CorticalBoneHU = 1200.0f;
constexpr float CalcificationHU = 1000.0f;

/** A control point of a vessel: position (mm, at scale 1, x for the left side) and lumen radius (mm).
 * Below the groin (InLegFrame) y is not given directly but as an offset from the leg's vessel plane, see
 * LegVesselY. */
struct ControlPoint
{
  double x, y, z, radius;
  bool   inLegFrame;
};

struct VesselDefinition
{
  int                       rightId;
  int                       leftId;
  const char *              name;
  std::vector<ControlPoint> controls;
};

constexpr double DesignAngleInDegrees = RunoffPhantomImageSource::DesignAngleInDegrees;

/** Anterior-posterior course of the leg vessels (z, y at scale 1): anterior in the thigh, behind the knee. */
double
LegVesselPlaneY(double z);

/** Leg centre |x| at height z (scale 1). */
double
LegCenterX(double z);

/** y of a leg vessel point: on a plane through the leg's vessel course that faces the design angle, so that
 * depth -x sin(theta) + y cos(theta) is the same across the leg, plus a small offset (mm) per vessel. The
 * anatomical left-right order of the vessels is kept; only their depth order differs between the legs. */
double
LegVesselY(double side, double xLeft, double z, double offset)
{
  const double slope = std::tan(DesignAngleInDegrees * Math::pi / 180.0);
  return LegVesselPlaneY(z) + side * slope * (xLeft - LegCenterX(z)) + offset;
}

/** The arterial tree. x is given for the patient's left (LPS +x) and mirrored for the right; the aorta (ids 1,
 * 1) lies on the midline. Each branch starts at a control point of its parent. Leg-frame points give the depth
 * offset of LegVesselY instead of y. */
const std::vector<VesselDefinition> &
VesselDefinitions()
{
  static const std::vector<VesselDefinition> definitions = {
    { 1,
      1,
      "aorta",
      { { 8, 2, 5, 10.0, false }, { 6, 4, -60, 9.5, false }, { 3, 5, -120, 9.0, false }, { 0, 6, -170, 8.5, false } } },
    { 2, 3, "common iliac", { { 0, 6, -170, 6.5, false }, { 28, 8, -205, 6.0, false }, { 45, 10, -240, 5.5, false } } },
    { 4,
      5,
      "internal iliac",
      { { 45, 10, -240, 3.8, false },
        { 52, 24, -262, 3.4, false },
        { 57, 38, -290, 3.0, false },
        { 61, 45, -318, 2.6, false } } },
    { 6,
      7,
      "external iliac/femoral/popliteal",
      { { 45, 10, -240, 5.0, false },
        { 62, -8, -285, 4.8, false },
        { 76, 0, -330, 4.6, true },
        { 79, 0, -360, 4.2, true },
        { 78, 0, -430, 3.9, true },
        { 74, 0, -510, 3.6, true },
        { 71, 0, -575, 3.4, true },
        { 72, 0, -620, 3.2, true },
        { 73, 0, -660, 3.0, true } } },
    { 8,
      9,
      "deep femoral",
      { { 76, 0, -330, 3.6, true },
        { 88, -0.3, -370, 3.2, true },
        { 95, -0.6, -420, 2.9, true },
        { 98, -0.9, -470, 2.6, true },
        { 97, -1.0, -505, 2.3, true } } },
    { 10,
      11,
      "anterior tibial",
      { { 73, 0, -660, 2.6, true },
        { 86, -0.6, -690, 2.5, true },
        { 93, -0.9, -730, 2.4, true },
        { 93, -1.0, -820, 2.2, true },
        { 89, -1.0, -900, 2.0, true },
        { 84, -1.0, -975, 1.8, true } } },
    { 12,
      13,
      "tibioperoneal trunk/posterior tibial",
      { { 73, 0, -660, 2.9, true },
        { 72, 0, -690, 2.7, true },
        { 64, 0.4, -760, 2.5, true },
        { 58, 0.7, -860, 2.2, true },
        { 55, 0.8, -970, 1.9, true } } },
    { 14,
      15,
      "peroneal",
      { { 72, 0, -690, 2.4, true },
        { 78, 0.6, -760, 2.2, true },
        { 82, 1.0, -840, 2.0, true },
        { 83, 1.2, -895, 1.8, true } } },
  };
  return definitions;
}

/** A bone piece: a capsule with a cortical shell around marrow (or cancellous bone). Left side, scale 1. */
struct BoneDefinition
{
  std::array<double, 3> a, b;
  double                outerRadius, innerRadius;
  float                 innerHU;
  bool                  midline;
};

const std::vector<BoneDefinition> &
BoneDefinitions()
{
  static const std::vector<BoneDefinition> bones = []
  {
    std::vector<BoneDefinition> list;
    // Lumbar vertebral bodies and sacrum: cancellous bone in a thin shell, discs in between.
    for (int level = 0; level < 6; ++level)
    {
      const double top = 2.0 - level * 40.0;
      list.push_back({ { 0, 46, top - 6 }, { 0, 46, top - 26 }, 21.0, 18.5, 260.0f, true });
    }
    list.push_back({ { 88, 14, -300 }, { 88, 14, -300 }, 24.0, 19.0, 300.0f, false });  // femoral head
    list.push_back({ { 88, 14, -300 }, { 110, 20, -336 }, 15.0, 10.0, 200.0f, false }); // femoral neck
    list.push_back({ { 110, 26, -340 }, { 90, 18, -600 }, 14.0, 8.0, 20.0f, false });   // femoral shaft
    list.push_back({ { 72, 6, -618 }, { 100, 6, -618 }, 18.0, 14.5, 300.0f, false });   // femoral condyles
    list.push_back({ { 72, 4, -650 }, { 96, 4, -650 }, 15.0, 12.0, 300.0f, false });    // tibial plateau
    list.push_back({ { 84, 2, -660 }, { 78, -4, -955 }, 11.0, 5.5, 20.0f, false });     // tibial shaft
    list.push_back({ { 106, 28, -665 }, { 100, 26, -955 }, 6.0, 2.5, 100.0f, false });  // fibula
    return list;
  }();
  return bones;
}

/** Where calcified plaques sit: a branch, a fraction of its length and the side of the wall (angle, degrees). */
struct PlaqueDefinition
{
  int    vesselIndex;
  bool   left;
  double fraction;
  double angle;
};

const std::vector<PlaqueDefinition> &
PlaqueDefinitions()
{
  static const std::vector<PlaqueDefinition> plaques = {
    { 0, true, 0.70, 200 }, { 0, true, 0.88, 30 },   { 1, false, 0.5, 90 },  { 1, true, 0.8, 250 },
    { 3, true, 0.55, 120 }, { 3, true, 0.60, 300 },  { 3, false, 0.72, 60 }, { 3, false, 0.9, 180 },
    { 5, true, 0.45, 90 },  { 6, false, 0.35, 270 },
  };
  return plaques;
}

/** Uniform Catmull-Rom through the control points (ends repeated), sampled about every 2 mm. */
CenterlineBranch
SampleBranch(int id, const std::vector<ControlPoint> & controls, double side, double scale)
{
  std::vector<PointType> knots;
  std::vector<double>    radii;
  for (const auto & c : controls)
  {
    const double y = c.inLegFrame ? LegVesselY(side, c.x, c.z, c.y) : c.y;
    knots.push_back(detail::MakePhantomPoint(side * c.x * scale, y * scale, c.z * scale));
    radii.push_back(c.radius * scale);
  }
  return detail::SampleCatmullRomBranch(id, knots, radii, 2.0 * scale);
}

double
Interpolate(const std::vector<std::array<double, 3>> & table, double z, int column)
{
  if (z >= table.front()[0])
  {
    return table.front()[column];
  }
  for (std::size_t k = 1; k < table.size(); ++k)
  {
    if (z >= table[k][0])
    {
      const double f = (z - table[k - 1][0]) / (table[k][0] - table[k - 1][0]);
      return table[k - 1][column] + f * (table[k][column] - table[k - 1][column]);
    }
  }
  return table.back()[column];
}

/** Body outline at height z (scale 1): the trunk ellipse above the thighs, two leg ellipses below. */
struct BodySection
{
  bool   hasTrunk;
  double trunkHalfWidth, trunkHalfDepth;
  bool   hasLegs;
  double legCenter, legRadius;
};

BodySection
BodyAt(double z)
{
  // z, half width, half depth of the trunk.
  static const std::vector<std::array<double, 3>> trunk = {
    { 10, 140, 100 }, { -150, 150, 102 }, { -260, 168, 106 }, { -330, 172, 106 }
  };
  // z, leg centre |x|, leg radius.
  static const std::vector<std::array<double, 3>> legs = { { -290, 90, 78 }, { -340, 90, 80 }, { -450, 89, 74 },
                                                           { -600, 84, 58 }, { -650, 82, 55 }, { -720, 81, 57 },
                                                           { -850, 79, 45 }, { -980, 77, 33 }, { -1010, 77, 30 } };
  BodySection                                     section{};
  section.hasTrunk = z > -330.0;
  section.trunkHalfWidth = Interpolate(trunk, z, 1);
  section.trunkHalfDepth = Interpolate(trunk, z, 2);
  section.hasLegs = z < -290.0 && z > -1005.0;
  section.legCenter = Interpolate(legs, z, 1);
  section.legRadius = Interpolate(legs, z, 2);
  return section;
}

double
LegCenterX(double z)
{
  return BodyAt(z).legCenter;
}

double
LegVesselPlaneY(double z)
{
  static const std::vector<std::array<double, 3>> plane = { { -300, -14, 0 }, { -340, -16, 0 }, { -450, -10, 0 },
                                                            { -560, 8, 0 },   { -600, 36, 0 },  { -640, 48, 0 },
                                                            { -690, 44, 0 },  { -760, 32, 0 },  { -860, 24, 0 },
                                                            { -980, 16, 0 } };
  return Interpolate(plane, z, 1);
}

/** Distance (mm) from (x, y) to the nearest of \a count intermuscular fat planes radiating from (cx, cy),
 * whose angles wander slowly with height so that they cut the reformation surface at visible lines. */
double
DistanceToSepta(double x, double y, double z, double cx, double cy, int count, double phase)
{
  const double radius = std::hypot(x - cx, y - cy);
  const double angle = std::atan2(y - cy, x - cx);
  double       nearest = std::numeric_limits<double>::infinity();
  for (int k = 0; k < count; ++k)
  {
    const double septum = phase + k * 2.0 * Math::pi / count + 0.35 * std::sin(z / 70.0 + 1.7 * k);
    const double difference = std::remainder(angle - septum, 2.0 * Math::pi);
    nearest = std::min(nearest, radius * std::abs(std::sin(std::min(std::abs(difference), 0.5 * Math::pi))));
  }
  return nearest;
}

/** Soft tissue at (x, y, z) of a body section (scale 1): air, subcutaneous fat, or muscle with fat septa and
 * a gentle texture, as a CT shows it. */
float
SoftTissue(const BodySection & body, double x, double y, double z)
{
  double depthInside = -1.0; // mm from the skin, negative outside
  double septa = std::numeric_limits<double>::infinity();
  if (body.hasTrunk)
  {
    const double q = std::hypot(x / body.trunkHalfWidth, (y - 8.0) / body.trunkHalfDepth);
    depthInside = std::max(depthInside, (1.0 - q) * std::min(body.trunkHalfWidth, body.trunkHalfDepth));
    septa = DistanceToSepta(x, y, z, 0.0, 30.0, 9, 0.2);
  }
  if (body.hasLegs)
  {
    for (const double side : { -1.0, 1.0 })
    {
      const double cx = side * body.legCenter;
      const double q = std::hypot((x - cx) / body.legRadius, (y - 6.0) / (0.95 * body.legRadius));
      const double inside = (1.0 - q) * 0.95 * body.legRadius;
      if (inside > depthInside)
      {
        depthInside = inside;
        septa = DistanceToSepta(x, y, z, cx + side * 8.0, 14.0, 7, side > 0 ? 0.4 : Math::pi - 0.4);
      }
    }
  }
  if (depthInside < 0.0)
  {
    return AirHU;
  }
  const double fatThickness = (body.hasTrunk ? 14.0 : 9.0) + 3.0 * std::sin(z / 45.0 + x / 60.0);
  if (depthInside < fatThickness)
  {
    return FatHU;
  }
  const double texture = 10.0 * std::sin(x / 7.0 + 1.3 * std::sin(z / 23.0)) * std::sin(y / 9.0 + z / 31.0);
  const double septumWeight = std::min(1.0, std::max(0.0, 1.5 - septa)); // about 2 mm thick fat planes
  return static_cast<float>((MuscleHU + texture) * (1.0 - septumWeight) + (FatHU + 20.0) * septumWeight);
}

detail::PhantomLayers
BuildGeometry(const CenterlineTree & tree, double scale)
{
  detail::PhantomLayers geometry;
  geometry.CorticalBoneHU = CorticalBoneHU;
  geometry.CalcificationHU = CalcificationHU;
  geometry.AirHU = AirHU;
  for (const auto & branch : tree.GetBranches())
  {
    for (std::size_t p = 0; p + 1 < branch.Points.size(); ++p)
    {
      geometry.Vessels.push_back(
        MakeCapsule(branch.Points[p], branch.Points[p + 1], branch.Radii[p], branch.Radii[p + 1], 0.0, 0.0, 0.0f));
      // Contrast fades distally: about 390 HU in the aorta, 310 HU at the ankle.
      const double height = 0.5 * (branch.Points[p][2] + branch.Points[p + 1][2]) / scale;
      geometry.VesselHU.push_back(static_cast<float>(390.0 + 0.08 * std::max(-1000.0, std::min(0.0, height))));
    }
  }
  for (const auto & bone : BoneDefinitions())
  {
    for (const double side : { -1.0, 1.0 })
    {
      if (bone.midline && side < 0.0)
      {
        continue;
      }
      const PointType a = detail::MakePhantomPoint(side * bone.a[0] * scale, bone.a[1] * scale, bone.a[2] * scale);
      const PointType b = detail::MakePhantomPoint(side * bone.b[0] * scale, bone.b[1] * scale, bone.b[2] * scale);
      geometry.Bones.push_back(MakeCapsule(a,
                                           b,
                                           bone.outerRadius * scale,
                                           bone.outerRadius * scale,
                                           bone.innerRadius * scale,
                                           bone.innerRadius * scale,
                                           bone.innerHU));
    }
  }
  const auto & definitions = VesselDefinitions();
  for (const auto & plaque : PlaqueDefinitions())
  {
    const auto &             definition = definitions[plaque.vesselIndex];
    const int                id = plaque.left ? definition.leftId : definition.rightId;
    const CenterlineBranch * branch = nullptr;
    for (const auto & candidate : tree.GetBranches())
    {
      branch = candidate.Id == id ? &candidate : branch;
    }
    const std::size_t n = branch->Points.size();
    const std::size_t p = std::min(n - 2, static_cast<std::size_t>(plaque.fraction * (n - 1)));
    Vector<double, 3> tangent = branch->Points[p + 1] - branch->Points[p];
    tangent.Normalize();
    Vector<double, 3> across = CrossProduct(tangent, detail::MakeVector3(0.0, 0.0, 1.0));
    if (across.GetNorm() < 1e-3)
    {
      across = detail::MakeVector3(1.0, 0.0, 0.0);
    }
    across.Normalize();
    const Vector<double, 3> other = CrossProduct(tangent, across);
    const double            angle = plaque.angle * Math::pi / 180.0;
    const double            radius = branch->Radii[p];
    const PointType center = branch->Points[p] + (across * std::cos(angle) + other * std::sin(angle)) * (0.9 * radius);
    const double    plaqueRadius = std::max(1.2 * scale, 0.45 * radius);
    geometry.Calcifications.push_back(MakeCapsule(center, center, plaqueRadius, plaqueRadius, 0.0, 0.0, 0.0f));
  }
  return geometry;
}
} // namespace

RunoffPhantomImageSource::RunoffPhantomImageSource()
{
  this->SetNumberOfRequiredInputs(0);
}

CenterlineTree
RunoffPhantomImageSource::GetCenterlineTree() const
{
  CenterlineTree tree;
  for (const auto & definition : VesselDefinitions())
  {
    if (definition.rightId == definition.leftId)
    {
      tree.AddBranch(SampleBranch(definition.leftId, definition.controls, 1.0, m_Scale));
      continue;
    }
    tree.AddBranch(SampleBranch(definition.rightId, definition.controls, -1.0, m_Scale));
    tree.AddBranch(SampleBranch(definition.leftId, definition.controls, 1.0, m_Scale));
  }
  // The names travel with the branches, so that any later renumbering of ids keeps each vessel's name.
  for (auto & branch : tree.GetBranches())
  {
    branch.Name = GetBranchName(branch.Id);
  }
  return tree;
}

std::string
RunoffPhantomImageSource::GetBranchName(int id)
{
  for (const auto & definition : VesselDefinitions())
  {
    if (definition.rightId == definition.leftId && id == definition.leftId)
    {
      return definition.name;
    }
    if (id == definition.rightId)
    {
      return std::string("right ") + definition.name;
    }
    if (id == definition.leftId)
    {
      return std::string("left ") + definition.name;
    }
  }
  return "unknown";
}

void
RunoffPhantomImageSource::VerifyPreconditions() ITKv5_CONST
{
  if (!(std::isfinite(m_Spacing) && m_Spacing > 0.0))
  {
    itkExceptionMacro(<< "Spacing = " << m_Spacing << " mm is invalid: it must be finite and > 0");
  }
  if (!(std::isfinite(m_Scale) && m_Scale > 0.0))
  {
    itkExceptionMacro(<< "Scale = " << m_Scale << " is invalid: it must be finite and > 0");
  }
  if (!(std::isfinite(m_NoiseStandardDeviation) && m_NoiseStandardDeviation >= 0.0))
  {
    itkExceptionMacro(<< "NoiseStandardDeviation = " << m_NoiseStandardDeviation
                      << " HU is invalid: it must be finite and >= 0");
  }
  const double voxels = (2.0 * HalfWidthOfFieldOfView / m_Spacing) *
                        ((PosteriorEdgeOfFieldOfView - AnteriorEdgeOfFieldOfView) / m_Spacing) *
                        ((TopOfFieldOfView - BottomOfFieldOfView) / m_Spacing) * m_Scale * m_Scale * m_Scale;
  if (voxels > 2.0e9)
  {
    itkExceptionMacro(<< "Spacing = " << m_Spacing << " mm at Scale = " << m_Scale << " would need " << voxels
                      << " voxels; choose a coarser spacing");
  }
}

void
RunoffPhantomImageSource::GenerateOutputInformation()
{
  ImageType *            output = this->GetOutput();
  ImageType::SizeType    size;
  ImageType::PointType   origin;
  ImageType::SpacingType spacing;
  const double           low[3] = { -HalfWidthOfFieldOfView, AnteriorEdgeOfFieldOfView, BottomOfFieldOfView };
  const double           high[3] = { HalfWidthOfFieldOfView, PosteriorEdgeOfFieldOfView, TopOfFieldOfView };
  for (unsigned int axis = 0; axis < 3; ++axis)
  {
    size[axis] = static_cast<SizeValueType>(std::ceil((high[axis] - low[axis]) * m_Scale / m_Spacing));
    origin[axis] = low[axis] * m_Scale + 0.5 * m_Spacing;
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
RunoffPhantomImageSource::DynamicThreadedGenerateData(const OutputImageRegionType & region)
{
  // Cheap to rebuild per work unit, and it keeps the source free of mutable caches.
  const CenterlineTree        tree = this->GetCenterlineTree();
  const detail::PhantomLayers layers = BuildGeometry(tree, m_Scale);
  const double                scale = m_Scale;
  auto                        tissueAtHeight = [scale](double z)
  {
    const BodySection body = BodyAt(z / scale);
    return [body, z, scale](double x, double y) { return SoftTissue(body, x / scale, y / scale, z / scale); };
  };
  detail::RenderPhantomRegion(this->GetOutput(), region, layers, tissueAtHeight, m_NoiseStandardDeviation, m_Seed);
}

void
RunoffPhantomImageSource::PrintSelf(std::ostream & os, Indent indent) const
{
  Superclass::PrintSelf(os, indent);
  os << indent << "Spacing (mm): " << m_Spacing << std::endl;
  os << indent << "Scale: " << m_Scale << std::endl;
  os << indent << "NoiseStandardDeviation (HU): " << m_NoiseStandardDeviation << std::endl;
  os << indent << "Seed: " << m_Seed << std::endl;
}

} // namespace itk
