// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrSegmentationIO.h"

#include "itkMetaDataObject.h"

#include "vrITKMessages.h"
#include "vrInputError.h"
#include "vrImageIOChoice.h"
#include "vrInputFileChecks.h"
#include "vrURINames.h"

// The reader pulls in the IO factory registration (see vrVolumeIO.cxx).
#include "itkImageFileReader.h"
#include "itkImageIOFactory.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <set>
#include <cstdlib>
#include <sstream>

namespace vr
{
namespace
{
/** 3D Slicer's segment names in a .seg.nrrd header (SegmentN_Name, SegmentN_LabelValue, SegmentN_Layer): the
 * segments of layer 0 (the voxels a single label map holds), by label value. */
std::map<int, std::string>
LabelNamesOf(const itk::MetaDataDictionary & dictionary)
{
  std::map<int, std::string> names;
  for (int segment = 0; segment < 1000; ++segment)
  {
    const std::string prefix = "Segment" + std::to_string(segment) + "_";
    std::string       name;
    std::string       value;
    std::string       layer = "0";
    if (!itk::ExposeMetaData<std::string>(dictionary, prefix + "Name", name))
    {
      break;
    }
    if (!itk::ExposeMetaData<std::string>(dictionary, prefix + "LabelValue", value))
    {
      continue;
    }
    itk::ExposeMetaData<std::string>(dictionary, prefix + "Layer", layer);
    char *     end = nullptr;
    const long label = std::strtol(value.c_str(), &end, 10);
    if (layer == "0" && end != value.c_str() && *end == '\0' && label > 0 && label < 65536 && !name.empty())
    {
      names[static_cast<int>(label)] = name;
    }
  }
  return names;
}

using FloatVolume = itk::Image<float, 3>;

std::string
FormatNumber(double value)
{
  std::ostringstream text;
  text << value;
  return text.str();
}

/** The distinct values of a buffer (up to 12) or their range, for messages. */
std::string
DescribeValues(const float * values, std::size_t count)
{
  std::set<float> distinct;
  float           smallest = values[0];
  float           largest = values[0];
  for (std::size_t k = 0; k < count; ++k)
  {
    smallest = std::min(smallest, values[k]);
    largest = std::max(largest, values[k]);
    if (distinct.size() <= 12)
    {
      distinct.insert(values[k]);
    }
  }
  if (distinct.size() > 12)
  {
    return FormatNumber(smallest) + " to " + FormatNumber(largest);
  }
  std::string text;
  for (const float value : distinct)
  {
    text += (text.empty() ? "" : " ") + FormatNumber(value);
  }
  return text;
}
} // namespace

SegmentationMaskType::Pointer
MakeSegmentationMask(const itk::Image<float, 3> * values,
                     const std::vector<double> &  labels,
                     const std::string &          where,
                     SegmentationReadReport *     report)
{
  const std::size_t count = values->GetBufferedRegion().GetNumberOfPixels();
  const float *     buffer = values->GetBufferPointer();

  bool  whole = true;
  float smallest = buffer[0];
  float largest = buffer[0];
  for (std::size_t k = 0; k < count; ++k)
  {
    const float value = buffer[k];
    if (std::isnan(value))
    {
      throw InputError(where + ": voxel " + std::to_string(k) + " is NaN");
    }
    whole = whole && value == std::round(value);
    smallest = std::min(smallest, value);
    largest = std::max(largest, value);
  }
  SegmentationReadReport found;
  found.Values = DescribeValues(buffer, count);
  enum class Rule
  {
    Labels,
    NonZero,
    Negative,
    Half
  };
  Rule rule = labels.empty() ? Rule::NonZero : Rule::Labels;
  found.Kind = "label map";
  if (!whole)
  {
    if (smallest < 0.0f)
    {
      rule = Rule::Negative;
      found.Kind = "level set (inside where < 0)";
    }
    else if (largest <= 1.0f)
    {
      rule = Rule::Half;
      found.Kind = "probability map (inside where >= 0.5)";
    }
    else
    {
      throw InputError(where + ": its values (" + found.Values +
                       ") are neither labels (whole numbers), nor a level set (negative inside), nor probabilities "
                       "(0 to 1)");
    }
    if (!labels.empty())
    {
      throw InputError(where + ": a " + found.Kind + ", not a label map; labels cannot be chosen in it");
    }
  }
  std::vector<float> sortedLabels(labels.begin(), labels.end());
  std::sort(sortedLabels.begin(), sortedLabels.end());

  auto mask = SegmentationMaskType::New();
  mask->CopyInformation(values);
  mask->SetRegions(values->GetLargestPossibleRegion());
  mask->Allocate();
  unsigned char * out = mask->GetBufferPointer();
  for (std::size_t k = 0; k < count; ++k)
  {
    const float value = buffer[k];
    bool        inside = false;
    switch (rule)
    {
      case Rule::Labels:
        inside = std::binary_search(sortedLabels.begin(), sortedLabels.end(), value);
        break;
      case Rule::NonZero:
        inside = value != 0.0f;
        break;
      case Rule::Negative:
        inside = value < 0.0f;
        break;
      case Rule::Half:
        inside = value >= 0.5f;
        break;
    }
    out[k] = inside ? 1 : 0;
    found.ForegroundVoxels += inside ? 1 : 0;
  }
  if (report != nullptr)
  {
    *report = found;
  }
  return mask;
}

SegmentationMaskType::Pointer
ReadSegmentationMask(const std::string & path, const std::vector<double> & labels, SegmentationReadReport * report)
{
  const std::string where = "segmentation " + path;
  const bool        uri = IsURIName(path); // a name for an ImageIO of the host process goes to ITK as it is
  if (!uri)
  {
    if (detail::CheckInputPath(path, "segmentation", true) == detail::InputKind::Folder)
    {
      throw InputError(where + ": is a folder; a segmentation is one image file (NIfTI, NRRD, MetaImage)");
    }
    for (const std::string & dataFile : detail::DetachedDataFiles(path))
    {
      detail::CheckInputPath(dataFile, where + ": the data file");
    }
  }
  itk::ImageIOBase::Pointer io = detail::CreateImageIOWithoutDICOM(path);
  if (io.IsNull())
  {
    throw InputError(where + ": no ITK reader recognises this file (NIfTI, NRRD or MetaImage are expected)");
  }
  try
  {
    if (!uri)
    {
      detail::CheckImageIOIsOneWeRead(io->GetNameOfClass(), where, false);
    }
    if (!uri)
    {
      detail::CheckHeaderBeforeITKReads(*io, path, where);
    }
    io->SetFileName(path);
    io->ReadImageInformation();
  }
  catch (const itk::ExceptionObject & exception)
  {
    throw InputError(where + ": the header cannot be read: " + detail::CondenseITKMessage(exception));
  }
  // A NIfTI or NRRD with a third axis of one slice is still a 2D image.
  const unsigned int dimensions = io->GetNumberOfDimensions();
  if (dimensions < 3 || (dimensions == 3 && io->GetDimensions(2) < 2))
  {
    std::ostringstream size;
    for (unsigned int axis = 0; axis < dimensions; ++axis)
    {
      size << (axis == 0 ? "" : " x ") << io->GetDimensions(axis);
    }
    throw InputError(where + ": a 2D image (" + size.str() + " pixels); a segmentation must be 3D");
  }
  if (dimensions > 3)
  {
    throw InputError(where + ": the image has " + std::to_string(dimensions) +
                     " dimensions; a segmentation must be 3D");
  }
  if (io->GetNumberOfComponents() != 1)
  {
    throw InputError(where + ": " + std::to_string(io->GetNumberOfComponents()) +
                     " components per voxel; a segmentation must be one label or value per voxel");
  }
  // float holds every label below 2^24 exactly, and level sets and probabilities as they are.
  auto reader = itk::ImageFileReader<FloatVolume>::New();
  reader->SetImageIO(io);
  reader->SetFileName(path);
  try
  {
    reader->Update();
  }
  catch (const itk::ExceptionObject & exception)
  {
    throw InputError(where + ": the voxel data cannot be read (truncated?): " + detail::CondenseITKMessage(exception));
  }
  SegmentationMaskType::Pointer mask = MakeSegmentationMask(reader->GetOutput(), labels, where, report);
  if (report != nullptr && report->Kind == "label map")
  {
    report->LabelNames = LabelNamesOf(io->GetMetaDataDictionary());
    report->LabelValues = report->LabelNames.empty() ? nullptr : reader->GetOutput();
  }
  return mask;
}
} // namespace vr
