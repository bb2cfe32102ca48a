// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// Depth -> relax -> resample on a tree and a volume made in code, with the filters alone. The volume's value is
// x + 2 y + 3 z (LPS mm), so every CPR pixel inside it must equal that function at the sampled point, which the
// consumer computes itself from the view: exits 0 when all of them do (within float rounding).
#include "itkBilateralDepthRelaxFilter.h"
#include "itkCPRDepthImageFilter.h"
#include "itkCPRResampleImageFilter.h"

#include <cmath>
#include <iostream>

int
main()
{
  using Volume = itk::Image<float, 3>;
  using Depth = itk::Image<float, 2>;
  auto             volume = Volume::New();
  Volume::SizeType size{ { 40, 40, 60 } };
  volume->SetRegions(Volume::RegionType(size));
  volume->Allocate();
  for (unsigned int k = 0; k < 60; ++k)
  {
    for (unsigned int j = 0; j < 40; ++j)
    {
      for (unsigned int i = 0; i < 40; ++i)
      {
        volume->SetPixel({ { i, j, k } }, static_cast<float>(i + 2.0 * j + 3.0 * k));
      }
    }
  }

  itk::CenterlineTree   tree;
  itk::CenterlineBranch branch;
  branch.Id = 1;
  itk::Point<double, 3> a;
  itk::Point<double, 3> b;
  a[0] = 15.0, a[1] = 20.0, a[2] = 8.0;
  b[0] = 22.0, b[1] = 18.0, b[2] = 50.0;
  branch.Points = { a, b };
  tree.AddBranch(branch);

  auto depth = itk::CPRDepthImageFilter<Depth>::New();
  depth->SetCenterlineTree(tree);
  depth->SetReferenceVolume(volume);
  auto relax = itk::BilateralDepthRelaxFilter<Depth>::New();
  relax->SetInput(depth->GetDepthOutput());
  relax->SetFixedMask(depth->GetFixedMaskOutput());
  relax->SetNumberOfIterations(20);
  auto resample = itk::CPRResampleImageFilter<Volume, Depth>::New();
  resample->SetVolume(volume);
  resample->SetDepth(relax->GetOutput());
  resample->Update();

  const auto &       view = resample->GetView();
  const Depth *      cpr = resample->GetOutput();
  const Depth *      relaxed = relax->GetOutput();
  const auto         extent = cpr->GetLargestPossibleRegion().GetSize();
  unsigned long long checked = 0;
  for (unsigned int row = 0; row < extent[1]; ++row)
  {
    for (unsigned int column = 0; column < extent[0]; ++column)
    {
      const auto x = view.SurfacePoint(column, row, relaxed->GetPixel({ { column, row } }));
      if (x[0] < 0.0 || x[0] > 39.0 || x[1] < 0.0 || x[1] > 39.0 || x[2] < 0.0 || x[2] > 59.0)
      {
        continue;
      }
      const double expected = x[0] + 2.0 * x[1] + 3.0 * x[2];
      const double got = cpr->GetPixel({ { column, row } });
      if (std::abs(got - expected) > 1e-3 * std::max(1.0, std::abs(expected)))
      {
        std::cerr << "pixel (" << column << ", " << row << "): " << got << " instead of " << expected << std::endl;
        return 1;
      }
      ++checked;
    }
  }
  std::cout << "CPR " << extent << ", " << checked << " pixels inside the volume equal the analytic value" << std::endl;
  return checked > 100 ? 0 : 1;
}
