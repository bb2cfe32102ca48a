// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrViewerOptions.h"

#include "vrCenterlineExtraction.h"
#include "vrInputError.h"
#include "vrModulePanel.h"
#include "vrParameterName.h"
#include "vrParameterTable.h"
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

/** The reformation's parameters the viewer takes on its command line, by their keys in the parameter table. */
const std::vector<std::string> ViewerParameterKeys = { "up",         "angle",         "size",       "spacing",
                                                       "mode",       "interpolation", "relaxation", "jumpThreshold",
                                                       "anisotropy", "solver",        "iterations", "backend",
                                                       "fixLumen",   "window",        "level" };

/** The viewer's flag for a parameter named by meaning (vr::ParameterName), from the parameter table; "" when the
 * viewer has none. */
std::string
FlagOf(const std::string & meaning)
{
  for (const std::string & flag : FlagsOfMeaning(meaning))
  {
    for (const std::string & key : ViewerParameterKeys)
    {
      if (Parameter(key).Flag == flag)
      {
        return "--" + flag;
      }
    }
  }
  return std::string();
}

/** The help of a parameter's option: the table's description and default. */
std::string
HelpOf(const ParameterSpec & spec)
{
  return spec.Description + (spec.Default && !spec.Default->empty() ? " (default " + *spec.Default + ")" : "");
}
} // namespace

std::optional<int>
ParseViewerOptions(int argc, char ** argv, ViewerOptions & options, std::string & message)
{
  CLI::App app{ "VesselReformationViewer: rotate a multipath curved planar reformation of a vessel tree, with "
                "bilateral depth filtering (Kretschmer, Preim, Stamminger, EuroVis 2014). Without files it opens a "
                "built-in phantom." };
  app.set_version_flag("--version", "VesselReformationViewer");
  std::vector<std::string>           files;
  std::string                        phantom = options.Phantom;
  std::string                        phantomSpacing;
  std::string                        segmentation;
  std::string                        overlays, compare, windowSize;
  std::map<std::string, std::string> given; // the reformation's parameters given, by key
  app
    .add_option("files",
                files,
                "volume (NRRD, NIfTI, MetaImage, DICOM folder) and centerlines (.vtp, .vtk, "
                ".mrk.json, .tre, .csv)")
    ->expected(0, 2);
  app.add_option("--series",
                 options.DICOMSeries,
                 "which series of a DICOM folder that holds several: its number in the list the viewer gives, or "
                 "its Series Instance UID (without it, the viewer asks)");
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
  // The reformation's parameters: flag, help and default from the parameter table.
  for (const std::string & key : ViewerParameterKeys)
  {
    const ParameterSpec & spec = Parameter(key);
    app.add_option("--" + spec.Flag, given[key], HelpOf(spec));
  }
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
    const std::string &     window = given["window"];
    const std::string &     level = given["level"];
    if (!given["jumpThreshold"].empty() && !given["anisotropy"].empty())
    {
      throw InputError("both --jumpThreshold and --anisotropy give the range kernel (a = 1/J^2); give one of them");
    }
    if (window.empty() != level.empty())
    {
      throw InputError(std::string(window.empty() ? "--level" : "--window") +
                       " needs its partner: give --window and --level together");
    }
    for (const std::string & key : ViewerParameterKeys)
    {
      if (!given[key].empty())
      {
        SetReformationParameter(p, key, given[key], "--" + Parameter(key).Flag);
      }
    }
    if (!given["jumpThreshold"].empty())
    {
      p.Anisotropy.reset();
    }
    if (!given["anisotropy"].empty())
    {
      p.JumpThreshold.reset();
    }
    if (!window.empty())
    {
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
