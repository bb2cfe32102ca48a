# Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
# Installs the build tree to a temporary prefix, then configures, builds and runs Consumer/ against it with
# find_package(VesselReformation). Run by CTest: cmake -DBUILD_DIR=... -DWORK_DIR=... -DSOURCE_DIR=... -P this.
foreach(variable BUILD_DIR WORK_DIR SOURCE_DIR GENERATOR C_COMPILER CXX_COMPILER ITK_DIR VTK_DIR)
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
# Only the installed package may be found: not the build tree, and not a package registry.
run_step("configure the consumer" ${CMAKE_COMMAND} -S ${SOURCE_DIR}/Consumer -B ${WORK_DIR}/build -G ${GENERATOR}
  -DCMAKE_BUILD_TYPE=Release -DCMAKE_C_COMPILER=${C_COMPILER} -DCMAKE_CXX_COMPILER=${CXX_COMPILER}
  -DCMAKE_PREFIX_PATH=${WORK_DIR}/prefix -DITK_DIR=${ITK_DIR} -DVTK_DIR=${VTK_DIR}
  -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF "-DCMAKE_CXX_FLAGS=${CXX_FLAGS}" "-DCMAKE_EXE_LINKER_FLAGS=${CXX_FLAGS}")
run_step("build the consumer" ${CMAKE_COMMAND} --build ${WORK_DIR}/build -j 1)
run_step("run the consumer" ${WORK_DIR}/build/Consumer)
message(STATUS "${last_output}")
