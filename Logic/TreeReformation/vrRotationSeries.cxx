// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrRotationSeries.h"

#include "itkLinearInterpolateImageFunction.h"
#include "itkNearestNeighborExtrapolateImageFunction.h"
#include "itkResampleImageFilter.h"
#include "vrBurnedInLabels.h"
#include "vrImageIO.h"
#include "vrInputError.h"
#include "vrIntensityWindow.h"
#include "vrNodeConversion.h"
#include "vrSecondaryCaptureIO.h"
#include "vrStagedOutputs.h"
#include "vrWindowLevel.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <regex>
#include <sstream>
#include <system_error>

namespace vr
{
namespace fs = std::filesystem;

namespace
{
constexpr const char * IndexName = "rotation-angles.csv";

/** \return \a value in the fewest digits that keep it (10, 2.5, -7.25). */
std::string
Number(double value)
{
  std::ostringstream text;
  text << std::setprecision(10) << value;
  return text.str();
}

std::string
Attribute(VolumeNode * node, const char * key)
{
  const char * value = node != nullptr ? node->GetAttribute(key) : nullptr;
  return value != nullptr ? std::string(value) : std::string();
}

/** The input's patient and study, or a made-up one that says so. */
DICOMIdentity
IdentityOf(VolumeNode * volume, bool & madeUp)
{
  DICOMIdentity identity;
  identity.StudyInstanceUID = Attribute(volume, DICOMAttribute::StudyInstanceUID);
  madeUp = identity.StudyInstanceUID.empty();
  if (!madeUp)
  {
    identity.PatientName = Attribute(volume, DICOMAttribute::PatientName);
    identity.PatientID = Attribute(volume, DICOMAttribute::PatientID);
    identity.PatientBirthDate = Attribute(volume, DICOMAttribute::PatientBirthDate);
    identity.PatientSex = Attribute(volume, DICOMAttribute::PatientSex);
    identity.StudyID = Attribute(volume, DICOMAttribute::StudyID);
    identity.StudyDate = Attribute(volume, DICOMAttribute::StudyDate);
    identity.StudyTime = Attribute(volume, DICOMAttribute::StudyTime);
    identity.AccessionNumber = Attribute(volume, DICOMAttribute::AccessionNumber);
    identity.StudyDescription = Attribute(volume, DICOMAttribute::StudyDescription);
    return identity;
  }
  identity.StudyInstanceUID = NewDICOMUID();
  identity.PatientName = MadeUpPatientName;
  // Unique enough to keep two made-up patients apart in a PACS: the study UID's last digits.
  const std::string & uid = identity.StudyInstanceUID;
  identity.PatientID = "VR-" + uid.substr(uid.size() > 16 ? uid.size() - 16 : 0);
  identity.StudyDate = DICOMDateNow(identity.StudyTime);
  identity.StudyID = "VR";
  const std::string source = volume != nullptr ? volume->GetName() : std::string("the volume");
  identity.StudyDescription = "VesselReformation, identity made up: input not DICOM";
  identity.PatientComments = "Patient and study made up by VesselReformation: the input volume (" + source +
                             ") was not DICOM, so it named no patient or study.";
  return identity;
}

/** Removes a folder this run created, unless it holds anything. */
struct CreatedFolder
{
  fs::path Path;
  bool     Created{ false };
  ~CreatedFolder()
  {
    std::error_code ignored;
    if (Created)
    {
      fs::remove(Path, ignored); // fails, harmlessly, when the folder holds files
    }
  }
};

bool
IsSeriesFile(const std::string & name)
{
  static const std::regex series("rotation-[0-9]+\\.(png|dcm)");
  return name == IndexName || std::regex_match(name, series);
}
} // namespace

void
RotationAngles::Validate(const std::string & what) const
{
  std::ostringstream problem;
  if (!std::isfinite(Start) || !std::isfinite(Step))
  {
    problem << what << ": start " << Start << " and step " << Step << " degrees must be finite numbers";
  }
  else if (Count < 1 || Count > MaximumCount)
  {
    problem << what << ": " << Count << " views; give 1 to " << MaximumCount;
  }
  else if (Step == 0.0 && Count > 1)
  {
    problem << what << ": step 0 degrees would repeat one view " << Count << " times; give a step or count 1";
  }
  else if (!std::isfinite(At(static_cast<std::size_t>(Count - 1))))
  {
    problem << what << ": the last angle " << At(static_cast<std::size_t>(Count - 1)) << " is not finite";
  }
  else
  {
    return;
  }
  throw InputError(problem.str());
}

RotationAngles
ParseRotationAngles(const std::string & text, const std::string & flag)
{
  const std::string        usage = flag + " \"" + text + "\": expected start,step,count in degrees (e.g. 0,10,36)";
  std::vector<std::string> fields;
  std::string              field;
  std::istringstream       stream(text);
  while (std::getline(stream, field, ','))
  {
    fields.push_back(field);
  }
  if (fields.size() != 3 || (!text.empty() && text.back() == ','))
  {
    throw InputError(usage);
  }
  const auto number = [&](const std::string & value, const char * name)
  {
    std::size_t used = 0;
    double      result = 0.0;
    try
    {
      result = std::stod(value, &used);
    }
    catch (const std::exception &)
    {
      used = 0;
    }
    while (used < value.size() && value[used] == ' ')
    {
      ++used;
    }
    if (used == 0 || used != value.size())
    {
      throw InputError(usage + "; " + name + " \"" + value + "\" is not a number");
    }
    return result;
  };
  RotationAngles angles;
  angles.Start = number(fields[0], "start");
  angles.Step = number(fields[1], "step");
  const double count = number(fields[2], "count");
  if (!(count == std::floor(count)) || !(std::fabs(count) < 1e9))
  {
    throw InputError(usage + "; count \"" + fields[2] + "\" is not a whole number");
  }
  angles.Count = static_cast<long long>(count);
  angles.Validate(flag);
  return angles;
}

struct RotationSeriesExport::Internals
{
  RotationSeriesSettings   Settings;
  std::string              Flag;
  CreatedFolder            Folder; // declared before Staged: removed after the staging folder is
  StagedOutputs            Staged;
  std::vector<std::size_t> PNG;
  std::vector<std::size_t> DICOM;
  std::size_t              Index{ 0 };
  std::vector<std::string> PNGPaths;
  std::vector<std::string> DICOMPaths;
  std::string              IndexPath;
  bool                     Written{ false };
};

RotationSeriesExport::RotationSeriesExport(const RotationSeriesSettings & settings, const std::string & flag)
  : m_Internals(std::make_unique<Internals>())
{
  Internals & self = *m_Internals;
  self.Settings = settings;
  self.Flag = flag;
  settings.Angles.Validate(flag + " angles");
  if (settings.DisplayLongSide > RotationSeriesSettings::MaximumDisplayLongSide)
  {
    throw InputError(flag + ": a display size of " + std::to_string(settings.DisplayLongSide) +
                     " pixels; give 0 (the CPR's own size) to " +
                     std::to_string(RotationSeriesSettings::MaximumDisplayLongSide));
  }
  if (settings.Window > 0.0 && (!std::isfinite(settings.Window) || !std::isfinite(settings.Level)))
  {
    std::ostringstream problem;
    problem << flag << ": window " << settings.Window << " and level " << settings.Level << " must be finite";
    throw InputError(problem.str());
  }
  if (settings.Folder.empty())
  {
    throw InputError(flag + ": no folder given");
  }
  fs::path folder = fs::absolute(fs::path(settings.Folder)).lexically_normal();
  if (folder.filename().empty())
  {
    folder = folder.parent_path(); // "out/" names the folder "out"
  }
  std::error_code error;
  const auto      status = fs::status(folder, error);
  if (fs::exists(status))
  {
    if (!fs::is_directory(status))
    {
      throw InputError(flag + " " + settings.Folder + ": exists and is not a folder");
    }
  }
  else
  {
    const fs::path parent = folder.parent_path();
    if (!fs::is_directory(parent, error))
    {
      throw InputError(flag + " " + settings.Folder + ": cannot be created, its parent folder " + parent.string() +
                       " does not exist");
    }
    if (!fs::create_directory(folder, error) && error)
    {
      throw InputError(flag + " " + settings.Folder + ": cannot be created (" + error.message() + ")");
    }
    self.Folder.Path = folder;
    self.Folder.Created = true;
  }
  for (const auto & entry : fs::directory_iterator(folder, error))
  {
    const std::string name = entry.path().filename().string();
    if (IsSeriesFile(name))
    {
      throw InputError(flag + " " + settings.Folder + ": already holds a rotation series (" + name +
                       "); choose another folder or remove the old series");
    }
  }
  if (error)
  {
    throw InputError(flag + " " + settings.Folder + ": cannot be read (" + error.message() + ")");
  }

  const auto        count = static_cast<std::size_t>(settings.Angles.Count);
  const std::size_t digits = std::max<std::size_t>(3, std::to_string(count - 1).size());
  for (std::size_t k = 0; k < count; ++k)
  {
    std::ostringstream stem;
    stem << "rotation-" << std::setw(static_cast<int>(digits)) << std::setfill('0') << k;
    self.PNGPaths.push_back((folder / (stem.str() + ".png")).string());
    self.DICOMPaths.push_back((folder / (stem.str() + ".dcm")).string());
    self.PNG.push_back(self.Staged.Add(self.PNGPaths.back(), flag));
    self.DICOM.push_back(self.Staged.Add(self.DICOMPaths.back(), flag));
  }
  self.IndexPath = (folder / IndexName).string();
  self.Index = self.Staged.Add(self.IndexPath, flag);
}

RotationSeriesExport::~RotationSeriesExport() = default;

std::string
RotationSeriesExport::DescribeSeries(const RotationAngles & angles, const ReformationParameters & parameters)
{
  std::ostringstream text;
  text << "mpCPR rotation " << Number(angles.Start) << ".."
       << Number(angles.At(static_cast<std::size_t>(angles.Count - 1))) << " deg step " << Number(angles.Step);
  if (parameters.Relaxation == 0.0)
  {
    text << ", unfiltered";
  }
  else
  {
    const double a = parameters.EffectiveAnisotropy();
    text << ", bilateral ";
    if (a > 0.0)
    {
      text << "J " << std::setprecision(3) << 1.0 / std::sqrt(a) << " mm";
    }
    else
    {
      text << "isotropic";
    }
  }
  if (parameters.SlabThickness > 0.0)
  {
    text << ", " << ToString(parameters.SlabMode) << " slab " << std::setprecision(3) << parameters.SlabThickness
         << " mm";
  }
  std::string description = text.str();
  if (description.size() > 64)
  {
    description.resize(64);
  }
  return description;
}

DepthImageType::Pointer
RotationSeriesExport::ScaleForDisplay(const DepthImageType * image, unsigned int longSide)
{
  const auto size = image->GetLargestPossibleRegion().GetSize();
  const auto longest = std::max(size[0], size[1]);
  if (longSide == 0 || longest == 0 || longest >= longSide)
  {
    return const_cast<DepthImageType *>(image);
  }
  // The same extent in larger pixels' place: pixel centres of the first and last output pixels at the input's
  // outer edges less half an output pixel.
  const double                factor = static_cast<double>(longSide) / static_cast<double>(longest);
  DepthImageType::SizeType    outputSize;
  DepthImageType::SpacingType spacing;
  DepthImageType::PointType   origin;
  const auto &                inputSpacing = image->GetSpacing();
  for (unsigned int d = 0; d < 2; ++d)
  {
    outputSize[d] = std::max<itk::SizeValueType>(1, static_cast<itk::SizeValueType>(std::lround(size[d] * factor)));
    spacing[d] = inputSpacing[d] * static_cast<double>(size[d]) / static_cast<double>(outputSize[d]);
  }
  // The origin of the first output pixel's centre, in the image's own (index-aligned) frame.
  DepthImageType::PointType       edge;
  itk::ContinuousIndex<double, 2> corner;
  corner[0] = -0.5;
  corner[1] = -0.5;
  image->TransformContinuousIndexToPhysicalPoint(corner, edge);
  for (unsigned int d = 0; d < 2; ++d)
  {
    origin[d] = edge[d];
    for (unsigned int e = 0; e < 2; ++e)
    {
      origin[d] += image->GetDirection()[d][e] * 0.5 * spacing[e];
    }
  }
  using Resample = itk::ResampleImageFilter<DepthImageType, DepthImageType>;
  auto resample = Resample::New();
  resample->SetInput(image);
  resample->SetSize(outputSize);
  resample->SetOutputSpacing(spacing);
  resample->SetOutputOrigin(origin);
  resample->SetOutputDirection(image->GetDirection());
  resample->SetInterpolator(itk::LinearInterpolateImageFunction<DepthImageType, double>::New());
  // The outer half pixel lies beyond the last pixel centre: the edge's value, not black.
  resample->SetExtrapolator(itk::NearestNeighborExtrapolateImageFunction<DepthImageType, double>::New());
  resample->SetDefaultPixelValue(0.0f);
  resample->Update();
  DepthImageType::Pointer scaled = resample->GetOutput();
  scaled->DisconnectPipeline();
  return scaled;
}

RotationSeriesResult
RotationSeriesExport::Write(VesselReformationLogic & logic, const RotationSeriesProgress & progress)
{
  Internals &                    self = *m_Internals;
  const RotationSeriesSettings & settings = self.Settings;
  if (self.Written)
  {
    throw std::logic_error("RotationSeriesExport::Write called twice");
  }
  self.Written = true;

  RotationSeriesResult result;
  result.Window = settings.Window;
  result.Level = settings.Level;
  if (!(settings.Window > 0.0))
  {
    DefaultWindowOf(logic.GetVolumeNode(), result.Window, result.Level);
    if (!(result.Window > 0.0))
    {
      throw InputError(self.Flag + ": the volume has no finite intensity to choose a window from");
    }
  }
  const DICOMIdentity identity = IdentityOf(logic.GetVolumeNode(), result.IdentityMadeUp);
  result.StudyInstanceUID = identity.StudyInstanceUID;
  result.PatientID = identity.PatientID;
  result.SeriesInstanceUID = NewDICOMUID();
  const ReformationParameters original = logic.GetParameters();
  result.SeriesDescription = DescribeSeries(settings.Angles, original);
  SecondaryCaptureFields fields;
  fields.Identity = identity;
  fields.SeriesInstanceUID = result.SeriesInstanceUID;
  fields.SeriesNumber = settings.SeriesNumber;
  fields.SeriesDescription = result.SeriesDescription;
  fields.SeriesDate = DICOMDateNow(fields.SeriesTime);

  // The logic's state is the caller's: restored however the series ends.
  const bool surface = logic.GetSurfaceEnabled();
  struct Restore
  {
    VesselReformationLogic &      Logic;
    const ReformationParameters & Parameters;
    bool                          Surface;
    ~Restore()
    {
      Logic.SetProgressCallback({});
      Logic.SetParameters(Parameters);
      Logic.SetSurfaceEnabled(Surface);
    }
  } restore{ logic, original, surface };
  logic.SetSurfaceEnabled(false);

  const auto  count = static_cast<std::size_t>(settings.Angles.Count);
  std::size_t view = 0;
  bool        cancelled = false;
  const auto  report = [&](double withinView)
  {
    if (progress && !cancelled &&
        !progress(view, count, (static_cast<double>(view) + withinView) / static_cast<double>(count)))
    {
      cancelled = true;
    }
    return !cancelled;
  };
  logic.SetProgressCallback(
    [&](double fraction, const std::string &)
    {
      if (!report(std::min(std::max(fraction, 0.0), 1.0)))
      {
        logic.AbortUpdate();
      }
    });

  std::ostringstream index;
  index << "view,angle_deg,png,dicom\n";
  for (view = 0; view < count; ++view)
  {
    if (!report(0.0))
    {
      throw Cancelled("the rotation series was cancelled at view " + std::to_string(view + 1) + " of " +
                      std::to_string(count));
    }
    const double          angle = settings.Angles.At(view);
    ReformationParameters parameters = original;
    parameters.AngleInDegrees = angle;
    logic.SetParameters(parameters);
    const ReformationOutputs & outputs = logic.Update();
    if (cancelled)
    {
      throw Cancelled("the rotation series was cancelled at view " + std::to_string(view + 1) + " of " +
                      std::to_string(count));
    }
    // The picture a reader gets: the CPR at the display size, through window/level, its labels burned in; the PNG and
    // the DICOM file hold the same pixels.
    const DepthImageType::Pointer cpr =
      ScaleForDisplay(ConvertVolumeNodeToDepthImage(outputs.CPR), settings.DisplayLongSide);
    auto grey = MaskImageType::New();
    grey->CopyInformation(cpr);
    grey->SetRegions(cpr->GetLargestPossibleRegion());
    grey->Allocate();
    const std::size_t pixels = cpr->GetLargestPossibleRegion().GetNumberOfPixels();
    for (std::size_t k = 0; k < pixels; ++k)
    {
      grey->GetBufferPointer()[k] = WindowLevelToByte(cpr->GetBufferPointer()[k], result.Window, result.Level);
    }
    if (settings.BurnInLabels)
    {
      BurnInViewLabels(grey, outputs.View.GetU(), outputs.View.GetUp(), angle);
    }
    self.Staged.Write(self.PNG[view], [&](const std::string & path) { WriteGreyPNG(grey, path); });
    fields.SOPInstanceUID = NewDICOMUID();
    fields.InstanceNumber = static_cast<long long>(view) + 1;
    fields.ImageComments = "mpCPR view " + std::to_string(view + 1) + " of " + std::to_string(count) + " at angle " +
                           Number(angle) + " deg about the view's up axis";
    self.Staged.Write(self.DICOM[view], [&](const std::string & path) { WriteSecondaryCapture(grey, fields, path); });

    result.Angles.push_back(angle);
    index << view << ',' << Number(angle) << ',' << fs::path(self.PNGPaths[view]).filename().string() << ','
          << fs::path(self.DICOMPaths[view]).filename().string() << '\n';
  }
  self.Staged.Write(self.Index,
                    [&](const std::string & path)
                    {
                      std::ofstream file(path, std::ios::binary);
                      file << index.str();
                      file.close();
                      if (!file)
                      {
                        throw InputError("rotation series index " + self.IndexPath + ": could not be written");
                      }
                    });
  report(1.0);
  result.PNGFiles = self.PNGPaths;
  result.DICOMFiles = self.DICOMPaths;
  result.IndexFile = self.IndexPath;
  return result;
}

void
RotationSeriesExport::Commit()
{
  m_Internals->Staged.CommitAll();
  m_Internals->Folder.Created = false; // it holds the series now
}

RotationSeriesResult
ExportRotationSeries(VesselReformationLogic &       logic,
                     const RotationSeriesSettings & settings,
                     const RotationSeriesProgress & progress,
                     const std::string &            flag)
{
  RotationSeriesExport series(settings, flag);
  RotationSeriesResult result = series.Write(logic, progress);
  series.Commit();
  return result;
}
} // namespace vr
