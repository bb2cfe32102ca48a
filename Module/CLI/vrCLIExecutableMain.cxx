// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// The executable of a command-line module: the same code as its shared library, entered the same way.
extern "C" int
ModuleEntryPoint(int argc, char * argv[]);

int
main(int argc, char * argv[])
{
  return ModuleEntryPoint(argc, argv);
}
