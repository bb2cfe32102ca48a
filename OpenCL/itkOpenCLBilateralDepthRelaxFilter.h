// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef itkOpenCLBilateralDepthRelaxFilter_h
#define itkOpenCLBilateralDepthRelaxFilter_h

#include "itkBilateralDepthRelaxFilter.h"

#include <memory>
#include <string>

namespace itk
{

/** \class OpenCLBilateralDepthRelaxFilter
 * \brief BilateralDepthRelaxFilter on an OpenCL device: the same parameters, equation and output contract.
 *
 * Relaxes the depth map with the paper's iterated 4-neighbour bilateral filter (Kretschmer, Preim, Stamminger,
 * "Bilateral Depth Filtering for Enhanced Vessel Reformation", EuroVis 2014, Eq. 1 and 2), exactly as
 * BilateralDepthRelaxFilter documents it, with the kernel of OpenCL/BilateralDepthRelax.cl. One Update() uploads
 * the depth and the fixed mask once, runs the N Jacobi iterations on the device between two ping-pong buffers
 * (no host round trip), and downloads the result once. It reports progress, and honours AbortGenerateData,
 * about ten times per update, waiting for the queue once per tenth of the iterations. Arithmetic is in single
 * precision; on the paper's depth maps the result agrees with the CPU filter to within 1e-4 mm.
 *
 * Parameters are checked, the depth is checked to be finite and the input's metadata dictionary (the CPR view)
 * is passed on by the base class, exactly as on the CPU. Only GenerateData() differs (the ITK/RTK pattern of a
 * GPU filter deriving from its CPU filter). The Steady solver has no OpenCL kernel: with SetSolver(Steady) this
 * filter relaxes on the CPU (BilateralDepthRelaxSteadySolver), without touching the device.
 *
 * The device: SetDeviceRequest(), else the environment variable VR_OPENCL_DEVICE, else the first GPU, else the
 * first CPU device; see vr::ChooseOpenCLDevice() for the syntax ("P:D" or a name substring). The context, queue,
 * program and buffers belong to the filter and are kept between updates (rebuilt when the device changes); the
 * kernel is specialised for the device's preferred vector width through -D definitions in the program's build
 * options; the source handed to the compiler is the .cl file unchanged, so that its messages count the file's lines.
 *
 * Errors, as itk::ExceptionObject: a requested device that does not exist (the message lists those that do), no
 * usable device, a failed program build (the message carries the compiler's log), any failed OpenCL call (the
 * message names the call and the status).
 *
 * \sa BilateralDepthRelaxFilter, vr::ListOpenCLDevices, vr::CreateRelaxFilter
 * \ingroup VesselReformation
 */
class OpenCLBilateralDepthRelaxFilter : public BilateralDepthRelaxFilter<Image<float, 2>>
{
public:
  ITK_DISALLOW_COPY_AND_MOVE(OpenCLBilateralDepthRelaxFilter);

  using Self = OpenCLBilateralDepthRelaxFilter;
  using Superclass = BilateralDepthRelaxFilter<Image<float, 2>>;
  using Pointer = SmartPointer<Self>;
  using ConstPointer = SmartPointer<const Self>;

  itkNewMacro(Self);
  itkTypeMacro(OpenCLBilateralDepthRelaxFilter, BilateralDepthRelaxFilter);

  /** Which OpenCL device to run on: "P:D" (platform and device index, as vr::ListOpenCLDevices() numbers them)
   * or a case-insensitive substring of the device or platform name. Empty (the default) defers to the environment
   * variable VR_OPENCL_DEVICE (same syntax), and without it to the first GPU, else the first CPU device. */
  itkSetStringMacro(DeviceRequest);
  itkGetStringMacro(DeviceRequest);

  /** Chooses the device, creates its context and queue and builds the kernel now rather than in the next
   * Update(); does nothing when that is already done for the same device. Throws itk::ExceptionObject as the
   * class comment says. */
  void
  PrepareDevice();

  /** The device the last PrepareDevice() or Update() chose, as vr::OpenCLDeviceInfo::Label() names it ("" until
   * then). */
  std::string
  GetDeviceLabel() const;

  /** The build options (-D NAME=VALUE definitions of the kernel's layout) of the program the last PrepareDevice()
   * or Update() built ("" until then). */
  std::string
  GetBuildOptions() const;

  /** The source of that program as the OpenCL driver holds it (clGetProgramInfo, "" until then): what its compiler
   * read, line for line. */
  std::string
  GetProgramSource() const;

  /** The OpenCL C source the filter builds (unchanged; the definitions go in the build options):
   * OpenCL/BilateralDepthRelax.cl as embedded at build time, or what SetKernelSourceForTesting() put in its place. */
  static std::string
  GetKernelSource();

  /** TEST HOOK ONLY: replaces the OpenCL source of every filter built afterwards (in this process) by \a source,
   * so a test can make the program build fail; an empty string restores the real kernel. Production code must
   * never call it. */
  static void
  SetKernelSourceForTesting(const std::string & source);

  /** TEST HOOK ONLY: forces the kernel's layout instead of choosing it from the device, so that a test on a CPU
   * device also runs the code paths a GPU takes: \a vectorWidth lanes per vector (1, 2, 4, 8 or 16) and, with
   * \a gpuLayout, one pixel column per work-item in wide work-groups (what GPUs get) rather than wide blocks per
   * work-item (what CPU devices get). A \a vectorWidth of 0 restores the automatic choice. */
  void
  SetKernelLayoutForTesting(unsigned int vectorWidth, bool gpuLayout);

  /** Jacobi: where the device is a CPU, whose memory is the host's, the device's two buffers of high and low planes
   * and the mask on rows of the layout's pitch, which the filter keeps between updates (known once the device is
   * prepared: PrepareDevice() or an update; 0 before); a GPU's are in its own memory (0). The low plane the result
   * is downloaded through (4 bytes a pixel) is freed at the end of the update. Steady runs on the CPU: the
   * superclass's bytes. */
  std::size_t
  GetWorkspaceBytes(const SizeType & size) override;

protected:
  OpenCLBilateralDepthRelaxFilter();
  ~OpenCLBilateralDepthRelaxFilter() override;

  /** Allocates the output, checks every depth is finite, then relaxes on the device (Jacobi) or on the CPU
   * (Steady). */
  void
  GenerateData() override;

  void
  PrintSelf(std::ostream & os, Indent indent) const override;

private:
  /** The context, queue, program and buffers of the chosen device (RAII; defined in the .cxx so that this header
   * does not need OpenCL's). */
  struct DeviceState;

  /** Uploads, iterates on the device, downloads into the output. */
  void
  RelaxOnDevice();

  std::string                  m_DeviceRequest;
  unsigned int                 m_ForcedVectorWidth{ 0 }; // 0: the device's preferred width
  bool                         m_ForcedGPULayout{ false };
  std::unique_ptr<DeviceState> m_DeviceState;
};

} // namespace itk

#endif
