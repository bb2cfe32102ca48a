// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrDICOMFaults_h
#define vrDICOMFaults_h

#include "vrDICOMTestSeries.h"

#include <cstdint>
#include <set>
#include <string>
#include <vector>

/** The semantic faults of the DICOM campaign (issue 37): each a change a real folder suffers (a file lost in a
 * transfer, a copy, a second series, a wrong attribute, a false transfer syntax, stray files, a gantry tilt...), made
 * in a sound series written by vrDICOMTestSeries, with the outcome docs/dicom-series.md documents for it. */
namespace vr::test
{
/** A random generator whose draws are the same with every compiler and library (splitmix64). */
class CampaignRandom
{
public:
  explicit CampaignRandom(std::uint64_t seed)
    : m_State(seed)
  {
  }
  std::uint64_t
  Next();
  /** A number in [0, count). */
  std::size_t
  Below(std::size_t count);
  /** A number in [low, high). */
  double
  Between(double low, double high);

private:
  std::uint64_t m_State;
};

/** What reading a folder should give. */
enum class DICOMOutcome
{
  /** Read, no warning, the same image as the sound series. */
  Identical,
  /** Read with a warning that names the fault (the files). */
  Warning,
  /** Refused, the message naming the file (or the series, or the reason). */
  Refused
};

std::string
ToString(DICOMOutcome outcome);

/** One fault made in a copy. */
struct DICOMFault
{
  std::string  Kind;
  std::string  Detail;
  DICOMOutcome Expected{ DICOMOutcome::Identical };
  /** The reader's message (refused) or warnings (read with a warning) must name one of these: file names, a UID, a
   * word ("tilt"). */
  std::vector<std::string> Named;
};

/** A kind of fault and its documented outcome. */
struct DICOMFaultKind
{
  std::string  Name;
  DICOMOutcome Expected;
};

/** Every kind the campaign makes, in a fixed order. */
const std::vector<DICOMFaultKind> &
DICOMFaultKinds();

/** Makes a fault of \a kind in \a files (a series MakeCTSeries made, perhaps with faults already), choosing the file
 * and the value with \a random; the series' files an earlier fault changed, and their neighbours, are listed in
 * \a touched and left alone. Throws std::logic_error for an unknown kind. */
DICOMFault
ApplyDICOMFault(const std::string &          kind,
                std::vector<DICOMTestFile> & files,
                CampaignRandom &             random,
                std::set<std::string> &      touched);

/** The outcome a copy with \a faults should have: refused if one fault is refused, else with a warning if one
 * warns, else identical. */
DICOMOutcome
ExpectedOutcome(const std::vector<DICOMFault> & faults);
} // namespace vr::test

#endif
