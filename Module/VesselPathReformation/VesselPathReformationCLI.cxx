// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// The VesselPathReformation command-line module: volume + centerlines (or a vessel segmentation) -> one vessel's
// straightened or stretched CPR, its cross-sections, its lumen table and stenosis grading.
// It only collects parameters and files; vr::VesselPathLogic computes.

#include "vrCLIModuleRunner.h"
#include "vrCLIVolumeInput.h"
#include "vrCenterlineExtraction.h"
#include "vrCenterlineIO.h"
#include "vrInputError.h"
#include "vrLumenMeasurement.h"
#include "vrModuleExport.h"
#include "vrNodeConversion.h"
#include "vrParameterName.h"
#include "vrReformationParameters.h"
#include "vrText.h"
#include "vrVesselPathLogic.h"
#include "vrVesselPathOutputWriter.h"
#include "vrVolumeIO.h"

#include <cmath>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <utility>

extern "C" VR_MODULE_EXPORT char XMLModuleDescription[];

namespace
{
/** This module's output parameters and the outputs they name. */
const std::pair<const char *, vr::VesselPathOutput> OutputFlags[] = {
  { "outputCPR", vr::VesselPathOutput::CPR },
  { "outputCrossSections", vr::VesselPathOutput::CrossSections },
  { "outputPoints", vr::VesselPathOutput::Points },
  { "outputFoldMask", vr::VesselPathOutput::FoldMask },
  { "outputLumenTable", vr::VesselPathOutput::LumenTable },
};

/** The numbers of a float-vector parameter (the parser has checked that each is a finite number). */
std::vector<double>
Numbers(const vr::CLIArguments & arguments, const std::string & name)
{
  std::vector<double> numbers;
  for (const std::string & item : vr::SplitAndTrim(arguments.String(name), ','))
  {
    double value = 0.0;
    if (!vr::ParseWholeDouble(item, value))
    {
      throw vr::InputError(arguments.Spelling(name) + " = " + arguments.String(name) + ": \"" + item +
                           "\" is not a number");
    }
    numbers.push_back(value);
  }
  return numbers;
}

vr::VesselPathParameters
ParametersFrom(const vr::CLIArguments & arguments)
{
  vr::VesselPathParameters parameters;
  parameters.BranchId = static_cast<int>(arguments.Integer("branch"));
  if (arguments.Given("pathRange"))
  {
    const std::vector<double> range = Numbers(arguments, "pathRange");
    if (range.size() != 2)
    {
      throw vr::InputError(arguments.Spelling("pathRange") + " = " + arguments.String("pathRange") +
                           ": give two arc lengths, start,end in mm");
    }
    parameters.HasRange = true;
    parameters.RangeStart = range[0];
    parameters.RangeEnd = range[1];
  }
  const std::string reformation = arguments.String("reformation");
  parameters.Reformation =
    reformation == "stretched" ? vr::PathReformation::Stretched : vr::PathReformation::Straightened;
  parameters.RollInDegrees = arguments.Double("roll");
  parameters.Width = arguments.Double("width");
  if (arguments.Given("spacing"))
  {
    parameters.PixelSpacing = arguments.Double("spacing");
    if (!(parameters.PixelSpacing > 0.0))
    {
      throw vr::InputError("pixel spacing = " + arguments.String("spacing") + " mm: must be > 0",
                           vr::ParameterName::PixelSpacing);
    }
  }
  if (arguments.Given("sectionSpacing"))
  {
    parameters.SectionSpacing = arguments.Double("sectionSpacing");
    if (!(parameters.SectionSpacing > 0.0))
    {
      throw vr::InputError("section spacing = " + arguments.String("sectionSpacing") + " mm: must be > 0",
                           vr::ParameterName::SectionSpacing);
    }
  }
  const vr::UpAxisChoice up = vr::ParseUpAxis(arguments.String("up"), "--up");
  parameters.AutomaticUp = up.Automatic;
  parameters.Up = up.Vector;
  parameters.ViewAngleInDegrees = arguments.Double("angle");
  parameters.Interpolation = vr::ParseInterpolation(arguments.String("interpolation"), "--interpolation");
  parameters.SlabThickness = arguments.Double("slabThickness");
  parameters.SlabMode = vr::ParseSlabMode(arguments.String("slabMode"), "--slabMode");
  if (arguments.Given("referencePoints"))
  {
    parameters.ReferencePoints = Numbers(arguments, "referencePoints");
  }
  parameters.ReferenceMethod = arguments.String("referenceMethod") == "robust"
                                 ? vr::VesselReferenceMethod::RobustFit
                                 : vr::VesselReferenceMethod::Interpolated;
  if (!vr::ParseStenosisScale(arguments.String("gradingScale"), parameters.GradingScale))
  {
    throw vr::InputError(arguments.Spelling("gradingScale") + " = " + arguments.String("gradingScale") +
                           ": use automatic, cad-rads, peripheral, carotid or aorta",
                         vr::ParameterName::GradingScale);
  }
  parameters.Validate();
  return parameters;
}

std::string
Number(double value)
{
  if (!std::isfinite(value))
  {
    return "0";
  }
  std::ostringstream text;
  text << std::setprecision(6) << value;
  return text.str();
}

void
RunVesselPathReformation(const vr::CLIArguments & arguments, vr::CLIProgress & progress)
{
  const vr::VesselPathParameters parameters = ParametersFrom(arguments);
  const vr::CoordinateSpace      centerlineSpace =
    vr::ParseCoordinateSpace(arguments.String("centerlineSpace"), "--centerlineSpace");

  // Every output path is checked before the work, and nothing lands until all are written.
  vr::VesselPathOutputWriter writer;
  for (const auto & [name, output] : OutputFlags)
  {
    if (arguments.Given(name))
    {
      writer.Add(output, arguments.String(name), arguments.Spelling(name));
    }
  }

  const bool hasSegmentation = arguments.Given("segmentation");
  if (!hasSegmentation && !arguments.Given("inputCenterlines"))
  {
    throw vr::InputError("no centerlines: give " + arguments.Spelling("inputCenterlines") +
                         " (the second argument) or a vessel segmentation with " + arguments.Spelling("segmentation"));
  }
  progress.Update(0.0, "reading");
  // The volume in its file's pixel type, read once and sampled where it lies.
  std::vector<std::string> inputWarnings;
  const vr::StoredVolume   volume = vr::ReadModuleVolume(arguments, "inputVolume", progress, inputWarnings);

  vr::Segmentation segmentation;
  std::string      segmentationName;
  if (hasSegmentation)
  {
    std::vector<std::string> warnings;
    segmentation = vr::ReadSegmentation(vr::SplitSegmentationPaths(arguments.String("segmentation")), {}, warnings);
    for (const auto & warning : warnings)
    {
      progress.Print(std::cerr, "warning: " + warning);
    }
    inputWarnings.insert(inputWarnings.end(), warnings.begin(), warnings.end());
    segmentationName = "segmentation " + arguments.String("segmentation");
  }

  itk::CenterlineTree tree;
  std::string         source;
  if (arguments.Given("inputCenterlines"))
  {
    const std::string        centerlinePath = arguments.String("inputCenterlines");
    vr::CenterlineReadReport report;
    tree = vr::ReadCenterlines(centerlinePath, centerlineSpace, &report);
    source = report.Format + ", " + vr::ToString(report.FileSpace);
  }
  else
  {
    std::vector<std::string> warnings;
    tree = vr::ExtractCenterlineTree(
      segmentation.Mask,
      segmentationName,
      vr::CenterlineExtractionParameters(),
      [&progress](double fraction, const std::string & stage) { progress.Update(0.1 + 0.4 * fraction, stage); },
      warnings);
    for (const auto & warning : warnings)
    {
      progress.Print(std::cerr, "warning: " + warning);
    }
    source = "extracted from " + segmentationName;
  }
  // A cancel request (3D Slicer's Abort) is honoured between the stages; nothing is written then.
  const auto stopIfCancelled = [&progress](const char * stage)
  {
    if (progress.AbortRequested())
    {
      throw vr::Cancelled(std::string(stage) + ": cancelled");
    }
  };
  stopIfCancelled("reading");

  // The logic takes nodes, as a platform holds them: the volume's voxels shared, the centerlines in RAS with the tree
  // read as their conversion (the branches as the file numbers them).
  vr::VesselPathLogic logic;
  logic.SetVolumeNode(vr::ConvertStoredVolumeToVolumeNode(volume, "volume"));
  const auto centerlines = vr::ConvertTreeToCenterlineNode(tree, "centerlines");
  logic.GetInputCache()->SetCenterlines(centerlines, tree);
  logic.SetCenterlineNode(centerlines);
  if (hasSegmentation)
  {
    logic.SetSegmentationNode(vr::MakeSegmentationNode(segmentation));
  }
  logic.SetParameters(parameters);
  logic.SetCrossSectionsEnabled(writer.Has(vr::VesselPathOutput::CrossSections));
  logic.SetPointImageEnabled(writer.Has(vr::VesselPathOutput::Points));
  progress.Update(0.5, "reformation");
  const vr::VesselPathOutputs & results = logic.Update();
  for (const std::string & warning : results.Warnings)
  {
    progress.Print(std::cerr, "warning: " + warning);
  }
  stopIfCancelled("reformation");
  progress.Update(0.9, "writing");
  writer.Write(results);
  writer.CommitAll();

  // The lumen's values as vr::LumenSummaryValues names them (all empty without a lumen), the path's own length.
  const auto & stenosis = results.Stenosis;
  for (const auto & [name, value] : vr::LumenSummaryValues({ results.Lumen, stenosis }))
  {
    progress.SetReturnValue(name, results.HasLumen ? value : std::string(name == "lumenSource" ? "none" : ""));
  }
  progress.SetReturnValue("pathLength", Number(results.Path.GetLength()));
  progress.SetReturnValue("sectionsOutsideSegmentation", std::to_string(results.Lumen.SectionsOutsideSegmentation));
  progress.SetReturnValue("foldedPixels", std::to_string(results.FoldedPixels));
  progress.SetReturnValue("inputWarnings", vr::JoinedWarnings(inputWarnings));

  std::ostringstream summary;
  const auto &       chain = results.Path.GetBranchChain();
  summary << "VesselPathReformation: path of " << std::fixed << std::setprecision(1) << results.Path.GetLength()
          << " mm, " << results.PathName << " (branches";
  for (const int id : chain)
  {
    summary << " " << id;
  }
  summary << ")";
  summary << " (" << source << "); CPR " << results.CPR->GetLargestPossibleRegion().GetSize()[0] << " x "
          << results.CPR->GetLargestPossibleRegion().GetSize()[1] << " pixels of " << std::setprecision(3)
          << results.PixelSpacing << " mm, " << results.Sections.size() << " sections every " << results.SectionSpacing
          << " mm";
  if (!results.HasLumen)
  {
    summary << "; lumen not measured";
  }
  progress.Print(std::cout, summary.str());
  if (results.HasLumen)
  {
    // The grading segment by segment, as the lumen table's comment lines state it.
    for (const std::string & line : vr::LumenSummaryLines({ results.Lumen, stenosis }))
    {
      progress.Print(std::cout, "  " + line);
    }
  }
}
} // namespace

extern "C" VR_MODULE_EXPORT int
ModuleEntryPoint(int argc, char * argv[])
{
  return vr::RunCLIModule(argc,
                          argv,
                          XMLModuleDescription,
                          "VesselPathReformation",
                          "One vessel of the tree: straightened CPR, cross-sections and lumen",
                          RunVesselPathReformation);
}
