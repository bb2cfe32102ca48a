// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// Measures how much of each depth step the relaxation keeps, per step size, for the paper's default (a = 0.5 mm^-2)
// and ours (J = 3 mm), on the run-off phantom, the thoracic phantom and the real VMTK aorta MRA: the evidence behind
// the default jump threshold (issue 13). A step is vr::test::FindDepthSteps' (two free 4-neighbours differing by at
// least 0.2 mm and by at least 4 times the differences just before and after along the same axis); its keep
// fraction is |D'_q - D'_p| / |D_q - D_p| after relaxation. Prints one Markdown table per data set: the median keep
// fraction and the number of steps in each size bin.
//
//   MeasureKeepFractions [shared data folder]

#include "itkBilateralDepthRelaxFilter.h"
#include "itkCPRDepthImageFilter.h"
#include "itkCTAPhantom.h"
#include "vrCenterlineIO.h"
#include "vrTestImages.h"
#include "vrVolumeIO.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace
{
using DepthImage = itk::Image<float, 2>;
using DepthFilter = itk::CPRDepthImageFilter<DepthImage>;
using RelaxFilter = itk::BilateralDepthRelaxFilter<DepthImage>;

struct Setting
{
  std::string                    Name;
  std::optional<double>          Anisotropy; // else J = 3 mm
  itk::BilateralDepthRelaxSolver Solver;
};

struct Bin
{
  double Low, High;
};

const std::vector<Bin> Bins = { { 0.2, 2.0 },
                                { 2.0, 5.0 },
                                { 5.0, 10.0 },
                                { 10.0, 20.0 },
                                { 20.0, std::numeric_limits<double>::infinity() } };

void
Measure(const std::string & title, DepthFilter * depth)
{
  const auto steps = vr::test::FindDepthSteps(depth->GetDepthOutput(), depth->GetFixedMaskOutput(), 0.2);
  const auto size = depth->GetDepthOutput()->GetLargestPossibleRegion().GetSize();
  const auto spacing = depth->GetDepthOutput()->GetSpacing();
  std::cout << "\n### " << title << " (" << size[0] << " x " << size[1] << " pixels of " << spacing[0] << " mm)\n\n"
            << "| setting |";
  for (const auto & bin : Bins)
  {
    std::cout << ' ' << bin.Low << (std::isinf(bin.High) ? "+" : "-" + std::to_string(static_cast<int>(bin.High)))
              << " mm |";
  }
  std::cout << "\n| --- |";
  for (std::size_t k = 0; k < Bins.size(); ++k)
  {
    std::cout << " --- |";
  }
  std::cout << "\n| steps |";
  for (const auto & bin : Bins)
  {
    std::cout << ' '
              << std::count_if(steps.begin(),
                               steps.end(),
                               [&](const vr::test::DepthStep & s) { return s.Size >= bin.Low && s.Size < bin.High; })
              << " |";
  }
  std::cout << '\n';
  const std::vector<Setting> settings = {
    { "a = 0.5 mm^-2 (paper), 500 Jacobi", 0.5, itk::BilateralDepthRelaxSolver::Jacobi },
    { "J = 3 mm (ours), 500 Jacobi", std::nullopt, itk::BilateralDepthRelaxSolver::Jacobi },
    { "J = 3 mm, steady", std::nullopt, itk::BilateralDepthRelaxSolver::Steady },
  };
  for (const auto & setting : settings)
  {
    auto relax = RelaxFilter::New();
    relax->SetInput(depth->GetDepthOutput());
    relax->SetFixedMask(depth->GetFixedMaskOutput());
    relax->SetSolver(setting.Solver);
    relax->SetSteadyTolerance(1e-3);
    if (setting.Anisotropy)
    {
      relax->SetAnisotropy(*setting.Anisotropy);
    }
    relax->Update();
    std::cout << "| " << setting.Name << " |";
    for (const auto & bin : Bins)
    {
      std::vector<vr::test::DepthStep> selected;
      std::copy_if(steps.begin(),
                   steps.end(),
                   std::back_inserter(selected),
                   [&](const vr::test::DepthStep & s) { return s.Size >= bin.Low && s.Size < bin.High; });
      if (selected.empty())
      {
        std::cout << " - |";
        continue;
      }
      std::cout << ' ' << std::fixed << std::setprecision(3)
                << vr::test::Median(vr::test::StepRatios(selected, relax->GetOutput())) << std::defaultfloat << " |";
    }
    std::cout << std::endl;
  }
}

DepthFilter::Pointer
DepthOf(const itk::CenterlineTree & tree,
        double                      angle,
        unsigned int                width,
        unsigned int                height,
        const itk::ImageBase<3> *   volume)
{
  auto depth = DepthFilter::New();
  depth->SetCenterlineTree(tree);
  itk::CPRViewSpecification view;
  view.AngleInDegrees = angle;
  view.ImageSize = { { width, height } };
  // Real scans are not always stored head-up: with a volume, the axis along which the tree extends most is up.
  view.AutomaticUp = volume != nullptr;
  depth->SetViewSpecification(view);
  depth->SetReferenceVolume(volume);
  depth->Update();
  return depth;
}
} // namespace

int
main(int argc, char * argv[])
{
  try
  {
    const std::filesystem::path data = argc > 1 ? argv[1] : VR_SHARED_DATA_DIR;
    std::cout << "Median keep fraction |D'_q - D'_p| / |D_q - D_p| of the depth steps, per step size; w = 1."
              << std::endl;
    for (const auto kind : { itk::CTAPhantomKind::Runoff, itk::CTAPhantomKind::Thorax })
    {
      const auto phantom = itk::MakeCTAPhantom(kind);
      Measure(phantom.Description + ", " + std::to_string(static_cast<int>(phantom.DesignAngleInDegrees)) + " degrees",
              DepthOf(phantom.Tree, phantom.DesignAngleInDegrees, 512, 1024, nullptr));
    }
    const auto folder = data / "vmtk-aorta-mra";
    const auto volume = vr::ReadVolume((folder / "aorta.mha").string());
    const auto tree = vr::ReadCenterlines((folder / "aorta-centerline.vtp").string());
    for (const double angle : { 0.0, 30.0, 90.0 })
    {
      Measure("VMTK aorta MRA, " + std::to_string(static_cast<int>(angle)) + " degrees, automatic up, default view",
              DepthOf(tree, angle, 0, 0, volume));
    }
    return EXIT_SUCCESS;
  }
  catch (const std::exception & error)
  {
    std::cerr << "error: " << error.what() << std::endl;
  }
  return EXIT_FAILURE;
}
