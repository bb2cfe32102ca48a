// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef itkCPRViewGeometry_h
#define itkCPRViewGeometry_h

#include "itkCenterlineTree.h"
#include "itkImage.h"
#include "itkMetaDataDictionary.h"
#include "itkPoint.h"
#include "itkSize.h"
#include "itkVector.h"

namespace itk
{

/** \class CPRViewSpecification
 * \brief What a user asks of a view (docs/design.md "View"); unset parts take defaults from the centerline tree
 * and the volume when CPRViewGeometry::Resolve() completes it.
 * \ingroup VesselReformation
 */
struct CPRViewSpecification
{
  using PointType = Point<double, 3>;
  using VectorType = Vector<double, 3>;

  /** Every member at its default (below). */
  CPRViewSpecification();

  /** The rotation axis, in LPS; default patient superior, (0, 0, 1). Ignored when AutomaticUp is on. */
  VectorType Up;
  /** Take the volume axis along which the tree extends most as the rotation axis (real scans are not always
   * stored head-up). Its sign points from the tree's centre towards its root (the first point of the first
   * branch). Needs a reference volume. */
  bool AutomaticUp{ false };
  /** Rotation angle theta about Up, in degrees (right-hand rule). */
  double AngleInDegrees{ 0.0 };
  /** View centre C (LPS mm); default the centre of the tree's bounding box. */
  bool      HasCenter{ false };
  PointType Center{};
  /** Image size W x H in pixels; 0 takes the default. */
  Size<2> ImageSize{ { 0, 0 } };
  /** Pixel spacing sx, sy in mm; 0 takes the default. */
  Vector<double, 2> PixelSpacing;
  /** Margin around the projected tree in the default image extent, in mm on each side. */
  double MarginInMillimetres{ 10.0 };

  /** Chooses the rotation axis for AutomaticUp: the direction column of \a volume along which \a tree extends
   * most, signed towards the tree's root. */
  static VectorType
  AutomaticUpAxis(const CenterlineTree & tree, const ImageBase<3> & volume);

  /** Every member equal (with AutomaticUp, Up is ignored; without HasCenter, Center is). */
  bool
  operator==(const CPRViewSpecification & other) const;
  bool
  operator!=(const CPRViewSpecification & other) const
  {
    return !(*this == other);
  }
};

/** \class CPRViewGeometry
 * \brief A complete, resolved view of a multipath CPR (docs/design.md "View").
 *
 * Screen-right u, view direction v and the rotation axis up form a right-handed frame with u = v x up. At
 * theta = 0 and up = superior the view looks from anterior to posterior: v = LPS (0, 1, 0), u = LPS (1, 0, 0).
 * Pixel (i, j) lies on the plane at B(i, j) = C + (i - (W-1)/2) sx u - (j - (H-1)/2) sy up, and a depth d
 * along v names the point X = B(i, j) + d v.
 *
 * Every 2D output carries the view in its MetaDataDictionary (as strings, so NRRD keeps them) and has spacing
 * (sx, sy), identity direction and origin (-(W-1)/2 sx, -(H-1)/2 sy): its physical coordinates are screen
 * millimetres from C, right and down.
 *
 * \sa CPRDepthImageFilter, CPRResampleImageFilter
 * \ingroup VesselReformation
 */
class CPRViewGeometry
{
public:
  using PointType = Point<double, 3>;
  using VectorType = Vector<double, 3>;
  using SizeType = Size<2>;
  using SpacingType = Vector<double, 2>;

  /** Continuous view coordinates of a world point: column i, row j (pixel units) and depth d (mm). */
  struct ViewCoordinates
  {
    double Column;
    double Row;
    double Depth;
  };

  /** The default view: up superior, theta = 0, centre at the origin, one pixel of 1 mm. */
  CPRViewGeometry();
  /** A view from explicit values; throws itk::ExceptionObject naming the bad value (zero or non-finite up,
   * non-finite angle or centre, zero size, spacing not > 0). */
  /** The most pixels per side Resolve() computes from a tree and a spacing (2^31 - 1). */
  static constexpr double MaximumPixelsPerSide = 2147483647.0;

  CPRViewGeometry(const VectorType &  up,
                  double              angleInDegrees,
                  const PointType &   center,
                  const SizeType &    size,
                  const SpacingType & spacing);

  /** Completes \a specification: centre, size and spacing default from \a tree (and \a volume, may be null)
   * so that the tree fits at every angle about up, at the volume's smallest spacing (1 mm without a volume).
   * Throws when the specification is invalid, the tree is empty, or the size it computes would exceed
   * MaximumPixelsPerSide (checked before any conversion to an integer). */
  static CPRViewGeometry
  Resolve(const CPRViewSpecification & specification, const CenterlineTree & tree, const ImageBase<3> * volume);

  const VectorType &
  GetUp() const
  {
    return m_Up;
  }
  const VectorType &
  GetU() const
  {
    return m_U;
  }
  const VectorType &
  GetV() const
  {
    return m_V;
  }
  double
  GetAngleInDegrees() const
  {
    return m_AngleInDegrees;
  }
  const PointType &
  GetCenter() const
  {
    return m_Center;
  }
  const SizeType &
  GetSize() const
  {
    return m_Size;
  }
  const SpacingType &
  GetSpacing() const
  {
    return m_Spacing;
  }

  /** B(i, j): the point of pixel (i, j) on the plane through C. */
  PointType
  PlanePoint(double column, double row) const;
  /** X = B(i, j) + d v. */
  PointType
  SurfacePoint(double column, double row, double depth) const;
  /** The inverse of SurfacePoint. */
  ViewCoordinates
  ToView(const PointType & point) const;

  /** Physical origin and spacing of the 2D images on this view (see the class comment). */
  Point<double, 2>
  GetImageOrigin() const;

  /** Sets the largest possible, buffered and requested regions, spacing, origin, identity direction and the view
   * metadata of a 2D image (an image made outside a pipeline, about to be allocated). */
  template<typename TImage>
  void
  ConfigureImage(TImage * image) const
  {
    ConfigureImageInformation(image);
    image->SetRegions(image->GetLargestPossibleRegion());
  }

  /** Sets the largest possible region, spacing, origin, identity direction and the view metadata of a 2D image,
   * leaving its requested region alone: what a filter's GenerateOutputInformation() does. */
  template<typename TImage>
  void
  ConfigureImageInformation(TImage * image) const
  {
    typename TImage::RegionType region;
    region.SetSize(m_Size);
    image->SetLargestPossibleRegion(region);
    image->SetSpacing(m_Spacing);
    image->SetOrigin(GetImageOrigin());
    typename TImage::DirectionType direction;
    direction.SetIdentity();
    image->SetDirection(direction);
    WriteToDictionary(image->GetMetaDataDictionary());
  }

  /** Stores C, u, v, up, theta, size and spacing as "CPR_*" string entries (LPS). */
  void
  WriteToDictionary(MetaDataDictionary & dictionary) const;
  /** True when \a dictionary holds every entry WriteToDictionary writes. */
  static bool
  DictionaryHasView(const MetaDataDictionary & dictionary);
  /** Reads a view back; throws naming the missing or malformed entry. */
  static CPRViewGeometry
  ReadFromDictionary(const MetaDataDictionary & dictionary);

  bool
  operator==(const CPRViewGeometry & other) const;
  bool
  operator!=(const CPRViewGeometry & other) const
  {
    return !(*this == other);
  }

  void
  Print(std::ostream & os, Indent indent) const;

private:
  VectorType  m_Up;
  VectorType  m_U;
  VectorType  m_V;
  double      m_AngleInDegrees{ 0.0 };
  PointType   m_Center{};
  SizeType    m_Size{ { 1, 1 } };
  SpacingType m_Spacing;
};

std::ostream &
operator<<(std::ostream & os, const CPRViewGeometry & view);

} // namespace itk

#endif
