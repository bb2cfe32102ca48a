// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrDICOMCampaign_h
#define vrDICOMCampaign_h

#include "vrDICOMFaults.h"
#include "vrImageTypes.h"

#include <cstdint>
#include <string>
#include <vector>

/** The tag-aware DICOM campaign (issue 37): a sound CT series written from a volume, copies of it with one to three
 * semantic faults (vrDICOMFaults.h), the VesselReformation module run on each copy, and each run put in a class by
 * what it gave. Used by Testing/Tools/DICOMFaultCampaign (thousands of copies) and by the test that replays a kept
 * set of them. */
namespace vr::test
{
/** What the campaign runs on. */
struct DICOMCampaignSetup
{
  /** The VesselReformation executable. */
  std::string Module;
  /** A folder of the campaign's own (emptied first). */
  std::string WorkFolder;
  /** The volume the series is made of, whole numbers in HU (QuantizedCT), identity direction; and its centerlines
   * (LPS, a .vtp the module reads). */
  VolumeImageType::Pointer Volume;
  std::string              Centerlines;
  /** Arguments after the module's three (volume, centerlines, CPR), e.g. a small view for speed. */
  std::vector<std::string> ModuleArguments;
};

/** One copy's run. */
struct DICOMCampaignRun
{
  std::uint64_t Seed{ 0 };
  unsigned int  Copy{ 0 };
  /** How the sound series was written (encoding, head or feet first, pixel format, rescale). */
  std::string             Variant;
  std::vector<DICOMFault> Faults;
  DICOMOutcome            Expected{ DICOMOutcome::Identical };
  /** read-identical, read-with-warning, refused-naming-the-file; or what is wrong: refused-naming-nothing-at-fault,
   * refused-and-wrote, wrong (exit 0, another image, no warning), warning-naming-nothing-at-fault, crashed. */
  std::string Observed;
  /** Observed is the class Expected documents (and what it names is right). */
  bool Correct{ false };
  /** The module's message (a refusal) or warnings, and what the check found. */
  std::string Message;
  std::string Finding;
  double      Seconds{ 0.0 };
};

class DICOMCampaign
{
public:
  /** Writes the volume as NRRD and runs the module on it: the reference every copy's CPR is compared with. Throws
   * std::runtime_error when that run fails. */
  explicit DICOMCampaign(DICOMCampaignSetup setup);

  /** Makes copy \a copy of seed \a seed (the same faults on every machine), runs the module on it, classifies. */
  DICOMCampaignRun
  Run(std::uint64_t seed, unsigned int copy);

  /** Runs the module on \a folder, a copy with \a faults of a series written as \a variant says, and classifies the
   * run as Run() does. */
  DICOMCampaignRun
  Classify(const std::string & folder, const std::vector<DICOMFault> & faults, const std::string & variant = "");

  const std::vector<float> &
  ReferenceCPR() const
  {
    return m_ReferenceCPR;
  }

private:
  DICOMCampaignSetup m_Setup;
  std::vector<float> m_ReferenceCPR;
};

/** The reference slices (indices along \a reference's third axis) where \a read differs from \a reference at the
 * same physical points; every slice when the two do not cover one grid (another size, or points between voxels).
 * \param tolerance the largest difference of values that counts as none. */
std::vector<unsigned int>
SlicesThatDiffer(const VolumeImageType * read, const VolumeImageType * reference, double tolerance = 1e-3);
} // namespace vr::test

#endif
