// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrParameterTable_h
#define vrParameterTable_h

#include <optional>
#include <string>
#include <vector>

namespace vr
{
/** \class ParameterSpec
 * \brief One parameter of the logic as every front end shows it (docs/parameters.md): the modules' XML, the
 * command-line parsers' messages, the viewer's options and the module panel's controls are all made from these
 * entries, which the build generates from the one table, Resources/Parameters/vrParameters.json.
 * \ingroup VesselReformation
 */
struct ParameterSpec
{
  /** Unique among the entries; a module's XML template names the parameter by it. */
  std::string Key;
  /** The module flag (--Flag) and the viewer's option; two entries of different modules may share a flag. */
  std::string Flag;
  /** What the parameter is, as vr::InputError::Parameter() and the logic's warnings name it (vr::ParameterName). */
  std::string Meaning;
  /** Its unit ("mm", "degrees", "mm^-2", "pixels", "intensity"), empty for none. */
  std::string Unit;
  /** The Slicer Execution Model element: float, integer, string, string-enumeration, float-vector, ... */
  std::string Type;
  /** The short label (the module GUI's, the panel's caption). */
  std::string Label;
  /** What it does: the XML description, the help text, the panel's tooltip. */
  std::string Description;
  /** The default as the modules take it, when there is one. */
  std::optional<std::string> Default;
  std::optional<double>      Minimum;
  std::optional<double>      Maximum;
  std::optional<double>      Step;
  /** The values of a string-enumeration. */
  std::vector<std::string> Elements;
};

/** \return every entry of the table, in its order. */
const std::vector<ParameterSpec> &
ParameterTable();

/** \return the entry of \a key; throws std::logic_error naming the key when the table has none (a programming
 * error: front ends name only keys the table holds, and a test checks it). */
const ParameterSpec &
Parameter(const std::string & key);

/** \return the flags of the entries with the meaning \a meaning (vr::ParameterName), in table order. */
std::vector<std::string>
FlagsOfMeaning(const std::string & meaning);
} // namespace vr

#endif
