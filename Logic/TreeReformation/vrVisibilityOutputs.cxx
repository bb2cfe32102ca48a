// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrVisibilityOutputs.h"

#include <algorithm>
#include <chrono>

namespace vr::detail
{
std::string
DescribeBranchesWithoutRadii(const itk::CenterlineTree & tree)
{
  std::vector<std::string> missing;
  for (const itk::CenterlineBranch & branch : tree.GetBranches())
  {
    if (!branch.HasRadii())
    {
      missing.push_back(branch.Name.empty() ? "branch " + std::to_string(branch.Id)
                                            : "\"" + branch.Name + "\" (branch " + std::to_string(branch.Id) + ")");
    }
  }
  if (missing.empty())
  {
    return "";
  }
  std::string list;
  for (std::size_t k = 0; k < std::min<std::size_t>(missing.size(), 4); ++k)
  {
    list += (k ? ", " : "") + missing[k];
  }
  if (missing.size() > 4)
  {
    list += " and " + std::to_string(missing.size() - 4) + " more";
  }
  return "visibility mode: " + std::to_string(missing.size()) + " of " + std::to_string(tree.GetNumberOfBranches()) +
         " branches have no lumen radius (" + list +
         "): their footprint is their centerline alone, so where they overlap another vessel the depth map resolves "
         "it only where the centerlines cross, their lumen is not held fixed, and their hidden length counts only "
         "those crossings. Centerlines with radii (VMTK's MaximumInscribedSphereRadius, a Radius array) give the "
         "whole footprint.";
}

std::vector<BranchOcclusionRow>
NameBranchOcclusions(const itk::CenterlineTree & tree, const std::vector<itk::CPRBranchOcclusion> & occlusions)
{
  std::vector<BranchOcclusionRow> rows;
  for (std::size_t b = 0; b < occlusions.size() && b < tree.GetNumberOfBranches(); ++b)
  {
    rows.push_back({ occlusions[b].BranchId,
                     tree.GetBranches()[b].Name,
                     occlusions[b].Length,
                     occlusions[b].HiddenLength,
                     occlusions[b].HiddenStretches });
  }
  return rows;
}

std::shared_ptr<const itk::CPROcclusionProfile>
OcclusionProfileCache::Get(const std::shared_ptr<const itk::CenterlineTree> & tree,
                           const itk::CPRViewGeometry &                       view,
                           double &                                           seconds)
{
  seconds = 0.0;
  if (m_Profile && m_Tree == tree && m_View.GetUp() == view.GetUp() && m_View.GetCenter() == view.GetCenter() &&
      m_View.GetSpacing() == view.GetSpacing())
  {
    return m_Profile;
  }
  const auto start = std::chrono::steady_clock::now();
  m_Profile = std::make_shared<const itk::CPROcclusionProfile>(itk::ComputeCPROcclusionProfile(*tree, view));
  m_Tree = tree;
  m_View = view;
  seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return m_Profile;
}
} // namespace vr::detail
