// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrOpenCLSession_h
#define vrOpenCLSession_h

#include "vrOpenCLDevices.h"

#include <cstddef>
#include <memory>
#include <string>

namespace vr
{
struct OpenCLSessionState;

/** \class OpenCLSession
 * \brief One OpenCL device, its context and its in-order queue, shared by the OpenCL filters of one view
 * (docs/opencl.md "The whole view on the device").
 *
 * The filters of a view (depth map, relaxation, resampling) that share a session hand their results on in the
 * device's memory: a filter whose input was produced by another filter of the same session reads the producer's
 * device buffer instead of uploading the host image, and the volume is uploaded once per session and kept there
 * (in its stored pixel type) until another volume replaces it. The programs are built once per session and
 * source. Every filter still fills its host output image (one download per output and update), so an ITK pipeline
 * around them sees ordinary images.
 *
 * A session is used by one thread at a time (the filters of one pipeline). Create() throws vr::InputError when the
 * request names no usable device, and itk::ExceptionObject when the device cannot be opened.
 * \ingroup VesselReformation
 */
class OpenCLSession
{
public:
  /** Opens the device \a request names (vr::FindOpenCLDevice: "" = VR_OPENCL_DEVICE, else the first GPU, else
   * the first CPU device); \a origin names the request in messages. */
  static std::shared_ptr<OpenCLSession>
  Create(const std::string & request, const std::string & origin);

  /** Opens \a device, as ListOpenCLDevices() reported it. */
  static std::shared_ptr<OpenCLSession>
  Create(const OpenCLDeviceInfo & device);

  ~OpenCLSession();
  OpenCLSession(const OpenCLSession &) = delete;
  OpenCLSession &
  operator=(const OpenCLSession &) = delete;

  /** The device, as ListOpenCLDevices() names it. */
  const OpenCLDeviceInfo &
  GetDeviceInfo() const;

  /** Whether the device computes in double precision (cl_khr_fp64), which the depth map's Nearest mode and the
   * resampling need to choose exactly what the CPU chooses. */
  bool
  HasDoublePrecision() const;

  /** The bytes the session holds on the device for the volume (0 without one). */
  std::size_t
  GetVolumeBytes() const;

  /** How many times a volume was uploaded, and how many host images the session's filters read from another
   * filter's device buffer instead of uploading them (for tests and benchmarks). */
  std::size_t
  GetVolumeUploads() const;
  std::size_t
  GetDeviceHandOffs() const;

  /** Drops the device copy of the volume (it is uploaded again when next needed). */
  void
  ReleaseVolume();

  /** What the library's OpenCL code works with; defined in vrOpenCLSessionState.h (not installed). */
  OpenCLSessionState &
  GetInternals();

private:
  explicit OpenCLSession(std::unique_ptr<OpenCLSessionState> internals);

  std::unique_ptr<OpenCLSessionState> m_Internals;
};
} // namespace vr

#endif
