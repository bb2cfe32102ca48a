// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrCLIArguments_h
#define vrCLIArguments_h

#include "vrCLIModuleDescription.h"

#include <map>
#include <string>

namespace vr
{
/** \class CLIArguments
 * \brief A parsed command line of a module: the values given for its parameters, checked against the XML.
 * \ingroup VesselReformation
 */
class CLIArguments
{
public:
  /** Parses argv[1..] against \a description.
   *
   * Flags are "--flag value" or "--flag=value"; a boolean parameter is a bare flag (true when present, as 3D Slicer
   * passes it). Positional parameters fill the indices in order; one whose XML gives a <default> may be left out
   * (with fewer arguments than indices, such ones are skipped, first ones first), as when another flag stands in
   * for it. Values are checked by type: whole numbers for integer, finite numbers for float and double, comma lists of
   * numbers for the vectors, three numbers for a point, one of the elements (any case) for string-enumeration;
   * numbers must lie within the XML's constraints.
   *
   * A module that returns values (CLIModuleDescription::ReturnValues) accepts one argument after its positional ones
   * when it is a valid value of one of them, and ignores it: a host that reads the CTK flavour of the description
   * (index 1000) passes the current value of a return parameter there, as CTK's local-process backend and 3D Slicer
   * both do (each keeps one value per index).
   *
   * \param description the module's description (kept by reference).
   * \param argc, argv the command line; argv[0] is the program.
   * \return the arguments. Throws vr::InputError naming the flag or argument on an unknown flag, a missing value,
   * a value of the wrong type or range, a missing or surplus positional argument (unless --xml or --help). */
  static CLIArguments
  Parse(const CLIModuleDescription & description, int argc, char * argv[]);

  bool XMLRequested{ false };
  bool HelpRequested{ false };
  /** The address 3D Slicer gave with --processinformationaddress, or null. */
  void * ProcessInformation{ nullptr };
  /** The file given with --returnparameterfile, or empty. */
  std::string ReturnParameterFile;

  /** \param name a parameter's name in the XML.
   * \return whether the command line gave it. Throws std::logic_error when the XML has no such parameter. */
  bool
  Given(const std::string & name) const;
  /** \param name a parameter's name in the XML.
   * \return the value given for it, else its XML default (empty when it has none). */
  std::string
  String(const std::string & name) const;
  /** \param name a float parameter's name.
   * \return String(name) as a number; the parser has checked it. */
  double
  Double(const std::string & name) const;
  /** \param name an integer parameter's name.
   * \return String(name) as a whole number; the parser has checked it. */
  long long
  Integer(const std::string & name) const;
  /** \param name a parameter's name in the XML.
   * \return "--flag" for a flag, "<name>" for a positional parameter: how messages name it. */
  std::string
  Spelling(const std::string & name) const;

  /** \return the module's description the arguments were parsed against. */
  const CLIModuleDescription &
  Description() const
  {
    return *m_Description;
  }

  /** \param description the module's description.
   * \param program the module's name.
   * \return the usage text: every flag with its type, default and description, the values the module returns, then
   * the reserved flags. */
  static std::string
  Usage(const CLIModuleDescription & description, const std::string & program);

private:
  explicit CLIArguments(const CLIModuleDescription & description)
    : m_Description(&description)
  {
  }

  const CLIModuleDescription *       m_Description;
  std::map<std::string, std::string> m_Values;
};
} // namespace vr

#endif
