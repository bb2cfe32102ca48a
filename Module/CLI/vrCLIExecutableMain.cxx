// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// The executable of a command-line module: the same code as its shared library, entered the same way, except for
// --processinformationaddress. 3D Slicer passes that flag only to a module it loads as a shared library, in its
// own process, where the address is its progress structure; an executable has no such structure in its address
// space, and dereferencing whatever number it was given would crash it. So the executable refuses the flag before
// the module sees it.
#include <cstring>
#include <iostream>
#include <string>

extern "C" int
ModuleEntryPoint(int argc, char * argv[]);

int
main(int argc, char * argv[])
{
  for (int k = 1; k < argc; ++k)
  {
    const char * flag = "--processinformationaddress";
    if (argv[k] != nullptr && std::strncmp(argv[k], flag, std::strlen(flag)) == 0 &&
        (argv[k][std::strlen(flag)] == '\0' || argv[k][std::strlen(flag)] == '='))
    {
      std::string program = argc > 0 && argv[0] != nullptr ? argv[0] : "module";
      program = program.substr(program.find_last_of('/') + 1);
      std::cerr << program
                << ": error: --processinformationaddress is only for 3D Slicer running this module in-process as a "
                   "shared library; the executable does not take it"
                << std::endl;
      return 1;
    }
  }
  return ModuleEntryPoint(argc, argv);
}
