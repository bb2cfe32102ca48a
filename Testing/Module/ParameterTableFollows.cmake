# Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
# cmake -DSOURCE_DIR=<project> -DWORK_DIR=<folder> -P ParameterTableFollows.cmake
# Makes the modules' XML elements and the C++ table from the parameter table and from a copy with the iterations'
# default changed (500 -> 321) and a new value list for the depth mode, and checks that each change reaches both:
# nothing else describes these parameters.
cmake_minimum_required(VERSION 3.19)
set(PROJECT_SOURCE_DIR ${SOURCE_DIR})
include(${SOURCE_DIR}/CMake/VesselReformationParameters.cmake)
file(MAKE_DIRECTORY ${WORK_DIR})
set(table ${SOURCE_DIR}/Resources/Parameters/vrParameters.json)

# require_found(<position> <message>): fails with <message> when string(FIND) found nothing.
function(require_found position message)
  if(position EQUAL -1)
    message(FATAL_ERROR "${message}")
  endif()
endfunction()

vr_read_parameter_table(${table} ${WORK_DIR}/original.cxx)
file(READ ${WORK_DIR}/original.cxx original_cxx)
string(FIND "${VR_PARAMETER_iterations}" "<default>500</default>" at)
require_found(${at} "the table's own iterations element has no default 500:\n${VR_PARAMETER_iterations}")

# The copy: the iterations' default 321, and depth modes scanline, nearest and a third.
file(READ ${table} json)
string(JSON count LENGTH "${json}" parameters)
math(EXPR last "${count} - 1")
foreach(index RANGE ${last})
  string(JSON key GET "${json}" parameters ${index} key)
  if(key STREQUAL "iterations")
    string(JSON json SET "${json}" parameters ${index} default "\"321\"")
  elseif(key STREQUAL "mode")
    string(JSON json SET "${json}" parameters ${index} elements "[\"scanline\", \"nearest\", \"third\"]")
  endif()
endforeach()
file(WRITE ${WORK_DIR}/changed.json "${json}")
vr_read_parameter_table(${WORK_DIR}/changed.json ${WORK_DIR}/changed.cxx)
file(READ ${WORK_DIR}/changed.cxx changed_cxx)

string(FIND "${VR_PARAMETER_iterations}" "<default>321</default>" at)
require_found(${at} "a default changed in the table did not reach the modules' XML:\n${VR_PARAMETER_iterations}")
string(FIND "${VR_PARAMETER_mode}" "<element>third</element>" at)
require_found(${at} "a value added in the table did not reach the modules' XML:\n${VR_PARAMETER_mode}")
string(FIND "${changed_cxx}" "R\"vrp(321)vrp\"" at)
require_found(${at} "a default changed in the table did not reach the C++ table (the viewer, the panel, the logic)")
string(FIND "${changed_cxx}" "\"third\"" at)
require_found(${at} "a value added in the table did not reach the C++ table")
string(FIND "${original_cxx}" "R\"vrp(321)vrp\"" at)
if(NOT at EQUAL -1)
  message(FATAL_ERROR "the original C++ table already holds 321: the check proves nothing")
endif()
message(STATUS "a changed default and a new value reach both the XML and the C++ table")
