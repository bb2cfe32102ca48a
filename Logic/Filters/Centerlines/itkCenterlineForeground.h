// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef itkCenterlineForeground_h
#define itkCenterlineForeground_h

#include "itkImage.h"

#include <array>
#include <cstdint>
#include <vector>

namespace itk
{
namespace detail
{
/** \class CenterlineForeground
 * \brief The foreground voxels of a mask as a compact list and their 26-neighbour graph, with the distance from
 * each to the nearest background voxel centre (mm).
 *
 * The distance is the exact Euclidean distance transform (the one itk::SignedMaurerDistanceMapImageFilter gives the
 * foreground when the background is its object; a test checks they agree), computed by the separable lower
 * envelope of parabolas (Felzenszwalb and Huttenlocher 2012) along only the lines of the buffer that cross the
 * foreground: background voxels are 0 and only the two that bound each run of foreground voxels can be nearest,
 * so the work grows with the foreground, not with the box around it (vessels fill about 1 % of their box).
 *
 * Built on a mask that has a background margin of at least one voxel on every side (so that every neighbour of a
 * foreground voxel lies inside the buffer), it holds three arrays over the foreground only and one over the
 * buffer (the compact index of each voxel): the extraction never walks the whole grid. Distances between voxels
 * are physical: steps are scaled by the spacing, and the direction cosines, being orthonormal, do not change them.
 * Internal to CenterlineExtractionFilter.
 *
 * \ingroup VesselReformation
 */
struct CenterlineForeground
{
  using MaskImageType = Image<unsigned char, 3>;
  using IndexType = MaskImageType::IndexType;

  /** Buffer offset of each foreground voxel, in buffer order. */
  std::vector<uint32_t> Offset;
  /** Per buffer voxel: its compact index, or -1 for background. */
  std::vector<int32_t> CompactIndex;
  /** Per foreground voxel: distance to the nearest background voxel centre, in mm. */
  std::vector<float> Distance;
  /** Buffer offsets and lengths (mm) of the 26 neighbour steps. */
  std::array<std::ptrdiff_t, 26> NeighbourOffset{};
  std::array<double, 26>         NeighbourStep{};
  /** The buffer's size and start index; the voxel spacing (mm). */
  std::array<SizeValueType, 3> BufferSize{};
  IndexType                    BufferStart{};
  std::array<double, 3>        Spacing{};

  std::size_t
  Size() const
  {
    return Offset.size();
  }
  /** The image index of a foreground voxel. */
  IndexType
  IndexOf(uint32_t voxel) const;
  /** Its position in mm in the image's index frame scaled by the spacing (not LPS: no origin, no direction). */
  std::array<double, 3>
  ScaledPosition(uint32_t voxel) const;
  /** The distance to the background, trilinearly interpolated at a position given like ScaledPosition's (mm); 0 on
   * background voxels and outside the buffer. */
  double
  InterpolatedDistance(const std::array<double, 3> & position) const;
  /** The physical distance (mm) between two foreground voxels. */
  double
  DistanceBetween(uint32_t a, uint32_t b) const;
  /** Calls \a visit(neighbour, stepLength) for each foreground 26-neighbour of \a voxel. */
  template<typename TVisit>
  void
  ForEachNeighbour(uint32_t voxel, TVisit && visit) const
  {
    const std::ptrdiff_t offset = Offset[voxel];
    for (unsigned int n = 0; n < 26; ++n)
    {
      const int32_t neighbour = CompactIndex[static_cast<std::size_t>(offset + NeighbourOffset[n])];
      if (neighbour >= 0)
      {
        visit(static_cast<uint32_t>(neighbour), NeighbourStep[n]);
      }
    }
  }
};

/** Builds the compact foreground of \a mask (non-zero voxels) and its distance to the background. Throws when a
 * foreground voxel touches the buffer's edge (the caller must pad) or the buffer has 2^31 voxels or more. */
CenterlineForeground
MakeCenterlineForeground(const CenterlineForeground::MaskImageType * mask);

/** The connected components (26-connectivity) of the foreground, largest first; each a list of compact indices. */
std::vector<std::vector<uint32_t>>
FindForegroundComponents(const CenterlineForeground & foreground);

} // namespace detail
} // namespace itk

#endif
