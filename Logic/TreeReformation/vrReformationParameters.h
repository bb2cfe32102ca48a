// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrReformationParameters_h
#define vrReformationParameters_h

#include "itkBilateralDepthRelaxSolver.h"
#include "itkCPRDepthMode.h"
#include "itkCPRResampleImageFilter.h"
#include "itkCPRViewGeometry.h"
#include "vrParameterName.h"
#include "vrRelaxBackend.h"

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace vr
{
/** \class ReformationParameters
 * \brief Every setting of a vessel reformation in one object (3D Slicer's parameter node): the view, the depth
 * mode, the relaxation, the backend, the lumen fixing, the sampling and the display window.
 *
 * Geometry is in LPS millimetres, like the views stored in the outputs. Zero sizes and spacings mean "fit the
 * centerline tree" (docs/design.md "View"). Validate() names the parameter by its meaning (vr::ParameterName) and the
 * bad value. The module logic compares the parameters of successive runs to recompute only what a change invalidates
 * (docs/design.md "Module logic").
 *
 * \sa VesselReformationLogic
 * \ingroup VesselReformation
 */
struct ReformationParameters
{
  using VectorType = itk::Vector<double, 3>;
  using PointType = itk::Point<double, 3>;

  /** Every parameter at its default: the parameter table's (vrParameterTable.h) where it gives one, else the one
   * below. */
  ReformationParameters();

  /** Take the volume axis along which the tree extends most as the rotation axis. */
  bool AutomaticUp{ false };
  /** The rotation axis in LPS when AutomaticUp is off; default superior. */
  VectorType Up;
  /** Rotation angle theta about up, in degrees. */
  double AngleInDegrees{ 0.0 };
  /** Take instead the angle of 0-179 degrees at which the view hides the least centerline length behind other lumens
   * (itk::ComputeCPROcclusionProfile; of equal ones the nearest to 0); AngleInDegrees is then ignored, and the
   * outputs say which angle was taken. */
  bool LeastOccludedAngle{ false };
  /** View centre C in LPS mm; without one, the centre of the tree's bounding box. */
  bool      HasCenter{ false };
  PointType Center{};
  /** Image size W x H in pixels; 0 x 0 fits the tree. */
  itk::Size<2> ImageSize{ { 0, 0 } };
  /** Pixel spacing sx, sy in mm; 0 x 0 takes the default (the volume's smallest spacing, or what
   * fits the tree into ImageSize). */
  itk::Vector<double, 2> PixelSpacing;

  /** Scanline (mpCPR), Nearest or Visibility (occlusion-aware) depth assignment. */
  itk::CPRDepthMode Mode{ itk::CPRDepthMode::Scanline };
  /** Fix the lumen (pixels within the owner's radius) as well as the centerline pixels. */
  bool FixLumen{ true };

  /** Relaxation w in [0, 1]. */
  double Relaxation{ 1.0 };
  /** The range kernel R(x) = exp(-(x / J)^2) by its meaning, the jump threshold J in mm (finite, > 0): depth steps
   * well below J are smoothed away, steps of several J stay. Unset: DefaultJumpThreshold, unless Anisotropy is set.
   * Set at most one of JumpThreshold and Anisotropy. */
  std::optional<double> JumpThreshold;
  /** The paper's parametrisation of the same kernel, R(x) = exp(-a x^2) with the anisotropy a = 1/J^2 >= 0 in
   * mm^-2 (0: isotropic smoothing across every jump). The paper's a = 0.5 mm^-2 (J = 1.4 mm) leaves the 2-10 mm
   * seams of real thoracic CTA in place, hence the default J = 3 mm. */
  std::optional<double> Anisotropy;
  /** J when neither JumpThreshold nor Anisotropy is set, mm (itk::BilateralDepthRelaxFilter's default). */
  static constexpr double DefaultJumpThreshold = 3.0;
  /** Jacobi iterations N >= 0 (the Jacobi solver's); signed so that a negative request is reported, not wrapped. */
  long long Iterations{ 500 };
  /** Jacobi: the paper's N passes (the result depends on N and on the pixel count). Steady: the relaxation's fixed
   * point, independent of both (N and w do not apply). */
  itk::BilateralDepthRelaxSolver Solver{ itk::BilateralDepthRelaxSolver::Jacobi };
  /** Where the relaxation runs, and which OpenCL device is asked for ("" = the default choice). */
  RelaxBackend Backend{ RelaxBackend::Auto };
  std::string  OpenCLDevice;

  /** How the volume is sampled on the cut surface. */
  itk::CPRInterpolationMode Interpolation{ itk::CPRInterpolationMode::Linear };
  /** Slab thickness T >= 0 along the view direction, in mm; 0 samples the surface alone. */
  double SlabThickness{ 0.0 };
  /** How a slab's samples combine. */
  itk::CPRSlabMode SlabMode{ itk::CPRSlabMode::MIP };

  /** Display window width (>= 0; 0 = the CPR's full range) and level, in the volume's intensity unit. Changing
   * them recomputes nothing. */
  double Window{ 0.0 };
  double Level{ 0.0 };

  /** Checks every parameter; throws vr::InputError naming the first invalid one (by meaning, also in
   * InputError::Parameter()) and its value. */
  void
  Validate() const;

  /** \return the anisotropy a in mm^-2 the filter gets: Anisotropy if set, else 1/J^2 of JumpThreshold or of
   * DefaultJumpThreshold. */
  double
  EffectiveAnisotropy() const;

  /** \return the view part as itk::CPRDepthImageFilter takes it (default margin). */
  itk::CPRViewSpecification
  ToViewSpecification() const;

  /** Sets the relaxation part on \a filter: w, the range kernel (J or a, as given; J's default when neither), N and
   * the solver. The one place the logic's relax parameters reach a relax filter. */
  void
  ConfigureRelaxFilter(RelaxFilterType * filter) const;
};

/** The rotation axis as a user writes it: "S" (or I, A, P, L, R), "x,y,z" in LPS, or "auto".
 * \ingroup VesselReformation
 */
struct UpAxisChoice
{
  bool Automatic{ false };
  /** The axis; superior while Automatic (then unused). */
  itk::Vector<double, 3> Vector{ std::array<double, 3>{ 0.0, 0.0, 1.0 }.data() };
};

/** Parsers for the text forms of the parameters (command line, presets).
 * \param text the value as written.
 * \param what how the caller names it in messages (a command line passes its flag, e.g. "--up").
 * \return the value; each throws vr::InputError naming \a what and \a text when the text is not a valid value. */
UpAxisChoice
ParseUpAxis(const std::string & text, const std::string & what);
/** "W,H" in pixels, both >= 1. */
itk::Size<2>
ParseImageSize(const std::string & text, const std::string & what);
/** "s" (both axes) or "sx,sy" in mm, finite and > 0. */
itk::Vector<double, 2>
ParsePixelSpacing(const std::string & text, const std::string & what);
/** The view angle as a user writes it: degrees, or "best" for the least occluded angle.
 * \ingroup VesselReformation
 */
struct AngleChoice
{
  bool   LeastOccluded{ false };
  double Degrees{ 0.0 };
};
/** A finite number of degrees, or "best" (any case). */
AngleChoice
ParseAngle(const std::string & text, const std::string & what);
/** "scanline", "nearest" or "visibility". */
itk::CPRDepthMode
ParseDepthMode(const std::string & text, const std::string & what);
/** "linear", "nearest" or "cubic". */
itk::CPRInterpolationMode
ParseInterpolation(const std::string & text, const std::string & what);
/** "mip", "minip" or "mean". */
itk::CPRSlabMode
ParseSlabMode(const std::string & text, const std::string & what);
/** "jacobi" or "steady". */
itk::BilateralDepthRelaxSolver
ParseRelaxSolver(const std::string & text, const std::string & what);
/** "on"/"off" (also "true"/"false", "yes"/"no", "1"/"0"). */
bool
ParseOnOff(const std::string & text, const std::string & what);

/** \return the keys of the parameter table (vrParameterTable.h) that are fields of vr::ReformationParameters, in
 * table order: the whole-tree reformation's settings as every front end spells them. */
const std::vector<std::string> &
ReformationParameterKeys();

/** Sets the field of \a parameters that the table's entry \a key describes from its text \a text, parsed as the
 * command-line modules parse it (ParseUpAxis, ParseImageSize, ...; a number for the numbers).
 * \param spelling how messages name it (a flag such as "--angle", or the parameter's meaning).
 * Throws vr::InputError naming \a spelling and \a text when the text is no valid value, std::logic_error for a key
 * that is not one of ReformationParameterKeys(). Only the form is checked; ReformationParameters::Validate() checks
 * the ranges. An empty text clears what can be unset (size, spacing, jump threshold, anisotropy, OpenCL device). */
void
SetReformationParameter(ReformationParameters & parameters,
                        const std::string &     key,
                        const std::string &     text,
                        const std::string &     spelling);
/** \param mode a mode.
 * \return its text form: "scanline", "linear", "mip", ... */
const char *
ToString(itk::CPRDepthMode mode);
const char *
ToString(itk::CPRInterpolationMode mode);
const char *
ToString(itk::CPRSlabMode mode);
const char *
ToString(itk::BilateralDepthRelaxSolver solver);
} // namespace vr

#endif
