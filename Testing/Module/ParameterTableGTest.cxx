// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// The one parameter table (docs/parameters.md) against every front end that shows a parameter: each module's --xml
// and --help, the viewer's --help and the logic's defaults. A description, label, default, range or value list edited
// by hand in one of them, instead of in Resources/Parameters/vrParameters.json, fails here (the module panel is checked
// by the widgets' tests).
#include "vrCLIModuleDescription.h"
#include "vrParameterTable.h"
#include "vrReformationParameters.h"
#include "vrTestFiles.h"
#include "vrTestProcess.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace
{
using namespace vr;

/** A folder for a run's captured output. */
std::string
Scratch()
{
  return test::FreshFolderForThisTest(VR_TEST_OUTPUT_DIR, "parameter-table-").string();
}

std::vector<std::string>
Split(const std::string & text, char separator)
{
  std::vector<std::string> parts;
  std::stringstream        stream(text);
  std::string              part;
  while (std::getline(stream, part, separator))
  {
    if (!part.empty())
    {
      parts.push_back(part);
    }
  }
  return parts;
}

/** The entries with \a flag. */
std::vector<const ParameterSpec *>
EntriesWithFlag(const std::string & flag)
{
  std::vector<const ParameterSpec *> entries;
  for (const ParameterSpec & spec : ParameterTable())
  {
    if (spec.Flag == flag)
    {
      entries.push_back(&spec);
    }
  }
  return entries;
}

/** Empty when \a parameter is exactly what \a spec says; else what differs. */
std::string
Difference(const CLIParameter & parameter, const ParameterSpec & spec)
{
  std::ostringstream what;
  if (parameter.Tag != spec.Type)
    what << " element <" << parameter.Tag << "> instead of <" << spec.Type << ">;";
  if (parameter.Label != spec.Label)
    what << " label \"" << parameter.Label << "\" instead of \"" << spec.Label << "\";";
  if (parameter.Description != spec.Description)
    what << " description differs;";
  if (parameter.HasDefault != spec.Default.has_value() || (spec.Default && parameter.Default != *spec.Default))
    what << " default \"" << parameter.Default << "\" instead of \"" << spec.Default.value_or("(none)") << "\";";
  if (parameter.Elements != spec.Elements)
    what << " values differ;";
  if (parameter.HasConstraints != (spec.Minimum.has_value() || spec.Maximum.has_value()) ||
      (spec.Minimum && parameter.Minimum != *spec.Minimum) || (spec.Maximum && parameter.Maximum != *spec.Maximum))
    what << " range differs;";
  return what.str();
}

struct Module
{
  std::string Name;
  std::string Executable;
};

std::vector<Module>
Modules()
{
  std::vector<Module> modules;
  for (const std::string & name : Split(VR_CLI_MODULE_NAMES, ','))
  {
    modules.push_back({ name, std::string(VR_CLI_MODULES_DIR) + "/" + name });
  }
  return modules;
}

TEST(ParameterTable, KeysAreUniqueAndEveryEntryIsComplete)
{
  std::set<std::string> keys;
  for (const ParameterSpec & spec : ParameterTable())
  {
    EXPECT_TRUE(keys.insert(spec.Key).second) << spec.Key;
    EXPECT_FALSE(spec.Flag.empty()) << spec.Key;
    EXPECT_FALSE(spec.Meaning.empty()) << spec.Key;
    EXPECT_FALSE(spec.Label.empty()) << spec.Key;
    EXPECT_FALSE(spec.Description.empty()) << spec.Key;
    if (spec.Type == "string-enumeration")
    {
      ASSERT_FALSE(spec.Elements.empty()) << spec.Key;
      ASSERT_TRUE(spec.Default.has_value()) << spec.Key;
      EXPECT_NE(std::find(spec.Elements.begin(), spec.Elements.end(), *spec.Default), spec.Elements.end())
        << spec.Key << ": the default is not one of the values";
    }
    if (spec.Minimum && spec.Maximum)
    {
      EXPECT_LT(*spec.Minimum, *spec.Maximum) << spec.Key;
    }
  }
  for (const std::string & key : ReformationParameterKeys())
  {
    EXPECT_NO_THROW(Parameter(key)) << key << " is a field of the reformation's parameters but not in the table";
  }
  EXPECT_THROW(Parameter("no such parameter"), std::logic_error);
}

TEST(ParameterTable, EveryModuleDescribesEachOfItsFlagsAsTheTableDoes)
{
  std::size_t checked = 0;
  for (const Module & module : Modules())
  {
    const test::ProcessResult xml = test::RunProcess({ module.Executable, "--xml" }, Scratch());
    ASSERT_EQ(xml.ExitCode, 0) << module.Name << ": " << xml.Err;
    const CLIModuleDescription description = CLIModuleDescription::FromXML(xml.Out.c_str());
    const test::ProcessResult  help = test::RunProcess({ module.Executable, "--help" }, Scratch());
    ASSERT_EQ(help.ExitCode, 0) << module.Name;
    for (const CLIParameter & parameter : description.Parameters)
    {
      const std::vector<const ParameterSpec *> entries = EntriesWithFlag(parameter.LongFlag);
      if (parameter.LongFlag.empty() || entries.empty())
      {
        continue; // a module's own inputs, outputs and returned values
      }
      std::string           differences;
      const ParameterSpec * match = nullptr;
      for (const ParameterSpec * spec : entries)
      {
        const std::string difference = Difference(parameter, *spec);
        if (difference.empty())
        {
          match = spec;
        }
        differences += "\n  against \"" + spec->Key + "\":" + difference;
      }
      ++checked;
      ASSERT_NE(match, nullptr) << module.Name << " --" << parameter.LongFlag
                                << " is not as the parameter table describes it (edit "
                                   "Resources/Parameters/vrParameters.json, not the module's XML):"
                                << differences;
      // The usage text is made from the same XML: the label, the description and the default reach the user.
      EXPECT_NE(help.Out.find("--" + match->Flag), std::string::npos) << module.Name << " --help";
      EXPECT_NE(help.Out.find(match->Description), std::string::npos) << module.Name << " --help, " << match->Key;
      if (match->Default && !match->Default->empty())
      {
        EXPECT_NE(help.Out.find("--" + match->Flag + " <" + match->Type), std::string::npos);
        EXPECT_NE(help.Out.find("(default " + *match->Default + ")"), std::string::npos)
          << module.Name << " --help, " << match->Key;
      }
    }
  }
  // The four modules declare 45 of the table's parameters between them (some twice).
  EXPECT_GE(checked, 40u);
}

TEST(ParameterTable, EveryEntryIsUsedByAModule)
{
  std::set<std::string> used;
  for (const Module & module : Modules())
  {
    const test::ProcessResult  xml = test::RunProcess({ module.Executable, "--xml" }, Scratch());
    const CLIModuleDescription description = CLIModuleDescription::FromXML(xml.Out.c_str());
    for (const CLIParameter & parameter : description.Parameters)
    {
      for (const ParameterSpec * spec : EntriesWithFlag(parameter.LongFlag))
      {
        if (Difference(parameter, *spec).empty())
        {
          used.insert(spec->Key);
        }
      }
    }
  }
  for (const ParameterSpec & spec : ParameterTable())
  {
    EXPECT_EQ(used.count(spec.Key), 1u) << spec.Key << ": an entry no module declares";
  }
}

TEST(ParameterTable, TheLogicStartsFromTheTablesDefaults)
{
  const ReformationParameters defaults;
  EXPECT_EQ(defaults.Iterations, std::stoll(*Parameter("iterations").Default));
  EXPECT_DOUBLE_EQ(defaults.Relaxation, std::stod(*Parameter("relaxation").Default));
  EXPECT_DOUBLE_EQ(defaults.AngleInDegrees, std::stod(*Parameter("angle").Default));
  EXPECT_STREQ(ToString(defaults.Mode), Parameter("mode").Default->c_str());
  EXPECT_STREQ(ToString(defaults.Solver), Parameter("solver").Default->c_str());
  EXPECT_STREQ(ToString(defaults.Interpolation), Parameter("interpolation").Default->c_str());
  EXPECT_STREQ(ToString(defaults.SlabMode), Parameter("slabMode").Default->c_str());
  EXPECT_EQ(defaults.FixLumen, *Parameter("fixLumen").Default == "on");
  // "S": superior, LPS (0, 0, 1).
  ASSERT_EQ(*Parameter("up").Default, "S");
  EXPECT_FALSE(defaults.AutomaticUp);
  EXPECT_DOUBLE_EQ(defaults.Up[2], 1.0);
  EXPECT_FALSE(defaults.JumpThreshold.has_value());
  EXPECT_FALSE(Parameter("jumpThreshold").Default.has_value());
}

#ifdef VR_VIEWER_EXE
TEST(ParameterTable, TheViewersHelpDescribesItsParametersAsTheTableDoes)
{
  const test::ProcessResult help = test::RunProcess({ VR_VIEWER_EXE, "--help" }, Scratch());
  ASSERT_EQ(help.ExitCode, 0) << help.Err;
  // CLI11 may break long lines; compare with the whitespace folded.
  auto fold = [](const std::string & text)
  {
    std::string folded;
    for (const char c : text)
    {
      const bool space = c == ' ' || c == '\n' || c == '\t';
      if (!(space && !folded.empty() && folded.back() == ' '))
      {
        folded += space ? ' ' : c;
      }
    }
    return folded;
  };
  const std::string text = fold(help.Out);
  for (const char * key : { "up",
                            "angle",
                            "size",
                            "spacing",
                            "mode",
                            "interpolation",
                            "relaxation",
                            "jumpThreshold",
                            "anisotropy",
                            "solver",
                            "iterations",
                            "backend",
                            "fixLumen",
                            "window",
                            "level" })
  {
    const ParameterSpec & spec = Parameter(key);
    EXPECT_NE(text.find("--" + spec.Flag), std::string::npos) << key;
    EXPECT_NE(text.find(fold(spec.Description)), std::string::npos) << key << ": the viewer's help";
    if (spec.Default && !spec.Default->empty())
    {
      EXPECT_NE(text.find(fold(spec.Description) + " (default " + *spec.Default + ")"), std::string::npos) << key;
    }
  }
}
#endif
} // namespace
