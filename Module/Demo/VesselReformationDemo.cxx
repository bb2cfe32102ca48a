// The main job on a built-in default: a synthetic leg run-off CTA, reformatted as a multipath CPR with and
// without bilateral depth filtering, written as pictures (the paper's Figure 2 among them).
//
//   VesselReformationDemo [--output DIR] [--angle DEG] [--size W,H] [--iterations N] [--backend B]

#include "itkBilateralDepthRelaxFilter.h"
#include "itkCPRDepthImageFilter.h"
#include "itkCPRResampleImageFilter.h"
#include "itkRunoffPhantomImageSource.h"
#include "vrFigure.h"
#include "vrInputError.h"
#include "vrRelaxBackend.h"

#include <CLI/CLI.hpp>

#include <chrono>
#include <filesystem>
#include <iomanip>
#include <iostream>

namespace
{
using DepthImage = itk::Image<float, 2>;
using VolumeImage = itk::Image<float, 3>;
using Clock = std::chrono::steady_clock;

// A CTA window that shows contrast-filled lumen, soft tissue and bone at once.
constexpr double Window = 900.0;
constexpr double Level = 200.0;

double
Milliseconds(Clock::time_point start)
{
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

struct Result
{
  DepthImage::Pointer Depth;
  DepthImage::Pointer CPR;
  double              RelaxMilliseconds{ 0.0 };
};

DepthImage::Pointer
Resample(const VolumeImage * volume, const DepthImage * depth)
{
  auto resample = itk::CPRResampleImageFilter<VolumeImage, DepthImage, DepthImage>::New();
  resample->SetVolume(volume);
  resample->SetDepth(depth);
  resample->SetDefaultValue(-1000.0f); // air around the patient
  resample->Update();
  DepthImage::Pointer cpr = resample->GetOutput();
  cpr->DisconnectPipeline();
  return cpr;
}

Result
Relax(itk::CPRDepthImageFilter<DepthImage> * depth, const VolumeImage * volume, double w, double a,
      unsigned int iterations, vr::RelaxBackend backend)
{
  std::string notice;
  auto        relax = vr::CreateRelaxFilter(backend, "", notice);
  if (!notice.empty())
  {
    std::cout << "  note: " << notice << std::endl;
  }
  relax->SetInput(depth->GetDepthOutput());
  relax->SetFixedMask(depth->GetFixedMaskOutput());
  relax->SetRelaxation(w);
  relax->SetAnisotropy(a);
  relax->SetNumberOfIterations(iterations);
  const auto start = Clock::now();
  relax->Update();
  Result result;
  result.RelaxMilliseconds = Milliseconds(start);
  result.Depth = relax->GetOutput();
  result.Depth->DisconnectPipeline();
  result.CPR = Resample(volume, result.Depth);
  return result;
}

std::string
Parameters(double w, double a)
{
  std::ostringstream stream;
  stream << "w = " << w << ", a = " << a << " mm^-2";
  return stream.str();
}
} // namespace

int
main(int argc, char * argv[])
{
  CLI::App    app{ "VesselReformation demo: a synthetic leg run-off CTA, reformatted with and without bilateral "
                "depth filtering (Kretschmer et al., EuroVis 2014). Writes PNG pictures." };
  std::string output = "vessel-reformation-demo";
  double      angle = 30.0;
  std::vector<unsigned int> size = { 512, 1024 };
  unsigned int              iterations = 500;
  double                    spacing = 1.5;
  std::string               backendName = "auto";
  app.add_option("--output", output, "folder for the pictures")->capture_default_str();
  app.add_option("--angle", angle, "view angle about the patient's superior axis, degrees")->capture_default_str();
  app.add_option("--size", size, "CPR image size W,H in pixels")->delimiter(',')->expected(2)->capture_default_str();
  app.add_option("--iterations", iterations, "bilateral filter iterations")->capture_default_str();
  app.add_option("--phantomSpacing", spacing, "voxel spacing of the phantom, mm")->capture_default_str();
  app.add_option("--backend", backendName, "relax filter backend: auto, cpu or opencl")->capture_default_str();
  CLI11_PARSE(app, argc, argv);

  try
  {
    const vr::RelaxBackend backend = vr::ParseRelaxBackend(backendName, "--backend");
    if (size[0] == 0 || size[1] == 0)
    {
      throw vr::InputError("--size " + std::to_string(size[0]) + "," + std::to_string(size[1]) +
                           ": both must be >= 1");
    }
    std::filesystem::create_directories(output);
    std::cout << "VesselReformation demo: synthetic run-off CTA, view " << angle << " degrees about superior, "
              << size[0] << " x " << size[1] << " pixels" << std::endl;

    auto start = Clock::now();
    auto phantom = itk::RunoffPhantomImageSource::New();
    phantom->SetSpacing(spacing);
    phantom->Update();
    const auto volumeSize = phantom->GetOutput()->GetLargestPossibleRegion().GetSize();
    std::cout << "  phantom " << volumeSize[0] << " x " << volumeSize[1] << " x " << volumeSize[2] << " voxels at "
              << spacing << " mm: " << std::fixed << std::setprecision(0) << Milliseconds(start) << " ms"
              << std::endl;

    start = Clock::now();
    auto depth = itk::CPRDepthImageFilter<DepthImage>::New();
    depth->SetCenterlineTree(phantom->GetCenterlineTree());
    itk::CPRViewSpecification view;
    view.AngleInDegrees = angle;
    view.ImageSize[0] = size[0];
    view.ImageSize[1] = size[1];
    depth->SetViewSpecification(view);
    depth->SetReferenceVolume(phantom->GetOutput());
    depth->Update();
    std::cout << "  mpCPR depth map: " << Milliseconds(start) << " ms" << std::endl;

    const VolumeImage * volume = phantom->GetOutput();
    const Result unfiltered{ depth->GetDepthOutput(), Resample(volume, depth->GetDepthOutput()), 0.0 };
    const Result isotropic = Relax(depth, volume, 1.0, 0.0, iterations, backend);
    std::cout << "  isotropic relaxation (" << Parameters(1.0, 0.0) << ", " << iterations
              << " iterations): " << isotropic.RelaxMilliseconds << " ms" << std::endl;
    const Result bilateral = Relax(depth, volume, 1.0, 0.5, iterations, backend);
    std::cout << "  bilateral relaxation (" << Parameters(1.0, 0.5) << ", " << iterations
              << " iterations): " << bilateral.RelaxMilliseconds << " ms" << std::endl;

    // One colour range for every depth map, so they compare.
    const auto * values = unfiltered.Depth->GetBufferPointer();
    const auto   count = unfiltered.Depth->GetBufferedRegion().GetNumberOfPixels();
    const double nearest = *std::min_element(values, values + count);
    const double farthest = *std::max_element(values, values + count);

    const auto path = [&](const char * name) { return (std::filesystem::path(output) / name).string(); };
    const auto unfilteredCPR = vr::RenderWindowLevel(unfiltered.CPR, Window, Level);
    const auto isotropicCPR = vr::RenderWindowLevel(isotropic.CPR, Window, Level);
    const auto bilateralCPR = vr::RenderWindowLevel(bilateral.CPR, Window, Level);
    const auto unfilteredDepth = vr::RenderDepth(unfiltered.Depth, nearest, farthest);
    const auto isotropicDepth = vr::RenderDepth(isotropic.Depth, nearest, farthest);
    const auto bilateralDepth = vr::RenderDepth(bilateral.Depth, nearest, farthest);
    vr::WriteRGBPNG(unfilteredCPR, path("cpr-unfiltered.png"));
    vr::WriteRGBPNG(bilateralCPR, path("cpr-filtered.png"));
    vr::WriteRGBPNG(unfilteredDepth, path("depth-unfiltered.png"));
    vr::WriteRGBPNG(bilateralDepth, path("depth-filtered.png"));

    const std::string unfilteredTitle = "unfiltered (w = 0)";
    const std::string isotropicTitle = "isotropic (" + Parameters(1.0, 0.0) + ")";
    const std::string bilateralTitle = "bilateral (" + Parameters(1.0, 0.5) + ")";
    std::ostringstream caption;
    caption << "Synthetic run-off CTA, mpCPR at " << angle << " degrees, " << iterations
            << " iterations. Top: CPR (W " << Window << " / L " << Level << " HU). Bottom: depth map.";
    // A detail of the patient's left thigh and knee (the screen's right half), magnified, with the depth in a
    // tight colour range: there the small seams are what the eye sees.
    const unsigned int detailX = static_cast<unsigned int>(0.50 * size[0]);
    const unsigned int detailY = static_cast<unsigned int>(0.35 * size[1]);
    const unsigned int detailWidth = static_cast<unsigned int>(0.30 * size[0]);
    const unsigned int detailHeight = static_cast<unsigned int>(0.30 * size[1]);
    const auto [detailNear, detailFar] =
      vr::RangeWithin(unfiltered.Depth, detailX, detailY, detailWidth, detailHeight, 0.05, 0.95);
    const unsigned int panelWidth = (3 * size[0] + 16) / 4;
    auto detail = [&](const vr::RGBImageType * image) {
      return vr::Magnify(vr::Crop(image, detailX, detailY, detailWidth, detailHeight), panelWidth);
    };
    const auto figure = vr::ComposeFigure(
      { { { unfilteredCPR, unfilteredTitle }, { isotropicCPR, isotropicTitle }, { bilateralCPR, bilateralTitle } },
        { { unfilteredDepth, "depth, unfiltered" },
          { isotropicDepth, "depth, isotropic" },
          { bilateralDepth, "depth, bilateral" } },
        { { vr::RenderDepthColorBar(nearest, farthest, size[0]), "" } },
        { { detail(unfilteredCPR), "detail: left thigh, unfiltered" },
          { detail(bilateralCPR), "detail: bilateral" },
          { detail(vr::RenderDepthRelief(unfiltered.Depth, detailNear, detailFar)), "detail depth (relief), unfiltered" },
          { detail(vr::RenderDepthRelief(bilateral.Depth, detailNear, detailFar)), "detail depth (relief), bilateral" } },
        { { vr::RenderDepthColorBar(detailNear, detailFar, size[0]), "" } } },
      caption.str());
    vr::WriteRGBPNG(figure, path("figure2-comparison.png"));

    std::cout << "Wrote to " << std::filesystem::absolute(output).string() << ":" << std::endl
              << "  cpr-unfiltered.png, cpr-filtered.png     the CPR before and after bilateral filtering" << std::endl
              << "  depth-unfiltered.png, depth-filtered.png the depth maps (viridis: near dark, far yellow)"
              << std::endl
              << "  figure2-comparison.png                   unfiltered | isotropic | bilateral (the paper's Fig. 2)"
              << std::endl;
    return EXIT_SUCCESS;
  }
  catch (const vr::InputError & error)
  {
    std::cerr << "error: " << error.what() << std::endl;
  }
  catch (const itk::ExceptionObject & error)
  {
    std::cerr << "error: " << error.GetDescription() << std::endl;
  }
  catch (const std::exception & error)
  {
    std::cerr << "error: " << error.what() << std::endl;
  }
  return EXIT_FAILURE;
}
