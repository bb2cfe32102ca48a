# Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
# Turns an OpenCL C file into a C++ header holding it as a raw string literal, so the kernel is compiled into the
# library (never read from the build tree at run time) and the OpenCL compiler's line numbers match the .cl file.
#
#   cmake -DINPUT=<file.cl> -DOUTPUT=<header.h> -DVARIABLE=<C++ name> -P EmbedOpenCLSource.cmake
foreach(argument INPUT OUTPUT VARIABLE)
  if(NOT DEFINED ${argument})
    message(FATAL_ERROR "EmbedOpenCLSource.cmake: -D${argument}=... is missing")
  endif()
endforeach()

file(READ "${INPUT}" source)
set(delimiter "VR_OPENCL_SOURCE")
string(FIND "${source}" ")${delimiter}\"" clash)
if(NOT clash EQUAL -1)
  message(FATAL_ERROR "${INPUT} contains the raw string delimiter )${delimiter}\" and cannot be embedded")
endif()
get_filename_component(name "${INPUT}" NAME)

# The source starts right after the opening delimiter: line n of the string is line n of the file.
set(header "// Generated from OpenCL/${name} by OpenCL/EmbedOpenCLSource.cmake: edit the .cl file, not this one.
#pragma once

namespace vr::opencl_sources
{
inline constexpr const char ${VARIABLE}FileName[] = \"${name}\";
inline constexpr const char ${VARIABLE}[] = R\"${delimiter}(${source})${delimiter}\";
} // namespace vr::opencl_sources
")
# Rewrite only on change, so an untouched kernel recompiles nothing.
file(WRITE "${OUTPUT}.tmp" "${header}")
configure_file("${OUTPUT}.tmp" "${OUTPUT}" COPYONLY)
file(REMOVE "${OUTPUT}.tmp")
