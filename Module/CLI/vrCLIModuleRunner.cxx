// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrCLIModuleRunner.h"

#include "vrParameterTable.h"

#include "vrAtomicOutput.h"
#include "vrInputError.h"

#include "itkMacro.h"

#include <fstream>
#include <iostream>
#include <memory>
#include <new>
#include <stdexcept>
#include <unistd.h>

namespace vr
{
namespace
{
/** \return the return values in 3D Slicer's parameter-file format, one "name = value" line per return parameter of
 * the description, in its order. Throws std::logic_error when the module set no value for one of them. */
std::string
ReturnParameterText(const CLIModuleDescription & description, const CLIProgress & progress)
{
  const auto & values = progress.GetReturnValues();
  std::string  text;
  for (const CLIParameter * parameter : description.ReturnValues())
  {
    auto value = values.begin();
    while (value != values.end() && value->first != parameter->Name)
    {
      ++value;
    }
    if (value == values.end())
    {
      throw std::logic_error("the module set no value for its return parameter " + parameter->Name);
    }
    text += parameter->Name + " = " + value->second + "\n";
  }
  return text;
}

void
WriteReturnParameterFile(AtomicOutput & output, const std::string & text)
{
  std::ofstream file(output.TemporaryPath(), std::ios::binary | std::ios::trunc);
  file << text;
  file.close();
  if (!file)
  {
    throw InputError("--returnparameterfile " + output.FinalPath() + ": could not be written");
  }
  output.Commit();
}
} // namespace

std::string
SpellingOfParameter(const CLIModuleDescription & description, const std::string & meaning)
{
  for (const std::string & flag : FlagsOfMeaning(meaning))
  {
    if (const CLIParameter * parameter = description.FindFlag(flag))
    {
      return parameter->Spelling();
    }
  }
  return std::string();
}

int
RunCLIModule(int                   argc,
             char *                argv[],
             const char *          xml,
             const std::string &   name,
             const std::string &   comment,
             const CLIModuleBody & body)
{
  int                  status = 1;
  CLIModuleDescription description;
  try
  {
    description = CLIModuleDescription::FromXML(xml);
    const CLIArguments arguments = CLIArguments::Parse(description, argc, argv);
    if (arguments.XMLRequested)
    {
      std::cout << xml;
      status = 0;
    }
    else if (arguments.HelpRequested)
    {
      std::cout << CLIArguments::Usage(description, name);
      status = 0;
    }
    else
    {
      // The return-parameter file's folder is checked before the work, like every output's.
      std::unique_ptr<AtomicOutput> returnFile;
      if (!arguments.ReturnParameterFile.empty())
      {
        try
        {
          returnFile = std::make_unique<AtomicOutput>(arguments.ReturnParameterFile);
        }
        catch (const InputError & problem)
        {
          throw InputError(std::string("--returnparameterfile: ") + problem.what());
        }
      }
      auto *      information = static_cast<vrModuleProcessInformation *>(arguments.ProcessInformation);
      CLIProgress progress(
        name, comment, information, std::cout, information == nullptr && ::isatty(STDOUT_FILENO) == 1);
      progress.Start();
      body(arguments, progress);
      const std::string returned = ReturnParameterText(description, progress);
      if (returnFile)
      {
        WriteReturnParameterFile(*returnFile, returned);
      }
      progress.End();
      status = 0;
    }
  }
  catch (const InputError & error)
  {
    const std::string flag = SpellingOfParameter(description, error.Parameter());
    std::cerr << name << ": error: " << (flag.empty() ? "" : flag + ": ") << error.what() << std::endl;
  }
  catch (const Cancelled & cancelled)
  {
    std::cerr << name << ": " << cancelled.what() << std::endl;
    status = ExitCodeCancelled;
  }
  catch (const std::bad_alloc &)
  {
    std::cerr << name << ": error: out of memory" << std::endl;
  }
  catch (const itk::ExceptionObject & error)
  {
    std::cerr << name << ": error: " << error.GetDescription() << std::endl;
  }
  catch (const std::exception & error)
  {
    std::cerr << name << ": error: " << error.what() << std::endl;
  }
  catch (...)
  {
    std::cerr << name << ": error: unexpected failure" << std::endl;
  }
  std::cout.flush();
  return status;
}
} // namespace vr
