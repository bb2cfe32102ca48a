// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrPythonErrors.h"

#include "vrParameterName.h"

#include <map>

namespace vr::python
{
namespace
{
/** The logic's parameters by meaning -> the package's keyword arguments (the modules' CLIParameterMap, for Python). */
const std::map<std::string, std::string> Keywords = {
  { ParameterName::UpAxis, "up" },
  { ParameterName::Angle, "angle" },
  { ParameterName::ViewCenter, "center" },
  { ParameterName::ViewSize, "size" },
  { ParameterName::PixelSpacing, "spacing" },
  { ParameterName::DepthMode, "mode" },
  { ParameterName::FixLumen, "fix_lumen" },
  { ParameterName::Relaxation, "relaxation" },
  { ParameterName::Anisotropy, "anisotropy" },
  { ParameterName::JumpThreshold, "jump_threshold" },
  { ParameterName::Solver, "solver" },
  { ParameterName::Iterations, "iterations" },
  { ParameterName::Backend, "backend" },
  { ParameterName::OpenCLDevice, "opencl_device" },
  { ParameterName::Interpolation, "interpolation" },
  { ParameterName::SlabThickness, "slab_thickness" },
  { ParameterName::SlabMode, "slab_mode" },
  { ParameterName::Window, "window" },
  { ParameterName::Level, "level" },
  { ParameterName::CenterlineSpace, "space" },
  { ParameterName::VesselLabels, "labels" },
  { ParameterName::RootPoint, "root_points" },
  { ParameterName::RootPointTolerance, "root_point_tolerance" },
  { ParameterName::MinimumBranchLength, "minimum_branch_length" },
  { ParameterName::ReferencePoints, "reference_points" },
  { ParameterName::ReferenceMethod, "reference_method" },
  { ParameterName::LumenSampling, "lumen_sampling" },
  { ParameterName::Branch, "branch" },
  { ParameterName::PathRange, "path_range" },
  { ParameterName::Roll, "roll" },
  { ParameterName::Width, "width" },
  { ParameterName::SectionSpacing, "section_spacing" },
};
} // namespace

std::string
KeywordOf(const std::string & meaning)
{
  const auto entry = Keywords.find(meaning);
  return entry == Keywords.end() ? std::string() : entry->second;
}

std::string
MessageOf(const InputError & error)
{
  const std::string keyword = KeywordOf(error.Parameter());
  return keyword.empty() ? std::string(error.what()) : keyword + ": " + error.what();
}

void
RaiseValueError(const std::string & message)
{
  throw py::value_error(message);
}

void
RaiseOSError(const std::string & message, const std::string & path)
{
  // OSError(message) with its filename set: str() shows the engine's message as it is (it names the file already).
  py::object error = py::reinterpret_borrow<py::object>(PyExc_OSError)(message);
  if (!path.empty())
  {
    error.attr("filename") = path;
  }
  PyErr_SetObject(PyExc_OSError, error.ptr());
  throw py::error_already_set();
}

void
OnFiles(const std::string & path, const std::function<void()> & work)
{
  try
  {
    work();
  }
  catch (const InputError & error)
  {
    RaiseOSError(MessageOf(error), path);
  }
}

void
OnArguments(const std::function<void()> & work)
{
  try
  {
    work();
  }
  catch (const InputError & error)
  {
    RaiseValueError(MessageOf(error));
  }
  catch (const FileError & error)
  {
    RaiseOSError(error.what());
  }
}

void
RegisterErrors(py::module_ & module)
{
  static py::exception<Cancelled> cancelled(module, "Cancelled");
  cancelled.doc() = "A run stopped because its progress callback returned False: nothing was written, no result.";
  py::register_exception_translator(
    [](std::exception_ptr pointer)
    {
      try
      {
        if (pointer)
        {
          std::rethrow_exception(pointer);
        }
      }
      catch (const Cancelled & error)
      {
        cancelled(error.what());
      }
      catch (const InputError & error)
      {
        // An engine error not routed through OnFiles or OnArguments: a bad argument all the same.
        PyErr_SetString(PyExc_ValueError, MessageOf(error).c_str());
      }
    });
}
} // namespace vr::python
