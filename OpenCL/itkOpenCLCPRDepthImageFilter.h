// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef itkOpenCLCPRDepthImageFilter_h
#define itkOpenCLCPRDepthImageFilter_h

#include "itkCPRDepthImageFilter.h"
#include "vrOpenCLSession.h"

#include <memory>
#include <string>

namespace itk
{

/** \class OpenCLCPRDepthImageFilter
 * \brief CPRDepthImageFilter on an OpenCL device: the same view, modes, outputs and bits.
 *
 * Computes the mpCPR depth map, fixed mask and owner labels of CPRDepthImageFilter (docs/design.md "Depth") with
 * the kernels of OpenCL/CPRDepth.cl. The host rasterises the centerlines into the list of centerline pixels (the
 * segments' cell traversal and the nearer-vessel rule, as on the CPU) and uploads that list, a few KB, per view;
 * the device assigns every pixel its nearest centerline pixel by the CPU's rules and order, so the outputs are
 * identical to the CPU filter's. The three outputs are downloaded once per update, and the depth and the mask stay
 * on the device for the relaxation and the resampling of the same vr::OpenCLSession.
 *
 * Modes: Scanline and Nearest run on the device; Nearest needs double precision there (cl_khr_fp64). Any other
 * mode, or Nearest on a device without double precision, is computed by the CPU filter (Superclass::GenerateData),
 * and GetHostReason() says why; that is a choice, not an error. Everything else (the view, the reference volume's
 * geometry, the errors, the metadata) is the superclass's. Only GenerateData() differs.
 *
 * The device: SetSession()'s, else SetDeviceRequest() (vr::FindOpenCLDevice's syntax), opened on first use.
 * Errors, as itk::ExceptionObject: no usable device, a failed program build (with the compiler's log), a failed
 * OpenCL call (naming it), and the superclass's own (no centerline pixel in the image).
 *
 * \sa CPRDepthImageFilter, OpenCLBilateralDepthRelaxFilter, OpenCLCPRResampleImageFilter, vr::OpenCLSession
 * \ingroup VesselReformation
 */
class OpenCLCPRDepthImageFilter : public CPRDepthImageFilter<Image<float, 2>>
{
public:
  ITK_DISALLOW_COPY_AND_MOVE(OpenCLCPRDepthImageFilter);

  using Self = OpenCLCPRDepthImageFilter;
  using Superclass = CPRDepthImageFilter<Image<float, 2>>;
  using Pointer = SmartPointer<Self>;
  using ConstPointer = SmartPointer<const Self>;

  itkNewMacro(Self);
  itkTypeMacro(OpenCLCPRDepthImageFilter, CPRDepthImageFilter);

  /** The device to open when no session is set ("" = VR_OPENCL_DEVICE, else the first GPU, else the first CPU
   * device). */
  itkSetStringMacro(DeviceRequest);
  itkGetStringMacro(DeviceRequest);

  /** The session to run in, shared with the view's other OpenCL filters; null opens one for the DeviceRequest. */
  void
  SetSession(std::shared_ptr<vr::OpenCLSession> session);
  std::shared_ptr<vr::OpenCLSession>
  GetSession() const;

  /** Opens the device and builds the kernels now rather than in the next Update(). */
  void
  PrepareDevice();

  /** "" when the last update ran on the device; otherwise why the CPU computed it (a mode without a kernel, or
   * Nearest on a device without double precision). */
  const std::string &
  GetHostReason() const
  {
    return m_HostReason;
  }

  /** The device the filter runs on ("" before it is prepared). */
  std::string
  GetDeviceLabel() const;

  /** The OpenCL C source the filter builds: OpenCL/CPRDepth.cl as embedded at build time. */
  static std::string
  GetKernelSource();

protected:
  OpenCLCPRDepthImageFilter();
  ~OpenCLCPRDepthImageFilter() override;

  void
  GenerateData() override;

  void
  PrintSelf(std::ostream & os, Indent indent) const override;

private:
  /** The program, kernels and buffers (defined in the .cxx, which includes OpenCL's headers). */
  struct DeviceState;

  /** Why \a mode cannot run on the device, or "". */
  std::string
  WhyHost(CPRDepthMode mode) const;

  void
  ComputeOnDevice();

  /** Takes back from the session the device copies of every image the filter published (its device buffers are
   * about to change, or go away). */
  void
  WithdrawOutputs();

  std::string                        m_DeviceRequest;
  std::shared_ptr<vr::OpenCLSession> m_Session;
  std::string                        m_HostReason;
  std::unique_ptr<DeviceState>       m_DeviceState;
};

} // namespace itk

#endif
