// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrAtomicOutput_h
#define vrAtomicOutput_h

#include <string>

namespace vr
{
/** \class AtomicOutput
 * \brief Writes a result under a temporary name beside its final path and renames it into place on Commit(),
 * so an existing result is never half-overwritten (DESIGN section 5).
 *
 * The temporary name keeps the final extension (".name.tmp-<pid>-<n>.nrrd") so ITK and VTK writers still
 * pick the format from it. Without Commit() the destructor removes the temporary file. A URI name (vr::IsURIName,
 * e.g. 3D Slicer's in-memory "slicer:0x...#node") is no file: it is written directly, for the ImageIO of the host
 * process that owns the scheme.
 * \ingroup VesselReformation
 */
class AtomicOutput
{
public:
  /** Throws vr::InputError when the folder of \a finalPath does not exist. */
  explicit AtomicOutput(std::string finalPath);
  ~AtomicOutput();
  AtomicOutput(const AtomicOutput &) = delete;
  AtomicOutput &
  operator=(const AtomicOutput &) = delete;

  /** Where the writer should write. */
  const std::string &
  TemporaryPath() const
  {
    return m_TemporaryPath;
  }
  const std::string &
  FinalPath() const
  {
    return m_FinalPath;
  }
  /** Renames the temporary file onto the final path; throws vr::InputError naming the path on failure. */
  void
  Commit();

private:
  std::string m_FinalPath;
  std::string m_TemporaryPath;
  bool        m_Committed{ false };
  bool        m_Direct{ false };
};
} // namespace vr

#endif
