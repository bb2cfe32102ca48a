# Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
# Installs the build tree to a temporary prefix, checks the installed module folder (only the modules; each executable
# answers --xml within 5 s from where it is installed), then configures, builds and runs three projects of someone
# else's against it with find_package(VesselReformation). Run by CTest:
#   cmake -DBUILD_DIR=... -DWORK_DIR=... -DSOURCE_DIR=... -DGENERATOR=... -DC_COMPILER=... -DCXX_COMPILER=...
#         -DITK_DIR=... -DVTK_DIR=... -DMODULES_DIR=<folder under the prefix> -DMODULES=<name,name...>
#         -P RunPackageTest.cmake
# - FiltersConsumer links VesselReformation::Filters alone; it is configured with VTK's package disabled and a VTK_DIR
#   that does not exist, and its compile lines must hold no VTK include directory.
# - NRRDConsumer reads a NRRD with itk::ImageFileReader without include(${ITK_USE_FILE}).
# - PipelineConsumer runs the logic's relax backend in an ITK pipeline on the run-off phantom.
cmake_policy(SET CMP0057 NEW) # if(... IN_LIST ...)
foreach(variable BUILD_DIR WORK_DIR SOURCE_DIR GENERATOR C_COMPILER CXX_COMPILER ITK_DIR VTK_DIR MODULES_DIR MODULES)
  if(NOT DEFINED ${variable})
    message(FATAL_ERROR "RunPackageTest.cmake needs -D${variable}=...")
  endif()
endforeach()

file(REMOVE_RECURSE ${WORK_DIR})

function(run_step name)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE status OUTPUT_VARIABLE output ERROR_VARIABLE output)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "${name} failed (${status}):\n${output}")
  endif()
  message(STATUS "${name}: ok")
  set(last_output "${output}" PARENT_SCOPE)
endfunction()

# configure_and_build(<project> <extra cmake arguments>...)
function(configure_and_build project)
  # Only the installed package may be found: not the build tree, and not a package registry.
  run_step("configure ${project}" ${CMAKE_COMMAND} -S ${SOURCE_DIR}/${project} -B ${WORK_DIR}/${project} -G ${GENERATOR}
    -DCMAKE_BUILD_TYPE=Release -DCMAKE_C_COMPILER=${C_COMPILER} -DCMAKE_CXX_COMPILER=${CXX_COMPILER}
    -DCMAKE_PREFIX_PATH=${WORK_DIR}/prefix -DITK_DIR=${ITK_DIR} -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF
    "-DCMAKE_CXX_FLAGS=${CXX_FLAGS}" "-DCMAKE_EXE_LINKER_FLAGS=${CXX_FLAGS}" ${ARGN})
  run_step("build ${project}" ${CMAKE_COMMAND} --build ${WORK_DIR}/${project} -j 1)
endfunction()

run_step("install" ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${WORK_DIR}/prefix)

# The installed headers are the interface: no internal namespace (detail) in them, and every header of the project's
# own that one includes is installed too (an internal header included by a public one would be an interface by the
# back door, or a compile error for consumers).
get_filename_component(project_root ${SOURCE_DIR}/../.. ABSOLUTE)
file(GLOB_RECURSE project_headers RELATIVE ${project_root} ${project_root}/*.h ${project_root}/*.hxx)
list(FILTER project_headers EXCLUDE REGEX "^(build|Testing)")
set(project_header_names "")
foreach(header ${project_headers})
  get_filename_component(name ${header} NAME)
  list(APPEND project_header_names ${name})
endforeach()
file(GLOB installed_headers ${WORK_DIR}/prefix/include/VesselReformation/*)
if(NOT installed_headers)
  message(FATAL_ERROR "no header installed in ${WORK_DIR}/prefix/include/VesselReformation")
endif()
foreach(header ${installed_headers})
  get_filename_component(name ${header} NAME)
  file(STRINGS ${header} internal REGEX "detail::|namespace detail|namespace [a-z]+::detail")
  if(internal)
    message(FATAL_ERROR "the installed header ${name} names an internal (detail) namespace:\n${internal}")
  endif()
  file(STRINGS ${header} includes REGEX "^#include \"")
  foreach(line ${includes})
    string(REGEX REPLACE "^#include \"([^\"]+)\".*" "\\1" included "${line}")
    if(NOT EXISTS ${WORK_DIR}/prefix/include/VesselReformation/${included} AND included IN_LIST project_header_names)
      message(FATAL_ERROR "the installed header ${name} includes ${included}, one of the project's headers that is "
                          "not installed (internal)")
    endif()
  endforeach()
endforeach()
list(LENGTH installed_headers installed_count)
message(STATUS "installed headers: ${installed_count}, none internal, none including an internal one")

# The module folder a platform is pointed at: the modules and nothing else (executable, shared library, 3D Slicer's
# description), the executables runnable from there, the others not executable (MITK runs every executable file).
string(REPLACE "," ";" MODULES "${MODULES}")
set(modules_dir ${WORK_DIR}/prefix/${MODULES_DIR})
set(expected "")
foreach(module ${MODULES})
  list(APPEND expected ${module} lib${module}Lib.so ${module}.xml)
endforeach()
list(SORT expected)
file(GLOB found RELATIVE ${modules_dir} ${modules_dir}/*)
list(SORT found)
if(NOT found STREQUAL expected)
  message(FATAL_ERROR "the installed module folder ${modules_dir} holds [${found}], not [${expected}]")
endif()
foreach(module ${MODULES})
  execute_process(COMMAND ${modules_dir}/${module} --xml RESULT_VARIABLE status OUTPUT_VARIABLE xml
    ERROR_VARIABLE errors TIMEOUT 5)
  if(NOT status EQUAL 0 OR NOT errors STREQUAL "" OR NOT xml MATCHES "^<\\?xml ")
    message(FATAL_ERROR "installed ${module} --xml: status ${status}, stderr: ${errors}")
  endif()
  foreach(other lib${module}Lib.so ${module}.xml)
    execute_process(COMMAND test -x ${modules_dir}/${other} RESULT_VARIABLE executable)
    if(executable EQUAL 0)
      message(FATAL_ERROR "installed ${other} is executable: MITK's folder scan would run it")
    endif()
  endforeach()
endforeach()
message(STATUS "installed module folder ${MODULES_DIR}: ${found}")

configure_and_build(FiltersConsumer -DVTK_DIR=${WORK_DIR}/no-vtk-here -DCMAKE_DISABLE_FIND_PACKAGE_VTK=ON)
file(READ ${WORK_DIR}/FiltersConsumer/compile_commands.json compile_commands)
string(TOLOWER "${compile_commands}" compile_commands)
if(NOT compile_commands MATCHES "filtersconsumer.cxx")
  message(FATAL_ERROR "FiltersConsumer: compile_commands.json lists no compile line:\n${compile_commands}")
endif()
if(compile_commands MATCHES "vtk")
  message(FATAL_ERROR "FiltersConsumer links VesselReformation::Filters alone, yet its compile line names VTK:\n"
                      "${compile_commands}")
endif()
message(STATUS "FiltersConsumer: no VTK on its compile line")
run_step("run FiltersConsumer" ${WORK_DIR}/FiltersConsumer/FiltersConsumer)
message(STATUS "${last_output}")

configure_and_build(NRRDConsumer -DVTK_DIR=${VTK_DIR})
run_step("run NRRDConsumer" ${WORK_DIR}/NRRDConsumer/NRRDConsumer ${WORK_DIR}/handwritten.nrrd)
message(STATUS "${last_output}")

configure_and_build(PipelineConsumer -DVTK_DIR=${VTK_DIR})
run_step("run PipelineConsumer" ${WORK_DIR}/PipelineConsumer/Consumer)
message(STATUS "${last_output}")
