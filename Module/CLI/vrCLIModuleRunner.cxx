// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrCLIModuleRunner.h"

#include "vrInputError.h"

#include "itkMacro.h"

#include <iostream>
#include <new>
#include <unistd.h>

namespace vr
{
std::string
SpellingOfParameter(const CLIModuleDescription & description,
                    const CLIParameterMap &      parameters,
                    const std::string &          meaning)
{
  const auto entry = parameters.find(meaning);
  return entry == parameters.end() ? std::string() : description.Find(entry->second).Spelling();
}

int
RunCLIModule(int                     argc,
             char *                  argv[],
             const char *            xml,
             const std::string &     name,
             const std::string &     comment,
             const CLIModuleBody &   body,
             const CLIParameterMap & parameters)
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
      auto *      information = static_cast<vrModuleProcessInformation *>(arguments.ProcessInformation);
      CLIProgress progress(
        name, comment, information, std::cout, information == nullptr && ::isatty(STDOUT_FILENO) == 1);
      progress.Start();
      body(arguments, progress);
      progress.End();
      status = 0;
    }
  }
  catch (const InputError & error)
  {
    const std::string flag = SpellingOfParameter(description, parameters, error.Parameter());
    std::cerr << name << ": error: " << (flag.empty() ? "" : flag + ": ") << error.what() << std::endl;
  }
  catch (const Cancelled & cancelled)
  {
    std::cerr << name << ": " << cancelled.what() << std::endl;
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
