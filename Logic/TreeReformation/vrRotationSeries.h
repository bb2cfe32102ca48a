// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrRotationSeries_h
#define vrRotationSeries_h

#include "vrDICOMIdentity.h"
#include "vrVesselReformationLogic.h"

#include <cstddef>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace vr
{
/** The Patient Name of a series whose input was not DICOM (the identity is made up and says so). */
constexpr const char * MadeUpPatientName = "VesselReformation^Unknown";

/** The angles of a rotation series: Start, Start + Step, ..., Start + (Count - 1) Step degrees about the view's up
 * axis (the angle of vr::ReformationParameters).
 * \ingroup VesselReformation
 */
struct RotationAngles
{
  double    Start{ 0.0 };
  double    Step{ 10.0 };
  long long Count{ 36 };

  /** The largest number of views a series may have (a tenth of a degree apart over a full turn). */
  static constexpr long long MaximumCount = 3600;

  /** Throws vr::InputError naming \a what (a flag, a field) when Start or Step is not finite, Count is not in
   * 1..MaximumCount, or Step is 0 with more than one view. */
  void
  Validate(const std::string & what) const;
  /** \return the angle of view \a k (0-based), in degrees. */
  double
  At(std::size_t k) const
  {
    return Start + static_cast<double>(k) * Step;
  }
};

/** Parses "start,step,count" (e.g. "0,10,36") and validates it; throws vr::InputError naming \a flag. */
RotationAngles
ParseRotationAngles(const std::string & text, const std::string & flag);

/** What a rotation series writes and how.
 * \ingroup VesselReformation
 */
struct RotationSeriesSettings
{
  /** The output folder; created when missing (its parent must exist). */
  std::string    Folder;
  RotationAngles Angles;
  /** The greyscale: Window > 0 gives window and level; else the volume's default (vr::DefaultWindowOf: the CTA
   * window for a CT, else its 1st-99th percentile window). */
  double Window{ 0.0 };
  double Level{ 0.0 };
  /** Series Number (0020,0011): high, away from a scanner's own series. */
  long long SeriesNumber{ 9000 };
  /** The pictures' long side at least this many pixels (docs/viewer.md, "Rotation series"): a CPR whose long side is
   * shorter is enlarged (linear interpolation, the aspect kept, the pixel spacing scaled to match); a longer one stays
   * as computed. 0: every picture at the CPR's own size. A reading room shows a 71 x 125 picture as a stamp. */
  unsigned int                  DisplayLongSide{ DefaultDisplayLongSide };
  static constexpr unsigned int DefaultDisplayLongSide = 512;
  /** The largest long side accepted (a PACS's pictures, not a poster). */
  static constexpr unsigned int MaximumDisplayLongSide = 8192;
  /** Burn the view's angle and the screen edges' orientation letters into every picture (vr::BurnInViewLabels). */
  bool BurnInLabels{ true };
};

/** What a rotation series wrote.
 * \ingroup VesselReformation
 */
struct RotationSeriesResult
{
  std::vector<double>      Angles;
  std::vector<std::string> PNGFiles;
  std::vector<std::string> DICOMFiles;
  /** The index, rotation-angles.csv: file names and angle of each view. */
  std::string IndexFile;
  double      Window{ 0.0 };
  double      Level{ 0.0 };
  std::string SeriesInstanceUID;
  std::string SeriesDescription;
  std::string StudyInstanceUID;
  std::string PatientID;
  /** True when the input was not DICOM and the patient and study were made up. */
  bool IdentityMadeUp{ false };
};

/** Receives the progress of a series: the view being computed (0-based), the number of views, and the overall
 * fraction in [0, 1]. \return false to cancel (the series then throws vr::Cancelled and writes nothing). Called on
 * the thread that runs the series, also from within the logic's Update(). */
using RotationSeriesProgress = std::function<bool(std::size_t view, std::size_t count, double fraction)>;

/** \class RotationSeriesExport
 * \brief A rotation series of the CPR (issue 24): the reformation at each of N angles, at the logic's current
 * settings, written into one folder as
 * - rotation-000.png, rotation-001.png, ...: 8-bit grey pictures of the relaxed CPR through window/level, at the
 *   display size (RotationSeriesSettings::DisplayLongSide) with the angle and the screen edges' orientation letters
 *   burned in (R/L, A/P, S/I as the view's axes have them), numbered in angle order;
 * - rotation-000.dcm, ...: the same pictures, pixel for pixel (Rows and Columns the PNG's), as a DICOM Secondary
 *   Capture series (vr::WriteSecondaryCapture), one file per angle with
 *   Instance Number 1..N in angle order, one new Series Instance UID, a new SOP Instance UID per file, the angle in
 *   Image Comments and a Series Description such as "mpCPR rotation 0..350 deg step 10, bilateral J 3 mm". Patient
 *   and study come from the volume node's DICOM.* attributes (vr::DICOMAttribute, vrDICOMIdentity.h; a DICOM
 *   reader sets them with vr::DICOMAttributesOf) when it has a Study Instance UID;
 *   otherwise they are made up (MadeUpPatientName, a new patient ID and study UID) and the Patient Comments and
 *   Study Description say so;
 * - rotation-angles.csv: "view,angle_deg,png,dicom", one line per view.
 *
 * Every file goes through the export's own vr::StagedOutputs, so a failure or a cancel publishes none of them. The
 * folder is created when missing (its parent must exist) and removed again when the series is not published. A
 * folder that already holds a rotation series (a file named rotation-<digits>.png or .dcm, or rotation-angles.csv)
 * is refused: mixing two series' files would give a PACS two series under one name, so the user chooses another
 * folder or removes the old series. Other files in the folder are left alone.
 *
 * The constructor checks everything and reserves the files before any work (so a bad folder fails at once); Write()
 * computes and stages; Commit() publishes (a command line commits its other outputs first, then the series).
 * \ingroup VesselReformation
 */
class RotationSeriesExport
{
public:
  /** Validates the settings, creates the folder when missing and reserves every file.
   * \param settings the folder, angles and window.
   * \param flag how messages name the folder ("--rotationSeries", "the rotation series folder").
   * Throws vr::InputError naming \a flag (bad angles, window or display size, a folder whose parent is missing, a file
   * that is no folder, a folder holding a series already, one that cannot be written). */
  RotationSeriesExport(const RotationSeriesSettings & settings, const std::string & flag);
  /** Without Commit(): removes the staged files, and the folder when the constructor created it. */
  ~RotationSeriesExport();
  RotationSeriesExport(const RotationSeriesExport &) = delete;
  RotationSeriesExport &
  operator=(const RotationSeriesExport &) = delete;

  /** Runs the reformation at each angle and stages the files. The logic's parameters are restored afterwards (its
   * angle too), and its progress callback is cleared: the series sets its own while it runs.
   * \param logic a logic with its inputs and parameters set (the volume node's attributes give the identity).
   * \param progress may be empty.
   * \return what was written (file paths are the final ones, published by Commit()).
   * Throws vr::InputError (the logic's errors, a file that could not be written) or vr::Cancelled. */
  RotationSeriesResult
  Write(VesselReformationLogic & logic, const RotationSeriesProgress & progress = {});

  /** Publishes the files Write() staged (vr::StagedOutputs::CommitAll). Throws vr::InputError naming the path. */
  void
  Commit();

  /** The CPR \a image enlarged so that its long side is at least \a longSide pixels (linear interpolation; the
   * physical extent and the aspect kept, the spacing scaled), or \a image itself when it is that long already or
   * \a longSide is 0. */
  static DepthImageType::Pointer
  ScaleForDisplay(const DepthImageType * image, unsigned int longSide);

  /** \return the Series Description for \a angles and the logic's \a parameters, at most 64 characters. */
  static std::string
  DescribeSeries(const RotationAngles & angles, const ReformationParameters & parameters);

private:
  struct Internals;
  std::unique_ptr<Internals> m_Internals;
};

/** Reserves, writes and publishes a rotation series in one step (RotationSeriesExport). \return what was written.
 * Throws as RotationSeriesExport does. */
RotationSeriesResult
ExportRotationSeries(VesselReformationLogic &       logic,
                     const RotationSeriesSettings & settings,
                     const RotationSeriesProgress & progress = {},
                     const std::string &            flag = "the rotation series folder");
} // namespace vr

#endif
