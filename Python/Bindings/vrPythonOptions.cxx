// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrPythonOptions.h"

#include "vrPythonErrors.h"
#include "vrReformationParameters.h"
#include "vrVolumeIO.h"

#include <cmath>

namespace vr::python
{
namespace
{
std::string
Repr(const py::handle & value)
{
  return py::repr(value).cast<std::string>();
}

bool
IsNumber(const py::handle & value)
{
  // int, float and numpy's scalars; not bool (True is no angle), text or sequences.
  return !py::isinstance<py::bool_>(value) &&
         (py::isinstance<py::int_>(value) || py::isinstance<py::float_>(value) ||
          (py::hasattr(value, "__float__") && !py::isinstance<py::str>(value) && !py::hasattr(value, "__len__")));
}
} // namespace

OptionReader::OptionReader(const py::kwargs & options)
  : m_Options(options)
{
}

bool
OptionReader::Has(const std::string & name)
{
  m_Used.insert(name);
  return m_Options.contains(name) && !m_Options[name.c_str()].is_none();
}

py::object
OptionReader::Object(const std::string & name)
{
  return Has(name) ? py::reinterpret_borrow<py::object>(m_Options[name.c_str()]) : py::none();
}

std::string
OptionReader::Text(const std::string & name, const std::string & fallback)
{
  if (!Has(name))
  {
    return fallback;
  }
  const py::object value = m_Options[name.c_str()];
  if (!py::isinstance<py::str>(value))
  {
    RaiseValueError(name + ": expected text, got " + Repr(value));
  }
  return value.cast<std::string>();
}

double
OptionReader::Number(const std::string & name, double fallback)
{
  if (!Has(name))
  {
    return fallback;
  }
  const py::object value = m_Options[name.c_str()];
  if (!IsNumber(value))
  {
    RaiseValueError(name + ": expected a number, got " + Repr(value));
  }
  return value.cast<double>();
}

long long
OptionReader::Integer(const std::string & name, long long fallback)
{
  if (!Has(name))
  {
    return fallback;
  }
  const py::object value = m_Options[name.c_str()];
  if (!IsNumber(value) || (py::isinstance<py::float_>(value) && !value.attr("is_integer")().cast<bool>()))
  {
    RaiseValueError(name + ": expected a whole number, got " + Repr(value));
  }
  return py::int_(value).cast<long long>();
}

bool
OptionReader::Flag(const std::string & name, bool fallback)
{
  if (!Has(name))
  {
    return fallback;
  }
  const py::object value = m_Options[name.c_str()];
  if (!py::isinstance<py::bool_>(value))
  {
    RaiseValueError(name + ": expected True or False, got " + Repr(value));
  }
  return value.cast<bool>();
}

std::vector<double>
OptionReader::Numbers(const std::string & name, std::size_t count)
{
  const py::object    value = Object(name);
  std::vector<double> numbers;
  if (py::isinstance<py::sequence>(value) && !py::isinstance<py::str>(value))
  {
    for (const auto & item : value)
    {
      if (!IsNumber(item))
      {
        numbers.clear();
        break;
      }
      numbers.push_back(item.cast<double>());
    }
  }
  if (numbers.size() != count)
  {
    RaiseValueError(name + ": expected " + std::to_string(count) + " numbers, got " + Repr(value));
  }
  return numbers;
}

std::vector<unsigned long>
OptionReader::Whole(const std::string & name, std::size_t count)
{
  std::vector<unsigned long> whole;
  for (const double number : Numbers(name, count))
  {
    if (!(number >= 1.0 && number <= 2147483647.0 && number == std::floor(number)))
    {
      RaiseValueError(name + ": expected " + std::to_string(count) + " whole numbers >= 1, got " +
                      Repr(m_Options[name.c_str()]));
    }
    whole.push_back(static_cast<unsigned long>(number));
  }
  return whole;
}

std::vector<double>
OptionReader::Spacing(const std::string & name)
{
  const py::object    value = Object(name);
  std::vector<double> spacing = IsNumber(value) ? std::vector<double>(2, value.cast<double>()) : Numbers(name, 2);
  for (const double s : spacing)
  {
    if (!(std::isfinite(s) && s > 0.0))
    {
      RaiseValueError(name + ": " + Repr(value) + ": a spacing must be finite and > 0 mm");
    }
  }
  return spacing;
}

void
OptionReader::Up(const std::string & name, bool & automatic, itk::Vector<double, 3> & up)
{
  if (!Has(name))
  {
    return;
  }
  const py::object value = m_Options[name.c_str()];
  UpAxisChoice     choice;
  if (py::isinstance<py::str>(value))
  {
    choice = ParseUpAxis(value.cast<std::string>(), name);
  }
  else
  {
    // Three numbers, LPS; ReformationParameters::Validate() refuses a zero or non-finite vector.
    const auto vector = Numbers(name, 3);
    choice.Automatic = false;
    for (unsigned int k = 0; k < 3; ++k)
    {
      choice.Vector[k] = vector[k];
    }
  }
  automatic = choice.Automatic;
  up = choice.Vector;
}

void
OptionReader::CheckAllUsed(const std::string & function) const
{
  for (const auto & entry : m_Options)
  {
    const std::string key = py::str(entry.first).cast<std::string>();
    if (m_Used.count(key) == 0)
    {
      throw py::type_error(function + "() got an unexpected keyword argument '" + key + "'");
    }
  }
}

Volume
VolumeOf(const py::object & value)
{
  if (py::isinstance<Volume>(value))
  {
    return value.cast<Volume>();
  }
  if (py::isinstance<py::str>(value) || py::hasattr(value, "__fspath__"))
  {
    return py::module_::import("vesselreformation._engine").attr("read_volume")(value).cast<Volume>();
  }
  RaiseValueError("volume: give a Volume (Volume(array, spacing=...), Volume.from_affine, read_volume) or a path; "
                  "got " +
                  Repr(py::type::of(value)));
}

std::string
PathOf(const py::handle & value)
{
  return py::str(py::module_::import("os").attr("fspath")(value)).cast<std::string>();
}
} // namespace vr::python
