// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrViewerOptions.h"

#include "vrCenterlineExtraction.h"
#include "vrInputError.h"
#include "vrModulePanel.h"
#include "vrParameterName.h"
#include "vrReformationInputs.h"
#include "vrRelaxBackend.h"
#include "vrText.h"

#include <CLI/CLI.hpp>

#include <map>
#include <sstream>

namespace vr
{
namespace
{
double
ParseNumber(const std::string & text, const std::string & flag)
{
  double value = 0.0;
  if (!ParseWholeDouble(text, value))
  {
    throw InputError(flag + " \"" + text + "\": expected a number");
  }
  return value;
}

long long
ParseCount(const std::string & text, const std::string & flag)
{
  long long value = 0;
  if (!ParseWholeInteger(text, value))
  {
    throw InputError(flag + " \"" + text + "\": expected a whole number");
  }
  return value;
}

/** The viewer's flag for a parameter named by meaning (vr::ParameterName). */
std::string
FlagOf(const std::string & parameter)
{
  static const std::map<std::string, std::string> flags = { { ParameterName::UpAxis, "--up" },
                                                            { ParameterName::Angle, "--angle" },
                                                            { ParameterName::ViewSize, "--size" },
                                                            { ParameterName::PixelSpacing, "--spacing" },
                                                            { ParameterName::DepthMode, "--mode" },
                                                            { ParameterName::FixLumen, "--fixLumen" },
                                                            { ParameterName::Relaxation, "--relaxation" },
                                                            { ParameterName::Anisotropy, "--anisotropy" },
                                                            { ParameterName::JumpThreshold, "--jumpThreshold" },
                                                            { ParameterName::Solver, "--solver" },
                                                            { ParameterName::Iterations, "--iterations" },
                                                            { ParameterName::Backend, "--backend" },
                                                            { ParameterName::Interpolation, "--interpolation" },
                                                            { ParameterName::Window, "--window" },
                                                            { ParameterName::Level, "--level" } };
  const auto                                      found = flags.find(parameter);
  return found != flags.end() ? found->second : std::string();
}
} // namespace

std::optional<int>
ParseViewerOptions(int argc, char ** argv, ViewerOptions & options, std::string & message)
{
  CLI::App app{ "VesselReformationViewer: rotate a multipath curved planar reformation of a vessel tree, with "
                "bilateral depth filtering (Kretschmer, Preim, Stamminger, EuroVis 2014). Without files it opens a "
                "built-in phantom." };
  app.set_version_flag("--version", "VesselReformationViewer");
  std::vector<std::string> files;
  std::string              phantom = options.Phantom;
  std::string              phantomSpacing;
  std::string              segmentation;
  std::string angle, up, size, spacing, mode, interpolation, relaxation, anisotropy, jumpThreshold, solver, iterations,
    backend, fixLumen, window, level, overlays, compare, windowSize;
  app
    .add_option("files",
                files,
                "volume (NRRD, NIfTI, MetaImage, DICOM folder) and centerlines (.vtp, .vtk, "
                ".mrk.json, .tre, .csv)")
    ->expected(0, 2);
  app.add_option("--segmentation",
                 segmentation,
                 "vessel segmentation FILE[,FILE...] (label map, mask, VMTK level set; several are combined) whose "
                 "centerlines the logic extracts, instead of the centerlines argument");
  app
    .add_option("--phantom",
                phantom,
                "built-in phantom when no files are given: runoff (aorta to the ankles) or thorax (the aortic arch)")
    ->capture_default_str();
  app.add_option("--phantomSpacing", phantomSpacing, "the phantom's voxel spacing, mm (default 1.5)");
  app.add_option("--angle", angle, "view angle about the up axis, degrees (default 0)");
  app.add_option("--up", up, "rotation axis: S, I, A, P, L, R, auto, or an LPS vector x,y,z (default S)");
  app.add_option("--size", size, "CPR image size W,H in pixels (default: fit the tree)");
  app.add_option("--spacing", spacing, "pixel spacing s or sx,sy in mm (default: the volume's smallest)");
  app.add_option("--mode", mode, "depth mode: scanline, nearest or visibility (default scanline)");
  app.add_option("--interpolation", interpolation, "linear, nearest or cubic (default linear)");
  app.add_option("--relaxation", relaxation, "relaxation w in [0, 1] (default 1)");
  app.add_option("--jumpThreshold",
                 jumpThreshold,
                 "range kernel by its jump threshold J in mm, R(x) = exp(-(x/J)^2): steps well below J are smoothed, "
                 "steps of several J stay (default 3)");
  app.add_option("--anisotropy",
                 anisotropy,
                 "range kernel as the paper gives it, R(x) = exp(-a x^2), a = 1/J^2 in mm^-2 (the paper: 0.5); "
                 "instead of --jumpThreshold, not with it");
  app.add_option("--solver",
                 solver,
                 "relax solver: jacobi (the paper's N passes) or steady (the fixed point, independent of N and the "
                 "pixel count) (default jacobi)");
  app.add_option("--iterations", iterations, "filter iterations N (default 500)");
  app.add_option("--backend", backend, "relax backend: auto, cpu or opencl (default auto)");
  app.add_option("--fixLumen", fixLumen, "fix the lumen: on or off (default on)");
  app.add_option("--window", window, "display window width, in the volume's unit (HU for CT)");
  app.add_option("--level", level, "display window level, in the volume's unit (HU for CT)");
  app.add_option("--preset",
                 options.Preset,
                 "window/level preset: CTA, bone, soft-tissue, percentile (the volume's 1st to 99th percentile) or "
                 "full (default: CTA for a CT, percentile for other data)");
  app.add_option("--overlays",
                 overlays,
                 "overlays, comma-separated: centerlines, mask, labels, depth; or none "
                 "(default centerlines)");
  app.add_option("--compare", compare, "filtered, unfiltered, split or side-by-side (default filtered)");
  app.add_option("--screenshot",
                 options.ScreenshotPath,
                 "render once, write the window to this PNG and exit (0 on "
                 "success, 1 with a message on bad input)");
  app.add_option("--windowSize", windowSize, "window size W,H in pixels (default 1600,1000)");
  try
  {
    app.parse(argc, argv);
  }
  catch (const CLI::CallForHelp &)
  {
    message = app.help();
    return 0;
  }
  catch (const CLI::CallForVersion &)
  {
    message = "VesselReformationViewer";
    return 0;
  }
  catch (const CLI::ParseError & error)
  {
    message = error.what();
    return 1;
  }

  try
  {
    if (!segmentation.empty())
    {
      options.SegmentationPaths = SplitSegmentationPaths(segmentation);
      if (options.SegmentationPaths.empty())
      {
        throw InputError("--segmentation \"" + segmentation + "\": no file named");
      }
      if (files.size() != 1)
      {
        throw InputError(files.empty() ? "--segmentation needs the volume as well: VesselReformationViewer volume "
                                         "--segmentation FILE[,FILE...]"
                                       : "both the centerlines " + files[1] +
                                           " and --segmentation give centerlines; "
                                           "give one of them");
      }
      options.VolumePath = files[0];
    }
    else if (files.size() == 1)
    {
      throw InputError("give both a volume and centerlines, or a volume and --segmentation (or neither, for the "
                       "phantom); got only " +
                       files[0]);
    }
    if (files.size() == 2 && segmentation.empty())
    {
      options.VolumePath = files[0];
      options.CenterlinePath = files[1];
    }
    bool knownPhantom = false;
    for (const auto & name : PhantomNames())
    {
      knownPhantom = knownPhantom || name == ToLower(phantom);
    }
    if (!knownPhantom)
    {
      std::string known;
      for (const auto & name : PhantomNames())
      {
        known += (known.empty() ? "" : ", ") + name;
      }
      throw InputError("--phantom \"" + phantom + "\": unknown; the built-in phantoms are " + known);
    }
    options.Phantom = ToLower(phantom);
    if (!phantomSpacing.empty())
    {
      options.PhantomSpacing = ParseNumber(phantomSpacing, "--phantomSpacing");
      if (!(options.PhantomSpacing > 0.0))
      {
        throw InputError("--phantomSpacing " + phantomSpacing + ": must be > 0 mm");
      }
    }
    ReformationParameters & p = options.Parameters;
    if (!angle.empty())
    {
      p.AngleInDegrees = ParseNumber(angle, "--angle");
    }
    if (!up.empty())
    {
      const UpAxisChoice choice = ParseUpAxis(up, "--up");
      p.AutomaticUp = choice.Automatic;
      p.Up = choice.Vector;
    }
    if (!size.empty())
    {
      p.ImageSize = ParseImageSize(size, "--size");
    }
    if (!spacing.empty())
    {
      p.PixelSpacing = ParsePixelSpacing(spacing, "--spacing");
    }
    if (!mode.empty())
    {
      p.Mode = ParseDepthMode(mode, "--mode");
    }
    if (!interpolation.empty())
    {
      p.Interpolation = ParseInterpolation(interpolation, "--interpolation");
    }
    if (!relaxation.empty())
    {
      p.Relaxation = ParseNumber(relaxation, "--relaxation");
    }
    if (!jumpThreshold.empty() && !anisotropy.empty())
    {
      throw InputError("both --jumpThreshold and --anisotropy give the range kernel (a = 1/J^2); give one of them");
    }
    if (!jumpThreshold.empty())
    {
      p.JumpThreshold = ParseNumber(jumpThreshold, "--jumpThreshold");
      p.Anisotropy.reset();
    }
    if (!anisotropy.empty())
    {
      p.Anisotropy = ParseNumber(anisotropy, "--anisotropy");
      p.JumpThreshold.reset();
    }
    if (!solver.empty())
    {
      p.Solver = ParseRelaxSolver(solver, "--solver");
    }
    if (!iterations.empty())
    {
      p.Iterations = ParseCount(iterations, "--iterations");
    }
    if (!backend.empty())
    {
      p.Backend = ParseRelaxBackend(backend, "--backend");
    }
    if (!fixLumen.empty())
    {
      p.FixLumen = ParseOnOff(fixLumen, "--fixLumen");
    }
    if (!window.empty() || !level.empty())
    {
      if (window.empty() || level.empty())
      {
        throw InputError(std::string(window.empty() ? "--level" : "--window") +
                         " needs its partner: give --window and --level together");
      }
      p.Window = ParseNumber(window, "--window");
      p.Level = ParseNumber(level, "--level");
      if (!(p.Window > 0.0))
      {
        throw InputError("--window " + window + ": must be > 0");
      }
      options.HasWindowLevel = true;
    }
    if (!options.Preset.empty())
    {
      const std::string                        key = ToLower(options.Preset);
      const std::map<std::string, std::string> presets = { { "cta", "CTA" },
                                                           { "bone", "Bone" },
                                                           { "soft-tissue", "Soft tissue" },
                                                           { "percentile", PercentilePresetName },
                                                           { "full", "Full range" } };
      const auto                               found = presets.find(key);
      if (found == presets.end())
      {
        throw InputError("--preset \"" + options.Preset + "\": use CTA, bone, soft-tissue, percentile or full");
      }
      if (options.HasWindowLevel)
      {
        throw InputError("--preset and --window/--level both set the window: give one of them");
      }
      options.Preset = found->second;
    }
    if (!overlays.empty())
    {
      options.Overlays = CPROverlays{ false, false, false, false };
      for (const std::string & name : SplitAndTrim(ToLower(overlays), ','))
      {
        if (name == "centerlines")
          options.Overlays.Centerlines = true;
        else if (name == "mask")
          options.Overlays.FixedMask = true;
        else if (name == "labels")
          options.Overlays.OwnerLabels = true;
        else if (name == "depth")
          options.Overlays.DepthMap = true;
        else if (name != "none")
          throw InputError("--overlays \"" + overlays + "\": \"" + name +
                           "\" is not an overlay; use centerlines, mask, labels, depth or none");
      }
    }
    if (!compare.empty())
    {
      const std::map<std::string, CPRComparison> comparisons = { { "filtered", CPRComparison::Filtered },
                                                                 { "unfiltered", CPRComparison::Unfiltered },
                                                                 { "split", CPRComparison::Split },
                                                                 { "side-by-side", CPRComparison::SideBySide } };
      const auto                                 found = comparisons.find(ToLower(compare));
      if (found == comparisons.end())
      {
        throw InputError("--compare \"" + compare + "\": use filtered, unfiltered, split or side-by-side");
      }
      options.Comparison = found->second;
    }
    if (!windowSize.empty())
    {
      const itk::Size<2> parsed = ParseImageSize(windowSize, "--windowSize");
      if (parsed[0] < 640 || parsed[1] < 480 || parsed[0] > 8192 || parsed[1] > 8192)
      {
        throw InputError("--windowSize " + windowSize + ": between 640,480 and 8192,8192 pixels");
      }
      options.WindowWidth = static_cast<int>(parsed[0]);
      options.WindowHeight = static_cast<int>(parsed[1]);
    }
    if (!options.ScreenshotPath.empty())
    {
      const std::string lower = ToLower(options.ScreenshotPath);
      if (lower.size() < 4 || lower.compare(lower.size() - 4, 4, ".png") != 0)
      {
        throw InputError("--screenshot " + options.ScreenshotPath + ": the file must end in .png");
      }
    }
    try
    {
      p.Validate();
    }
    catch (const InputError & error)
    {
      const std::string flag = FlagOf(error.Parameter());
      throw InputError(flag.empty() ? error.what() : flag + ": " + error.what());
    }
  }
  catch (const InputError & error)
  {
    message = error.what();
    return 1;
  }
  return std::nullopt;
}
} // namespace vr
