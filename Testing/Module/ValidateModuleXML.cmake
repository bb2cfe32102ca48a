# Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
# Validates a command-line module's --xml description against CTK's schema with xmllint, as MITK's command-line
# module support (CTK's ctkCmdLineModuleXmlValidator) would, and checks that the validation can fail: the same
# description with one parameter's description and label in the old order (docs/design.md, "Command-line modules")
# must be rejected.
# Run by CTest: cmake -DMODULE=<executable> -DSCHEMA=<ctkCmdLineModule.xsd> -DXMLLINT=<xmllint> -DWORK_DIR=<dir> -P this
# An empty SCHEMA takes the environment's VR_CTK_SCHEMA. Without a schema the check prints "SKIPPED: no CTK schema"
# with the reason, which CTest reports as skipped (SKIP_REGULAR_EXPRESSION): the project does not ship CTK's schema.
foreach(variable MODULE SCHEMA XMLLINT WORK_DIR)
  if(NOT DEFINED ${variable})
    message(FATAL_ERROR "ValidateModuleXML.cmake needs -D${variable}=...")
  endif()
endforeach()
if(SCHEMA STREQUAL "")
  set(SCHEMA "$ENV{VR_CTK_SCHEMA}")
endif()
if(SCHEMA STREQUAL "")
  message("SKIPPED: no CTK schema: set VR_CTK_SCHEMA (environment or CMake cache) to a copy of CTK's "
    "ctkCmdLineModule.xsd (commontk/CTK, Libs/CommandLineModules/Core/Resources) to validate the modules' --xml")
  return()
endif()
if(NOT EXISTS "${SCHEMA}")
  # Named but missing: a mistake to report, not a check to skip.
  message(FATAL_ERROR "VR_CTK_SCHEMA names ${SCHEMA}, which does not exist")
endif()
if(NOT EXISTS "${XMLLINT}")
  message(FATAL_ERROR "xmllint not found (${XMLLINT}): install libxml2-utils (scripts/install-dependencies.sh)")
endif()
get_filename_component(module_name ${MODULE} NAME)
file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR})

# The schema's fileExtensions pattern uses Perl's non-capturing group "(?:", which XML Schema regular expressions do
# not have and libxml2 rejects; "(" matches the same language.
file(READ ${SCHEMA} schema)
string(REPLACE "(?:" "(" schema "${schema}")
file(WRITE ${WORK_DIR}/ctkCmdLineModule.xsd "${schema}")

# 3D Slicer gives a module 5 s to answer --xml.
execute_process(COMMAND ${MODULE} --xml RESULT_VARIABLE status OUTPUT_VARIABLE xml ERROR_VARIABLE errors TIMEOUT 5)
if(NOT status EQUAL 0 OR NOT errors STREQUAL "")
  message(FATAL_ERROR "${module_name} --xml: status ${status}, stderr: ${errors}")
endif()
file(WRITE ${WORK_DIR}/${module_name}.xml "${xml}")

execute_process(COMMAND ${XMLLINT} --noout --schema ${WORK_DIR}/ctkCmdLineModule.xsd ${WORK_DIR}/${module_name}.xml
  RESULT_VARIABLE status OUTPUT_VARIABLE output ERROR_VARIABLE output)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "${module_name} --xml does not validate against CTK's schema:\n${output}")
endif()
message(STATUS "${module_name} --xml validates against CTK's schema: ${output}")

# The control: the first parameter's description and label swapped back to the old order must fail.
string(REGEX MATCH "<description>[^<]*</description>[ \t\r\n]*<label>[^<]*</label>" pair "${xml}")
if(pair STREQUAL "")
  message(FATAL_ERROR "${module_name} --xml has no parameter with a description followed by a label")
endif()
string(REGEX REPLACE "(<description>[^<]*</description>)([ \t\r\n]*)(<label>[^<]*</label>)" "\\3\\2\\1" swapped
  "${pair}")
string(FIND "${xml}" "${pair}" at)
string(LENGTH "${pair}" length)
string(SUBSTRING "${xml}" 0 ${at} head)
math(EXPR rest_at "${at} + ${length}")
string(SUBSTRING "${xml}" ${rest_at} -1 tail)
file(WRITE ${WORK_DIR}/${module_name}-old-order.xml "${head}${swapped}${tail}")
execute_process(COMMAND ${XMLLINT} --noout --schema ${WORK_DIR}/ctkCmdLineModule.xsd
  ${WORK_DIR}/${module_name}-old-order.xml RESULT_VARIABLE status OUTPUT_VARIABLE output ERROR_VARIABLE output)
if(status EQUAL 0 OR NOT output MATCHES "Element 'label': This element is not expected")
  message(FATAL_ERROR "the validation cannot fail: label before description was accepted (${status}):\n${output}")
endif()
message(STATUS "control: label before description is rejected, as it must be")
