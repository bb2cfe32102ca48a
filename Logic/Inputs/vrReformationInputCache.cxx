// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrReformationInputCache.h"

#include "vrCenterlineExtraction.h"
#include "vrInputError.h"
#include "vrNodeConversion.h"
#include "vrParameterName.h"

#include "itkCPRVolumeSampler.h"

#include <sstream>

namespace vr
{
namespace
{
/** Whether \a node is another node than \a converted, or was modified since \a convertedTime. */
template<typename TNode>
bool
IsNew(TNode * node, const vtkWeakPointer<TNode> & converted, vtkMTimeType convertedTime)
{
  return node != converted.GetPointer() || node->GetMTime() != convertedTime;
}

/** The region names the node's attributes give (RegionNameAttributePrefix + value), by value. */
std::map<int, std::string>
RegionNamesOf(VolumeNode * node)
{
  std::map<int, std::string> names;
  const std::string          prefix = RegionNameAttributePrefix;
  for (const auto & [key, value] : node->GetAttributes())
  {
    if (key.compare(0, prefix.size(), prefix) == 0 && !value.empty())
    {
      try
      {
        names[std::stoi(key.substr(prefix.size()))] = value;
      }
      catch (const std::exception &)
      {
        // Not a region number: not ours to read.
      }
    }
  }
  return names;
}
} // namespace

ReformationInputCache::ReformationInputCache() = default;

ReformationInputCache::~ReformationInputCache() = default;

std::shared_ptr<const ReformationInputCache::Volume>
ReformationInputCache::GetVolume(VolumeNode * node)
{
  const std::lock_guard<std::mutex> lock(m_Mutex);
  if (m_Volume && !IsNew(node, m_VolumeNode, m_VolumeTime))
  {
    return m_Volume;
  }
  m_Volume = nullptr;
  const vtkMTimeType time = node->GetMTime();
  KeepVolume(node, time, ConvertVolumeNodeToStoredVolume(node));
  return m_Volume;
}

void
ReformationInputCache::SetVolume(VolumeNode * node, VolumeImageType::Pointer image)
{
  const std::lock_guard<std::mutex> lock(m_Mutex);
  m_Volume = nullptr;
  KeepVolume(node, node->GetMTime(), StoredVolume{ image.GetPointer(), itk::CPRIntensityRescale() });
}

void
ReformationInputCache::SetCenterlines(CenterlineNode * node, const itk::CenterlineTree & tree)
{
  const std::lock_guard<std::mutex> lock(m_Mutex);
  m_Centerlines = std::make_shared<const itk::CenterlineTree>(tree);
  m_CenterlineNode = node;
  m_CenterlineTime = node->GetMTime();
}

void
ReformationInputCache::KeepVolume(VolumeNode * node, vtkMTimeType time, const StoredVolume & stored)
{
  auto volume = std::make_shared<Volume>();
  volume->Image = stored.Image;
  volume->Rescale = stored.Rescale;
  itk::CPRVolumeMinimum<itk::ImageBase<3>> minimum;
  volume->Minimum = minimum.Get(stored.Image, stored.Rescale);
  m_Volume = std::move(volume);
  m_VolumeNode = node;
  m_VolumeTime = time;
}

std::shared_ptr<const itk::CenterlineTree>
ReformationInputCache::GetCenterlines(CenterlineNode * node)
{
  const std::lock_guard<std::mutex> lock(m_Mutex);
  if (m_Centerlines && !IsNew(node, m_CenterlineNode, m_CenterlineTime))
  {
    return m_Centerlines;
  }
  m_Centerlines = nullptr;
  const vtkMTimeType time = node->GetMTime();
  m_Centerlines = std::make_shared<const itk::CenterlineTree>(ConvertCenterlineNodeToTree(node));
  m_CenterlineNode = node;
  m_CenterlineTime = time;
  return m_Centerlines;
}

std::shared_ptr<const ReformationInputCache::Segmentation>
ReformationInputCache::GetSegmentation(VolumeNode * node, const std::vector<double> & labels)
{
  const std::lock_guard<std::mutex> lock(m_Mutex);
  if (m_Segmentation && !IsNew(node, m_SegmentationNode, m_SegmentationTime) && labels == m_SegmentationLabels)
  {
    return m_Segmentation;
  }
  m_Segmentation = nullptr;
  const vtkMTimeType             time = node->GetMTime();
  const std::string              name = DescribeSegmentationNode(node);
  const VolumeImageType::Pointer values = ConvertVolumeNodeToItkImage(node);
  SegmentationReadReport         report;
  auto                           segmentation = std::make_shared<Segmentation>();
  segmentation->Mask = MakeSegmentationMask(values, labels, name, &report);
  segmentation->RegionNames = RegionNamesOf(node);
  segmentation->Values = segmentation->RegionNames.empty() ? nullptr : values;
  if (report.ForegroundVoxels == 0)
  {
    if (labels.empty())
    {
      throw InputError(name + ": no vessel voxel: every voxel is 0");
    }
    std::ostringstream text;
    for (std::size_t k = 0; k < labels.size(); ++k)
    {
      text << (k == 0 ? "" : ", ") << labels[k];
    }
    throw InputError(name + ": no voxel with label " + text.str() + "; its values are " + report.Values,
                     ParameterName::VesselLabels);
  }
  m_Segmentation = std::move(segmentation);
  m_SegmentationNode = node;
  m_SegmentationTime = time;
  m_SegmentationLabels = labels;
  return m_Segmentation;
}

std::string
ReformationInputCache::DescribeSegmentationNode(const VolumeNode * node)
{
  const std::string & name = node->GetName();
  return name.empty() ? std::string("segmentation") : "segmentation \"" + name + "\"";
}
} // namespace vr
