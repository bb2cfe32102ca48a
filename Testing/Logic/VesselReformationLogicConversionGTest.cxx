// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// The module logic's node conversion (RAS <-> LPS) against hand-computed cases, and the cut surface.
#include "vrLogicTestFixture.h"

namespace
{
using namespace vr::test::logic;

// ---------------------------------------------------------------------------------------------------------------
// Node conversion against hand-computed cases.

TEST(NodeConversion, VolumeNodeGeometryBecomesLPS)
{
  // IJK->RAS with a rotation, anisotropic spacing and an offset:
  //   R = -2 j + 10,  A = 3 i + 20,  S = 4 k - 30.
  auto         matrix = vtkSmartPointer<vtkMatrix4x4>::New();
  const double elements[16] = { 0, -2, 0, 10, 3, 0, 0, 20, 0, 0, 4, -30, 0, 0, 0, 1 };
  matrix->DeepCopy(elements);
  auto data = vtkSmartPointer<vtkImageData>::New();
  data->SetExtent(0, 2, 0, 3, 0, 4);
  data->AllocateScalars(VTK_UNSIGNED_CHAR, 1);
  auto * voxels = static_cast<unsigned char *>(data->GetScalarPointer());
  for (int k = 0; k < 3 * 4 * 5; ++k)
  {
    voxels[k] = static_cast<unsigned char>(k);
  }
  auto node = vtkSmartPointer<vr::VolumeNode>::New();
  node->SetImageData(data);
  node->SetIJKToRASMatrix(matrix);

  auto image = vr::ConvertVolumeNodeToItkImage(node);
  // By hand: IJK->LPS = [[0, 2, 0, -10], [-3, 0, 0, -20], [0, 0, 4, -30]].
  EXPECT_DOUBLE_EQ(image->GetSpacing()[0], 3.0);
  EXPECT_DOUBLE_EQ(image->GetSpacing()[1], 2.0);
  EXPECT_DOUBLE_EQ(image->GetSpacing()[2], 4.0);
  EXPECT_DOUBLE_EQ(image->GetOrigin()[0], -10.0);
  EXPECT_DOUBLE_EQ(image->GetOrigin()[1], -20.0);
  EXPECT_DOUBLE_EQ(image->GetOrigin()[2], -30.0);
  const double direction[3][3] = { { 0, 1, 0 }, { -1, 0, 0 }, { 0, 0, 1 } };
  for (int r = 0; r < 3; ++r)
  {
    for (int c = 0; c < 3; ++c)
    {
      EXPECT_DOUBLE_EQ(image->GetDirection()[r][c], direction[r][c]) << r << "," << c;
    }
  }
  // Voxel (1, 2, 3): RAS (-2*2 + 10, 3*1 + 20, 4*3 - 30) = (6, 23, -18), so LPS (-6, -23, -18).
  vr::VolumeImageType::IndexType index = { { 1, 2, 3 } };
  itk::Point<double, 3>          point;
  image->TransformIndexToPhysicalPoint(index, point);
  EXPECT_NEAR(point[0], -6.0, 1e-12);
  EXPECT_NEAR(point[1], -23.0, 1e-12);
  EXPECT_NEAR(point[2], -18.0, 1e-12);
  EXPECT_EQ(image->GetPixel(index), static_cast<float>((3 * 4 + 2) * 3 + 1));

  // Back to a node: the same matrix and voxels.
  auto back = vr::ConvertItkImageToVolumeNode(image, "back");
  for (int r = 0; r < 4; ++r)
  {
    for (int c = 0; c < 4; ++c)
    {
      EXPECT_NEAR(back->GetIJKToRASMatrix()->GetElement(r, c), elements[4 * r + c], 1e-12) << r << "," << c;
    }
  }
  EXPECT_EQ(static_cast<float *>(back->GetImageData()->GetScalarPointer())[59], 59.0f);
}

TEST(NodeConversion, BadVolumeNodesAreNamed)
{
  auto node = vtkSmartPointer<vr::VolumeNode>::New();
  node->SetName("broken");
  try
  {
    vr::ConvertVolumeNodeToItkImage(node);
    FAIL() << "no error";
  }
  catch (const vr::InputError & error)
  {
    EXPECT_NE(std::string(error.what()).find("\"broken\""), std::string::npos) << error.what();
  }
  auto data = vtkSmartPointer<vtkImageData>::New();
  data->SetExtent(0, 1, 0, 1, 0, 1);
  data->AllocateScalars(VTK_FLOAT, 1);
  node->SetImageData(data);
  auto singular = vtkSmartPointer<vtkMatrix4x4>::New();
  singular->SetElement(2, 2, 0.0);
  node->SetIJKToRASMatrix(singular);
  EXPECT_THROW(vr::ConvertVolumeNodeToItkImage(node), vr::InputError);
  data->SetSpacing(2.0, 1.0, 1.0);
  node->SetIJKToRASMatrix(nullptr);
  EXPECT_THROW(vr::ConvertVolumeNodeToItkImage(node), vr::InputError);
}

TEST(NodeConversion, CenterlineNodePointsBecomeLPS)
{
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->InsertNextPoint(10.0, 20.0, 30.0);
  points->InsertNextPoint(-1.5, 2.5, -3.5);
  points->InsertNextPoint(7.0, -8.0, 9.0);
  auto            lines = vtkSmartPointer<vtkCellArray>::New();
  const vtkIdType first[2] = { 0, 1 };
  const vtkIdType second[1] = { 2 };
  lines->InsertNextCell(2, first);
  lines->InsertNextCell(1, second);
  auto radii = vtkSmartPointer<vtkDoubleArray>::New();
  radii->SetName("MaximumInscribedSphereRadius");
  radii->InsertNextValue(2.0);
  radii->InsertNextValue(2.5);
  radii->InsertNextValue(3.0);
  auto polyData = vtkSmartPointer<vtkPolyData>::New();
  polyData->SetPoints(points);
  polyData->SetLines(lines);
  polyData->GetPointData()->AddArray(radii);
  auto node = vtkSmartPointer<vr::CenterlineNode>::New();
  node->SetPolyData(polyData);

  const itk::CenterlineTree tree = vr::ConvertCenterlineNodeToTree(node);
  ASSERT_EQ(tree.GetNumberOfBranches(), 2u);
  const auto & trunk = tree.GetBranches()[0];
  EXPECT_EQ(trunk.Id, 1);
  ASSERT_EQ(trunk.Points.size(), 2u);
  EXPECT_DOUBLE_EQ(trunk.Points[0][0], -10.0);
  EXPECT_DOUBLE_EQ(trunk.Points[0][1], -20.0);
  EXPECT_DOUBLE_EQ(trunk.Points[0][2], 30.0);
  EXPECT_DOUBLE_EQ(trunk.Points[1][0], 1.5);
  EXPECT_DOUBLE_EQ(trunk.Points[1][1], -2.5);
  EXPECT_DOUBLE_EQ(trunk.Points[1][2], -3.5);
  EXPECT_DOUBLE_EQ(trunk.Radii[1], 2.5);
  EXPECT_EQ(tree.GetBranches()[1].Id, 2);
  EXPECT_DOUBLE_EQ(tree.GetBranches()[1].Points[0][1], 8.0);

  // Back to a node and again to a tree: ids and radii survive.
  auto   back = vr::ConvertTreeToCenterlineNode(tree, "back");
  double ras[3];
  back->GetPolyData()->GetPoint(0, ras);
  EXPECT_DOUBLE_EQ(ras[0], 10.0);
  EXPECT_DOUBLE_EQ(ras[1], 20.0);
  const itk::CenterlineTree again = vr::ConvertCenterlineNodeToTree(back);
  EXPECT_EQ(again.GetBranches()[1].Id, 2);
  EXPECT_DOUBLE_EQ(again.GetBranches()[0].Radii[0], 2.0);

  auto empty = vtkSmartPointer<vr::CenterlineNode>::New();
  empty->SetName("nothing");
  empty->SetPolyData(vtkSmartPointer<vtkPolyData>::New());
  EXPECT_THROW(vr::ConvertCenterlineNodeToTree(empty), vr::InputError);
}

TEST(NodeConversion, OutputImageNodeLiesOnTheViewPlane)
{
  // up S, angle 0: u = LPS (1, 0, 0), v = (0, 1, 0); C = (5, 6, 7), 4 x 3 pixels of 0.5 x 2 mm.
  const itk::CPRViewGeometry view(itk::detail::MakeVector3(0, 0, 1),
                                  0.0,
                                  MakePoint(5, 6, 7),
                                  itk::Size<2>{ { 4, 3 } },
                                  itk::detail::MakeVector2(0.5, 2.0));
  auto                       image = vr::DepthImageType::New();
  view.ConfigureImage(image.GetPointer());
  image->Allocate();
  for (int k = 0; k < 12; ++k)
  {
    image->GetBufferPointer()[k] = static_cast<float>(k) - 3.0f;
  }
  auto node = vr::ConvertItkImageToVolumeNode(image.GetPointer(), "Depth");
  // Pixel (i, j) at LPS B = C + (i - 1.5) 0.5 u - (j - 1) 2 up; pixel (3, 2): (5.75, 6, 5), RAS (-5.75, -6, 5).
  const double ijk[4] = { 3, 2, 0, 1 };
  double       ras[4];
  node->GetIJKToRASMatrix()->MultiplyPoint(ijk, ras);
  EXPECT_NEAR(ras[0], -5.75, 1e-12);
  EXPECT_NEAR(ras[1], -6.0, 1e-12);
  EXPECT_NEAR(ras[2], 5.0, 1e-12);
  // One slice step is one millimetre along v = LPS (0, 1, 0), RAS (0, -1, 0).
  EXPECT_NEAR(node->GetIJKToRASMatrix()->GetElement(1, 2), -1.0, 1e-12);
  EXPECT_STREQ(node->GetAttribute("CPR_Frame"), "LPS");

  auto back = vr::ConvertVolumeNodeToDepthImage(node);
  EXPECT_EQ(itk::CPRViewGeometry::ReadFromDictionary(back->GetMetaDataDictionary()), view);
  EXPECT_EQ(back->GetSpacing(), image->GetSpacing());
  EXPECT_EQ(back->GetOrigin(), image->GetOrigin());
  EXPECT_EQ(back->GetBufferPointer()[11], 8.0f);
}

// ---------------------------------------------------------------------------------------------------------------
// The cut surface.

TEST(CutSurface, PointsLieAtTheDepthAndJumpsStayOpen)
{
  // 3 x 2 pixels of 1 mm, C = 0, up S, angle 0. Depths: left column 0, the rest 0 except pixel (2, 1) = 10 mm.
  const itk::CPRViewGeometry view(itk::detail::MakeVector3(0, 0, 1),
                                  0.0,
                                  MakePoint(0, 0, 0),
                                  itk::Size<2>{ { 3, 2 } },
                                  itk::detail::MakeVector2(1.0, 1.0));
  auto                       depth = vr::DepthImageType::New();
  auto                       intensity = vr::DepthImageType::New();
  view.ConfigureImage(depth.GetPointer());
  view.ConfigureImage(intensity.GetPointer());
  depth->Allocate();
  intensity->Allocate();
  const float depths[6] = { 0, 0, 0, 0, 0, 10 };
  for (int k = 0; k < 6; ++k)
  {
    depth->GetBufferPointer()[k] = depths[k];
    intensity->GetBufferPointer()[k] = 100.0f + k;
  }
  auto surface = vr::BuildCutSurface(depth, intensity, view, 4.0);
  ASSERT_EQ(surface->GetNumberOfPoints(), 6);
  // Pixel (2, 1): B = (2 - 1) u - (1 - 0.5) up = LPS (1, 0, -0.5); X = B + 10 v = (1, 10, -0.5); RAS (-1, -10, -0.5).
  double x[3];
  surface->GetPoint(5, x);
  EXPECT_NEAR(x[0], -1.0, 1e-6);
  EXPECT_NEAR(x[1], -10.0, 1e-6);
  EXPECT_NEAR(x[2], -0.5, 1e-6);
  EXPECT_EQ(surface->GetPointData()->GetScalars()->GetComponent(5, 0), 105.0);
  // Two squares, four triangles; the two of the right square that touch pixel 5 cross the 10 mm jump.
  EXPECT_EQ(surface->GetNumberOfPolys(), 2);
  // With a threshold above the jump all four stay.
  EXPECT_EQ(vr::BuildCutSurface(depth, intensity, view, 10.0)->GetNumberOfPolys(), 4);
}
} // namespace
