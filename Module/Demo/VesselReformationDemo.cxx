// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// The main job on a built-in default: a synthetic CTA (leg run-off or thorax), reformatted as a multipath CPR with
// and without bilateral depth filtering, written as pictures (the paper's Figure 2, or its thoracic figure).
//
//   VesselReformationDemo [--phantom runoff|thorax] [--output DIR] [--angle DEG] [--size W,H] [--iterations N]
//                         [--solver jacobi|steady] [--backend B] [--mode scanline|nearest|visibility]
//   VesselReformationDemo --phantom runoff|thorax [--phantomSpacing MM] --writePhantom DIR
//                         only writes the phantom's volume and exact centerlines there, as inputs for other tools

#include "itkCTAPhantom.h"
#include "vrFigure.h"
#include "vrFilterSettingsText.h"
#include "vrCenterlineIO.h"
#include "vrInputError.h"
#include "vrNodeConversion.h"
#include "vrOutputWriter.h"
#include "vrVesselReformationLogic.h"
#include "vrVolumeIO.h"
#include "vrVisibilityFigure.h"

#include <CLI/CLI.hpp>

#include <chrono>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <optional>
#include <sstream>

namespace
{
using DepthImage = itk::Image<float, 2>;
using Clock = std::chrono::steady_clock;

// A CTA window that shows contrast-filled lumen, soft tissue and bone at once.
constexpr double Window = 900.0;
constexpr double Level = 200.0;

double
Milliseconds(Clock::time_point start)
{
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

/** A relaxed depth map and the CPR sampled on it. */
struct Result
{
  DepthImage::Pointer Depth;
  DepthImage::Pointer CPR;
};

/** Where each phantom's seams are what the eye should see: a detail rectangle, in fractions of the image. */
struct DetailRegion
{
  double       X, Y, Width, Height;
  const char * Name;
};

void
PrintStages(const vr::ReformationOutputs &     outputs,
            const vr::ReformationStageCounts & before,
            const vr::ReformationStageCounts & after)
{
  auto line = [](const char * stage, double seconds, unsigned int runs)
  {
    std::cout << "    " << std::left << std::setw(11) << stage << std::right
              << (runs ? std::to_string(static_cast<long>(std::lround(seconds * 1000.0))) + " ms" : "not rerun")
              << std::endl;
  };
  line("conversion", outputs.Times.Conversion, after.Conversion - before.Conversion);
  line("depth", outputs.Times.Depth, after.Depth - before.Depth);
  line("relax", outputs.Times.Relax, after.Relax - before.Relax);
  line("resample", outputs.Times.Resample, after.Resample - before.Resample);
  line("surface", outputs.Times.Surface, after.Surface - before.Surface);
}

int
RunDemo(int argc, char * argv[])
{
  CLI::App    app{ "VesselReformation demo: a synthetic CTA (leg run-off or thorax), reformatted with and without "
                   "bilateral depth filtering (Kretschmer et al., EuroVis 2014) through the module logic. Writes PNG "
                   "pictures, NRRD images and the cut surface." };
  std::string output = "vessel-reformation-demo";
  std::string phantomName = "runoff";
  std::string solverName = "jacobi";
  double      angle = 0.0;
  std::vector<unsigned int> size = { 512, 1024 };
  long long                 iterations = 500;
  double                    spacing = 1.5;
  std::string               backendName = "auto";
  std::string               phantomFolder;
  std::string               modeName = "scanline";
  app.add_option("--phantom", phantomName, "the synthetic CTA: runoff (legs) or thorax (aortic arch)")
    ->capture_default_str();
  app.add_option("--output", output, "folder for the pictures")->capture_default_str();
  auto * angleOption = app.add_option("--angle",
                                      angle,
                                      "view angle about the patient's superior axis, degrees (default: the "
                                      "phantom's design angle, 30 for runoff, 0 for thorax)");
  app.add_option("--size", size, "CPR image size W,H in pixels")->delimiter(',')->expected(2)->capture_default_str();
  app.add_option("--iterations", iterations, "bilateral filter iterations")->capture_default_str();
  app.add_option("--phantomSpacing", spacing, "voxel spacing of the phantom, mm")->capture_default_str();
  app.add_option("--solver", solverName, "relaxation solver: jacobi (the paper's N passes) or steady (fixed point)")
    ->capture_default_str();
  app.add_option("--backend", backendName, "relax filter backend: auto, cpu or opencl")->capture_default_str();
  app.add_option("--writePhantom",
                 phantomFolder,
                 "only write the phantom's volume (<phantom>.nrrd, HU) and exact centerlines "
                 "(<phantom>-centerlines.vtp, RAS as VMTK writes them) into this folder, and stop");
  app
    .add_option("--mode",
                modeName,
                "depth mode: scanline, nearest or visibility (visibility also writes visibility-comparison.png, "
                "scanline beside visibility; without --angle at the angle that hides the most)")
    ->capture_default_str();
  CLI11_PARSE(app, argc, argv);

  try
  {
    itk::CTAPhantomKind kind;
    try
    {
      kind = itk::ParseCTAPhantomKind(phantomName);
    }
    catch (const std::invalid_argument & error)
    {
      throw vr::InputError(std::string("--phantom: ") + error.what());
    }
    const bool thorax = kind == itk::CTAPhantomKind::Thorax;
    auto       phantom = itk::MakeCTAPhantom(kind, spacing);
    if (!phantomFolder.empty())
    {
      // Inputs for the modules, the Python package or a cohort: the files a user's own data would come as.
      std::filesystem::create_directories(phantomFolder);
      const auto base = std::filesystem::path(phantomFolder) / phantom.Name;
      phantom.Source->Update();
      vr::WriteVolume(phantom.Source->GetOutput(), base.string() + ".nrrd");
      vr::WriteCenterlines(phantom.Tree, base.string() + "-centerlines.vtp");
      std::cout << "VesselReformation demo: " << phantom.Description << " written to " << base.string() << ".nrrd and "
                << base.string() << "-centerlines.vtp" << std::endl;
      return EXIT_SUCCESS;
    }
    if (angleOption->count() == 0)
    {
      angle = phantom.DesignAngleInDegrees;
    }
    vr::ReformationParameters parameters;
    parameters.AngleInDegrees = angle;
    parameters.ImageSize[0] = size[0];
    parameters.ImageSize[1] = size[1];
    parameters.Iterations = iterations;
    parameters.Backend = vr::ParseRelaxBackend(backendName, "--backend");
    parameters.Relaxation = 1.0;
    parameters.Solver = vr::ParseRelaxSolver(solverName, "--solver");
    parameters.Mode = vr::ParseDepthMode(modeName, "--mode");
    const bool visibility = parameters.Mode == itk::CPRDepthMode::Visibility;
    parameters.Validate();
    std::filesystem::create_directories(output);
    const bool         chooseAngle = visibility && angleOption->count() == 0;
    std::ostringstream shownAngle;
    shownAngle << angle << " degrees";
    std::cout << "VesselReformation demo: " << phantom.Description << ", view "
              << (chooseAngle ? std::string("at the angle that hides the most (below)") : shownAngle.str())
              << " about superior, " << size[0] << " x " << size[1] << " pixels" << std::endl;

    auto start = Clock::now();
    phantom.Source->Update();
    const auto volumeSize = phantom.Source->GetOutput()->GetLargestPossibleRegion().GetSize();
    std::cout << "  phantom " << volumeSize[0] << " x " << volumeSize[1] << " x " << volumeSize[2] << " voxels at "
              << spacing << " mm, " << phantom.Tree.GetNumberOfBranches()
              << " arteries: " << std::lround(Milliseconds(start)) << " ms" << std::endl;

    // The platform's view of the data: a volume node and a centerline node in RAS, as a 3D Slicer scene holds them.
    vr::VesselReformationLogic logic;
    const std::string          nodeName = thorax ? "Thorax" : "Runoff";
    logic.SetVolumeNode(vr::ConvertItkImageToVolumeNode(phantom.Source->GetOutput(), nodeName + "Phantom"));
    logic.SetCenterlineNode(vr::ConvertTreeToCenterlineNode(phantom.Tree, nodeName + "Centerlines"));
    logic.SetWarningCallback([](const std::string & message, const std::string &)
                             { std::cout << "  warning: " << message << std::endl; });
    if (visibility)
    {
      // Where overlaps matter most: the occlusion profile over 0-179 degrees (the logic's, about the same view).
      logic.SetOcclusionProfileEnabled(true);
      logic.SetParameters(parameters);
      const auto         profile = logic.Update().OcclusionProfile;
      const unsigned int worst = profile->MostOccludedAngle();
      const unsigned int best = profile->LeastOccludedAngle();
      std::cout << "  occlusion profile: " << std::lround(profile->HiddenLength[worst]) << " of "
                << std::lround(profile->TreeLength) << " mm hidden at " << worst << " degrees (the most), "
                << std::lround(profile->HiddenLength[best]) << " mm at " << best << " degrees (the least)" << std::endl;
      if (chooseAngle)
      {
        angle = worst;
        parameters.AngleInDegrees = angle;
        std::cout << "  view at " << angle << " degrees, where vessels hide each other the most" << std::endl;
      }
    }

    // The middle column: plain smoothing (a = 0) on the run-off phantom, as in the paper's Figure 2; on the thorax the
    // paper's a = 0.5 mm^-2, which leaves the arch's seams of 2-10 mm in place. The right column: our default J.
    auto run = [&](std::optional<double> anisotropy, const char * what)
    {
      parameters.Anisotropy = anisotropy;
      logic.SetParameters(parameters);
      const auto   before = logic.GetStageCounts();
      const auto & outputs = logic.Update();
      std::cout << "  " << what << " relaxation (" << vr::DescribeFilterSettings(parameters) << ", "
                << outputs.RelaxBackendUsed << "):" << std::endl;
      std::cout << "    backend    " << outputs.RelaxBackendUsed << ": " << outputs.RelaxBackendReason << std::endl;
      std::cout << "    view       depth map on " << outputs.DepthBackendUsed << ", resampling on "
                << outputs.ResampleBackendUsed << std::endl;
      PrintStages(outputs, before, logic.GetStageCounts());
      return Result{ vr::ConvertVolumeNodeToDepthImage(outputs.RelaxedDepth),
                     vr::ConvertVolumeNodeToDepthImage(outputs.CPR) };
    };
    const double middleAnisotropy = thorax ? 0.5 : 0.0;
    const Result middle = run(middleAnisotropy, thorax ? "paper's bilateral" : "isotropic");
    parameters.Anisotropy = middleAnisotropy;
    const std::string middleSettings = vr::DescribeFilterSettings(parameters);
    const Result      bilateral = run(std::nullopt, "bilateral"); // a new kernel reruns relax and resample only
    const std::string bilateralSettings = vr::DescribeFilterSettings(parameters);
    const auto &      outputs = logic.GetOutputs();
    const Result      unfiltered{ vr::ConvertVolumeNodeToDepthImage(outputs.Depth),
                             vr::ConvertVolumeNodeToDepthImage(outputs.UnfilteredCPR) };

    // One colour range for every depth map, so they compare.
    const auto * values = unfiltered.Depth->GetBufferPointer();
    const auto   count = unfiltered.Depth->GetBufferedRegion().GetNumberOfPixels();
    const double nearest = *std::min_element(values, values + count);
    const double farthest = *std::max_element(values, values + count);

    const auto path = [&](const char * name) { return (std::filesystem::path(output) / name).string(); };
    const auto unfilteredCPR = vr::RenderWindowLevel(unfiltered.CPR, Window, Level);
    const auto middleCPR = vr::RenderWindowLevel(middle.CPR, Window, Level);
    const auto bilateralCPR = vr::RenderWindowLevel(bilateral.CPR, Window, Level);
    const auto unfilteredDepth = vr::RenderDepth(unfiltered.Depth, nearest, farthest);
    const auto middleDepth = vr::RenderDepth(middle.Depth, nearest, farthest);
    const auto bilateralDepth = vr::RenderDepth(bilateral.Depth, nearest, farthest);
    vr::WriteRGBPNG(unfilteredCPR, path("cpr-unfiltered.png"));
    vr::WriteRGBPNG(bilateralCPR, path("cpr-filtered.png"));
    vr::WriteRGBPNG(unfilteredDepth, path("depth-unfiltered.png"));
    vr::WriteRGBPNG(bilateralDepth, path("depth-filtered.png"));
    // The images and the cut surface of the last run (its unfiltered images are every run's), through the one writer
    // of a reformation's outputs: all or nothing, the surface in LPS as 3D Slicer writes models.
    vr::OutputSelection selection;
    selection.CPRPNG = false; // the figures above are the pictures
    selection.FixedMask = false;
    selection.OwnerLabels = false;
    vr::WriteOutputs(outputs, selection, output, Window, Level);

    const std::string unfilteredTitle = vr::UnfilteredSettingsText;
    const std::string middleName = thorax ? "paper's bilateral" : "isotropic";
    // "paper" alone above the thoracic CPR: with the settings, "paper's bilateral" would run into the next title.
    const std::string  middleTitle = (thorax ? std::string("paper") : middleName) + " (" + middleSettings + ")";
    const std::string  bilateralTitle = "bilateral (" + bilateralSettings + ")";
    std::ostringstream caption;
    caption << "Synthetic " << (thorax ? "thoracic" : "run-off") << " CTA, mpCPR at " << angle
            << " degrees. Top: CPR (W " << Window << " / L " << Level << " HU). Bottom: depth map."
            << (thorax ? " Detail CPR: W 400 / L 40 HU." : "");
    // A detail, magnified, with the depth in a tight colour range: there the small seams are what the eye sees. On
    // the run-off phantom the patient's left thigh and knee (the screen's right half); on the thorax the arch and
    // the supra-aortic branches.
    const DetailRegion region =
      thorax ? DetailRegion{ 0.22, 0.10, 0.56, 0.30, "arch" } : DetailRegion{ 0.50, 0.35, 0.30, 0.30, "left thigh" };
    const unsigned int detailX = static_cast<unsigned int>(region.X * size[0]);
    const unsigned int detailY = static_cast<unsigned int>(region.Y * size[1]);
    const unsigned int detailWidth = static_cast<unsigned int>(region.Width * size[0]);
    const unsigned int detailHeight = static_cast<unsigned int>(region.Height * size[1]);
    const auto [detailNear, detailFar] =
      vr::RangeWithin(unfiltered.Depth, detailX, detailY, detailWidth, detailHeight, 0.05, 0.95);
    const unsigned int panelWidth = (3 * size[0] + 16) / 4;
    auto               detail = [&](const vr::RGBImageType * image)
    { return vr::Magnify(vr::Crop(image, detailX, detailY, detailWidth, detailHeight), panelWidth); };
    // On the thorax the seams run through fat, muscle and heart: a soft-tissue window shows them in the CPR.
    auto detailCPR = [&](const DepthImage * cpr)
    { return thorax ? vr::RenderWindowLevel(cpr, 400.0, 40.0) : vr::RenderWindowLevel(cpr, Window, Level); };
    const auto figure = vr::ComposeFigure(
      { { { unfilteredCPR, unfilteredTitle }, { middleCPR, middleTitle }, { bilateralCPR, bilateralTitle } },
        { { unfilteredDepth, "depth, unfiltered" },
          { middleDepth, "depth, " + middleName },
          { bilateralDepth, "depth, bilateral" } },
        { { vr::RenderDepthColorBar(nearest, farthest, size[0]), "" } },
        { { detail(detailCPR(unfiltered.CPR)), std::string("detail: ") + region.Name + ", unfiltered" },
          { detail(detailCPR(bilateral.CPR)), "detail: bilateral" },
          { detail(vr::RenderDepthRelief(unfiltered.Depth, detailNear, detailFar)),
            "detail depth (relief), unfiltered" },
          { detail(vr::RenderDepthRelief(bilateral.Depth, detailNear, detailFar)),
            "detail depth (relief), bilateral" } },
        { { vr::RenderDepthColorBar(detailNear, detailFar, size[0]), "" } } },
      caption.str());
    const char * figureName = thorax ? "thorax-comparison.png" : "figure2-comparison.png";
    vr::WriteRGBPNG(figure, path(figureName));
    if (visibility)
    {
      // Scanline beside visibility where vessels overlap, the hidden stretches dashed; then what lies hidden, through
      // the one writer.
      parameters.Anisotropy.reset();
      const vr::ReformationOutputs shown = vr::WriteVisibilityFigure(logic,
                                                                     parameters,
                                                                     phantom.Tree,
                                                                     thorax ? "thoracic" : "run-off",
                                                                     Window,
                                                                     Level,
                                                                     path("visibility-comparison.png"));
      vr::OutputSelection          hidden;
      hidden.CPR = hidden.CPRPNG = hidden.UnfilteredCPR = hidden.DepthMaps = hidden.FixedMask = false;
      hidden.OwnerLabels = hidden.CutSurface = false;
      hidden.HiddenLabels = hidden.HiddenLengths = hidden.OcclusionProfile = true;
      vr::WriteOutputs(shown, hidden, output, Window, Level);
      double hiddenLength = 0.0;
      for (const auto & row : shown.BranchOcclusions)
      {
        hiddenLength += row.HiddenLength;
        if (row.HiddenLength >= 1.0)
        {
          std::cout << "  hidden: " << row.Name << " " << std::lround(row.HiddenLength) << " mm" << std::endl;
        }
      }
      std::cout << "  hidden in all: " << std::lround(hiddenLength) << " mm" << std::endl;
    }

    std::cout << "Wrote to " << std::filesystem::absolute(output).string() << ":" << std::endl
              << "  cpr-unfiltered.png, cpr-filtered.png     the CPR before and after bilateral filtering" << std::endl
              << "  depth-unfiltered.png, depth-filtered.png the depth maps (viridis: near dark, far yellow)"
              << std::endl
              << "  " << std::left << std::setw(41) << figureName << "unfiltered | " << middleName << " | bilateral"
              << (thorax ? " (the paper's thoracic figure)" : " (the paper's Fig. 2)") << std::right << std::endl
              << "  depth.nrrd, depth-relaxed.nrrd, cpr.nrrd, cpr-unfiltered.nrrd  the images, view in their metadata"
              << std::endl
              << "  cut-surface.vtp                          the relaxed cut surface in 3D (LPS, SPACE recorded, as 3D "
                 "Slicer stores models), coloured by HU"
              << std::endl;
    if (visibility)
    {
      std::cout << "  visibility-comparison.png                scanline | visibility, hidden stretches dashed"
                << std::endl
                << "  hidden-labels.nrrd, hidden-lengths.csv, occlusion-profile.csv  what lies hidden, and where to "
                   "look from"
                << std::endl;
    }
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
} // namespace

int
main(int argc, char * argv[])
{
  try
  {
    return RunDemo(argc, argv);
  }
  catch (const std::exception & error) // outside RunDemo's own handlers: allocation, the output stream
  {
    std::cerr << "error: " << error.what() << std::endl;
  }
  catch (...)
  {
    std::cerr << "error: an unknown exception" << std::endl;
  }
  return EXIT_FAILURE;
}
