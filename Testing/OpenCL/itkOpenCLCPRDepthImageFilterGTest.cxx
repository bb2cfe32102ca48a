// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// The OpenCL depth filter against the CPU filter (docs/opencl.md "The whole view on the device"): the same depth
// map, fixed mask and owner labels, bit for bit, on both phantoms and the VMTK aorta, in both modes, at sizes that
// cut the device's work-groups unevenly; the fallback to the CPU for a mode without a kernel; the hand-off of the
// depth map and the mask to the relaxation on the device. Skipped, with the reason, without an OpenCL device.
#include "itkBilateralDepthRelaxFilter.h"
#include "itkCPRDepthImageFilter.h"
#include "itkCTAPhantom.h"
#include "itkOpenCLBilateralDepthRelaxFilter.h"
#include "itkOpenCLCPRDepthImageFilter.h"
#include "vrCenterlineIO.h"
#include "vrOpenCLSession.h"
#include "vrOpenCLTestSupport.h"
#include "vrTestImages.h"
#include "vrVolumeIO.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace
{
using CPUFilter = itk::CPRDepthImageFilter<itk::Image<float, 2>>;
using OpenCLFilter = itk::OpenCLCPRDepthImageFilter;

/** A tree and the volume whose geometry gives the view its defaults (null for none). */
struct Scene
{
  std::string                     Name;
  itk::CenterlineTree             Tree;
  itk::ImageBase<3>::ConstPointer Reference;
};

const Scene &
RunoffScene()
{
  static const Scene scene{ "run-off phantom", itk::MakeCTAPhantom(itk::CTAPhantomKind::Runoff).Tree, nullptr };
  return scene;
}

const Scene &
ThoraxScene()
{
  static const Scene scene{ "thoracic phantom", itk::MakeCTAPhantom(itk::CTAPhantomKind::Thorax).Tree, nullptr };
  return scene;
}

const Scene &
AortaScene()
{
  static const Scene scene = []
  {
    const std::filesystem::path folder = std::filesystem::path(VR_SHARED_DATA_DIR) / "vmtk-aorta-mra";
    return Scene{ "VMTK aorta",
                  vr::ReadCenterlines((folder / "aorta-centerline.vtp").string()),
                  vr::ReadVolume((folder / "aorta.mha").string()).GetPointer() };
  }();
  return scene;
}

itk::CPRViewSpecification
View(unsigned int width, unsigned int height, double angle, bool automaticUp = false)
{
  itk::CPRViewSpecification view;
  view.ImageSize[0] = width;
  view.ImageSize[1] = height;
  view.AngleInDegrees = angle;
  view.AutomaticUp = automaticUp;
  return view;
}

template<typename TFilter>
void
Configure(TFilter *                         filter,
          const Scene &                     scene,
          const itk::CPRViewSpecification & view,
          itk::CPRDepthMode                 mode,
          bool                              fixLumen)
{
  filter->SetCenterlineTree(scene.Tree);
  filter->SetReferenceVolume(scene.Reference);
  filter->SetViewSpecification(view);
  filter->SetMode(mode);
  filter->SetFixLumen(fixLumen);
}

/** Runs both filters and expects the same three outputs, bit for bit. */
void
ExpectSameAsCPU(const Scene & scene, const itk::CPRViewSpecification & view, itk::CPRDepthMode mode, bool fixLumen)
{
  auto cpu = CPUFilter::New();
  auto opencl = OpenCLFilter::New();
  Configure(cpu.GetPointer(), scene, view, mode, fixLumen);
  Configure(opencl.GetPointer(), scene, view, mode, fixLumen);
  cpu->Update();
  opencl->Update();
  const std::string what = scene.Name + ", " + std::to_string(view.ImageSize[0]) + " x " +
                           std::to_string(view.ImageSize[1]) + ", " + std::to_string(view.AngleInDegrees) +
                           " degrees, " + (mode == itk::CPRDepthMode::Scanline ? "Scanline" : "Nearest") +
                           (fixLumen ? ", lumen fixed" : "");
  EXPECT_EQ(opencl->GetHostReason(), "") << what;
  EXPECT_EQ(vr::test::PixelsOf(opencl->GetDepthOutput()), vr::test::PixelsOf(cpu->GetDepthOutput())) << what;
  EXPECT_EQ(vr::test::PixelsOf(opencl->GetFixedMaskOutput()), vr::test::PixelsOf(cpu->GetFixedMaskOutput())) << what;
  EXPECT_EQ(vr::test::PixelsOf(opencl->GetOwnerLabelOutput()), vr::test::PixelsOf(cpu->GetOwnerLabelOutput())) << what;
  // Not vacuous: the map has centerline pixels, fixed pixels and depth that varies.
  const auto fixed = vr::test::PixelsOf(cpu->GetFixedMaskOutput());
  EXPECT_GT(std::count(fixed.begin(), fixed.end(), 1), 0) << what;
  EXPECT_EQ(opencl->GetView(), cpu->GetView()) << what;
}
} // namespace

TEST(OpenCLCPRDepth, ScanlineAndNearestMatchTheCPUBitForBitOnBothPhantoms)
{
  VR_SKIP_WITHOUT_OPENCL_DEVICE();
  for (const Scene * scene : { &RunoffScene(), &ThoraxScene() })
  {
    for (const auto mode : { itk::CPRDepthMode::Scanline, itk::CPRDepthMode::Nearest })
    {
      for (const bool fixLumen : { true, false })
      {
        ExpectSameAsCPU(*scene, View(256, 512, 30.0), mode, fixLumen);
      }
      // Rows and columns longer than a work-group's scan (128), sizes no multiple of anything; another angle.
      ExpectSameAsCPU(*scene, View(301, 517, 95.0), mode, true);
      ExpectSameAsCPU(*scene, View(7, 5, 10.0), mode, true);
    }
  }
  ExpectSameAsCPU(RunoffScene(), View(512, 1024, 30.0), itk::CPRDepthMode::Scanline, true);
}

// The real aorta: the view's defaults from the volume (automatic up, the volume's spacing), the two iliacs in front
// of each other at 90 degrees, radii from VMTK.
TEST(OpenCLCPRDepth, ScanlineAndNearestMatchTheCPUBitForBitOnTheVMTKAorta)
{
  VR_SKIP_WITHOUT_OPENCL_DEVICE();
  for (const auto mode : { itk::CPRDepthMode::Scanline, itk::CPRDepthMode::Nearest })
  {
    for (const double angle : { 0.0, 90.0, 137.0 })
    {
      ExpectSameAsCPU(AortaScene(), View(256, 512, angle, true), mode, true);
    }
    ExpectSameAsCPU(AortaScene(), View(0, 0, 45.0, true), mode, true); // the size that fits the tree
  }
}

// A depth mode without an OpenCL kernel is the CPU filter's work: the same outputs, and a reason that names it.
TEST(OpenCLCPRDepth, AModeWithoutAKernelIsComputedOnTheCPUAndSaysWhy)
{
  VR_SKIP_WITHOUT_OPENCL_DEVICE();
  const auto other = static_cast<itk::CPRDepthMode>(static_cast<int>(itk::CPRDepthMode::Nearest) + 1);
  auto       cpu = CPUFilter::New();
  auto       opencl = OpenCLFilter::New();
  Configure(cpu.GetPointer(), RunoffScene(), View(64, 128, 30.0), other, true);
  Configure(opencl.GetPointer(), RunoffScene(), View(64, 128, 30.0), other, true);
  cpu->Update();
  opencl->Update();
  EXPECT_NE(opencl->GetHostReason().find("has no OpenCL kernel: the CPU computes the depth map"), std::string::npos)
    << opencl->GetHostReason();
  EXPECT_EQ(vr::test::PixelsOf(opencl->GetDepthOutput()), vr::test::PixelsOf(cpu->GetDepthOutput()));

  // Back to a mode with a kernel: the device again, and no reason left over.
  opencl->SetMode(itk::CPRDepthMode::Scanline);
  opencl->Update();
  EXPECT_EQ(opencl->GetHostReason(), "");
}

TEST(OpenCLCPRDepth, AViewWithoutCenterlinesFailsWithTheCPUFiltersMessage)
{
  VR_SKIP_WITHOUT_OPENCL_DEVICE();
  itk::CPRViewSpecification view = View(32, 32, 30.0);
  view.HasCenter = true;
  view.Center = vr::test::P(5000.0, 5000.0, 5000.0);
  view.PixelSpacing[0] = view.PixelSpacing[1] = 1.0;
  auto opencl = OpenCLFilter::New();
  Configure(opencl.GetPointer(), RunoffScene(), view, itk::CPRDepthMode::Scanline, true);
  try
  {
    opencl->Update();
    FAIL() << "a view without centerlines gave a depth map";
  }
  catch (const itk::ExceptionObject & error)
  {
    EXPECT_NE(std::string(error.GetDescription()).find("no centerline point projects into the 32 x 32 image"),
              std::string::npos)
      << error.GetDescription();
  }
}

// The relaxation of the same session reads the depth map and the mask from the device (no upload), with the same
// bits as from uploaded copies; a new view is handed on again.
TEST(OpenCLCPRDepth, TheRelaxationOfTheSameSessionReadsTheDepthMapOnTheDevice)
{
  VR_SKIP_WITHOUT_OPENCL_DEVICE();
  const auto session = vr::OpenCLSession::Create("", "test");
  auto       depth = OpenCLFilter::New();
  depth->SetSession(session);
  Configure(depth.GetPointer(), RunoffScene(), View(200, 300, 30.0), itk::CPRDepthMode::Scanline, true);
  auto relax = itk::OpenCLBilateralDepthRelaxFilter::New();
  relax->SetSession(session);
  relax->SetInput(depth->GetDepthOutput());
  relax->SetFixedMask(depth->GetFixedMaskOutput());
  relax->SetNumberOfIterations(50);
  for (const double angle : { 30.0, 31.0 })
  {
    depth->SetViewSpecification(View(200, 300, angle));
    const std::size_t handOffs = session->GetDeviceHandOffs();
    relax->Update();
    EXPECT_TRUE(relax->GetInputsWereOnDevice());
    EXPECT_EQ(session->GetDeviceHandOffs(), handOffs + 2); // the depth map and the mask

    // The same relaxation from host copies (another filter, its own session): the same bits.
    auto copy = itk::OpenCLBilateralDepthRelaxFilter::New();
    auto depthCopy = vr::test::MakeDepthImage(200, 300, vr::test::PixelsOf(depth->GetDepthOutput()));
    auto maskCopy = vr::test::MakeMaskImage(200, 300, vr::test::PixelsOf(depth->GetFixedMaskOutput()));
    copy->SetInput(depthCopy);
    copy->SetFixedMask(maskCopy);
    copy->SetNumberOfIterations(50);
    copy->Update();
    EXPECT_FALSE(copy->GetInputsWereOnDevice());
    EXPECT_EQ(vr::test::PixelsOf(relax->GetOutput()), vr::test::PixelsOf(copy->GetOutput())) << angle << " degrees";
  }
}

// A relaxation in another session uploads (it cannot read another context's buffers).
TEST(OpenCLCPRDepth, ARelaxationInAnotherSessionUploads)
{
  VR_SKIP_WITHOUT_OPENCL_DEVICE();
  auto depth = OpenCLFilter::New();
  Configure(depth.GetPointer(), RunoffScene(), View(64, 96, 30.0), itk::CPRDepthMode::Scanline, true);
  auto relax = itk::OpenCLBilateralDepthRelaxFilter::New();
  relax->SetInput(depth->GetDepthOutput());
  relax->SetFixedMask(depth->GetFixedMaskOutput());
  relax->SetNumberOfIterations(5);
  relax->Update();
  EXPECT_FALSE(relax->GetInputsWereOnDevice());
}

// An output disconnected from the depth filter keeps its host pixels while the filter computes a new view into its
// device buffers: the relaxation must then upload it, not read the device buffer that holds the newer view.
TEST(OpenCLCPRDepth, AnOutputDisconnectedBeforeTheNextViewIsUploadedNotReadFromTheDevice)
{
  VR_SKIP_WITHOUT_OPENCL_DEVICE();
  const auto session = vr::OpenCLSession::Create("", "test");
  auto       depth = OpenCLFilter::New();
  depth->SetSession(session);
  Configure(depth.GetPointer(), RunoffScene(), View(120, 200, 30.0), itk::CPRDepthMode::Scanline, true);
  depth->Update();
  itk::Image<float, 2>::Pointer old = depth->GetDepthOutput();
  old->DisconnectPipeline();
  const auto oldPixels = vr::test::PixelsOf(old.GetPointer());
  depth->SetViewSpecification(View(120, 200, 45.0));
  depth->Update();
  ASSERT_NE(vr::test::PixelsOf(depth->GetDepthOutput()), oldPixels);

  auto relax = itk::OpenCLBilateralDepthRelaxFilter::New();
  relax->SetSession(session);
  relax->SetInput(old);
  relax->SetNumberOfIterations(20);
  relax->Update();
  EXPECT_FALSE(relax->GetInputsWereOnDevice());
  auto reference = itk::OpenCLBilateralDepthRelaxFilter::New();
  reference->SetInput(vr::test::MakeDepthImage(120, 200, oldPixels));
  reference->SetNumberOfIterations(20);
  reference->Update();
  EXPECT_EQ(vr::test::PixelsOf(relax->GetOutput()), vr::test::PixelsOf(reference->GetOutput()));
}
