// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrCLIModuleDescription_h
#define vrCLIModuleDescription_h

#include <string>
#include <vector>

namespace vr
{
/** One parameter of a command-line module, as its Slicer Execution Model XML declares it.
 * \ingroup VesselReformation
 */
struct CLIParameter
{
  /** The XML element: image, file, geometry, float, integer, string, string-enumeration, integer-vector, ... */
  std::string Tag;
  std::string Name;
  /** Without the leading "--"; empty for a positional parameter. */
  std::string LongFlag;
  /** Position among the positional parameters; -1 for a flag. */
  int         Index{ -1 };
  std::string Label;
  std::string Description;
  /** Empty when the XML gives no default (an optional parameter that is then unset). */
  std::string Default;
  bool        HasDefault{ false };
  /** "input", "output" or empty. */
  std::string Channel;
  /** string-enumeration elements. */
  std::vector<std::string> Elements;
  bool                     HasConstraints{ false };
  double                   Minimum{ 0.0 };
  double                   Maximum{ 0.0 };

  /** \return "--flag" for a flag, "<name>" for a positional parameter: how messages name it. */
  std::string
  Spelling() const
  {
    return LongFlag.empty() ? "<" + Name + ">" : "--" + LongFlag;
  }
};

/** \class CLIModuleDescription
 * \brief What a command-line module's XML says: its title and its parameters, in the order they appear.
 *
 * The XML compiled into each module is the single description of its command line: the parser
 * (vrCLIArguments.h) accepts exactly the flags listed here, and --xml prints the same text.
 * \ingroup VesselReformation
 */
struct CLIModuleDescription
{
  std::string               Title;
  std::string               Category;
  std::vector<CLIParameter> Parameters;

  /** Parses \a xml (with VTK's expat-based parser). Throws std::logic_error when the XML is malformed or a
   * parameter lacks a name, or has neither a longflag nor an index: a build error, not a user error.
   * \param xml the module's description.
   * \return the description. */
  static CLIModuleDescription
  FromXML(const char * xml);

  /** \param name a parameter's name.
   * \return the parameter; throws std::logic_error when the XML has none of that name. */
  const CLIParameter &
  Find(const std::string & name) const;
  /** \param flag a long flag without "--".
   * \return the parameter with that flag, or null. */
  const CLIParameter *
  FindFlag(const std::string & flag) const;
  /** \return the positional parameters, ordered by index. */
  std::vector<const CLIParameter *>
  Positionals() const;
};
} // namespace vr

#endif
