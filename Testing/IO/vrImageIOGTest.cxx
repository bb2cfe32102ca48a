// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// 2D outputs (issue 3): NRRD images keep values and the CPR view, masks of any integer type read as fixed/free,
// the windowed PNG, the cut surface as .vtp/.vtk, and failed writes that leave existing files alone.
#include "itkCPRVectorHelpers.h"
#include "vrImageIO.h"
#include "vrSurfaceIO.h"
#include "vrInputError.h"
#include "vrTestFiles.h"

#include "itkCPRViewGeometry.h"
#include "itkImageFileReader.h"
#include "itkImageFileWriter.h"

#include "vrTestImages.h"

#include <gtest/gtest.h>
#include <vtkCellArray.h>
#include <vtkFieldData.h>
#include <vtkFloatArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataReader.h>
#include <vtkStringArray.h>
#include <vtkXMLPolyDataReader.h>

#include <cmath>
#include <functional>
#include <iostream>

namespace
{
using vr::test::InputErrorOf;

#define EXPECT_MESSAGE_HAS(message, part)                                                                              \
  EXPECT_NE((message).find(part), std::string::npos) << "message: " << (message) << "\nmissing: " << (part)

itk::CPRViewGeometry
MakeView()
{
  itk::CPRViewGeometry::PointType center;
  center[0] = -12.5;
  center[1] = 40.125;
  center[2] = 1.0 / 3.0; // not a short decimal: the text must carry every digit
  return itk::CPRViewGeometry(itk::detail::MakeVector3(0.0, 0.0, 1.0),
                              37.5,
                              center,
                              itk::Size<2>{ { 5, 3 } },
                              itk::detail::MakeVector2(0.7, 0.9));
}

template<typename TImage>
typename TImage::Pointer
MakeViewImage(const std::function<typename TImage::PixelType(unsigned int)> & value)
{
  auto image = TImage::New();
  MakeView().ConfigureImage(image.GetPointer());
  image->Allocate();
  for (unsigned int k = 0; k < 15; ++k)
  {
    image->GetBufferPointer()[k] = value(k);
  }
  return image;
}

TEST(Image2DIO, NRRDDepthKeepsValuesGeometryAndTheView)
{
  vr::test::ScopedTemporaryFolder folder;
  const auto        depth = MakeViewImage<vr::DepthImageType>([](unsigned int k) { return -3.25f + 0.1f * k; });
  const std::string path = folder.File("depth.nrrd");
  vr::WriteImage2D(depth, path);
  EXPECT_EQ(folder.Entries(), std::vector<std::string>{ "depth.nrrd" });

  // NrrdImageIO writes string metadata as key:=value lines.
  const std::string header = vr::test::ReadTextFile(path);
  EXPECT_NE(header.find("CPR_Center:="), std::string::npos);
  EXPECT_NE(header.find("CPR_AngleDegrees:=37.5"), std::string::npos);

  const vr::DepthImageType::Pointer read = vr::ReadDepthImage(path);
  ASSERT_EQ(read->GetLargestPossibleRegion().GetSize(), depth->GetLargestPossibleRegion().GetSize());
  EXPECT_EQ(read->GetSpacing(), depth->GetSpacing());
  EXPECT_EQ(read->GetOrigin(), depth->GetOrigin());
  for (unsigned int k = 0; k < 15; ++k)
  {
    EXPECT_EQ(read->GetBufferPointer()[k], depth->GetBufferPointer()[k]);
  }
  ASSERT_TRUE(itk::CPRViewGeometry::DictionaryHasView(read->GetMetaDataDictionary()));
  EXPECT_EQ(itk::CPRViewGeometry::ReadFromDictionary(read->GetMetaDataDictionary()), MakeView());
}

TEST(Image2DIO, MetaImageKeepsTheViewToo)
{
  vr::test::ScopedTemporaryFolder folder;
  const auto                      depth = MakeViewImage<vr::DepthImageType>([](unsigned int k) { return 0.5f * k; });
  const std::string               path = folder.File("depth.mha");
  vr::WriteImage2D(depth, path);
  const vr::DepthImageType::Pointer read = vr::ReadDepthImage(path);
  EXPECT_EQ(read->GetBufferPointer()[14], 7.0f);
  EXPECT_EQ(itk::CPRViewGeometry::ReadFromDictionary(read->GetMetaDataDictionary()), MakeView());
}

TEST(Image2DIO, MaskAndLabelImagesRoundTrip)
{
  vr::test::ScopedTemporaryFolder folder;
  const auto mask = MakeViewImage<vr::MaskImageType>([](unsigned int k) { return k % 3 == 0 ? 1 : 0; });
  const auto labels = MakeViewImage<vr::LabelImageType>([](unsigned int k) { return k * 100000U; });
  vr::WriteImage2D(mask, folder.File("mask.nrrd"));
  vr::WriteImage2D(labels, folder.File("labels.nrrd"));

  const vr::MaskImageType::Pointer readMask = vr::ReadMaskImage(folder.File("mask.nrrd"));
  auto                             labelReader = itk::ImageFileReader<vr::LabelImageType>::New();
  labelReader->SetFileName(folder.File("labels.nrrd"));
  labelReader->Update();
  for (unsigned int k = 0; k < 15; ++k)
  {
    EXPECT_EQ(readMask->GetBufferPointer()[k], mask->GetBufferPointer()[k]);
    EXPECT_EQ(labelReader->GetOutput()->GetBufferPointer()[k], k * 100000U);
  }
  EXPECT_EQ(itk::CPRViewGeometry::ReadFromDictionary(readMask->GetMetaDataDictionary()), MakeView());
}

TEST(Image2DIO, AMaskOfAnyPixelTypeReadsNonZeroAsFixed)
{
  vr::test::ScopedTemporaryFolder folder;
  // 256 would wrap to 0 in a plain cast to unsigned char, 0.5 would truncate to 0.
  auto wide = itk::Image<unsigned short, 2>::New();
  wide->SetRegions(itk::ImageRegion<2>({ { 0, 0 } }, { { 4, 1 } }));
  wide->Allocate();
  const unsigned short wideValues[] = { 0, 1, 256, 300 };
  std::copy(std::begin(wideValues), std::end(wideValues), wide->GetBufferPointer());
  auto writer = itk::ImageFileWriter<itk::Image<unsigned short, 2>>::New();
  writer->SetInput(wide);
  writer->SetFileName(folder.File("wide.nrrd"));
  writer->Update();
  const auto fromWide = vr::ReadMaskImage(folder.File("wide.nrrd"));
  EXPECT_EQ(std::vector<unsigned char>(fromWide->GetBufferPointer(), fromWide->GetBufferPointer() + 4),
            (std::vector<unsigned char>{ 0, 1, 1, 1 }));

  auto fractions = itk::Image<float, 2>::New();
  fractions->SetRegions(itk::ImageRegion<2>({ { 0, 0 } }, { { 3, 1 } }));
  fractions->Allocate();
  fractions->GetBufferPointer()[0] = 0.0f;
  fractions->GetBufferPointer()[1] = 0.5f;
  fractions->GetBufferPointer()[2] = std::nanf("");
  auto floatWriter = itk::ImageFileWriter<itk::Image<float, 2>>::New();
  floatWriter->SetInput(fractions);
  floatWriter->SetFileName(folder.File("fractions.nrrd"));
  floatWriter->Update();
  const std::string message = InputErrorOf([&] { vr::ReadMaskImage(folder.File("fractions.nrrd")); });
  EXPECT_MESSAGE_HAS(message, folder.File("fractions.nrrd"));
  EXPECT_MESSAGE_HAS(message, "pixel (2, 0)");
}

TEST(Image2DIO, WindowedPNGMapsLevelPlusMinusHalfWindowToTheGreyRange)
{
  vr::test::ScopedTemporaryFolder folder;
  // Window 400 around level 100: -100 -> 0 and 300 -> 255, linear between, rounded to the nearest grey.
  const std::vector<float> values = { -500.0f, -100.0f, 100.0f, 200.0f, 300.0f, 1000.0f, std::nanf(""), 0.0f };
  const std::vector<int>   expected = { 0, 0, 128 /* 127.5 */, 191 /* 191.25 */, 255, 255, 0, 64 /* 63.75 */ };
  auto                     image = vr::DepthImageType::New();
  image->SetRegions(itk::ImageRegion<2>({ { 0, 0 } }, { { 4, 2 } }));
  image->Allocate();
  std::copy(values.begin(), values.end(), image->GetBufferPointer());
  const std::string path = folder.File("cpr.png");
  vr::WriteWindowedPNG(image, 400.0, 100.0, path);

  auto reader = itk::ImageFileReader<itk::Image<unsigned char, 2>>::New();
  reader->SetFileName(path);
  reader->Update();
  ASSERT_EQ(reader->GetOutput()->GetLargestPossibleRegion().GetSize(), (itk::Size<2>{ { 4, 2 } }));
  for (std::size_t k = 0; k < values.size(); ++k)
  {
    EXPECT_EQ(reader->GetOutput()->GetBufferPointer()[k], expected[k]) << "pixel " << k << " value " << values[k];
  }

  for (const double window : { 0.0, -5.0, std::nan("") })
  {
    const std::string bad = folder.File("bad.png");
    const std::string message = InputErrorOf([&] { vr::WriteWindowedPNG(image, window, 100.0, bad); });
    EXPECT_MESSAGE_HAS(message, "window");
    EXPECT_MESSAGE_HAS(message, bad);
  }
  EXPECT_MESSAGE_HAS(InputErrorOf([&] { vr::WriteWindowedPNG(image, 10.0, INFINITY, folder.File("bad.png")); }),
                     "level inf");
  EXPECT_EQ(folder.Entries(), std::vector<std::string>{ "cpr.png" });
}

/** A 2 x 2 grid of points with one quad and an "Intensity" point array. */
vtkSmartPointer<vtkPolyData>
MakeSurface()
{
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  points->InsertNextPoint(0.0, 0.0, 0.0);
  points->InsertNextPoint(1.5, 0.0, 0.25);
  points->InsertNextPoint(0.0, 2.0, -0.5);
  points->InsertNextPoint(1.5, 2.0, 0.0);
  auto            polys = vtkSmartPointer<vtkCellArray>::New();
  const vtkIdType quad[] = { 0, 1, 3, 2 };
  polys->InsertNextCell(4, quad);
  auto intensity = vtkSmartPointer<vtkFloatArray>::New();
  intensity->SetName("Intensity");
  for (const float value : { 230.0f, 1850.0f, 1900.5f, -12.0f })
  {
    intensity->InsertNextValue(value);
  }
  auto surface = vtkSmartPointer<vtkPolyData>::New();
  surface->SetPoints(points);
  surface->SetPolys(polys);
  surface->GetPointData()->SetScalars(intensity);
  return surface;
}

void
ExpectSameSurface(vtkPolyData * expected, vtkPolyData * actual)
{
  ASSERT_EQ(actual->GetNumberOfPoints(), expected->GetNumberOfPoints());
  ASSERT_EQ(actual->GetNumberOfPolys(), 1);
  for (vtkIdType k = 0; k < expected->GetNumberOfPoints(); ++k)
  {
    for (int axis = 0; axis < 3; ++axis)
    {
      EXPECT_EQ(actual->GetPoint(k)[axis], expected->GetPoint(k)[axis]);
    }
  }
  vtkDataArray * scalars = actual->GetPointData()->GetArray("Intensity");
  ASSERT_NE(scalars, nullptr);
  for (vtkIdType k = 0; k < expected->GetNumberOfPoints(); ++k)
  {
    EXPECT_EQ(scalars->GetTuple1(k), expected->GetPointData()->GetArray("Intensity")->GetTuple1(k));
  }
}

TEST(SurfaceIO, VTPAndVTKKeepPointsCellsAndIntensity)
{
  vr::test::ScopedTemporaryFolder folder;
  auto                            surface = MakeSurface();
  vr::WriteSurface(surface, folder.File("surface.vtp"), vr::CoordinateSpace::RAS);
  vr::WriteSurface(surface, folder.File("surface.vtk"), vr::CoordinateSpace::RAS);
  vr::WriteSurface(surface, folder.File("plain.vtp"));
  EXPECT_EQ(folder.Entries(), (std::vector<std::string>{ "plain.vtp", "surface.vtk", "surface.vtp" }));

  auto xml = vtkSmartPointer<vtkXMLPolyDataReader>::New();
  xml->SetFileName(folder.File("surface.vtp").c_str());
  xml->Update();
  ExpectSameSurface(surface, xml->GetOutput());
  auto * space = vtkStringArray::SafeDownCast(xml->GetOutput()->GetFieldData()->GetAbstractArray("SPACE"));
  ASSERT_NE(space, nullptr);
  EXPECT_EQ(space->GetValue(0), "RAS");
  EXPECT_EQ(surface->GetFieldData()->GetAbstractArray("SPACE"), nullptr) << "the caller's surface was changed";

  auto legacy = vtkSmartPointer<vtkPolyDataReader>::New();
  legacy->SetFileName(folder.File("surface.vtk").c_str());
  legacy->Update();
  ExpectSameSurface(surface, legacy->GetOutput());
  EXPECT_NE(std::string(legacy->GetHeader()).find("SPACE=RAS"), std::string::npos);
}

TEST(SurfaceIO, WritesModelsAsSlicerDoesInLPSWithTheSpaceRecorded)
{
  vr::test::ScopedTemporaryFolder folder;
  auto                            surface = MakeSurface(); // RAS, as the logic's cut surface
  auto                            normals = vtkSmartPointer<vtkFloatArray>::New();
  normals->SetName("Normals");
  normals->SetNumberOfComponents(3);
  for (int k = 0; k < 4; ++k)
  {
    normals->InsertNextTuple3(0.6, 0.8, 0.0);
  }
  surface->GetPointData()->SetNormals(normals);
  vr::WriteSurface(surface, folder.File("model.vtp"), vr::CoordinateSpace::RAS, vr::CoordinateSpace::LPS);
  vr::WriteSurface(surface, folder.File("model.vtk"), vr::CoordinateSpace::RAS, vr::CoordinateSpace::LPS);
  EXPECT_EQ(folder.Entries(), (std::vector<std::string>{ "model.vtk", "model.vtp" }));
  // The caller's surface is as it was.
  EXPECT_EQ(surface->GetPoint(1)[0], 1.5);
  EXPECT_EQ(surface->GetPointData()->GetNormals()->GetComponent(0, 0), 0.6f);

  auto xml = vtkSmartPointer<vtkXMLPolyDataReader>::New();
  xml->SetFileName(folder.File("model.vtp").c_str());
  xml->Update();
  auto legacy = vtkSmartPointer<vtkPolyDataReader>::New();
  legacy->SetFileName(folder.File("model.vtk").c_str());
  legacy->Update();
  auto * space = vtkStringArray::SafeDownCast(xml->GetOutput()->GetFieldData()->GetAbstractArray("SPACE"));
  ASSERT_NE(space, nullptr);
  EXPECT_EQ(space->GetValue(0), "LPS");
  EXPECT_NE(std::string(legacy->GetHeader()).find("SPACE=LPS"), std::string::npos) << legacy->GetHeader();
  for (vtkPolyData * read : { xml->GetOutput(), legacy->GetOutput() })
  {
    ASSERT_EQ(read->GetNumberOfPoints(), 4);
    for (vtkIdType k = 0; k < 4; ++k)
    {
      // RAS (x, y, z) is LPS (-x, -y, z); normals turn with the points, as in Slicer's model storage.
      EXPECT_EQ(read->GetPoint(k)[0], -surface->GetPoint(k)[0]);
      EXPECT_EQ(read->GetPoint(k)[1], -surface->GetPoint(k)[1]);
      EXPECT_EQ(read->GetPoint(k)[2], surface->GetPoint(k)[2]);
      EXPECT_FLOAT_EQ(static_cast<float>(read->GetPointData()->GetNormals()->GetComponent(k, 0)), -0.6f);
      EXPECT_FLOAT_EQ(static_cast<float>(read->GetPointData()->GetNormals()->GetComponent(k, 1)), -0.8f);
    }
    EXPECT_EQ(read->GetPointData()->GetArray("Intensity")->GetTuple1(1), 1850.0);
  }
}

TEST(SurfaceIO, ReadsTheRecordedSpaceAndTakesAnUnmarkedModelAsLPSAsSlicerDoes)
{
  vr::test::ScopedTemporaryFolder folder;
  auto                            surface = MakeSurface();
  vr::WriteSurface(surface, folder.File("lps.vtp"), vr::CoordinateSpace::RAS, vr::CoordinateSpace::LPS);
  vr::WriteSurface(surface, folder.File("lps.vtk"), vr::CoordinateSpace::RAS, vr::CoordinateSpace::LPS);
  vr::WriteSurface(surface, folder.File("ras.vtp"), vr::CoordinateSpace::RAS);
  vr::WriteSurface(surface, folder.File("ras.vtk"), vr::CoordinateSpace::RAS);
  vr::WriteSurface(surface, folder.File("plain.vtp"));
  const auto expect = [&](const std::string & name, vr::CoordinateSpace stored, double sign)
  {
    vr::CoordinateSpace found = vr::CoordinateSpace::Auto;
    const auto          ras = vr::ReadSurface(folder.File(name), vr::CoordinateSpace::RAS, &found);
    EXPECT_EQ(found, stored) << name;
    ASSERT_EQ(ras->GetNumberOfPoints(), 4) << name;
    // Back in RAS: the written surface itself, except the unmarked file, whose RAS points are taken for LPS.
    EXPECT_EQ(ras->GetPoint(1)[0], sign * 1.5) << name;
    EXPECT_EQ(ras->GetPoint(2)[1], sign * 2.0) << name;
    EXPECT_EQ(ras->GetPoint(2)[2], -0.5) << name;
    EXPECT_EQ(ras->GetFieldData()->GetAbstractArray("SPACE"), nullptr) << name << ": Slicer drops the marker";
    const auto asStored = vr::ReadSurface(folder.File(name), vr::CoordinateSpace::Auto);
    EXPECT_EQ(asStored->GetPoint(1)[0], stored == vr::CoordinateSpace::LPS ? -sign * 1.5 : 1.5) << name;
  };
  expect("lps.vtp", vr::CoordinateSpace::LPS, 1.0);
  expect("lps.vtk", vr::CoordinateSpace::LPS, 1.0);
  expect("ras.vtp", vr::CoordinateSpace::RAS, 1.0);
  expect("ras.vtk", vr::CoordinateSpace::RAS, 1.0);
  expect("plain.vtp", vr::CoordinateSpace::LPS, -1.0);
}

TEST(BadSurfaceInput, MissingUnknownAndBrokenFilesNameTheFile)
{
  vr::test::ScopedTemporaryFolder folder;
  std::string                     message = InputErrorOf([&] { vr::ReadSurface(folder.File("missing.vtp")); });
  EXPECT_MESSAGE_HAS(message, folder.File("missing.vtp"));
  EXPECT_MESSAGE_HAS(message, "no such file");
  vr::test::WriteTextFile(folder.File("surface.stl"), "solid\n");
  message = InputErrorOf([&] { vr::ReadSurface(folder.File("surface.stl")); });
  EXPECT_MESSAGE_HAS(message, "unknown extension");
  vr::WriteSurface(MakeSurface(), folder.File("whole.vtp"), vr::CoordinateSpace::RAS, vr::CoordinateSpace::LPS);
  const std::string whole = vr::test::ReadTextFile(folder.File("whole.vtp"));
  vr::test::WriteTextFile(folder.File("truncated.vtp"), whole.substr(0, whole.size() / 2));
  message = InputErrorOf([&] { vr::ReadSurface(folder.File("truncated.vtp")); });
  EXPECT_MESSAGE_HAS(message, folder.File("truncated.vtp"));
  vr::test::WriteTextFile(folder.File("text.vtk"), "not a VTK file\n");
  message = InputErrorOf([&] { vr::ReadSurface(folder.File("text.vtk")); });
  EXPECT_MESSAGE_HAS(message, folder.File("text.vtk"));
}

TEST(BadImageOutput, FailedWritesLeaveExistingFilesAndNoTemporaryOnes)
{
  vr::test::ScopedTemporaryFolder folder;
  // PNG holds no 32-bit integers: ITK refuses, and the previous labels.png stays.
  const std::string labelsPath = folder.File("labels.png");
  vr::test::WriteTextFile(labelsPath, "previous");
  const auto  labels = MakeViewImage<vr::LabelImageType>([](unsigned int k) { return k * 100000U; });
  std::string message = InputErrorOf([&] { vr::WriteImage2D(labels, labelsPath); });
  EXPECT_MESSAGE_HAS(message, labelsPath);
  EXPECT_EQ(vr::test::ReadTextFile(labelsPath), "previous");

  message = InputErrorOf([&] { vr::WriteSurface(MakeSurface(), folder.File("surface.stl")); });
  EXPECT_MESSAGE_HAS(message, "unknown extension");
  message = InputErrorOf([&] { vr::WriteSurface(vtkSmartPointer<vtkPolyData>::New(), folder.File("empty.vtp")); });
  EXPECT_MESSAGE_HAS(message, "no point");
  message = InputErrorOf(
    [&] { vr::WriteImage2D(static_cast<const vr::DepthImageType *>(nullptr), folder.File("depth.nrrd")); });
  EXPECT_MESSAGE_HAS(message, "no image");
  EXPECT_EQ(folder.Entries(), std::vector<std::string>{ "labels.png" });
}

TEST(BadImageInput, MissingCorruptThreeDimensionalAndTruncatedDepthImages)
{
  vr::test::ScopedTemporaryFolder folder;
  std::string                     message = InputErrorOf([&] { vr::ReadDepthImage(folder.File("missing.nrrd")); });
  EXPECT_MESSAGE_HAS(message, folder.File("missing.nrrd"));
  EXPECT_MESSAGE_HAS(message, "no such file");

  const std::string corrupt = folder.File("corrupt.nrrd");
  vr::test::WriteTextFile(corrupt, "NRRD0004\ntype: float\ndimension: 2\nsizes: 5\nencoding: raw\n\n");
  message = InputErrorOf([&] { vr::ReadDepthImage(corrupt); });
  EXPECT_MESSAGE_HAS(message, corrupt);
  EXPECT_MESSAGE_HAS(message, "header");

  const std::string volume = folder.File("volume.nrrd");
  vr::test::WriteTextFile(volume,
                          "NRRD0004\ntype: float\ndimension: 3\nsizes: 2 2 2\nendian: little\n"
                          "encoding: ascii\n\n1 2 3 4 5 6 7 8\n");
  message = InputErrorOf([&] { vr::ReadMaskImage(volume); });
  EXPECT_MESSAGE_HAS(message, volume);
  EXPECT_MESSAGE_HAS(message, "3 dimensions; it must be 2D");

  const std::string truncated = folder.File("truncated.nrrd");
  vr::test::WriteTextFile(truncated,
                          "NRRD0004\ntype: float\ndimension: 2\nsizes: 8 8\nendian: little\n"
                          "encoding: raw\n\n0123");
  message = InputErrorOf([&] { vr::ReadDepthImage(truncated); });
  EXPECT_MESSAGE_HAS(message, truncated);
}
} // namespace
