// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef itkPhantomRendering_h
#define itkPhantomRendering_h

#include "itkCenterlineTree.h"
#include "itkImage.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

/** What the built-in synthetic CTAs share (internal, not installed): smooth vessel courses through control points,
 * capsules (tapered cylinders with round ends) drawn with partial volume, reproducible noise, and the compositing
 * of bone, vessels and calcifications over a phantom's own soft tissue, slice by slice. */
namespace itk::detail
{
using PhantomPoint = Point<double, 3>;
using PhantomImage = Image<float, 3>;

inline PhantomPoint
MakePhantomPoint(double x, double y, double z)
{
  PhantomPoint p;
  p[0] = x;
  p[1] = y;
  p[2] = z;
  return p;
}

/** A branch through \a knots (mm) by uniform Catmull-Rom splines (ends repeated), a point about every \a step mm, with
 * radii interpolated linearly between the knots' \a radii. */
CenterlineBranch
SampleCatmullRomBranch(int id, const std::vector<PhantomPoint> & knots, const std::vector<double> & radii, double step);

/** A capsule from a to b whose outer and inner radii vary linearly from a to b; innerHU fills the inner part (bone:
 * marrow or cancellous bone). zMin and zMax bound it along z. */
struct Capsule
{
  PhantomPoint a, b;
  double       outerA, outerB;
  double       innerA, innerB;
  float        innerHU;
  double       zMin, zMax;
};

Capsule
MakeCapsule(const PhantomPoint & a,
            const PhantomPoint & b,
            double               outerA,
            double               outerB,
            double               innerA,
            double               innerB,
            float                innerHU);

/** Distance from p to segment ab and the segment parameter \a t of the nearest point. */
double
DistanceToSegment(const PhantomPoint & p, const PhantomPoint & a, const PhantomPoint & b, double & t);

/** Fraction of a voxel of size h inside a surface at signed distance (distance - radius): partial volume. */
inline double
Coverage(double distance, double radius, double h)
{
  return std::min(1.0, std::max(0.0, 0.5 - (distance - radius) / h));
}

/** A reproducible, roughly Gaussian number of unit variance (sum of three uniforms) from a voxel index and a seed. */
double
NoiseSample(std::uint64_t i, std::uint64_t j, std::uint64_t k, std::uint64_t seed);

/** The layers drawn over a phantom's soft tissue, in this order: bone (cortical shell over its inner HU), vessels
 * (each capsule with its HU), calcifications. */
struct PhantomLayers
{
  std::vector<Capsule> Bones;
  std::vector<Capsule> Vessels;
  std::vector<float>   VesselHU;
  std::vector<Capsule> Calcifications;
  float                CorticalBoneHU{ 1200.0f };
  float                CalcificationHU{ 1000.0f };
  /** Voxels at or below this value (air) get no noise. */
  float AirHU{ -1000.0f };
};

/** Draws \a region of \a output: for each slice z, \a tissueAtHeight(z) gives a callable (x, y) -> HU of the soft
 * tissue, over which the layers are composited with partial volume; then noise of \a noiseSigma HU. */
template<typename TTissueAtHeight>
void
RenderPhantomRegion(PhantomImage *                   output,
                    const PhantomImage::RegionType & region,
                    const PhantomLayers &            layers,
                    const TTissueAtHeight &          tissueAtHeight,
                    double                           noiseSigma,
                    unsigned int                     seed)
{
  const double h = output->GetSpacing()[0];
  const auto   start = region.GetIndex();
  const auto   size = region.GetSize();
  const long   width = static_cast<long>(size[0]);
  const long   height = static_cast<long>(size[1]);
  PhantomPoint corner;
  output->TransformIndexToPhysicalPoint(start, corner);

  std::vector<float>  slice(static_cast<std::size_t>(width * height));
  std::vector<double> boneOuter(slice.size());
  std::vector<double> boneInner(slice.size());
  std::vector<float>  marrowHU(slice.size());
  std::vector<double> vesselCoverage(slice.size());
  std::vector<float>  vesselValue(slice.size());
  std::vector<double> calcificationCoverage(slice.size());

  // Loops over the voxels of this slice within reach of a capsule.
  auto forEachVoxelNear = [&](const Capsule & capsule, double z, auto && visit)
  {
    const double reach = std::max(capsule.outerA, capsule.outerB) + h;
    const double xLow = std::min(capsule.a[0], capsule.b[0]) - reach;
    const double xHigh = std::max(capsule.a[0], capsule.b[0]) + reach;
    const double yLow = std::min(capsule.a[1], capsule.b[1]) - reach;
    const double yHigh = std::max(capsule.a[1], capsule.b[1]) + reach;
    const long   i0 = std::max(0L, static_cast<long>(std::floor((xLow - corner[0]) / h)));
    const long   i1 = std::min(width - 1, static_cast<long>(std::ceil((xHigh - corner[0]) / h)));
    const long   j0 = std::max(0L, static_cast<long>(std::floor((yLow - corner[1]) / h)));
    const long   j1 = std::min(height - 1, static_cast<long>(std::ceil((yHigh - corner[1]) / h)));
    for (long j = j0; j <= j1; ++j)
    {
      for (long i = i0; i <= i1; ++i)
      {
        const PhantomPoint p = MakePhantomPoint(corner[0] + i * h, corner[1] + j * h, z);
        double             t = 0.0;
        const double       distance = DistanceToSegment(p, capsule.a, capsule.b, t);
        visit(static_cast<std::size_t>(j * width + i), distance, t);
      }
    }
  };

  for (SizeValueType k = 0; k < size[2]; ++k)
  {
    const double z = corner[2] + k * h;
    const auto   tissue = tissueAtHeight(z);
    for (long j = 0; j < height; ++j)
    {
      for (long i = 0; i < width; ++i)
      {
        slice[j * width + i] = tissue(corner[0] + i * h, corner[1] + j * h);
      }
    }
    std::fill(boneOuter.begin(), boneOuter.end(), 0.0);
    std::fill(boneInner.begin(), boneInner.end(), 0.0);
    std::fill(vesselCoverage.begin(), vesselCoverage.end(), 0.0);
    std::fill(calcificationCoverage.begin(), calcificationCoverage.end(), 0.0);

    for (const auto & bone : layers.Bones)
    {
      if (z < bone.zMin - h || z > bone.zMax + h)
      {
        continue;
      }
      forEachVoxelNear(bone,
                       z,
                       [&](std::size_t v, double distance, double t)
                       {
                         const double outer = Coverage(distance, bone.outerA + t * (bone.outerB - bone.outerA), h);
                         const double inner = Coverage(distance, bone.innerA + t * (bone.innerB - bone.innerA), h);
                         boneOuter[v] = std::max(boneOuter[v], outer);
                         if (inner > boneInner[v])
                         {
                           boneInner[v] = inner;
                           marrowHU[v] = bone.innerHU;
                         }
                       });
    }
    for (std::size_t c = 0; c < layers.Vessels.size(); ++c)
    {
      const Capsule & vessel = layers.Vessels[c];
      if (z < vessel.zMin - h || z > vessel.zMax + h)
      {
        continue;
      }
      forEachVoxelNear(vessel,
                       z,
                       [&](std::size_t v, double distance, double t)
                       {
                         const double coverage =
                           Coverage(distance, vessel.outerA + t * (vessel.outerB - vessel.outerA), h);
                         if (coverage > vesselCoverage[v])
                         {
                           vesselCoverage[v] = coverage;
                           vesselValue[v] = layers.VesselHU[c];
                         }
                       });
    }
    for (const auto & calcification : layers.Calcifications)
    {
      if (z < calcification.zMin - h || z > calcification.zMax + h)
      {
        continue;
      }
      forEachVoxelNear(calcification,
                       z,
                       [&](std::size_t v, double distance, double) {
                         calcificationCoverage[v] =
                           std::max(calcificationCoverage[v], Coverage(distance, calcification.outerA, h));
                       });
    }

    for (long j = 0; j < height; ++j)
    {
      for (long i = 0; i < width; ++i)
      {
        const std::size_t v = static_cast<std::size_t>(j * width + i);
        double            value = slice[v];
        value = value * (1.0 - boneOuter[v]) + layers.CorticalBoneHU * (boneOuter[v] - boneInner[v]) +
                (boneInner[v] > 0.0 ? marrowHU[v] * boneInner[v] : 0.0);
        value = value * (1.0 - vesselCoverage[v]) + vesselValue[v] * vesselCoverage[v];
        value = value * (1.0 - calcificationCoverage[v]) + layers.CalcificationHU * calcificationCoverage[v];
        if (value > layers.AirHU + 1.0 && noiseSigma > 0.0)
        {
          value += noiseSigma * NoiseSample(static_cast<std::uint64_t>(start[0] + i),
                                            static_cast<std::uint64_t>(start[1] + j),
                                            static_cast<std::uint64_t>(start[2] + k),
                                            seed);
        }
        PhantomImage::IndexType index = { { start[0] + i, start[1] + j, start[2] + static_cast<IndexValueType>(k) } };
        output->SetPixel(index, static_cast<float>(value));
      }
    }
  }
}
} // namespace itk::detail

#endif
