// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrCLIArguments_h
#define vrCLIArguments_h

#include "vrCLIModuleDescription.h"

#include <map>
#include <string>

namespace vr
{
/** The flags every module accepts besides those of its XML, as 3D Slicer's generated modules do: --xml (print
 * the description), --help (print the usage) and --processinformationaddress (Slicer hands a running shared
 * library module its progress structure). */
constexpr const char * ReservedFlags[] = { "xml", "help", "processinformationaddress" };

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
   * passes it). Positional parameters fill the indices in order. Values are checked by type: whole numbers for
   * integer, finite numbers for float and double, comma lists of numbers for the vectors, one of the elements
   * (any case) for string-enumeration; numbers must lie within the XML's constraints.
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

  /** \param description the module's description.
   * \param program the module's name.
   * \return the usage text: every flag with its type, default and description, then the reserved flags. */
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
