# Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
# Small helpers every folder's CMakeLists.txt uses.

# vr_target_defaults(<target>): the project's warnings on a target of its own.
function(vr_target_defaults target)
  target_compile_options(${target} PRIVATE -Wall -Wextra)
endfunction()

# vr_install_library(<target> <export name> <export set> <public headers>...): installs a library under
# VesselReformation::<export name> in the export set VesselReformation<export set> (FiltersTargets: ITK only;
# LogicTargets: ITK and VTK), with exactly the headers listed. Headers not listed stay internal.
function(vr_install_library target export_name export_set)
  set_target_properties(${target} PROPERTIES EXPORT_NAME ${export_name})
  install(TARGETS ${target} EXPORT VesselReformation${export_set}
    ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
    LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
  install(FILES ${ARGN} DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/VesselReformation)
endfunction()

# vr_add_library(<target> EXPORT_NAME <name> EXPORT_SET <FiltersTargets|LogicTargets>
#                SOURCES <files>... PUBLIC_HEADERS <headers>... [INTERNAL_HEADERS <headers>...]):
# one layer's library, VesselReformation::<name>, whose folder and every subfolder holding one of its headers are on
# its consumers' include path (headers are included by name, as ITK's are; the subfolders only sort them by concern);
# the public headers are installed side by side, the internal ones are not.
function(vr_add_library target)
  cmake_parse_arguments(ARG "" "EXPORT_NAME;EXPORT_SET" "SOURCES;PUBLIC_HEADERS;INTERNAL_HEADERS" ${ARGN})
  add_library(${target} ${ARG_SOURCES} ${ARG_PUBLIC_HEADERS} ${ARG_INTERNAL_HEADERS})
  add_library(VesselReformation::${ARG_EXPORT_NAME} ALIAS ${target})
  set(header_folders ${CMAKE_CURRENT_SOURCE_DIR})
  foreach(header IN LISTS ARG_PUBLIC_HEADERS ARG_INTERNAL_HEADERS)
    get_filename_component(folder ${CMAKE_CURRENT_SOURCE_DIR}/${header} DIRECTORY)
    list(APPEND header_folders ${folder})
  endforeach()
  list(REMOVE_DUPLICATES header_folders)
  foreach(folder IN LISTS header_folders)
    target_include_directories(${target} PUBLIC $<BUILD_INTERFACE:${folder}>)
  endforeach()
  target_include_directories(${target} PUBLIC $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}/VesselReformation>)
  vr_target_defaults(${target})
  vr_install_library(${target} ${ARG_EXPORT_NAME} ${ARG_EXPORT_SET} ${ARG_PUBLIC_HEADERS})
endfunction()
