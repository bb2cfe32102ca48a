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
