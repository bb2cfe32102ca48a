// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// The VesselReformation command-line module: volume + centerlines (or a vessel segmentation) -> CPR images, depth
// maps, surface, PNG.
// It only collects parameters and files; vr::VesselReformationLogic computes.

#include "vrCLIModuleRunner.h"
#include "vrCLIRelaxParameters.h"
#include "vrCLIVolumeInput.h"
#include "vrCenterlineExtraction.h"
#include "vrCenterlineIO.h"
#include "vrFilterSettingsText.h"
#include "vrInputError.h"
#include "vrModuleExport.h"
#include "vrNodeConversion.h"
#include "vrParameterName.h"
#include "vrRotationSeries.h"
#include "vrOutputWriter.h"
#include "vrVesselReformationLogic.h"
#include "vrVolumeIO.h"

#include <filesystem>
#include <cmath>
#include <utility>
#include <memory>
#include <iomanip>
#include <iostream>
#include <sstream>

extern "C" VR_MODULE_EXPORT char XMLModuleDescription[];

namespace
{
/** This module's output parameters and the outputs they name. */
const std::pair<const char *, vr::ReformationOutput> OutputFlags[] = {
  { "outputCPR", vr::ReformationOutput::CPR },
  { "outputDepth", vr::ReformationOutput::Depth },
  { "outputRelaxedDepth", vr::ReformationOutput::RelaxedDepth },
  { "outputMask", vr::ReformationOutput::FixedMask },
  { "outputLabels", vr::ReformationOutput::OwnerLabels },
  { "outputHiddenLabels", vr::ReformationOutput::HiddenLabels },
  { "outputHiddenLengths", vr::ReformationOutput::HiddenLengths },
  { "outputOcclusionProfile", vr::ReformationOutput::OcclusionProfile },
  { "outputUnfilteredCPR", vr::ReformationOutput::UnfilteredCPR },
  { "outputSurface", vr::ReformationOutput::CutSurface },
  { "outputPNG", vr::ReformationOutput::CPRPNG },
};

std::string
FileName(const std::string & path)
{
  return std::filesystem::path(path).filename().string();
}

/** \return \a seconds in milliseconds with three decimals, as the return values give times. */
std::string
Milliseconds(double seconds)
{
  std::ostringstream text;
  text << std::fixed << std::setprecision(3) << 1e3 * seconds;
  return text.str();
}

/** \return \a value with \a decimals decimals. */
std::string
Fixed(double value, int decimals)
{
  std::ostringstream text;
  text << std::fixed << std::setprecision(decimals) << value;
  return text.str();
}

vr::ReformationParameters
ParametersFrom(const vr::CLIArguments & arguments)
{
  vr::ReformationParameters parameters;
  const vr::UpAxisChoice    up = vr::ParseUpAxis(arguments.String("up"), "--up");
  parameters.AutomaticUp = up.Automatic;
  parameters.Up = up.Vector;
  const vr::AngleChoice angle = vr::ParseAngle(arguments.String("angle"), arguments.Spelling("angle"));
  parameters.AngleInDegrees = angle.Degrees;
  parameters.LeastOccludedAngle = angle.LeastOccluded;
  if (arguments.Given("size"))
  {
    parameters.ImageSize = vr::ParseImageSize(arguments.String("size"), "--size");
  }
  if (arguments.Given("spacing"))
  {
    parameters.PixelSpacing = vr::ParsePixelSpacing(arguments.String("spacing"), "--spacing");
  }
  parameters.Mode = vr::ParseDepthMode(arguments.String("mode"), "--mode");
  parameters.FixLumen = vr::ParseOnOff(arguments.String("fixLumen"), "--fixLumen");
  vr::ReadRelaxParameters(arguments, parameters);
  parameters.Interpolation = vr::ParseInterpolation(arguments.String("interpolation"), "--interpolation");
  parameters.SlabThickness = arguments.Double("slabThickness");
  parameters.SlabMode = vr::ParseSlabMode(arguments.String("slabMode"), "--slabMode");
  parameters.Window = arguments.Double("window");
  parameters.Level = arguments.Double("level");
  parameters.Validate();
  return parameters;
}

void
RunVesselReformation(const vr::CLIArguments & arguments, vr::CLIProgress & progress)
{
  const vr::ReformationParameters parameters = ParametersFrom(arguments);
  const vr::CoordinateSpace       centerlineSpace =
    vr::ParseCoordinateSpace(arguments.String("centerlineSpace"), "--centerlineSpace");

  // Every output path is checked before the work, and nothing lands until all are written.
  vr::OutputWriter writer;
  for (const auto & [name, output] : OutputFlags)
  {
    if (arguments.Given(name))
    {
      writer.Add(output, arguments.String(name), arguments.Spelling(name));
    }
  }

  // The rotation series: its angles and folder checked, and its files reserved, before the work as well.
  // With a series, the run's own reformation is one view of count + 1 in the progress.
  std::unique_ptr<vr::RotationSeriesExport> series;
  double                                    views = 1.0;
  if (arguments.Given("rotationSeries"))
  {
    vr::RotationSeriesSettings settings;
    settings.Folder = arguments.String("rotationSeries");
    settings.Angles = vr::ParseRotationAngles(arguments.String("rotationAngles"), arguments.Spelling("rotationAngles"));
    settings.Window = parameters.Window;
    settings.Level = parameters.Level;
    const long long size = arguments.Integer("rotationSeriesSize");
    if (size < 0 || size > vr::RotationSeriesSettings::MaximumDisplayLongSide)
    {
      throw vr::InputError(arguments.Spelling("rotationSeriesSize") + " = " + std::to_string(size) +
                           ": give 0 (the CPR's own size) to " +
                           std::to_string(vr::RotationSeriesSettings::MaximumDisplayLongSide) + " pixels");
    }
    settings.DisplayLongSide = static_cast<unsigned int>(size);
    series = std::make_unique<vr::RotationSeriesExport>(settings, arguments.Spelling("rotationSeries"));
    views += static_cast<double>(settings.Angles.Count);
  }
  else if (arguments.Given("rotationAngles"))
  {
    // Checked all the same, but only a warning: 3D Slicer passes every parameter's value, defaults included.
    const vr::RotationAngles angles =
      vr::ParseRotationAngles(arguments.String("rotationAngles"), arguments.Spelling("rotationAngles"));
    const vr::RotationAngles defaults;
    if (angles.Start != defaults.Start || angles.Step != defaults.Step || angles.Count != defaults.Count)
    {
      progress.Print(std::cerr,
                     "warning: " + arguments.Spelling("rotationAngles") + " has no effect without " +
                       arguments.Spelling("rotationSeries") + ", the folder of the rotation series");
    }
  }
  // The centerlines come from a file, or are extracted from a segmentation: one of the two.
  const bool fromSegmentation = arguments.Given("segmentation");
  if (fromSegmentation && arguments.Given("inputCenterlines"))
  {
    throw vr::InputError("both " + arguments.Spelling("inputCenterlines") + " and " +
                         arguments.Spelling("segmentation") + " give centerlines; give one");
  }
  if (!fromSegmentation && !arguments.Given("inputCenterlines"))
  {
    throw vr::InputError("no centerlines: give " + arguments.Spelling("inputCenterlines") +
                         " (the second argument) or a vessel segmentation with " + arguments.Spelling("segmentation"));
  }

  // The volume in its file's pixel type, read once: the node, the logic's image and the resampler share its voxels.
  const std::string          volumePath = arguments.String("inputVolume");
  std::vector<std::string>   inputWarnings;
  vr::VesselReformationLogic logic;
  logic.SetVolumeNode(vr::ConvertStoredVolumeToVolumeNode(
    vr::ReadModuleVolume(arguments, "inputVolume", progress, inputWarnings), FileName(volumePath)));
  std::string source;
  if (fromSegmentation)
  {
    std::vector<std::string> warnings;
    const vr::Segmentation   segmentation =
      vr::ReadSegmentation(vr::SplitSegmentationPaths(arguments.String("segmentation")), {}, warnings);
    for (const auto & warning : warnings)
    {
      progress.Print(std::cerr, "warning: " + warning);
    }
    inputWarnings.insert(inputWarnings.end(), warnings.begin(), warnings.end());
    logic.SetSegmentationNode(vr::MakeSegmentationNode(segmentation));
    for (const auto & description : segmentation.Descriptions)
    {
      source += (source.empty() ? "extracted from " : "; ") + description;
    }
  }
  else
  {
    const std::string         centerlinePath = arguments.String("inputCenterlines");
    vr::CenterlineReadReport  report;
    const itk::CenterlineTree tree = vr::ReadCenterlines(centerlinePath, centerlineSpace, &report);
    logic.SetCenterlineNode(vr::ConvertTreeToCenterlineNode(tree, FileName(centerlinePath)));
    source = report.Format + ", " + vr::ToString(report.FileSpace);
  }
  logic.SetParameters(parameters);
  logic.SetSurfaceEnabled(writer.Has(vr::ReformationOutput::CutSurface));
  logic.SetOcclusionProfileEnabled(writer.Has(vr::ReformationOutput::OcclusionProfile));
  if ((writer.Has(vr::ReformationOutput::HiddenLabels) || writer.Has(vr::ReformationOutput::HiddenLengths)) &&
      parameters.Mode != itk::CPRDepthMode::Visibility)
  {
    // Refused before the work: only the visibility mode knows what lies hidden.
    throw vr::InputError((writer.Has(vr::ReformationOutput::HiddenLabels) ? arguments.Spelling("outputHiddenLabels")
                                                                          : arguments.Spelling("outputHiddenLengths")) +
                         ": what lies hidden is computed only with " + arguments.Spelling("mode") + " visibility");
  }
  logic.SetWarningCallback(
    [&progress, &arguments](const std::string & message, const std::string & parameter)
    {
      const std::string flag = vr::SpellingOfParameter(arguments.Description(), parameter);
      const std::string hint = flag.empty() ? "" : " (" + flag + ")";
      progress.Print(std::cerr, "warning: " + message + hint);
    });
  logic.SetProgressCallback(
    [&progress, &logic, views](double fraction, const std::string & stageName)
    {
      if (progress.AbortRequested())
      {
        logic.AbortUpdate();
      }
      progress.Update(fraction / views, stageName);
    });
  // A copy: the rotation series updates the logic again.
  const vr::ReformationOutputs results = logic.Update();

  double window = 0.0;
  double level = 0.0;
  logic.GetDisplayWindowLevel(window, level);
  writer.Write(results, window, level);
  vr::RotationSeriesResult rotation;
  if (series)
  {
    // The run's outputs are staged and kept (the series restores the logic's parameters, not its outputs).
    rotation = series->Write(logic,
                             [&progress, views](std::size_t view, std::size_t count, double fraction)
                             {
                               progress.Update((1.0 + fraction * (views - 1.0)) / views,
                                               "rotation series view " + std::to_string(std::min(view + 1, count)) +
                                                 " of " + std::to_string(count));
                               return !progress.AbortRequested();
                             });
  }
  writer.CommitAll();
  if (series)
  {
    series->Commit();
    std::ostringstream line;
    line << "VesselReformation: rotation series of " << rotation.PNGFiles.size() << " views (\""
         << rotation.SeriesDescription << "\", window " << rotation.Window << ", level " << rotation.Level
         << ") written to " << arguments.String("rotationSeries") << " as PNGs and DICOM Secondary Capture, "
         << (rotation.IdentityMadeUp ? "patient and study made up (the input was not DICOM)"
                                     : "patient " + rotation.PatientID + ", study " + rotation.StudyInstanceUID);
    progress.Print(std::cout, line.str());
  }

  const auto &      size = results.View.GetSize();
  const auto &      times = results.Times;
  const std::size_t branches = logic.GetDepthFilter()->GetCenterlineTree().GetNumberOfBranches();
  progress.SetReturnValue("backendUsed", results.RelaxBackendUsed);
  progress.SetReturnValue("imageSize", std::to_string(size[0]) + "," + std::to_string(size[1]));
  progress.SetReturnValue("numberOfBranches", std::to_string(branches));
  double hidden = 0.0;
  double length = 0.0;
  for (const vr::BranchOcclusionRow & row : results.BranchOcclusions)
  {
    hidden += row.HiddenLength;
    length += row.Length;
  }
  std::ostringstream angleUsed;
  angleUsed << results.View.GetAngleInDegrees();
  progress.SetReturnValue("angleUsed", angleUsed.str());
  progress.SetReturnValue("hiddenLength", Fixed(hidden, 3));
  progress.SetReturnValue("hiddenPercent", Fixed(length > 0.0 ? 100.0 * hidden / length : 0.0, 3));
  progress.SetReturnValue("conversionTime", Milliseconds(times.Conversion));
  progress.SetReturnValue("depthTime", Milliseconds(times.Depth));
  progress.SetReturnValue("relaxTime", Milliseconds(times.Relax));
  progress.SetReturnValue("resampleTime", Milliseconds(times.Resample));
  progress.SetReturnValue("surfaceTime", Milliseconds(times.Surface));
  progress.SetReturnValue("inputWarnings", vr::JoinedWarnings(inputWarnings));

  std::ostringstream summary;
  summary << "VesselReformation: " << branches << " branches (" << source << "), view " << size[0] << " x " << size[1]
          << " pixels of " << results.View.GetSpacing()[0] << " x " << results.View.GetSpacing()[1]
          << " mm; times (ms): " << std::fixed << std::setprecision(1) << "conversion " << 1e3 * times.Conversion
          << (fromSegmentation ? ", centerline extraction " : "")
          << (fromSegmentation ? std::to_string(std::lround(1e3 * times.Extraction)) : std::string()) << ", depth "
          << 1e3 * times.Depth << ", relax " << 1e3 * times.Relax << " (" << results.RelaxBackendUsed << ", "
          << vr::DescribeFilterSettings(parameters) << "), resample " << 1e3 * times.Resample << ", surface "
          << 1e3 * times.Surface << "; relax backend: " << results.RelaxBackendReason << "; depth map on "
          << results.DepthBackendUsed << " (" << results.DepthBackendReason << "), resampling on "
          << results.ResampleBackendUsed << " (" << results.ResampleBackendReason << ")";
  progress.Print(std::cout, summary.str());
  if (results.AngleChosen)
  {
    const itk::CPROcclusionProfile & profile = *results.OcclusionProfile;
    const unsigned int               best = profile.LeastOccludedAngle();
    const unsigned int               worst = profile.MostOccludedAngle();
    progress.Print(std::cout,
                   "VesselReformation: angle best: " + std::to_string(best) + " degrees hides " +
                     Fixed(profile.HiddenLength[best], 1) + " mm (" + Fixed(100.0 * profile.HiddenFraction(best), 1) +
                     " % of the tree), the least of 0-179 degrees (the most: " + Fixed(profile.HiddenLength[worst], 1) +
                     " mm at " + std::to_string(worst) + " degrees)");
  }
  if (parameters.Mode == itk::CPRDepthMode::Visibility)
  {
    std::string list;
    for (const vr::BranchOcclusionRow & row : results.BranchOcclusions)
    {
      if (row.HiddenLength > 0.05)
      {
        list += (list.empty() ? "" : "; ") + (row.Name.empty() ? "branch " + std::to_string(row.BranchId) : row.Name) +
                " " + Fixed(row.HiddenLength, 1) + " mm";
      }
    }
    progress.Print(std::cout,
                   "VesselReformation: hidden behind other vessels at " + angleUsed.str() + " degrees: " +
                     Fixed(hidden, 1) + " mm of " + Fixed(length, 1) + " mm" + (list.empty() ? "" : " (" + list + ")"));
  }
}
} // namespace

extern "C" VR_MODULE_EXPORT int
ModuleEntryPoint(int argc, char * argv[])
{
  return vr::RunCLIModule(argc,
                          argv,
                          XMLModuleDescription,
                          "VesselReformation",
                          "Multipath curved planar reformation with bilateral depth filtering",
                          RunVesselReformation);
}
