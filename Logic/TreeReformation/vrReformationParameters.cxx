// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrReformationParameters.h"

#include "itkCPRVectorHelpers.h"
#include "vrInputError.h"
#include "vrRelaxBackend.h"
#include "vrParameterTable.h"
#include "vrText.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <limits>
#include <cmath>
#include <cstdlib>
#include <sstream>
#include <vector>

namespace vr
{
namespace
{
std::string
Quoted(const std::string & text)
{
  return "\"" + text + "\"";
}

template<typename TValue>
std::string
Join(const TValue & values, unsigned int count)
{
  std::ostringstream stream;
  for (unsigned int k = 0; k < count; ++k)
  {
    stream << (k ? "," : "") << values[k];
  }
  return stream.str();
}
double
Number(const std::string & text, const std::string & spelling)
{
  double value = 0.0;
  if (!ParseWholeDouble(text, value))
  {
    throw InputError(spelling + " \"" + text + "\": expected a number");
  }
  return value;
}

long long
WholeNumber(const std::string & text, const std::string & spelling)
{
  long long value = 0;
  if (!ParseWholeInteger(text, value))
  {
    throw InputError(spelling + " \"" + text + "\": expected a whole number");
  }
  return value;
}
} // namespace

ReformationParameters::ReformationParameters()
  : Up(itk::detail::MakeVector3(0.0, 0.0, 1.0))
  , PixelSpacing(itk::detail::MakeVector2(0.0, 0.0))
{
  // The defaults every front end shows are the table's: a default changed there changes the logic's too.
  for (const std::string & key : ReformationParameterKeys())
  {
    const ParameterSpec & spec = Parameter(key);
    if (spec.Default)
    {
      SetReformationParameter(*this, key, *spec.Default, "the parameter table's default of " + spec.Flag);
    }
  }
}

void
ReformationParameters::Validate() const
{
  std::ostringstream problem;
  const char *       parameter = "";
  if (!AutomaticUp && !(std::isfinite(Up[0]) && std::isfinite(Up[1]) && std::isfinite(Up[2]) && Up.GetNorm() > 1e-12))
  {
    parameter = ParameterName::UpAxis;
    problem << "up axis = " << Join(Up, 3) << ": must be a finite, non-zero LPS vector, or automatic";
  }
  else if (!std::isfinite(AngleInDegrees))
  {
    parameter = ParameterName::Angle;
    problem << "angle = " << AngleInDegrees << " degrees: must be a finite number";
  }
  else if (HasCenter && !(std::isfinite(Center[0]) && std::isfinite(Center[1]) && std::isfinite(Center[2])))
  {
    parameter = ParameterName::ViewCenter;
    problem << "view centre = " << Join(Center, 3) << " mm: must be finite";
  }
  else if ((ImageSize[0] == 0) != (ImageSize[1] == 0))
  {
    parameter = ParameterName::ViewSize;
    problem << "view size = " << Join(ImageSize, 2) << ": W and H must both be >= 1 pixel (or both unset)";
  }
  else if (!(std::isfinite(PixelSpacing[0]) && std::isfinite(PixelSpacing[1]) && PixelSpacing[0] >= 0.0 &&
             PixelSpacing[1] >= 0.0) ||
           ((PixelSpacing[0] == 0.0) != (PixelSpacing[1] == 0.0)))
  {
    parameter = ParameterName::PixelSpacing;
    problem << "pixel spacing = " << Join(PixelSpacing, 2) << " mm: both must be finite and > 0 (or both unset)";
  }
  else if (!(std::isfinite(Relaxation) && Relaxation >= 0.0 && Relaxation <= 1.0))
  {
    parameter = ParameterName::Relaxation;
    problem << "relaxation w = " << Relaxation << ": must be in [0, 1]";
  }
  else if (JumpThreshold && Anisotropy)
  {
    // Two parametrisations of one kernel: which one the user meant is not for the logic to guess.
    parameter = ParameterName::JumpThreshold;
    problem << "both the " << ParameterName::JumpThreshold << " J = " << *JumpThreshold << " mm and the "
            << ParameterName::Anisotropy << " a = " << *Anisotropy
            << " mm^-2 are set; they are two forms of one range kernel (a = 1/J^2): set one";
  }
  else if (JumpThreshold && !(std::isfinite(*JumpThreshold) && *JumpThreshold > 0.0))
  {
    parameter = ParameterName::JumpThreshold;
    problem << "jump threshold J = " << *JumpThreshold << " mm: must be finite and > 0";
  }
  else if (Anisotropy && !(std::isfinite(*Anisotropy) && *Anisotropy >= 0.0))
  {
    parameter = ParameterName::Anisotropy;
    problem << "anisotropy a = " << *Anisotropy << " mm^-2: must be finite and >= 0";
  }
  else if (Iterations < 0 || Iterations > static_cast<long long>(std::numeric_limits<unsigned int>::max()))
  {
    parameter = ParameterName::Iterations;
    problem << "iterations N = " << Iterations << ": must be a whole number >= 0";
  }
  else if (!(std::isfinite(SlabThickness) && SlabThickness >= 0.0))
  {
    parameter = ParameterName::SlabThickness;
    problem << "slab thickness = " << SlabThickness << " mm: must be finite and >= 0";
  }
  else if (!(std::isfinite(Window) && Window >= 0.0))
  {
    parameter = ParameterName::Window;
    problem << "window = " << Window << ": must be finite and >= 0 (0 = the CPR's full range)";
  }
  else if (!std::isfinite(Level))
  {
    parameter = ParameterName::Level;
    problem << "level = " << Level << ": must be finite";
  }
  if (!problem.str().empty())
  {
    throw InputError(problem.str(), parameter);
  }
}

double
ReformationParameters::EffectiveAnisotropy() const
{
  if (Anisotropy)
  {
    return *Anisotropy;
  }
  const double J = JumpThreshold ? *JumpThreshold : DefaultJumpThreshold;
  return 1.0 / (J * J);
}

static_assert(ReformationParameters::DefaultJumpThreshold == RelaxFilterType::DefaultJumpThreshold,
              "the parameters' default jump threshold is the filter's");

void
ReformationParameters::ConfigureRelaxFilter(RelaxFilterType * filter) const
{
  filter->SetRelaxation(Relaxation);
  if (Anisotropy)
  {
    filter->SetAnisotropy(*Anisotropy);
  }
  else
  {
    filter->SetJumpThreshold(JumpThreshold ? *JumpThreshold : DefaultJumpThreshold);
  }
  filter->SetNumberOfIterations(static_cast<unsigned int>(Iterations));
  filter->SetSolver(Solver);
}

itk::CPRViewSpecification
ReformationParameters::ToViewSpecification() const
{
  itk::CPRViewSpecification specification;
  specification.AutomaticUp = AutomaticUp;
  specification.Up = Up;
  specification.AngleInDegrees = AngleInDegrees;
  specification.HasCenter = HasCenter;
  specification.Center = Center;
  specification.ImageSize = ImageSize;
  specification.PixelSpacing = PixelSpacing;
  return specification;
}

UpAxisChoice
ParseUpAxis(const std::string & text, const std::string & what)
{
  const std::string key = ToLower(Trim(text));
  UpAxisChoice      choice;
  if (key == "auto")
  {
    choice.Automatic = true;
    return choice;
  }
  // Patient directions in LPS: L = +x, P = +y, S = +z.
  const struct
  {
    const char * Name;
    double       X, Y, Z;
  } named[] = { { "s", 0, 0, 1 },  { "i", 0, 0, -1 }, { "p", 0, 1, 0 },
                { "a", 0, -1, 0 }, { "l", 1, 0, 0 },  { "r", -1, 0, 0 } };
  for (const auto & direction : named)
  {
    if (key == direction.Name)
    {
      choice.Vector = itk::detail::MakeVector3(direction.X, direction.Y, direction.Z);
      return choice;
    }
  }
  const auto parts = SplitAndTrim(key, ',');
  double     values[3];
  bool       valid = parts.size() == 3;
  for (std::size_t k = 0; valid && k < 3; ++k)
  {
    valid = ParseWholeDouble(parts[k], values[k]);
  }
  if (!valid || std::sqrt(values[0] * values[0] + values[1] * values[1] + values[2] * values[2]) < 1e-12)
  {
    throw InputError(what + " " + Quoted(text) +
                     ": expected S, I, A, P, L, R, auto, or a non-zero LPS vector x,y,z such as 0,1,0");
  }
  choice.Vector = itk::detail::MakeVector3(values[0], values[1], values[2]);
  return choice;
}

itk::Size<2>
ParseImageSize(const std::string & text, const std::string & what)
{
  const auto parts = SplitAndTrim(text, ',');
  long long  values[2];
  bool       valid = parts.size() == 2;
  for (std::size_t k = 0; valid && k < 2; ++k)
  {
    valid = ParseWholeInteger(parts[k], values[k]);
  }
  if (!valid)
  {
    throw InputError(what + " " + Quoted(text) + ": expected W,H in whole pixels, e.g. 512,1024");
  }
  if (values[0] < 1 || values[1] < 1)
  {
    throw InputError(what + " " + text + ": W and H must both be >= 1 pixel");
  }
  itk::Size<2> size;
  size[0] = static_cast<itk::SizeValueType>(values[0]);
  size[1] = static_cast<itk::SizeValueType>(values[1]);
  return size;
}

itk::Vector<double, 2>
ParsePixelSpacing(const std::string & text, const std::string & what)
{
  const auto parts = SplitAndTrim(text, ',');
  double     values[2] = { 0.0, 0.0 };
  bool       valid = parts.size() == 1 || parts.size() == 2;
  for (std::size_t k = 0; valid && k < parts.size(); ++k)
  {
    valid = ParseWholeDouble(parts[k], values[k]);
  }
  if (!valid)
  {
    throw InputError(what + " " + Quoted(text) + ": expected a spacing in mm (s, or sx,sy), e.g. 0.5");
  }
  if (parts.size() == 1)
  {
    values[1] = values[0];
  }
  if (!(values[0] > 0.0 && values[1] > 0.0))
  {
    throw InputError(what + " " + text + ": the spacing must be > 0 mm");
  }
  return itk::detail::MakeVector2(values[0], values[1]);
}

itk::CPRDepthMode
ParseDepthMode(const std::string & text, const std::string & what)
{
  const std::string key = ToLower(Trim(text));
  if (key == "scanline")
  {
    return itk::CPRDepthMode::Scanline;
  }
  if (key == "nearest")
  {
    return itk::CPRDepthMode::Nearest;
  }
  if (key == "visibility")
  {
    return itk::CPRDepthMode::Visibility;
  }
  throw InputError(what + " " + Quoted(text) + ": use scanline, nearest or visibility");
}

AngleChoice
ParseAngle(const std::string & text, const std::string & what)
{
  AngleChoice choice;
  if (ToLower(Trim(text)) == "best")
  {
    choice.LeastOccluded = true;
    return choice;
  }
  if (!ParseWholeDouble(Trim(text), choice.Degrees) || !std::isfinite(choice.Degrees))
  {
    throw InputError(what + " " + Quoted(text) +
                     ": expected an angle in degrees, e.g. 30, or best (the view that hides the least)");
  }
  return choice;
}

itk::CPRInterpolationMode
ParseInterpolation(const std::string & text, const std::string & what)
{
  const std::string key = ToLower(Trim(text));
  if (key == "linear")
  {
    return itk::CPRInterpolationMode::Linear;
  }
  if (key == "nearest")
  {
    return itk::CPRInterpolationMode::Nearest;
  }
  if (key == "cubic")
  {
    return itk::CPRInterpolationMode::Cubic;
  }
  throw InputError(what + " " + Quoted(text) + ": use linear, nearest or cubic");
}

itk::CPRSlabMode
ParseSlabMode(const std::string & text, const std::string & what)
{
  const std::string key = ToLower(Trim(text));
  if (key == "mip")
  {
    return itk::CPRSlabMode::MIP;
  }
  if (key == "minip")
  {
    return itk::CPRSlabMode::MinIP;
  }
  if (key == "mean")
  {
    return itk::CPRSlabMode::Mean;
  }
  throw InputError(what + " " + Quoted(text) + ": use mip, minip or mean");
}

itk::BilateralDepthRelaxSolver
ParseRelaxSolver(const std::string & text, const std::string & what)
{
  const std::string key = ToLower(Trim(text));
  if (key == "jacobi")
  {
    return itk::BilateralDepthRelaxSolver::Jacobi;
  }
  if (key == "steady")
  {
    return itk::BilateralDepthRelaxSolver::Steady;
  }
  throw InputError(what + " " + Quoted(text) + ": use jacobi or steady", ParameterName::Solver);
}

bool
ParseOnOff(const std::string & text, const std::string & what)
{
  const std::string key = ToLower(Trim(text));
  if (key == "on" || key == "true" || key == "yes" || key == "1")
  {
    return true;
  }
  if (key == "off" || key == "false" || key == "no" || key == "0")
  {
    return false;
  }
  throw InputError(what + " " + Quoted(text) + ": use on or off");
}

const char *
ToString(itk::CPRDepthMode mode)
{
  switch (mode)
  {
    case itk::CPRDepthMode::Nearest:
      return "nearest";
    case itk::CPRDepthMode::Visibility:
      return "visibility";
    default:
      return "scanline";
  }
}

const char *
ToString(itk::CPRInterpolationMode mode)
{
  switch (mode)
  {
    case itk::CPRInterpolationMode::Nearest:
      return "nearest";
    case itk::CPRInterpolationMode::Cubic:
      return "cubic";
    default:
      return "linear";
  }
}

const char *
ToString(itk::CPRSlabMode mode)
{
  switch (mode)
  {
    case itk::CPRSlabMode::MinIP:
      return "minip";
    case itk::CPRSlabMode::Mean:
      return "mean";
    default:
      return "mip";
  }
}

const char *
ToString(itk::BilateralDepthRelaxSolver solver)
{
  return solver == itk::BilateralDepthRelaxSolver::Steady ? "steady" : "jacobi";
}

const std::vector<std::string> &
ReformationParameterKeys()
{
  static const std::vector<std::string> keys = { "up",           "angle",         "size",          "spacing",
                                                 "mode",         "fixLumen",      "relaxation",    "jumpThreshold",
                                                 "anisotropy",   "iterations",    "solver",        "backend",
                                                 "openclDevice", "interpolation", "slabThickness", "slabMode",
                                                 "window",       "level" };
  return keys;
}

void
SetReformationParameter(ReformationParameters & p,
                        const std::string &     key,
                        const std::string &     text,
                        const std::string &     spelling)
{
  const std::string value = Trim(text);
  if (key == "up")
  {
    const UpAxisChoice choice = ParseUpAxis(value, spelling);
    p.AutomaticUp = choice.Automatic;
    p.Up = choice.Vector;
  }
  else if (key == "angle")
  {
    const AngleChoice choice = ParseAngle(value, spelling);
    p.LeastOccludedAngle = choice.LeastOccluded;
    p.AngleInDegrees = choice.Degrees;
  }
  else if (key == "size")
  {
    p.ImageSize = value.empty() ? itk::Size<2>{ { 0, 0 } } : ParseImageSize(value, spelling);
  }
  else if (key == "spacing")
  {
    p.PixelSpacing.Fill(0.0);
    if (!value.empty())
    {
      p.PixelSpacing = ParsePixelSpacing(value, spelling);
    }
  }
  else if (key == "mode")
  {
    p.Mode = ParseDepthMode(value, spelling);
  }
  else if (key == "fixLumen")
  {
    p.FixLumen = ParseOnOff(value, spelling);
  }
  else if (key == "relaxation")
  {
    p.Relaxation = Number(value, spelling);
  }
  else if (key == "jumpThreshold")
  {
    p.JumpThreshold.reset();
    if (!value.empty())
    {
      p.JumpThreshold = Number(value, spelling);
    }
  }
  else if (key == "anisotropy")
  {
    p.Anisotropy.reset();
    if (!value.empty())
    {
      p.Anisotropy = Number(value, spelling);
    }
  }
  else if (key == "iterations")
  {
    p.Iterations = WholeNumber(value, spelling);
  }
  else if (key == "solver")
  {
    p.Solver = ParseRelaxSolver(value, spelling);
  }
  else if (key == "backend")
  {
    p.Backend = ParseRelaxBackend(value, spelling);
  }
  else if (key == "openclDevice")
  {
    p.OpenCLDevice = value;
  }
  else if (key == "interpolation")
  {
    p.Interpolation = ParseInterpolation(value, spelling);
  }
  else if (key == "slabThickness")
  {
    p.SlabThickness = Number(value, spelling);
  }
  else if (key == "slabMode")
  {
    p.SlabMode = ParseSlabMode(value, spelling);
  }
  else if (key == "window")
  {
    p.Window = Number(value, spelling);
  }
  else if (key == "level")
  {
    p.Level = Number(value, spelling);
  }
  else
  {
    throw std::logic_error("SetReformationParameter: \"" + key + "\" is not a field of vr::ReformationParameters");
  }
}
} // namespace vr
