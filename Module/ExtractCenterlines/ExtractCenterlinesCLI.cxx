// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// The ExtractCenterlines command-line module: a vessel segmentation -> its centerline tree with radii, written as
// 3D Slicer markups curves, VMTK-style polylines, TubeTK tubes or CSV. It only collects parameters and files; the
// logic's vr::ReadSegmentation and vr::ExtractCenterlineTree compute.

#include "vrCLIModuleRunner.h"
#include "vrCenterlineExtraction.h"
#include "vrCenterlineIO.h"
#include "vrInputError.h"
#include "vrModuleExport.h"
#include "vrParameterName.h"
#include "vrStagedOutputs.h"

#include <chrono>
#include <iomanip>
#include <iostream>
#include <sstream>

extern "C" VR_MODULE_EXPORT char XMLModuleDescription[];

namespace
{
/** "1,2,3" -> {1, 2, 3}; the parser has checked the numbers. */
std::vector<double>
NumbersOf(const std::string & text)
{
  std::vector<double> numbers;
  std::istringstream  stream(text);
  std::string         part;
  while (std::getline(stream, part, ','))
  {
    numbers.push_back(std::stod(part));
  }
  return numbers;
}

void
RunExtractCenterlines(const vr::CLIArguments & arguments, vr::CLIProgress & progress)
{
  vr::CenterlineExtractionParameters parameters;
  if (arguments.Given("labels"))
  {
    parameters.Labels = NumbersOf(arguments.String("labels"));
  }
  if (arguments.Given("root"))
  {
    // A point parameter in RAS, as 3D Slicer passes it (coordinateSystem="ras"), as the logic takes it.
    const std::vector<double> ras = NumbersOf(arguments.String("root"));
    itk::Point<double, 3>     point;
    point[0] = ras[0];
    point[1] = ras[1];
    point[2] = ras[2];
    parameters.RootPointsRAS.push_back(point);
  }
  parameters.MinimumBranchLength = arguments.Double("minimumBranchLength");
  parameters.Validate();

  // The output path is checked before the work, and nothing lands until it is written.
  vr::CheckCenterlineFileName(arguments.String("outputCenterlines"), arguments.Spelling("outputCenterlines"));
  vr::StagedOutputs staged;
  const std::size_t output = staged.Add(arguments.String("outputCenterlines"), arguments.Spelling("outputCenterlines"));

  const auto               start = std::chrono::steady_clock::now();
  std::vector<std::string> warnings;
  const vr::Segmentation   segmentation =
    vr::ReadSegmentation(vr::SplitSegmentationPaths(arguments.String("segmentation")), parameters.Labels, warnings);
  progress.Update(0.1, "read");
  vr::CenterlineExtractionReport report;
  itk::CenterlineTree            tree = vr::ExtractCenterlineTree(
    segmentation.Mask,
    "segmentation " + segmentation.Name,
    parameters,
    [&progress](double fraction, const std::string & stage)
    {
      if (progress.AbortRequested())
      {
        throw vr::InputError("cancelled by the caller");
      }
      progress.Update(0.1 + 0.85 * fraction, stage);
    },
    warnings,
    &report);
  // Each branch named after the file its voxels came from (TotalSegmentator writes one file per vessel).
  vr::NameBranchesByRegion(tree, segmentation.Regions.GetPointer(), vr::RegionNamesOf(segmentation));
  for (const auto & warning : warnings)
  {
    progress.Print(std::cerr, "warning: " + warning);
  }
  staged.Write(output, [&tree](const std::string & path) { vr::WriteCenterlines(tree, path); });
  staged.CommitAll();

  double length = 0.0;
  for (const auto & branch : tree.GetBranches())
  {
    for (std::size_t k = 1; k < branch.Points.size(); ++k)
    {
      length += branch.Points[k - 1].EuclideanDistanceTo(branch.Points[k]);
    }
  }
  std::size_t roots = 0;
  for (const int parent : report.ParentBranchIds)
  {
    roots += parent == 0 ? 1 : 0;
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  progress.SetReturnValue("numberOfBranches", std::to_string(tree.GetNumberOfBranches()));
  progress.SetReturnValue("numberOfTrees", std::to_string(roots));
  std::ostringstream number;
  number << std::fixed << std::setprecision(1) << length;
  progress.SetReturnValue("centerlineLength", number.str());
  number.str("");
  number << std::fixed << std::setprecision(1) << 1e3 * seconds;
  progress.SetReturnValue("extractionTime", number.str());

  std::ostringstream summary;
  summary << "ExtractCenterlines: " << tree.GetNumberOfBranches() << " branches in " << roots
          << (roots == 1 ? " tree" : " trees") << ", " << tree.GetNumberOfPoints() << " points, " << std::fixed
          << std::setprecision(1) << length << " mm of centerline from " << report.Components
          << (report.Components == 1 ? " connected component" : " connected components") << " ("
          << segmentation.Descriptions.size() << (segmentation.Descriptions.size() == 1 ? " file: " : " files: ");
  for (std::size_t k = 0; k < segmentation.Descriptions.size(); ++k)
  {
    summary << (k == 0 ? "" : "; ") << segmentation.Descriptions[k];
  }
  summary << ") in " << std::setprecision(2) << seconds << " s";
  progress.Print(std::cout, summary.str());
}
} // namespace

extern "C" VR_MODULE_EXPORT int
ModuleEntryPoint(int argc, char * argv[])
{
  return vr::RunCLIModule(argc,
                          argv,
                          XMLModuleDescription,
                          "ExtractCenterlines",
                          "Centerline tree with radii from a vessel segmentation",
                          RunExtractCenterlines);
}
