// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// Volumes in their stored type through nodes and the logic (issue 40, docs/design.md "Volumes in their stored type"):
// the node and the ITK image share one buffer both ways, a buffer someone else owns is wrapped without a copy and its
// owner held to the end, the logic samples the node's voxels in place with their rescale, and a view that would not
// fit is refused naming the bytes.
#include "vrLogicTestFixture.h"
#include "vrIntensityWindow.h"
#include "vrMemoryBudget.h"
#include "vrStoredVolume.h"
#include "vrTestFiles.h"

#include "itkCPRVolumeSampler.h"

#include <cstring>
#include <memory>

namespace
{
using namespace vr::test::logic;

/** The logic's CPR on \a volume (the two vessels' centerlines), at the quick parameters and \a interpolation. */
std::vector<float>
CPROf(vtkSmartPointer<vr::VolumeNode> volume,
      itk::CPRInterpolationMode       interpolation = itk::CPRInterpolationMode::Linear,
      const std::vector<Polyline> &   vessels = TwoVessels())
{
  VesselReformationLogic logic;
  logic.SetVolumeNode(volume);
  logic.SetCenterlineNode(MakeCenterlineNode(vessels));
  auto parameters = QuickParameters();
  parameters.AngleInDegrees = 25.0;
  parameters.Interpolation = interpolation;
  logic.SetParameters(parameters);
  const auto outputs = logic.Update();
  return vr::test::PixelsOf(vr::ConvertVolumeNodeToDepthImage(outputs.CPR).GetPointer());
}

/** A node like \a source whose voxels are \a vtkType, each value through \a transform. */
vtkSmartPointer<vr::VolumeNode>
NodeOfType(vr::VolumeNode * source, int vtkType, const std::function<double(double)> & transform)
{
  auto data = vtkSmartPointer<vtkImageData>::New();
  data->SetExtent(source->GetImageData()->GetExtent());
  data->AllocateScalars(vtkType, 1);
  vtkDataArray * from = source->GetImageData()->GetPointData()->GetScalars();
  vtkDataArray * to = data->GetPointData()->GetScalars();
  for (vtkIdType k = 0; k < from->GetNumberOfTuples(); ++k)
  {
    to->SetComponent(k, 0, transform(from->GetComponent(k, 0)));
  }
  auto node = vtkSmartPointer<vr::VolumeNode>::New();
  node->SetName(source->GetName() + " as " + data->GetScalarTypeAsString());
  node->SetImageData(data);
  node->SetIJKToRASMatrix(source->GetIJKToRASMatrix());
  return node;
}

bool
SameBits(const std::vector<float> & a, const std::vector<float> & b)
{
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0;
}

const void *
ScalarsOf(vr::VolumeNode * node)
{
  return node->GetImageData()->GetScalarPointer();
}
} // namespace

TEST(StoredVolumeNodes, NodeAndImageShareOneBufferBothWays)
{
  auto                             image = itk::Image<short, 3>::New();
  itk::Image<short, 3>::RegionType region;
  region.SetIndex({ { 1, 2, 3 } });
  region.SetSize({ { 5, 4, 3 } });
  image->SetRegions(region);
  image->SetSpacing(itk::detail::MakeVector3(0.5, 0.75, 2.0));
  image->Allocate();
  for (std::size_t k = 0; k < region.GetNumberOfPixels(); ++k)
  {
    image->GetBufferPointer()[k] = static_cast<short>(3 * k - 20);
  }
  const short *    voxels = image->GetBufferPointer();
  vr::StoredVolume stored{ image.GetPointer(), itk::CPRIntensityRescale{ 0.5, -1024.0 } };
  EXPECT_EQ(stored.GetPixelType(), itk::IOComponentEnum::SHORT);
  EXPECT_EQ(stored.GetVoxelBytes(), 60u * 2u);

  auto node = vr::ConvertStoredVolumeToVolumeNode(stored, "shared");
  EXPECT_EQ(ScalarsOf(node), voxels);
  EXPECT_EQ(node->GetImageData()->GetScalarType(), VTK_SHORT);
  EXPECT_EQ(node->GetIntensityRescale(), stored.Rescale);
  // IJK -> RAS by hand: spacing (0.5, 0.75, 2), identity direction, origin 0; LPS to RAS negates x and y.
  const auto   matrix = vr::IJKToRASMatrixOf(*image);
  const double expected[16] = { -0.5, 0, 0, 0, 0, -0.75, 0, 0, 0, 0, 2.0, 0, 0, 0, 0, 1 };
  for (int k = 0; k < 16; ++k)
  {
    EXPECT_EQ(matrix->GetElement(k / 4, k % 4), expected[k]) << k;
    EXPECT_EQ(node->GetIJKToRASMatrix()->GetElement(k / 4, k % 4), expected[k]) << k;
  }

  vr::StoredVolume back = vr::ConvertVolumeNodeToStoredVolume(node);
  EXPECT_EQ(back.GetBufferPointer(), voxels);
  EXPECT_EQ(back.Rescale, stored.Rescale);
  EXPECT_EQ(back.Image->GetBufferedRegion(), region);
  EXPECT_EQ(back.Image->GetSpacing(), image->GetSpacing());

  // Whatever goes first, the voxels stay while one user is left (AddressSanitizer would see a read of freed memory).
  stored.Image = nullptr;
  image = nullptr;
  node = nullptr;
  const auto * kept = dynamic_cast<const itk::Image<short, 3> *>(back.Image.GetPointer());
  ASSERT_NE(kept, nullptr);
  for (std::size_t k = 0; k < 60; ++k)
  {
    ASSERT_EQ(kept->GetBufferPointer()[k], static_cast<short>(3 * k - 20));
  }
  // The float copy applies the rescale.
  const auto floats = vr::ConvertStoredVolumeToFloat(back);
  EXPECT_EQ(floats->GetBufferPointer()[7], static_cast<float>(0.5 * (3 * 7 - 20) - 1024.0));
}

TEST(StoredVolumeNodes, WrappedBufferIsReadInPlaceAndItsOwnerHeldToTheEnd)
{
  auto voxels = std::make_shared<std::vector<unsigned short>>(4 * 3 * 2);
  for (std::size_t k = 0; k < voxels->size(); ++k)
  {
    (*voxels)[k] = static_cast<unsigned short>(1000 + k);
  }
  std::weak_ptr<std::vector<unsigned short>> watch = voxels;
  unsigned short *                           first = voxels->data();
  auto                                       matrix = vtkSmartPointer<vtkMatrix4x4>::New();
  matrix->SetElement(0, 0, 2.0);
  auto node = vr::WrapVoxelBuffer(first,
                                  itk::IOComponentEnum::USHORT,
                                  { { 4, 3, 2 } },
                                  matrix,
                                  voxels,
                                  "numpy",
                                  itk::CPRIntensityRescale{ 1.0, -1024.0 });
  voxels = nullptr;
  EXPECT_FALSE(watch.expired()) << "the node holds the owner";
  EXPECT_EQ(ScalarsOf(node), first);
  vr::StoredVolume image = vr::ConvertVolumeNodeToStoredVolume(node);
  EXPECT_EQ(image.GetBufferPointer(), first);
  EXPECT_EQ(image.GetPixelType(), itk::IOComponentEnum::USHORT);
  EXPECT_DOUBLE_EQ(image.Image->GetSpacing()[0], 2.0);
  node = nullptr;
  EXPECT_FALSE(watch.expired()) << "the image holds the node's array, which holds the owner";
  image.Image = nullptr;
  EXPECT_TRUE(watch.expired()) << "the last user gone, the owner is released";

  // Bad buffers are named.
  short one = 0;
  EXPECT_NE(vr::test::InputErrorOf(
              [&] {
                vr::WrapVoxelBuffer(nullptr, itk::IOComponentEnum::SHORT, { { 1, 1, 1 } }, nullptr, {}, "b");
              })
              .find("null pointer"),
            std::string::npos);
  EXPECT_NE(vr::test::InputErrorOf(
              [&] {
                vr::WrapVoxelBuffer(&one, itk::IOComponentEnum::INT, { { 1, 1, 1 } }, nullptr, {}, "b");
              })
              .find("is not one a volume is kept in"),
            std::string::npos);
  EXPECT_NE(vr::test::InputErrorOf(
              [&] {
                vr::WrapVoxelBuffer(&one, itk::IOComponentEnum::SHORT, { { 1, 0, 1 } }, nullptr, {}, "b");
              })
              .find("leave an axis empty"),
            std::string::npos);
  EXPECT_NE(
    vr::test::InputErrorOf(
      [&]
      {
        vr::WrapVoxelBuffer(
          &one, itk::IOComponentEnum::SHORT, { { 1, 1, 1 } }, nullptr, {}, "b", itk::CPRIntensityRescale{ 0.0, 1.0 });
      })
      .find("intensity rescale"),
    std::string::npos);
}

// The logic samples the node's own voxels: the resampler's volume reads the node's buffer, and a 16-bit volume gives
// the CPR of the same values as float, bit for bit (16-bit integers are exact in float).
TEST(StoredVolumeLogic, TheResamplerReadsTheNodesVoxelsInPlace)
{
  const auto             vessels = TwoVessels();
  auto                   shorts = MakeVolumeNode(vessels); // VTK_SHORT
  VesselReformationLogic logic;
  logic.SetVolumeNode(shorts);
  logic.SetCenterlineNode(MakeCenterlineNode(vessels));
  logic.SetParameters(QuickParameters());
  logic.Update();
  const auto * volume = dynamic_cast<const itk::Image<short, 3> *>(logic.GetResampleFilter()->GetVolume());
  ASSERT_NE(volume, nullptr) << "the volume stays int16";
  EXPECT_EQ(static_cast<const void *>(volume->GetBufferPointer()), ScalarsOf(shorts));
  EXPECT_EQ(logic.GetUnfilteredResampleFilter()->GetVolume(), logic.GetResampleFilter()->GetVolume());

  const auto floats = NodeOfType(shorts, VTK_FLOAT, [](double v) { return v; });
  for (const auto mode :
       { itk::CPRInterpolationMode::Linear, itk::CPRInterpolationMode::Nearest, itk::CPRInterpolationMode::Cubic })
  {
    SCOPED_TRACE(static_cast<int>(mode));
    EXPECT_TRUE(SameBits(CPROf(shorts, mode), CPROf(floats, mode)));
  }
  // A type that is not kept (32-bit integers) is converted to float: the same CPR again.
  EXPECT_TRUE(SameBits(CPROf(NodeOfType(shorts, VTK_INT, [](double v) { return v; })), CPROf(floats)));
}

// The node's rescale reaches the resampler: the CPR equals that of a double node of the rescaled values, bit for bit
// (the filter rescales each voxel it reads with the same double arithmetic), and the display window follows it.
TEST(StoredVolumeLogic, TheNodesRescaleIsSampledAsRescaledValuesInDouble)
{
  const itk::CPRIntensityRescale rescale{ 0.25, -100.5 };
  auto                           shorts = MakeVolumeNode(TwoVessels());
  shorts->SetIntensityRescale(rescale);
  const auto doubles =
    NodeOfType(shorts, VTK_DOUBLE, [&rescale](double stored) { return rescale.Slope * stored + rescale.Intercept; });
  EXPECT_TRUE(SameBits(CPROf(shorts), CPROf(doubles)));
  EXPECT_TRUE(
    SameBits(CPROf(shorts, itk::CPRInterpolationMode::Nearest), CPROf(doubles, itk::CPRInterpolationMode::Nearest)));

  double window = 0.0;
  double level = 0.0;
  double doubleWindow = 0.0;
  double doubleLevel = 0.0;
  vr::PercentileWindowOf(shorts, window, level);
  vr::PercentileWindowOf(doubles, doubleWindow, doubleLevel);
  EXPECT_DOUBLE_EQ(window, doubleWindow);
  EXPECT_DOUBLE_EQ(level, doubleLevel);
  // Unsigned voxels with DICOM's -1024 intercept are a CT in HU.
  auto unsignedCT = NodeOfType(shorts, VTK_UNSIGNED_SHORT, [](double) { return 10.0; });
  EXPECT_EQ(vr::IntensityUnitOf(unsignedCT), "");
  unsignedCT->SetIntensityRescale(itk::CPRIntensityRescale{ 1.0, -1024.0 });
  EXPECT_EQ(vr::IntensityUnitOf(unsignedCT), "HU");
}

// A view too large for memory is refused before anything is allocated; the message names the bytes it would need
// and the bytes available, and with cubic interpolation the volume's coefficients among them.
TEST(StoredVolumeLogic, AViewThatDoesNotFitIsRefusedNamingTheBytes)
{
  const auto             vessels = TwoVessels();
  VesselReformationLogic logic;
  logic.SetVolumeNode(MakeVolumeNode(vessels));
  logic.SetCenterlineNode(MakeCenterlineNode(vessels));
  auto parameters = QuickParameters();
  parameters.ImageSize[0] = 400000;
  parameters.ImageSize[1] = 400000;
  logic.SetParameters(parameters);
  try
  {
    logic.Update();
    FAIL() << "no error";
  }
  catch (const vr::InputError & error)
  {
    const std::string message = error.what();
    EXPECT_EQ(error.Parameter(), vr::ParameterName::ViewSize);
    EXPECT_NE(message.find("view size = 400000,400000: the reformation would need about"), std::string::npos)
      << message;
    EXPECT_NE(message.find(" bytes), more than the "), std::string::npos) << message;
    EXPECT_NE(message.find(" bytes) of memory available"), std::string::npos) << message;
    EXPECT_EQ(message.find("cubic"), std::string::npos) << message;
  }
  parameters.Interpolation = itk::CPRInterpolationMode::Cubic;
  logic.SetParameters(parameters);
  const std::string cubic = vr::test::InputErrorOf([&] { logic.Update(); });
  // 40 x 40 x 50 voxels, two filters' float coefficients: 640,000 bytes.
  EXPECT_NE(cubic.find("(of it 0.61 MiB (640,000 bytes) for the cubic interpolation's coefficients of the volume)"),
            std::string::npos)
    << cubic;
  EXPECT_NE(cubic.find("or linear interpolation"), std::string::npos) << cubic;
  EXPECT_DOUBLE_EQ(vr::EstimateVolumeSamplingBytes(1e6, itk::CPRInterpolationMode::Linear), 0.0);
  EXPECT_DOUBLE_EQ(vr::EstimateVolumeSamplingBytes(1e6, itk::CPRInterpolationMode::Cubic), 8e6);
}
