// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// The one-vessel reading's summary on the thoracic phantom (its exact centerline radii) and on VMTK's aorta (its
// centerline radii, and its level set), for every root-to-branch path: what the viewer's path panel and the
// VesselPathReformation module report. Prints one line per path (issue 39: the figures before and after the grading
// by segment).
//
//   MeasureStenosisSummaries [shared data folder]

#include "itkCTAPhantom.h"
#include "vrCenterlineIO.h"
#include "vrLumenMeasurement.h"
#include "vrPathSegments.h"
#include "vrSegmentationIO.h"
#include "vrNodeConversion.h"
#include "vrVesselPathLogic.h"
#include "vrVolumeIO.h"

#include <filesystem>
#include <iomanip>
#include <iostream>
#include <string>

namespace
{
void
Report(const std::string &            data,
       const vr::VolumeImageType *    volume,
       const itk::CenterlineTree &    tree,
       const vr::LabelMapVolumeType * mask,
       const std::string &            maskName)
{
  std::vector<int> ends = { 0 };
  for (const auto & branch : tree.GetBranches())
  {
    ends.push_back(branch.Id);
  }
  for (const int end : ends)
  {
    vr::VesselPathLogic logic;
    logic.SetVolumeNode(vr::ConvertItkImageToVolumeNode(volume, "volume"));
    const auto centerlines = vr::ConvertTreeToCenterlineNode(tree, "centerlines");
    logic.GetInputCache()->SetCenterlines(centerlines, tree);
    logic.SetCenterlineNode(centerlines);
    logic.SetSegmentationNode(mask ? vr::ConvertItkImageToVolumeNode(mask, maskName) : nullptr);
    vr::VesselPathParameters parameters;
    parameters.BranchId = end;
    logic.SetParameters(parameters);
    const vr::VesselPathOutputs & results = logic.Update();
    std::vector<std::string>      names;
    for (const int id : results.Path.GetBranchChain())
    {
      std::string name = "branch " + std::to_string(id);
      for (const auto & branch : tree.GetBranches())
      {
        if (branch.Id == id && !branch.Name.empty())
        {
          name = branch.Name;
        }
      }
      names.push_back(name);
    }
    const auto & s = results.Stenosis;
    std::cout << std::fixed << std::setprecision(2) << "## " << data << ", path to "
              << (end == 0 ? std::string("the longest") : "branch " + std::to_string(end)) << " ("
              << results.Path.GetLength() << " mm: " << vr::JoinPathNames(names) << ")\n";
    std::cout << "old fields: MLD " << s.MinimalLumenDiameter << " mm at " << s.MinimalLumenDiameterArcLength
              << " mm, reference " << s.ReferenceDiameter << " mm, " << std::setprecision(1)
              << s.DiameterStenosisPercent << " % diameter, " << s.AreaStenosisPercent << " % area, CAD-RADS "
              << s.CADRADS << "\n";
    for (const std::string & line : vr::LumenSummaryLines({ results.Lumen, s }))
    {
      std::cout << "  " << line << "\n";
    }
  }
}
} // namespace

int
main(int argc, char * argv[])
{
  const std::filesystem::path shared = argc > 1 ? argv[1] : VR_SHARED_DATA_DIR;
  auto                        phantom = itk::MakeCTAPhantom(itk::CTAPhantomKind::Thorax, 1.5);
  phantom.Source->Update();
  for (auto & branch : phantom.Tree.GetBranches())
  {
    branch.Name = phantom.BranchName(branch.Id);
  }
  Report("thoracic phantom (1.5 mm, centerline radii)", phantom.Source->GetOutput(), phantom.Tree, nullptr, "");

  const auto folder = shared / "vmtk-aorta-mra";
  const auto volume = vr::ReadVolume((folder / "aorta.mha").string());
  const auto tree = vr::ReadCenterlines((folder / "aorta-centerline.vtp").string(), vr::CoordinateSpace::Auto);
  Report("VMTK's aorta (centerline radii)", volume, tree, nullptr, "");
  const std::string levelSet = (folder / "aorta-final-levelset.mha").string();
  const auto        mask = vr::ReadSegmentationMask(levelSet);
  Report("VMTK's aorta (level set)", volume, tree, mask, "segmentation aorta-final-levelset.mha");
  return 0;
}
