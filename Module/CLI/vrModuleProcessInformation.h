// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrModuleProcessInformation_h
#define vrModuleProcessInformation_h

/** The progress structure 3D Slicer hands a command-line module it runs in-process, as a shared library: its
 * address arrives with --processinformationaddress. The layout is SlicerExecutionModel's
 * ModuleProcessInformation (ModuleDescriptionParser/ModuleProcessInformation.h), field for field; the module
 * writes the progress fields and calls the callback, and reads Abort. */
extern "C"
{
  struct vrModuleProcessInformation
  {
    /** Set by the caller to ask the module to stop. */
    unsigned char Abort;
    /** Overall progress in [0, 1]. */
    float Progress;
    /** Progress of the current stage in [0, 1]. */
    float StageProgress;
    char  ProgressMessage[1024];
    void (*ProgressCallbackFunction)(void *);
    void * ProgressCallbackClientData;
    /** Seconds since the module started. */
    double ElapsedTime;
  };
}

#endif
