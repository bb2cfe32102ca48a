// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "itkCTAPhantom.h"

#include "itkRunoffPhantomImageSource.h"
#include "itkThoraxPhantomImageSource.h"

#include <algorithm>
#include <cctype>
#include <stdexcept>

namespace itk
{
std::ostream &
operator<<(std::ostream & os, CTAPhantomKind kind)
{
  return os << GetCTAPhantomNames()[static_cast<std::size_t>(kind)];
}

CTAPhantom
MakeCTAPhantom(CTAPhantomKind kind, double spacing)
{
  CTAPhantom phantom;
  phantom.Kind = kind;
  phantom.Name = GetCTAPhantomNames()[static_cast<std::size_t>(kind)];
  if (kind == CTAPhantomKind::Thorax)
  {
    auto source = ThoraxPhantomImageSource::New();
    source->SetSpacing(spacing);
    phantom.Description = "synthetic thoracic CTA (aortic arch and its branches)";
    phantom.Tree = source->GetCenterlineTree();
    phantom.DesignAngleInDegrees = ThoraxPhantomImageSource::DesignAngleInDegrees;
    phantom.BranchName = &ThoraxPhantomImageSource::GetBranchName;
    phantom.Source = source.GetPointer();
    return phantom;
  }
  auto source = RunoffPhantomImageSource::New();
  source->SetSpacing(spacing);
  phantom.Description = "synthetic leg run-off CTA";
  phantom.Tree = source->GetCenterlineTree();
  phantom.DesignAngleInDegrees = RunoffPhantomImageSource::DesignAngleInDegrees;
  phantom.BranchName = &RunoffPhantomImageSource::GetBranchName;
  phantom.Source = source.GetPointer();
  return phantom;
}

std::vector<std::string>
GetCTAPhantomNames()
{
  return { "runoff", "thorax" };
}

CTAPhantomKind
ParseCTAPhantomKind(const std::string & name)
{
  std::string lower = name;
  std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return std::tolower(c); });
  const auto names = GetCTAPhantomNames();
  for (std::size_t k = 0; k < names.size(); ++k)
  {
    if (lower == names[k])
    {
      return static_cast<CTAPhantomKind>(k);
    }
  }
  throw std::invalid_argument("phantom \"" + name + "\" is not known; use runoff or thorax");
}
} // namespace itk
