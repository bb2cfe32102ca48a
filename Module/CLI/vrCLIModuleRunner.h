// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrCLIModuleRunner_h
#define vrCLIModuleRunner_h

#include "vrCLIArguments.h"
#include "vrCLIProgress.h"

#include <functional>
#include <map>
#include <string>

namespace vr
{
/** The work of a command-line module: reads its arguments, runs, writes its outputs; throws on failure. */
using CLIModuleBody = std::function<void(const CLIArguments & arguments, CLIProgress & progress)>;

/** \param description the module's description.
 * \param meaning a parameter by its meaning (vr::ParameterName), or "".
 * \return how the command line spells it ("--anisotropy"): the flag the parameter table (vrParameterTable.h) gives
 * that meaning among the flags the module declares; "" when the module has no such parameter. */
std::string
SpellingOfParameter(const CLIModuleDescription & description, const std::string & meaning);

/** The exit status of a run that 3D Slicer cancelled through the process-information structure: 0. Slicer's CLI logic
 * (vtkSlicerCLIModuleLogic) marks an in-process run "Cancelled" only when ModuleEntryPoint returns 0 (or throws an
 * itk::ExceptionObject) while the run is being cancelled; a non-zero value turns it into "Completed with errors".
 * (An executable it kills, whatever its status.) */
constexpr int ExitCodeCancelled = 0;

/** Runs a command-line module the same way from its executable and from its shared library's ModuleEntryPoint:
 * --xml prints \a xml, --help the usage, otherwise the arguments are checked against the XML, progress is
 * reported (see CLIProgress) and \a body runs.
 *
 * The values the module returns (the XML's return parameters) are set by \a body through
 * CLIProgress::SetReturnValue; after a successful run they go, one "name = value" line per return parameter in the
 * XML's order, to the file given with --returnparameterfile (3D Slicer's format, read by its
 * ModuleDescription::ReadParameterFile), written under a temporary name and renamed into place. A body that leaves a
 * declared value unset is a programming error (std::logic_error, reported as an error).
 *
 * Every failure (vr::InputError from bad input, and anything unexpected) is caught and printed on stderr as
 * "<name>: error: <message>"; nothing escapes, so a host process loading the library survives. An InputError about
 * a parameter (InputError::Parameter()) is prefixed with that parameter's flag (SpellingOfParameter). A run stopped
 * through the process-information structure (vr::Cancelled) prints "<name>: <stage>: cancelled" and returns
 * ExitCodeCancelled; the body writes no output then (its staged outputs are never committed), nor does the runner
 * write the return-parameter file.
 *
 * \param argc, argv the command line (argv[0] the program or, in-process, the module).
 * \param xml the module's Slicer Execution Model description (its XMLModuleDescription).
 * \param name the module's name, for messages and filter-name.
 * \param comment what it does, for filter-comment.
 * \param body the module's work.
 * \return 0 on success, ExitCodeCancelled (0) when cancelled, 1 on any error. */
int
RunCLIModule(int                   argc,
             char *                argv[],
             const char *          xml,
             const std::string &   name,
             const std::string &   comment,
             const CLIModuleBody & body);
} // namespace vr

#endif
