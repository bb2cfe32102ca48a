// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "itkCPRViewGeometry.h"

#include "itkCPRVectorHelpers.h"
#include "itkMacro.h"
#include "itkMetaDataObject.h"

#include <cmath>
#include <iomanip>
#include <sstream>

namespace itk
{
namespace
{
using detail::MakeVector2;
using detail::MakeVector3;
using VectorType = CPRViewGeometry::VectorType;

const char * const KeyCenter = "CPR_Center";
const char * const KeyU = "CPR_U";
const char * const KeyV = "CPR_V";
const char * const KeyUp = "CPR_Up";
const char * const KeyAngle = "CPR_AngleDegrees";
const char * const KeySize = "CPR_Size";
const char * const KeySpacing = "CPR_Spacing";
const char * const KeyFrame = "CPR_Frame";

bool
IsFinite(const VectorType & vector)
{
  return std::isfinite(vector[0]) && std::isfinite(vector[1]) && std::isfinite(vector[2]);
}

VectorType
Cross(const VectorType & a, const VectorType & b)
{
  return MakeVector3(a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]);
}

template<typename TArray>
std::string
JoinNumbers(const TArray & values, unsigned int count)
{
  std::ostringstream stream;
  stream << std::setprecision(17);
  for (unsigned int k = 0; k < count; ++k)
  {
    stream << (k ? " " : "") << values[k];
  }
  return stream.str();
}

std::vector<double>
ReadNumbers(const MetaDataDictionary & dictionary, const char * key, unsigned int count)
{
  std::string text;
  if (!ExposeMetaData<std::string>(dictionary, key, text))
  {
    itkGenericExceptionMacro(<< "CPRViewGeometry: the image metadata has no entry " << key);
  }
  std::istringstream  stream(text);
  std::vector<double> values;
  double              value = 0.0;
  while (stream >> value)
  {
    values.push_back(value);
  }
  if (values.size() != count || !stream.eof())
  {
    itkGenericExceptionMacro(<< "CPRViewGeometry: metadata entry " << key << " = \"" << text << "\" is not " << count
                             << " numbers");
  }
  return values;
}

/** The theta = 0 view direction for a given up: P made orthogonal to up, or I when up is within 10 degrees
 * of the P axis (docs/design.md "View"). */
VectorType
ZeroAngleViewDirection(const VectorType & up)
{
  const VectorType posterior = MakeVector3(0.0, 1.0, 0.0);
  const VectorType inferior = MakeVector3(0.0, 0.0, -1.0);
  const double     cosineOfTenDegrees = std::cos(10.0 * Math::pi / 180.0);
  const VectorType reference = std::abs(up * posterior) >= cosineOfTenDegrees ? inferior : posterior;
  VectorType       direction = reference - (reference * up) * up;
  direction.Normalize();
  return direction;
}
} // namespace

CPRViewSpecification::CPRViewSpecification()
  : Up(MakeVector3(0.0, 0.0, 1.0))
  , PixelSpacing(MakeVector2(0.0, 0.0))
{
}

bool
CPRViewSpecification::operator==(const CPRViewSpecification & other) const
{
  return AutomaticUp == other.AutomaticUp && (AutomaticUp || Up == other.Up) &&
         AngleInDegrees == other.AngleInDegrees && HasCenter == other.HasCenter &&
         (!HasCenter || Center == other.Center) && ImageSize == other.ImageSize && PixelSpacing == other.PixelSpacing &&
         MarginInMillimetres == other.MarginInMillimetres;
}

CPRViewGeometry::CPRViewGeometry()
  : m_Up(MakeVector3(0.0, 0.0, 1.0))
  , m_U(MakeVector3(1.0, 0.0, 0.0))
  , m_V(MakeVector3(0.0, 1.0, 0.0))
  , m_Spacing(MakeVector2(1.0, 1.0))
{
}

CPRViewSpecification::VectorType
CPRViewSpecification::AutomaticUpAxis(const CenterlineTree & tree, const ImageBase<3> & volume)
{
  PointType minimum;
  PointType maximum;
  tree.GetBounds(minimum, maximum);
  const auto & direction = volume.GetDirection();
  unsigned int bestAxis = 0;
  double       bestExtent = -1.0;
  for (unsigned int axis = 0; axis < 3; ++axis)
  {
    const VectorType column = MakeVector3(direction[0][axis], direction[1][axis], direction[2][axis]);
    double           low = std::numeric_limits<double>::infinity();
    double           high = -low;
    for (const auto & branch : tree.GetBranches())
    {
      for (const auto & point : branch.Points)
      {
        const double coordinate = point.GetVectorFromOrigin() * column;
        low = std::min(low, coordinate);
        high = std::max(high, coordinate);
      }
    }
    if (high - low > bestExtent)
    {
      bestExtent = high - low;
      bestAxis = axis;
    }
  }
  VectorType up = MakeVector3(direction[0][bestAxis], direction[1][bestAxis], direction[2][bestAxis]);
  up.Normalize();
  const PointType  root = tree.GetBranches().front().Points.front();
  const VectorType towardsRoot = root - tree.GetBoundingBoxCenter();
  double           sign = towardsRoot * up;
  if (std::abs(sign) < 1e-9)
  {
    // The root sits at the centre: fall back to the axis's largest LPS component being positive.
    unsigned int largest = 0;
    for (unsigned int k = 1; k < 3; ++k)
    {
      largest = std::abs(up[k]) > std::abs(up[largest]) ? k : largest;
    }
    sign = up[largest];
  }
  return sign < 0.0 ? -up : up;
}

CPRViewGeometry::CPRViewGeometry(const VectorType &  up,
                                 double              angleInDegrees,
                                 const PointType &   center,
                                 const SizeType &    size,
                                 const SpacingType & spacing)
  : m_AngleInDegrees(angleInDegrees)
  , m_Center(center)
  , m_Size(size)
  , m_Spacing(spacing)
{
  if (!IsFinite(up) || up.GetNorm() < 1e-12)
  {
    itkGenericExceptionMacro(<< "CPRViewGeometry: up = " << up << " must be a finite, non-zero vector");
  }
  if (!std::isfinite(angleInDegrees))
  {
    itkGenericExceptionMacro(<< "CPRViewGeometry: angle = " << angleInDegrees << " degrees is not finite");
  }
  if (!IsFinite(center.GetVectorFromOrigin()))
  {
    itkGenericExceptionMacro(<< "CPRViewGeometry: center = " << center << " is not finite");
  }
  if (size[0] == 0 || size[1] == 0)
  {
    itkGenericExceptionMacro(<< "CPRViewGeometry: size = " << size[0] << "," << size[1]
                             << " pixels; both must be >= 1");
  }
  if (!(std::isfinite(spacing[0]) && spacing[0] > 0.0 && std::isfinite(spacing[1]) && spacing[1] > 0.0))
  {
    itkGenericExceptionMacro(<< "CPRViewGeometry: spacing = " << spacing[0] << "," << spacing[1]
                             << " mm; both must be finite and > 0");
  }
  m_Up = up;
  m_Up.Normalize();
  const VectorType v0 = ZeroAngleViewDirection(m_Up);
  const VectorType u0 = Cross(v0, m_Up);
  const double     theta = angleInDegrees * Math::pi / 180.0;
  const double     cosine = std::cos(theta);
  const double     sine = std::sin(theta);
  // Rodrigues' rotation about up of vectors orthogonal to it.
  m_V = v0 * cosine + Cross(m_Up, v0) * sine;
  m_U = u0 * cosine + Cross(m_Up, u0) * sine;
}

CPRViewGeometry
CPRViewGeometry::Resolve(const CPRViewSpecification & specification,
                         const CenterlineTree &       tree,
                         const ImageBase<3> *         volume)
{
  if (tree.IsEmpty())
  {
    itkGenericExceptionMacro(<< "CPRViewGeometry: the centerline tree is empty; a view needs at least one point");
  }
  VectorType up = specification.Up;
  if (specification.AutomaticUp)
  {
    if (volume == nullptr)
    {
      itkGenericExceptionMacro(<< "CPRViewGeometry: up = auto needs a volume to choose one of its axes");
    }
    up = CPRViewSpecification::AutomaticUpAxis(tree, *volume);
  }
  if (!IsFinite(up) || up.GetNorm() < 1e-12)
  {
    itkGenericExceptionMacro(<< "CPRViewGeometry: up = " << up << " must be a finite, non-zero vector");
  }
  up.Normalize();
  const double margin = specification.MarginInMillimetres;
  if (!(std::isfinite(margin) && margin >= 0.0))
  {
    itkGenericExceptionMacro(<< "CPRViewGeometry: margin = " << margin << " mm must be finite and >= 0");
  }
  for (unsigned int k = 0; k < 2; ++k)
  {
    const double s = specification.PixelSpacing[k];
    if (!(std::isfinite(s) && s >= 0.0))
    {
      itkGenericExceptionMacro(<< "CPRViewGeometry: spacing = " << specification.PixelSpacing[0] << ","
                               << specification.PixelSpacing[1] << " mm must be finite and > 0 (0 = default)");
    }
  }
  const PointType center = specification.HasCenter ? specification.Center : tree.GetBoundingBoxCenter();

  // Half extents that hold the tree at every angle: radial distance from the axis through C, and distance
  // along up, plus the largest lumen radius and the margin.
  double radial = 0.0;
  double axial = 0.0;
  double largestRadius = 0.0;
  for (const auto & branch : tree.GetBranches())
  {
    for (std::size_t p = 0; p < branch.Points.size(); ++p)
    {
      const VectorType offset = branch.Points[p] - center;
      const double     along = offset * up;
      axial = std::max(axial, std::abs(along));
      radial = std::max(radial, (offset - along * up).GetNorm());
      if (branch.HasRadii())
      {
        largestRadius = std::max(largestRadius, branch.Radii[p]);
      }
    }
  }
  const double halfWidth = radial + largestRadius + margin;
  const double halfHeight = axial + largestRadius + margin;

  SpacingType spacing = specification.PixelSpacing;
  const auto  width = specification.ImageSize[0];
  const auto  height = specification.ImageSize[1];
  if (spacing[0] == 0.0 || spacing[1] == 0.0)
  {
    double isotropic = std::max(spacing[0], spacing[1]);
    if (isotropic == 0.0)
    {
      if (width > 0 && height > 0)
      {
        isotropic = std::max(2.0 * halfWidth / width, 2.0 * halfHeight / height);
      }
      else if (width > 0)
      {
        isotropic = 2.0 * halfWidth / width;
      }
      else if (height > 0)
      {
        isotropic = 2.0 * halfHeight / height;
      }
      else if (volume != nullptr)
      {
        const auto & volumeSpacing = volume->GetSpacing();
        isotropic = std::min({ volumeSpacing[0], volumeSpacing[1], volumeSpacing[2] });
      }
      else
      {
        isotropic = 1.0;
      }
      if (!(isotropic > 0.0))
      {
        isotropic = 1.0; // a tree of a single point with no margin
      }
    }
    spacing.Fill(isotropic);
  }
  // Checked as doubles before any conversion: a tiny spacing or a huge tree asks for more pixels than any
  // integer holds.
  const double columns = std::ceil(2.0 * halfWidth / spacing[0]);
  const double rows = std::ceil(2.0 * halfHeight / spacing[1]);
  if ((width == 0 && !(columns <= MaximumPixelsPerSide)) || (height == 0 && !(rows <= MaximumPixelsPerSide)))
  {
    itkGenericExceptionMacro(<< "CPRViewGeometry: the tree spans " << 2.0 * halfWidth << " x " << 2.0 * halfHeight
                             << " mm; at a pixel spacing of " << spacing[0] << " x " << spacing[1] << " mm that is "
                             << columns << " x " << rows << " pixels, more than " << MaximumPixelsPerSide
                             << " per side: choose a larger spacing or an image size");
  }
  SizeType size;
  size[0] = width > 0 ? width : std::max<SizeValueType>(1, static_cast<SizeValueType>(columns));
  size[1] = height > 0 ? height : std::max<SizeValueType>(1, static_cast<SizeValueType>(rows));
  return CPRViewGeometry(up, specification.AngleInDegrees, center, size, spacing);
}

CPRViewGeometry::PointType
CPRViewGeometry::PlanePoint(double column, double row) const
{
  const double x = (column - 0.5 * (m_Size[0] - 1.0)) * m_Spacing[0];
  const double y = (row - 0.5 * (m_Size[1] - 1.0)) * m_Spacing[1];
  return m_Center + x * m_U - y * m_Up;
}

CPRViewGeometry::PointType
CPRViewGeometry::SurfacePoint(double column, double row, double depth) const
{
  return PlanePoint(column, row) + depth * m_V;
}

CPRViewGeometry::ViewCoordinates
CPRViewGeometry::ToView(const PointType & point) const
{
  const VectorType offset = point - m_Center;
  ViewCoordinates  coordinates;
  coordinates.Column = (offset * m_U) / m_Spacing[0] + 0.5 * (m_Size[0] - 1.0);
  coordinates.Row = -(offset * m_Up) / m_Spacing[1] + 0.5 * (m_Size[1] - 1.0);
  coordinates.Depth = offset * m_V;
  return coordinates;
}

Point<double, 2>
CPRViewGeometry::GetImageOrigin() const
{
  Point<double, 2> origin;
  origin[0] = -0.5 * (m_Size[0] - 1.0) * m_Spacing[0];
  origin[1] = -0.5 * (m_Size[1] - 1.0) * m_Spacing[1];
  return origin;
}

void
CPRViewGeometry::WriteToDictionary(MetaDataDictionary & dictionary) const
{
  EncapsulateMetaData<std::string>(dictionary, KeyCenter, JoinNumbers(m_Center, 3));
  EncapsulateMetaData<std::string>(dictionary, KeyU, JoinNumbers(m_U, 3));
  EncapsulateMetaData<std::string>(dictionary, KeyV, JoinNumbers(m_V, 3));
  EncapsulateMetaData<std::string>(dictionary, KeyUp, JoinNumbers(m_Up, 3));
  EncapsulateMetaData<std::string>(dictionary, KeyAngle, JoinNumbers(&m_AngleInDegrees, 1));
  EncapsulateMetaData<std::string>(dictionary, KeySize, JoinNumbers(m_Size, 2));
  EncapsulateMetaData<std::string>(dictionary, KeySpacing, JoinNumbers(m_Spacing, 2));
  EncapsulateMetaData<std::string>(dictionary, KeyFrame, "LPS");
}

bool
CPRViewGeometry::DictionaryHasView(const MetaDataDictionary & dictionary)
{
  for (const char * key : { KeyCenter, KeyUp, KeyAngle, KeySize, KeySpacing })
  {
    if (!dictionary.HasKey(key))
    {
      return false;
    }
  }
  return true;
}

CPRViewGeometry
CPRViewGeometry::ReadFromDictionary(const MetaDataDictionary & dictionary)
{
  std::string frame;
  if (ExposeMetaData<std::string>(dictionary, KeyFrame, frame) && frame != "LPS")
  {
    itkGenericExceptionMacro(<< "CPRViewGeometry: metadata entry " << KeyFrame << " = " << frame
                             << "; only LPS is written by this module");
  }
  const auto center = ReadNumbers(dictionary, KeyCenter, 3);
  const auto up = ReadNumbers(dictionary, KeyUp, 3);
  const auto angle = ReadNumbers(dictionary, KeyAngle, 1);
  const auto size = ReadNumbers(dictionary, KeySize, 2);
  const auto spacing = ReadNumbers(dictionary, KeySpacing, 2);
  for (const double s : size)
  {
    if (!(s >= 1.0 && s == std::floor(s)))
    {
      itkGenericExceptionMacro(<< "CPRViewGeometry: metadata entry " << KeySize << " holds " << s
                               << ", not a positive whole number");
    }
  }
  PointType   c;
  SizeType    imageSize;
  SpacingType pixelSpacing;
  for (unsigned int k = 0; k < 3; ++k)
  {
    c[k] = center[k];
  }
  for (unsigned int k = 0; k < 2; ++k)
  {
    imageSize[k] = static_cast<SizeValueType>(size[k]);
    pixelSpacing[k] = spacing[k];
  }
  CPRViewGeometry view(MakeVector3(up[0], up[1], up[2]), angle[0], c, imageSize, pixelSpacing);
  // Keep the stored frame bit for bit (re-normalising would move the last bits), once it agrees with the one
  // recomputed from up and the angle.
  const std::pair<const char *, VectorType *> stored[] = { { KeyUp, &view.m_Up },
                                                           { KeyU, &view.m_U },
                                                           { KeyV, &view.m_V } };
  for (const auto & [key, target] : stored)
  {
    if (!dictionary.HasKey(key))
    {
      continue;
    }
    const auto       values = ReadNumbers(dictionary, key, 3);
    const VectorType vector = MakeVector3(values[0], values[1], values[2]);
    if ((vector - *target).GetNorm() > 1e-9)
    {
      itkGenericExceptionMacro(<< "CPRViewGeometry: metadata entry " << key << " = " << vector
                               << " disagrees with the frame given by " << KeyUp << " and " << KeyAngle << " ("
                               << *target << ")");
    }
    *target = vector;
  }
  return view;
}

bool
CPRViewGeometry::operator==(const CPRViewGeometry & other) const
{
  return m_Up == other.m_Up && m_U == other.m_U && m_V == other.m_V && m_AngleInDegrees == other.m_AngleInDegrees &&
         m_Center == other.m_Center && m_Size == other.m_Size && m_Spacing == other.m_Spacing;
}

void
CPRViewGeometry::Print(std::ostream & os, Indent indent) const
{
  os << indent << "Center (LPS mm): " << m_Center << std::endl;
  os << indent << "Up: " << m_Up << std::endl;
  os << indent << "U (screen right): " << m_U << std::endl;
  os << indent << "V (view direction): " << m_V << std::endl;
  os << indent << "Angle (degrees): " << m_AngleInDegrees << std::endl;
  os << indent << "Size (pixels): " << m_Size << std::endl;
  os << indent << "Spacing (mm): " << m_Spacing << std::endl;
}

std::ostream &
operator<<(std::ostream & os, const CPRViewGeometry & view)
{
  view.Print(os, Indent(0));
  return os;
}

} // namespace itk
