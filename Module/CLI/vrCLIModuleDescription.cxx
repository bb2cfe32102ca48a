// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrCLIModuleDescription.h"
#include "vrText.h"

#include <vtkNew.h>
#include <vtkXMLDataElement.h>
#include <vtkXMLDataParser.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <sstream>
#include <stdexcept>

namespace vr
{
namespace
{
std::string
Trimmed(const char * text)
{
  if (text == nullptr)
  {
    return std::string();
  }
  return Trim(text);
}

std::string
ChildText(vtkXMLDataElement * element, const char * name)
{
  vtkXMLDataElement * child = element->FindNestedElementWithName(name);
  return child ? Trimmed(child->GetCharacterData()) : std::string();
}

CLIParameter
ReadParameter(vtkXMLDataElement * element)
{
  CLIParameter parameter;
  parameter.Tag = element->GetName();
  for (int k = 0; k < element->GetNumberOfNestedElements(); ++k)
  {
    vtkXMLDataElement * child = element->GetNestedElement(k);
    const std::string   tag = child->GetName();
    const std::string   text = Trimmed(child->GetCharacterData());
    if (tag == "name")
    {
      parameter.Name = text;
    }
    else if (tag == "longflag")
    {
      parameter.LongFlag = text.rfind("--", 0) == 0 ? text.substr(2) : text;
    }
    else if (tag == "index")
    {
      parameter.Index = std::atoi(text.c_str());
    }
    else if (tag == "label")
    {
      parameter.Label = text;
    }
    else if (tag == "description")
    {
      parameter.Description = text;
    }
    else if (tag == "default")
    {
      parameter.Default = text;
      parameter.HasDefault = true;
    }
    else if (tag == "channel")
    {
      parameter.Channel = text;
    }
    else if (tag == "element")
    {
      parameter.Elements.push_back(text);
    }
    else if (tag == "constraints")
    {
      parameter.HasConstraints = true;
      parameter.Minimum = std::strtod(ChildText(child, "minimum").c_str(), nullptr);
      parameter.Maximum = std::strtod(ChildText(child, "maximum").c_str(), nullptr);
    }
  }
  if (parameter.Name.empty() || (parameter.LongFlag.empty() && parameter.Index < 0 && !parameter.IsReturnValue()))
  {
    throw std::logic_error("module XML: a <" + parameter.Tag +
                           "> parameter needs a name and a longflag or index, unless it is an output it returns");
  }
  return parameter;
}
} // namespace

CLIModuleDescription
CLIModuleDescription::FromXML(const char * xml)
{
  vtkNew<vtkXMLDataParser> parser;
  parser->SetIgnoreCharacterData(0);
  if (xml == nullptr)
  {
    throw std::logic_error("module XML: none given");
  }
  // vtkXMLDataParser reads streams, not strings.
  std::istringstream stream(xml);
  parser->SetStream(&stream);
  if (!parser->Parse() || parser->GetRootElement() == nullptr)
  {
    throw std::logic_error("module XML: not well-formed");
  }
  vtkXMLDataElement *  root = parser->GetRootElement();
  CLIModuleDescription description;
  description.Title = ChildText(root, "title");
  description.Category = ChildText(root, "category");
  for (int g = 0; g < root->GetNumberOfNestedElements(); ++g)
  {
    vtkXMLDataElement * group = root->GetNestedElement(g);
    if (std::strcmp(group->GetName(), "parameters") != 0)
    {
      continue;
    }
    for (int p = 0; p < group->GetNumberOfNestedElements(); ++p)
    {
      vtkXMLDataElement * element = group->GetNestedElement(p);
      const std::string   tag = element->GetName();
      if (tag != "label" && tag != "description")
      {
        description.Parameters.push_back(ReadParameter(element));
      }
    }
  }
  return description;
}

const CLIParameter &
CLIModuleDescription::Find(const std::string & name) const
{
  for (const auto & parameter : Parameters)
  {
    if (parameter.Name == name)
    {
      return parameter;
    }
  }
  throw std::logic_error("module XML: no parameter named " + name);
}

const CLIParameter *
CLIModuleDescription::FindFlag(const std::string & flag) const
{
  for (const auto & parameter : Parameters)
  {
    if (!parameter.LongFlag.empty() && parameter.LongFlag == flag)
    {
      return &parameter;
    }
  }
  return nullptr;
}

std::vector<const CLIParameter *>
CLIModuleDescription::Positionals() const
{
  std::vector<const CLIParameter *> positionals;
  for (const auto & parameter : Parameters)
  {
    if (parameter.Index >= 0 && !parameter.IsReturnValue())
    {
      positionals.push_back(&parameter);
    }
  }
  std::sort(positionals.begin(),
            positionals.end(),
            [](const CLIParameter * a, const CLIParameter * b) { return a->Index < b->Index; });
  return positionals;
}

std::vector<const CLIParameter *>
CLIModuleDescription::ReturnValues() const
{
  std::vector<const CLIParameter *> values;
  for (const auto & parameter : Parameters)
  {
    if (parameter.IsReturnValue())
    {
      values.push_back(&parameter);
    }
  }
  return values;
}
} // namespace vr
