# Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
# Installs the build tree to a temporary prefix, checks the installed module folder (only the modules; each executable
# answers --xml within 5 s from where it is installed), then configures, builds and runs Consumer/ against it with
# find_package(VesselReformation). Run by CTest: cmake -DBUILD_DIR=... -DWORK_DIR=... -DSOURCE_DIR=... -P this.
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

run_step("install" ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${WORK_DIR}/prefix)

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
# Only the installed package may be found: not the build tree, and not a package registry.
run_step("configure the consumer" ${CMAKE_COMMAND} -S ${SOURCE_DIR}/Consumer -B ${WORK_DIR}/build -G ${GENERATOR}
  -DCMAKE_BUILD_TYPE=Release -DCMAKE_C_COMPILER=${C_COMPILER} -DCMAKE_CXX_COMPILER=${CXX_COMPILER}
  -DCMAKE_PREFIX_PATH=${WORK_DIR}/prefix -DITK_DIR=${ITK_DIR} -DVTK_DIR=${VTK_DIR}
  -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF)
run_step("build the consumer" ${CMAKE_COMMAND} --build ${WORK_DIR}/build -j 1)
run_step("run the consumer" ${WORK_DIR}/build/Consumer)
message(STATUS "${last_output}")
