// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrModuleExport_h
#define vrModuleExport_h

/** Marks the two symbols 3D Slicer looks up in a command-line module's shared library (XMLModuleDescription and
 * ModuleEntryPoint); everything else in the library stays hidden. */
#if defined(_WIN32)
#define VR_MODULE_EXPORT __declspec(dllexport)
#else
#define VR_MODULE_EXPORT __attribute__((visibility("default")))
#endif

#endif
