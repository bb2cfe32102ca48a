// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// CPRViewGeometry against docs/design.md "View", by hand.

#include "itkCPRVectorHelpers.h"
#include "itkCPRViewGeometry.h"
#include "itkMetaDataObject.h"

#include "vrTestImages.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace
{
using PointType = itk::Point<double, 3>;
using VectorType = itk::Vector<double, 3>;

using vr::test::P;

void
ExpectVectorNear(const VectorType & actual, double x, double y, double z)
{
  EXPECT_NEAR(actual[0], x, 1e-12) << actual;
  EXPECT_NEAR(actual[1], y, 1e-12) << actual;
  EXPECT_NEAR(actual[2], z, 1e-12) << actual;
}

itk::CPRViewGeometry
ViewAt(double angle, const VectorType & up = itk::detail::MakeVector3(0, 0, 1))
{
  itk::Size<2> size = { { 11, 7 } };
  return itk::CPRViewGeometry(up, angle, P(10, 20, 30), size, itk::detail::MakeVector2(0.5, 2.0));
}

itk::CenterlineTree
TwoPointTree(const PointType & a, const PointType & b)
{
  itk::CenterlineTree   tree;
  itk::CenterlineBranch branch;
  branch.Points = { a, b };
  branch.Radii = { 2.0, 1.0 };
  tree.AddBranch(branch);
  return tree;
}
} // namespace

TEST(CPRViewGeometry, ZeroAngleLooksFromAnteriorToPosterior)
{
  const auto view = ViewAt(0.0);
  ExpectVectorNear(view.GetV(), 0, 1, 0);
  ExpectVectorNear(view.GetU(), 1, 0, 0); // the patient's right on the screen's left
  ExpectVectorNear(view.GetUp(), 0, 0, 1);
}

TEST(CPRViewGeometry, AngleRotatesAboutUpByTheRightHandRule)
{
  // 90 degrees about +z turns v = +y into -x and u = +x into +y.
  const auto view = ViewAt(90.0);
  ExpectVectorNear(view.GetV(), -1, 0, 0);
  ExpectVectorNear(view.GetU(), 0, 1, 0);
  const auto oblique = ViewAt(30.0);
  ExpectVectorNear(oblique.GetV(), -0.5, std::sqrt(3.0) / 2.0, 0);
  ExpectVectorNear(oblique.GetU(), std::sqrt(3.0) / 2.0, 0.5, 0);
}

TEST(CPRViewGeometry, UIsVCrossUpForAnyUp)
{
  for (const VectorType & up :
       { itk::detail::MakeVector3(1, 2, 3), itk::detail::MakeVector3(-1, 0, 0.2), itk::detail::MakeVector3(0, 0, -1) })
  {
    for (const double angle : { 0.0, 37.0, -120.0 })
    {
      const auto   view = ViewAt(angle, up);
      const auto & v = view.GetV();
      const auto & w = view.GetUp();
      ExpectVectorNear(view.GetU(), v[1] * w[2] - v[2] * w[1], v[2] * w[0] - v[0] * w[2], v[0] * w[1] - v[1] * w[0]);
      EXPECT_NEAR(v * w, 0.0, 1e-12);
      EXPECT_NEAR(v.GetNorm(), 1.0, 1e-12);
    }
  }
}

TEST(CPRViewGeometry, ZeroAngleLooksAlongPosteriorMadeOrthogonalToUp)
{
  // up tilted in the y-z plane: v is P minus its component along up, normalised.
  const auto view = ViewAt(0.0, itk::detail::MakeVector3(0, 1, 1));
  ExpectVectorNear(view.GetV(), 0, std::sqrt(0.5), -std::sqrt(0.5));
}

TEST(CPRViewGeometry, UpNearThePosteriorAxisLooksAlongInferior)
{
  // docs/design.md "View": theta = 0 looks along P made orthogonal to up, or along I when up is within 10 degrees of
  // the P axis. The two rules give different directions for an up with an x component, so both are checked.
  auto orthogonalTo = [](const VectorType & axis, VectorType up)
  {
    up.Normalize();
    VectorType direction = axis - (axis * up) * up;
    direction.Normalize();
    return direction;
  };
  const VectorType posterior = itk::detail::MakeVector3(0, 1, 0);
  const VectorType inferior = itk::detail::MakeVector3(0, 0, -1);

  const VectorType nearPosterior = itk::detail::MakeVector3(0.08, 1.0, 0.05); // about 5.4 degrees from +P
  const VectorType alongInferior = orthogonalTo(inferior, nearPosterior);
  ASSERT_GT((alongInferior - orthogonalTo(posterior, nearPosterior)).GetNorm(), 0.1);
  const auto near = ViewAt(0.0, nearPosterior);
  ExpectVectorNear(near.GetV(), alongInferior[0], alongInferior[1], alongInferior[2]);

  const VectorType wide = itk::detail::MakeVector3(0.25, 1.0, 0.2); // about 17.7 degrees from +P
  const VectorType alongPosterior = orthogonalTo(posterior, wide);
  ASSERT_GT((alongPosterior - orthogonalTo(inferior, wide)).GetNorm(), 0.1);
  const auto other = ViewAt(0.0, wide);
  ExpectVectorNear(other.GetV(), alongPosterior[0], alongPosterior[1], alongPosterior[2]);
}

TEST(CPRViewGeometry, PlanePointFollowsTheDesignFormula)
{
  // B(i, j) = C + (i - (W-1)/2) sx u - (j - (H-1)/2) sy up with W = 11, H = 7, sx = 0.5, sy = 2 at theta = 0.
  const auto view = ViewAt(0.0);
  const auto b = view.PlanePoint(0, 0);
  EXPECT_NEAR(b[0], 10 - 5 * 0.5, 1e-12);
  EXPECT_NEAR(b[1], 20, 1e-12);
  EXPECT_NEAR(b[2], 30 + 3 * 2.0, 1e-12);
  const auto x = view.SurfacePoint(10, 6, 4.0);
  EXPECT_NEAR(x[0], 10 + 5 * 0.5, 1e-12);
  EXPECT_NEAR(x[1], 24, 1e-12);
  EXPECT_NEAR(x[2], 30 - 3 * 2.0, 1e-12);
}

TEST(CPRViewGeometry, ToViewInvertsSurfacePoint)
{
  const auto view = ViewAt(33.0, itk::detail::MakeVector3(0.2, -0.3, 1.0));
  const auto point = view.SurfacePoint(3.25, 4.5, -7.0);
  const auto back = view.ToView(point);
  EXPECT_NEAR(back.Column, 3.25, 1e-9);
  EXPECT_NEAR(back.Row, 4.5, 1e-9);
  EXPECT_NEAR(back.Depth, -7.0, 1e-9);
}

TEST(CPRViewGeometry, DictionaryRoundTripAndMissingEntries)
{
  const auto              view = ViewAt(12.5, itk::detail::MakeVector3(0.1, 0.2, 0.9));
  itk::MetaDataDictionary dictionary;
  view.WriteToDictionary(dictionary);
  EXPECT_TRUE(itk::CPRViewGeometry::DictionaryHasView(dictionary));
  EXPECT_EQ(itk::CPRViewGeometry::ReadFromDictionary(dictionary), view);

  itk::MetaDataDictionary partial;
  itk::EncapsulateMetaData<std::string>(partial, "CPR_Center", "1 2 3");
  EXPECT_FALSE(itk::CPRViewGeometry::DictionaryHasView(partial));
  try
  {
    itk::CPRViewGeometry::ReadFromDictionary(partial);
    ADD_FAILURE() << "no exception";
  }
  catch (const itk::ExceptionObject & error)
  {
    EXPECT_NE(std::string(error.GetDescription()).find("CPR_Up"), std::string::npos) << error.GetDescription();
  }
  itk::EncapsulateMetaData<std::string>(dictionary, "CPR_Spacing", "1 x");
  EXPECT_THROW(itk::CPRViewGeometry::ReadFromDictionary(dictionary), itk::ExceptionObject);
}

TEST(CPRViewGeometry, ResolveDefaultsFromTheTreeAndVolume)
{
  // A vertical segment from (0, 0, -50) to (20, 0, 50), radius at most 2 mm. Centre: the bounding box centre
  // (10, 0, 0). Half height: 50 + 2 + margin 10 = 62; half width (radial, any angle): 10 + 2 + 10 = 22.
  const auto tree = TwoPointTree(P(0, 0, -50), P(20, 0, 50));
  auto       volume = itk::Image<float, 3>::New();
  volume->SetSpacing(itk::detail::MakeVector3(0.8, 0.5, 2.0));

  itk::CPRViewSpecification specification;
  const auto                view = itk::CPRViewGeometry::Resolve(specification, tree, volume);
  EXPECT_NEAR(view.GetCenter()[0], 10.0, 1e-12);
  EXPECT_NEAR(view.GetCenter()[2], 0.0, 1e-12);
  EXPECT_DOUBLE_EQ(view.GetSpacing()[0], 0.5); // the volume's smallest spacing
  EXPECT_DOUBLE_EQ(view.GetSpacing()[1], 0.5);
  EXPECT_EQ(view.GetSize()[0], 88u);  // 44 mm / 0.5
  EXPECT_EQ(view.GetSize()[1], 248u); // 124 mm / 0.5
  // The default size is the same at every angle, so rotating the view keeps the image size.
  specification.AngleInDegrees = 70.0;
  EXPECT_EQ(itk::CPRViewGeometry::Resolve(specification, tree, volume).GetSize(), view.GetSize());
}

TEST(CPRViewGeometry, ThePapersSizesAreSettableExactly)
{
  const auto                tree = TwoPointTree(P(0, 0, -50), P(20, 0, 50));
  itk::CPRViewSpecification specification;
  specification.ImageSize[0] = 256;
  specification.ImageSize[1] = 768;
  const auto view = itk::CPRViewGeometry::Resolve(specification, tree, nullptr);
  EXPECT_EQ(view.GetSize()[0], 256u);
  EXPECT_EQ(view.GetSize()[1], 768u);
  // Spacing makes the 44 x 124 mm extent fit: max(44/256, 124/768) = 44/256.
  EXPECT_DOUBLE_EQ(view.GetSpacing()[0], 44.0 / 256.0);
  EXPECT_DOUBLE_EQ(view.GetSpacing()[1], 44.0 / 256.0);
}

TEST(CPRViewGeometry, AutomaticUpTakesTheVolumeAxisTheTreeExtendsAlong)
{
  // Volume axes: i along -x, j along -y, k along +z (like the VMTK aorta scan). The tree runs mostly along y,
  // its root (first point) at y = -40: up is the j axis column (0, -1, 0) pointing towards the root.
  auto                                volume = itk::Image<float, 3>::New();
  itk::Image<float, 3>::DirectionType direction;
  direction.SetIdentity();
  direction[0][0] = -1;
  direction[1][1] = -1;
  volume->SetDirection(direction);
  itk::CPRViewSpecification specification;
  specification.AutomaticUp = true;
  const auto view = itk::CPRViewGeometry::Resolve(specification, TwoPointTree(P(0, -40, 0), P(5, 60, 8)), volume);
  ExpectVectorNear(view.GetUp(), 0, -1, 0);
  const auto reversed = itk::CPRViewGeometry::Resolve(specification, TwoPointTree(P(5, 60, 8), P(0, -40, 0)), volume);
  ExpectVectorNear(reversed.GetUp(), 0, 1, 0);
  // Without a volume the automatic axis cannot be chosen.
  EXPECT_THROW(itk::CPRViewGeometry::Resolve(specification, TwoPointTree(P(0, 0, 0), P(0, 1, 0)), nullptr),
               itk::ExceptionObject);
}

TEST(CPRViewGeometry, RejectsBadValues)
{
  itk::Size<2> good = { { 4, 4 } };
  itk::Size<2> empty = { { 0, 10 } };
  const auto   c = P(0, 0, 0);
  EXPECT_THROW(itk::CPRViewGeometry(itk::detail::MakeVector3(0, 0, 0), 0, c, good, itk::detail::MakeVector2(1, 1)),
               itk::ExceptionObject);
  EXPECT_THROW(
    itk::CPRViewGeometry(itk::detail::MakeVector3(0, 0, 1), std::nan(""), c, good, itk::detail::MakeVector2(1, 1)),
    itk::ExceptionObject);
  EXPECT_THROW(itk::CPRViewGeometry(itk::detail::MakeVector3(0, 0, 1), 0, c, empty, itk::detail::MakeVector2(1, 1)),
               itk::ExceptionObject);
  EXPECT_THROW(itk::CPRViewGeometry(itk::detail::MakeVector3(0, 0, 1), 0, c, good, itk::detail::MakeVector2(-1, 1)),
               itk::ExceptionObject);
  try
  {
    itk::CPRViewGeometry(itk::detail::MakeVector3(0, 0, 1), 0, c, good, itk::detail::MakeVector2(1, std::nan("")));
    ADD_FAILURE() << "no exception";
  }
  catch (const itk::ExceptionObject & error)
  {
    EXPECT_NE(std::string(error.GetDescription()).find("spacing"), std::string::npos) << error.GetDescription();
  }
  itk::CenterlineTree emptyTree;
  EXPECT_THROW(itk::CPRViewGeometry::Resolve(itk::CPRViewSpecification{}, emptyTree, nullptr), itk::ExceptionObject);
}
