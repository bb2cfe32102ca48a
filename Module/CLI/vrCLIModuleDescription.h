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
  /** Position among the positional parameters; -1 for a flag; ReturnValueIndex for a value the module returns. */
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

  /** The index CTK's schema reserves for output parameters that the module returns rather than takes
   * ("simple return parameters"). */
  static constexpr int ReturnValueIndex = 1000;

  /** \return "--flag" for a flag, "<name>" for a positional parameter: how messages name it. */
  std::string
  Spelling() const
  {
    return LongFlag.empty() ? "<" + Name + ">" : "--" + LongFlag;
  }

  /** \return whether the module returns this parameter's value instead of taking it: an output parameter that has
   * index 1000 (CTK's rule) or neither flag nor index (3D Slicer's rule, ModuleParameter::IsReturnParameter). The two
   * flavours of a module's description declare the same values these two ways (Module/CLI/CMakeLists.txt). */
  bool
  IsReturnValue() const
  {
    return Channel == "output" && (Index == ReturnValueIndex || (LongFlag.empty() && Index < 0));
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
   * parameter lacks a name, or has neither a longflag nor an index without being a return value: a build error, not a
   * user error.
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
  /** \return the positional parameters the command line gives, ordered by index (return values excluded). */
  std::vector<const CLIParameter *>
  Positionals() const;
  /** \return the values the module returns (CLIParameter::IsReturnValue), in the order of the XML. */
  std::vector<const CLIParameter *>
  ReturnValues() const;
};
} // namespace vr

#endif
