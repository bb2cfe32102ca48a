// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrPythonOptions_h
#define vrPythonOptions_h

#include "itkVector.h"
#include "vrPythonErrors.h"
#include "vrPythonVolume.h"

#include <pybind11/pybind11.h>

#include <map>
#include <set>
#include <string>
#include <vector>

namespace vr::python
{
namespace py = pybind11;

/** \class OptionReader
 * \brief Reads a function's keyword arguments by name, with defaults: None means the default. A value of the wrong
 * kind raises ValueError naming the keyword; CheckAllUsed() raises TypeError for a keyword the function does not
 * have, as Python does. Values are checked for range by the engine's own parameter checks afterwards. */
class OptionReader
{
public:
  explicit OptionReader(const py::kwargs & options);

  bool
  Has(const std::string & name);
  py::object
  Object(const std::string & name);
  std::string
  Text(const std::string & name, const std::string & fallback);
  double
  Number(const std::string & name, double fallback);
  long long
  Integer(const std::string & name, long long fallback);
  bool
  Flag(const std::string & name, bool fallback);
  /** Exactly \a count numbers. */
  std::vector<double>
  Numbers(const std::string & name, std::size_t count);
  /** Exactly \a count whole numbers >= 1. */
  std::vector<unsigned long>
  Whole(const std::string & name, std::size_t count);
  /** A spacing: one number for both axes, or two. */
  std::vector<double>
  Spacing(const std::string & name);
  /** An up axis: "S", "I", "A", "P", "L", "R", "auto", "x,y,z" (vr::ParseUpAxis), or three numbers (LPS). */
  void
  Up(const std::string & name, bool & automatic, itk::Vector<double, 3> & up);

  /** TypeError for a keyword \a function has not (any not read). */
  void
  CheckAllUsed(const std::string & function) const;

private:
  py::kwargs            m_Options;
  std::set<std::string> m_Used;
};

/** \return the volume argument: a Volume, or a path read with vr::ReadVolume (OSError). */
Volume
VolumeOf(const py::object & value);
/** \return os.fspath(value). */
std::string
PathOf(const py::handle & value);
/** \return the keys of \a map, comma-separated. */
template<typename TValue>
std::string
KeysOf(const std::map<std::string, TValue> & map)
{
  std::string keys;
  for (const auto & entry : map)
  {
    keys += (keys.empty() ? "" : ", ") + entry.first;
  }
  return keys;
}

/** Reserves each output of \a outputs, a dict {kind: path} (or None: none), with \a writer (an OutputWriter or a
 * VesselPathOutputWriter), the kinds by the names of \a kinds. ValueError for anything but a dict or an unknown kind;
 * OSError naming the file that cannot be reserved. */
template<typename TWriter, typename TKind>
void
AddOutputFiles(const py::object & outputs, const std::map<std::string, TKind> & kinds, TWriter & writer)
{
  if (outputs.is_none())
  {
    return;
  }
  if (!py::isinstance<py::dict>(outputs))
  {
    RaiseValueError("outputs: give a dict {kind: path}, kinds " + KeysOf(kinds));
  }
  for (const auto & [key, path] : outputs.cast<py::dict>())
  {
    const std::string name = py::str(key).cast<std::string>();
    const auto        entry = kinds.find(name);
    if (entry == kinds.end())
    {
      RaiseValueError("outputs: unknown kind \"" + name + "\"; the kinds are " + KeysOf(kinds));
    }
    const std::string file = PathOf(path);
    OnFiles(file, [&] { writer.Add(entry->second, file, "outputs[\"" + name + "\"]"); });
  }
}
} // namespace vr::python

#endif
