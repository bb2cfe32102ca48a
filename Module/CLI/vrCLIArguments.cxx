// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrCLIArguments.h"

#include "vrInputError.h"
#include "vrText.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <sstream>

namespace vr
{
namespace
{
std::string
Ordinal(int index)
{
  static const char * names[] = { "first", "second", "third", "fourth", "fifth" };
  return index < 5 ? names[index] : std::to_string(index + 1) + "th";
}

std::string
FormatNumber(double value)
{
  std::ostringstream text;
  text << value;
  return text.str();
}

/** Checks \a value against the parameter's type and constraints; returns it in canonical form. */
std::string
CheckedValue(const CLIParameter & parameter, const std::string & value)
{
  const std::string   what = parameter.Spelling() + " \"" + value + "\"";
  const std::string & tag = parameter.Tag;
  const auto          checkRange = [&](double number)
  {
    if (parameter.HasConstraints && number < parameter.Minimum)
    {
      throw InputError(parameter.Spelling() + " " + value + ": must be >= " + FormatNumber(parameter.Minimum) + " (" +
                       parameter.Label + ")");
    }
    if (parameter.HasConstraints && number > parameter.Maximum)
    {
      throw InputError(parameter.Spelling() + " " + value + ": must be <= " + FormatNumber(parameter.Maximum) + " (" +
                       parameter.Label + ")");
    }
  };
  if (tag == "integer")
  {
    long long number = 0;
    if (!ParseWholeInteger(value, number))
    {
      throw InputError(what + ": not a whole number (" + parameter.Label + ")");
    }
    checkRange(static_cast<double>(number));
  }
  else if (tag == "float" || tag == "double")
  {
    double number = 0.0;
    if (!ParseWholeDouble(value, number))
    {
      throw InputError(what + ": not a finite number (" + parameter.Label + ")");
    }
    checkRange(number);
  }
  else if (tag == "integer-vector" || tag == "float-vector" || tag == "double-vector")
  {
    std::istringstream stream(value);
    std::string        part;
    bool               valid = !value.empty() && value.back() != ',';
    while (valid && std::getline(stream, part, ','))
    {
      long long whole = 0;
      double    number = 0.0;
      valid = tag == "integer-vector" ? ParseWholeInteger(part, whole) : ParseWholeDouble(part, number);
    }
    if (!valid)
    {
      throw InputError(what + ": expected comma-separated " +
                       std::string(tag == "integer-vector" ? "whole numbers" : "numbers") + " (" + parameter.Label +
                       ")");
    }
  }
  else if (tag == "point")
  {
    // Three coordinates "x,y,z", as 3D Slicer passes a point (in the XML's coordinateSystem).
    std::istringstream stream(value);
    std::string        part;
    int                count = 0;
    bool               valid = !value.empty() && value.back() != ',';
    while (valid && std::getline(stream, part, ','))
    {
      double number = 0.0;
      valid = ParseWholeDouble(part, number);
      ++count;
    }
    if (!valid || count != 3)
    {
      throw InputError(what + ": expected a point as three comma-separated numbers x,y,z (" + parameter.Label + ")");
    }
  }
  else if (tag == "string-enumeration")
  {
    for (const auto & element : parameter.Elements)
    {
      if (ToLower(element) == ToLower(value))
      {
        return element;
      }
    }
    std::string choices;
    for (std::size_t k = 0; k < parameter.Elements.size(); ++k)
    {
      choices += (k == 0 ? "" : k + 1 == parameter.Elements.size() ? " or " : ", ") + parameter.Elements[k];
    }
    throw InputError(what + ": use " + choices + " (" + parameter.Label + ")");
  }
  else if (tag == "boolean")
  {
    const std::string key = ToLower(value);
    if (key != "true" && key != "false")
    {
      throw InputError(what + ": use true or false, or the bare flag for true");
    }
    return key;
  }
  else if (value.empty() && (tag == "image" || tag == "file" || tag == "geometry" || tag == "directory"))
  {
    throw InputError(parameter.Spelling() + ": the file name is empty (" + parameter.Label + ")");
  }
  return value;
}
/** Whether \a value is a valid value of one of the values the module returns: what a host passes after the positional
 * arguments when it reads return parameters as index-1000 parameters. */
bool
IsValueOfAReturnParameter(const CLIModuleDescription & description, const std::string & value)
{
  for (const CLIParameter * parameter : description.ReturnValues())
  {
    try
    {
      CheckedValue(*parameter, value);
      return true;
    }
    catch (const InputError &)
    {
    }
  }
  return false;
}
} // namespace

CLIArguments
CLIArguments::Parse(const CLIModuleDescription & description, int argc, char * argv[])
{
  CLIArguments             arguments(description);
  std::vector<std::string> positionals;
  for (int k = 1; k < argc; ++k)
  {
    const std::string token = argv[k] ? argv[k] : "";
    if (token == "-h")
    {
      arguments.HelpRequested = true;
      continue;
    }
    if (token.rfind("--", 0) != 0 || token == "--")
    {
      positionals.push_back(token);
      continue;
    }
    std::string flag = token.substr(2);
    std::string value;
    const bool  inlineValue = flag.find('=') != std::string::npos;
    if (inlineValue)
    {
      value = flag.substr(flag.find('=') + 1);
      flag = flag.substr(0, flag.find('='));
    }
    const auto takeValue = [&](const std::string & spelling)
    {
      if (inlineValue)
      {
        return value;
      }
      if (k + 1 >= argc || std::string(argv[k + 1] ? argv[k + 1] : "").rfind("--", 0) == 0)
      {
        throw InputError(spelling + " needs a value");
      }
      ++k;
      return std::string(argv[k] ? argv[k] : "");
    };
    if (flag == "xml")
    {
      arguments.XMLRequested = true;
      continue;
    }
    if (flag == "help")
    {
      arguments.HelpRequested = true;
      continue;
    }
    if (flag == "processinformationaddress")
    {
      const std::string address = takeValue("--processinformationaddress");
      char *            end = nullptr;
      const auto        number = std::strtoull(address.c_str(), &end, 16);
      if (end == address.c_str() || *end != '\0')
      {
        if (address != "(nil)")
        {
          throw InputError("--processinformationaddress \"" + address + "\": not an address");
        }
      }
      arguments.ProcessInformation = reinterpret_cast<void *>(static_cast<std::uintptr_t>(number));
      continue;
    }
    if (flag == "returnparameterfile")
    {
      arguments.ReturnParameterFile = takeValue("--returnparameterfile");
      if (arguments.ReturnParameterFile.empty())
      {
        throw InputError("--returnparameterfile: the file name is empty");
      }
      continue;
    }
    const CLIParameter * parameter = description.FindFlag(flag);
    if (parameter == nullptr)
    {
      throw InputError("unknown flag --" + flag + "; run with --help for the flags this module accepts");
    }
    if (parameter->Tag == "boolean" && !inlineValue)
    {
      arguments.m_Values[parameter->Name] = "true";
      continue;
    }
    arguments.m_Values[parameter->Name] = CheckedValue(*parameter, takeValue(parameter->Spelling()));
  }
  if (arguments.XMLRequested || arguments.HelpRequested)
  {
    return arguments;
  }
  // 3D Slicer appends the value of a returned parameter as one more argument; it is not an input.
  const auto declared = description.Positionals();
  if (positionals.size() == declared.size() + 1 && IsValueOfAReturnParameter(description, positionals.back()))
  {
    positionals.pop_back();
  }
  // A positional parameter whose XML gives a <default> may be left out: with fewer arguments than positional
  // parameters, such ones are skipped, first ones first, and the arguments fill the others in order.
  std::vector<const CLIParameter *> expected = declared;
  const std::size_t                 optional = static_cast<std::size_t>(
    std::count_if(declared.begin(), declared.end(), [](const CLIParameter * p) { return p->HasDefault; }));
  if (positionals.size() < declared.size() && declared.size() - positionals.size() <= optional)
  {
    std::size_t skip = declared.size() - positionals.size();
    expected.clear();
    for (const CLIParameter * parameter : declared)
    {
      if (skip > 0 && parameter->HasDefault)
      {
        --skip;
        continue;
      }
      expected.push_back(parameter);
    }
  }
  if (positionals.size() > expected.size())
  {
    throw InputError("unexpected argument \"" + positionals[expected.size()] + "\": this module takes " +
                     std::to_string(expected.size()) + " positional arguments; run with --help");
  }
  if (positionals.size() < expected.size())
  {
    const CLIParameter & missing = *expected[positionals.size()];
    throw InputError("missing the " + Ordinal(static_cast<int>(positionals.size())) + " argument <" + missing.Name +
                     "> (" + missing.Label + "); run with --help");
  }
  for (std::size_t k = 0; k < expected.size(); ++k)
  {
    arguments.m_Values[expected[k]->Name] = CheckedValue(*expected[k], positionals[k]);
  }
  return arguments;
}

bool
CLIArguments::Given(const std::string & name) const
{
  m_Description->Find(name);
  return m_Values.count(name) != 0;
}

std::string
CLIArguments::String(const std::string & name) const
{
  const CLIParameter & parameter = m_Description->Find(name);
  const auto           found = m_Values.find(name);
  return found != m_Values.end() ? found->second : parameter.Default;
}

double
CLIArguments::Double(const std::string & name) const
{
  return std::strtod(String(name).c_str(), nullptr);
}

long long
CLIArguments::Integer(const std::string & name) const
{
  return std::strtoll(String(name).c_str(), nullptr, 10);
}

std::string
CLIArguments::Spelling(const std::string & name) const
{
  return m_Description->Find(name).Spelling();
}

std::string
CLIArguments::Usage(const CLIModuleDescription & description, const std::string & program)
{
  std::ostringstream usage;
  usage << description.Title << "\n\nUsage: " << program << " [flags]";
  for (const CLIParameter * positional : description.Positionals())
  {
    usage << (positional->HasDefault ? " [<" : " <") << positional->Name << (positional->HasDefault ? ">]" : ">");
  }
  usage << "\n\nArguments:\n";
  for (const CLIParameter * positional : description.Positionals())
  {
    usage << "  <" << positional->Name << ">  " << positional->Label << ". " << positional->Description << "\n";
  }
  usage << "\nFlags:\n";
  for (const auto & parameter : description.Parameters)
  {
    if (parameter.LongFlag.empty())
    {
      continue;
    }
    usage << "  --" << parameter.LongFlag << " <" << parameter.Tag;
    if (!parameter.Elements.empty())
    {
      usage << ":";
      for (std::size_t k = 0; k < parameter.Elements.size(); ++k)
      {
        usage << (k ? "|" : "") << parameter.Elements[k];
      }
    }
    usage << ">";
    if (parameter.HasDefault && !parameter.Default.empty())
    {
      usage << " (default " << parameter.Default << ")";
    }
    usage << "  " << parameter.Label << ". " << parameter.Description << "\n";
  }
  const auto returned = description.ReturnValues();
  if (!returned.empty())
  {
    usage << "\nReturned values (to --returnparameterfile as name = value lines, else as <filter-result> lines when "
             "stdout is not a terminal):\n";
    for (const CLIParameter * parameter : returned)
    {
      usage << "  " << parameter->Name << " <" << parameter->Tag << ">  " << parameter->Label << ". "
            << parameter->Description << "\n";
    }
  }
  usage << "\nAlso:\n"
        << "  --xml  print the Slicer Execution Model description and exit\n"
        << "  --help  print this text and exit\n"
        << "  --processinformationaddress <address>  used by 3D Slicer when it runs the module in-process\n"
        << "  --returnparameterfile <file>  write the returned values there, one name = value line each (3D Slicer)\n";
  return usage.str();
}
} // namespace vr
