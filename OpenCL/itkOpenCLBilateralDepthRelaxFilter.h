// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef itkOpenCLBilateralDepthRelaxFilter_h
#define itkOpenCLBilateralDepthRelaxFilter_h

#include "itkBilateralDepthRelaxFilter.h"
#include "vrOpenCLSession.h"

#include <memory>
#include <string>

namespace itk
{

/** \class OpenCLBilateralDepthRelaxFilter
 * \brief BilateralDepthRelaxFilter on an OpenCL device: the same parameters, equation and output contract.
 *
 * Relaxes the depth map with the paper's iterated 4-neighbour bilateral filter (Kretschmer, Preim, Stamminger,
 * "Bilateral Depth Filtering for Enhanced Vessel Reformation", EuroVis 2014, Eq. 1 and 2), exactly as
 * BilateralDepthRelaxFilter documents it, with the kernels of OpenCL/BilateralDepthRelax.cl. One Update() uploads
 * the depth and the fixed mask once (or, when a filter of the same vr::OpenCLSession produced them, copies them
 * from that filter's device buffers without an upload), runs the N Jacobi iterations on the device between two
 * ping-pong buffers (no host round trip), and downloads the result once; the relaxed depth stays on the device for
 * a resampling filter of the same session. On a GPU each launch runs several passes on tiles held in local memory
 * (PassesPerLaunch), so 500 passes take tens of launches rather than 500; the bits do not depend on how many. It
 * reports progress, and honours AbortGenerateData, about ten times per update, waiting for the queue once per
 * tenth of the launches. Arithmetic is in single precision; on the paper's depth maps the result agrees with the
 * CPU filter to within 1e-4 mm.
 *
 * Parameters are checked, the depth is checked to be finite and the input's metadata dictionary (the CPR view)
 * is passed on by the base class, exactly as on the CPU. Only GenerateData() differs (the ITK/RTK pattern of a
 * GPU filter deriving from its CPU filter). The Steady solver has no OpenCL kernel: with SetSolver(Steady) this
 * filter relaxes on the CPU (BilateralDepthRelaxSteadySolver), without touching the device.
 *
 * The device: SetSession()'s, else SetDeviceRequest(), else the environment variable VR_OPENCL_DEVICE, else the
 * first GPU, else the first CPU device; see vr::ChooseOpenCLDevice() for the syntax ("P:D" or a name substring).
 * Without a session set, the filter opens one of its own (context and queue). The program and buffers belong to
 * the filter and are kept between updates (rebuilt when the device changes); the
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

  /** The session (device, context, queue) to run in, shared with the other OpenCL filters of a view so that
   * images pass between them on the device; null (the default) opens one for the DeviceRequest. A session set
   * here takes precedence over the DeviceRequest. */
  void
  SetSession(std::shared_ptr<vr::OpenCLSession> session);
  /** The session in use: the one set, or the one PrepareDevice() opened (null before). */
  std::shared_ptr<vr::OpenCLSession>
  GetSession() const;

  /** Jacobi passes per kernel launch: 1 runs one launch per pass (the plain kernel); 2 to MaximumPassesPerLaunch
   * run that many passes per launch on tiles in local memory, each tile with a border of as many pixels computed
   * twice; 0 (the default) lets the device decide: DefaultPassesPerLaunchOnGPUs on a GPU or accelerator, 1 on a
   * CPU device (where a launch costs little and the wide-vector kernel is faster). The result is bit-identical
   * for every value from 2 up. */
  itkSetMacro(PassesPerLaunch, unsigned int);
  itkGetConstMacro(PassesPerLaunch, unsigned int);
  static constexpr unsigned int MaximumPassesPerLaunch = 16;
  static constexpr unsigned int DefaultPassesPerLaunchOnGPUs = 8;

  /** The passes per launch the last update ran (PassesPerLaunch, or the device's choice; 0 before). */
  unsigned int
  GetEffectivePassesPerLaunch() const;
  /** The kernel launches of the last Jacobi update: the relaxation's and the one that joins the depth pairs. */
  unsigned int
  GetNumberOfLaunches() const
  {
    return m_NumberOfLaunches;
  }
  /** Whether the last update copied its depth and mask from another filter's device buffers (no upload). */
  bool
  GetInputsWereOnDevice() const
  {
    return m_InputsWereOnDevice;
  }

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
   * work-item (what CPU devices get). A \a vectorWidth of 0 restores the automatic choice. With the GPU layout,
   * PassesPerLaunch from 2 up runs the multi-pass kernel (which is scalar: the width then only shifts the layout). */
  void
  SetKernelLayoutForTesting(unsigned int vectorWidth, bool gpuLayout);

  /** Jacobi: where the device is a CPU, whose memory is the host's, the device's two buffers of high and low planes
   * and the mask on rows of the layout's pitch, and the packed result (4 bytes a pixel), which the filter keeps
   * between updates (known once the device is prepared: PrepareDevice() or an update; 0 before); a GPU's are in
   * its own memory (0). Steady runs on the CPU: the superclass's bytes. */
  std::size_t
  GetWorkspaceBytes(const SizeType & size) override;

protected:
  OpenCLBilateralDepthRelaxFilter();
  ~OpenCLBilateralDepthRelaxFilter() override;

  /** Also checks PassesPerLaunch. */
  void
  VerifyPreconditions() ITKv5_CONST override;

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

  /** Puts the depth and the mask into the first ping-pong buffer: copied on the device when a filter of the
   * session published them, else uploaded. */
  void
  LoadInputs(std::size_t width, std::size_t height, std::size_t pitch, std::size_t plane);

  std::string                        m_DeviceRequest;
  std::shared_ptr<vr::OpenCLSession> m_Session;
  unsigned int                       m_PassesPerLaunch{ 0 };
  unsigned int                       m_ForcedVectorWidth{ 0 }; // 0: the device's preferred width
  bool                               m_ForcedGPULayout{ false };
  unsigned int                       m_NumberOfLaunches{ 0 };
  bool                               m_InputsWereOnDevice{ false };
  std::unique_ptr<DeviceState>       m_DeviceState;
};

} // namespace itk

#endif
