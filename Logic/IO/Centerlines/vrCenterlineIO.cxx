// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrCenterlineIO.h"
#include "vrText.h"

#include "vrAtomicOutput.h"
#include "vrCenterlineFormats.h"
#include "vrITKMessages.h"
#include "vrInputError.h"
#include "vrInputFileChecks.h"

#include "itkMacro.h"

#include <algorithm>
#include <cctype>
#include <filesystem>

namespace vr
{
namespace
{
enum class CenterlineFormat
{
  VTK,
  Markups,
  Tube,
  CSV
};

CenterlineFormat
FormatOf(const std::string & path, const std::string & role)
{
  const std::string lower = ToLower(std::filesystem::path(path).filename().string());
  if (EndsWith(lower, ".vtp") || EndsWith(lower, ".vtk"))
  {
    return CenterlineFormat::VTK;
  }
  if (EndsWith(lower, ".json"))
  {
    return CenterlineFormat::Markups;
  }
  if (EndsWith(lower, ".tre"))
  {
    return CenterlineFormat::Tube;
  }
  if (EndsWith(lower, ".csv"))
  {
    return CenterlineFormat::CSV;
  }
  throw InputError(role + " " + path +
                   ": unknown centerline format; use .vtp or .vtk (VMTK, 3D Slicer), .mrk.json (3D Slicer markups "
                   "curves), .tre (TubeTK) or .csv");
}
} // namespace

namespace detail
{
itk::CenterlineTree
FlipRASLPS(const itk::CenterlineTree & tree)
{
  itk::CenterlineTree flipped = tree;
  for (auto & branch : flipped.GetBranches())
  {
    for (auto & point : branch.Points)
    {
      point = RASToLPS(point);
    }
  }
  return flipped;
}
} // namespace detail

void
CheckCenterlineFileName(const std::string & path, const std::string & role)
{
  FormatOf(path, role);
}

itk::CenterlineTree
ReadCenterlines(const std::string & path, CoordinateSpace space, CenterlineReadReport * report)
{
  const CenterlineFormat format = FormatOf(path, "centerline file");
  detail::CheckInputPath(path, "centerline file");
  if (detail::InputFileSize(path) > MaximumCenterlineFileBytes)
  {
    throw InputError("centerline file " + path + ": is " + std::to_string(detail::InputFileSize(path)) +
                     " bytes; centerline files of more than " + std::to_string(MaximumCenterlineFileBytes) +
                     " bytes are refused");
  }

  CenterlineReadReport found;
  itk::CenterlineTree  tree;
  switch (format)
  {
    case CenterlineFormat::VTK:
      tree = detail::ReadVTKCenterlines(path, space, found);
      break;
    case CenterlineFormat::Markups:
      tree = detail::ReadMarkupsCurves(path, space, found);
      break;
    case CenterlineFormat::Tube:
      tree = detail::ReadTubeTree(path, space, found);
      break;
    case CenterlineFormat::CSV:
      tree = detail::ReadCenterlineCSV(path, space, found);
      break;
  }
  try
  {
    tree.Validate();
  }
  catch (const itk::ExceptionObject & exception)
  {
    throw InputError("centerline file " + path + ": " + detail::CondenseITKMessage(exception));
  }
  if (report != nullptr)
  {
    *report = found;
  }
  return tree;
}

void
WriteCenterlines(const itk::CenterlineTree & tree, const std::string & path, CoordinateSpace space)
{
  const CenterlineFormat format = FormatOf(path, "centerline output");
  try
  {
    tree.Validate();
  }
  catch (const itk::ExceptionObject & exception)
  {
    throw InputError("centerline output " + path +
                     ": nothing written, the tree is invalid: " + detail::CondenseITKMessage(exception));
  }
  AtomicOutput output(path);
  switch (format)
  {
    case CenterlineFormat::VTK:
      detail::WriteVTKCenterlines(tree, path, output.TemporaryPath(), space);
      break;
    case CenterlineFormat::Markups:
      detail::WriteMarkupsCurves(tree, path, output.TemporaryPath(), space);
      break;
    case CenterlineFormat::Tube:
      detail::WriteTubeTree(tree, path, output.TemporaryPath(), space);
      break;
    case CenterlineFormat::CSV:
      detail::WriteCenterlineCSV(tree, path, output.TemporaryPath(), space);
      break;
  }
  output.Commit();
}
} // namespace vr
