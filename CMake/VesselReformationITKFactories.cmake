# Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
# vr_register_itk_io_factories(<target>): what include(${ITK_USE_FILE}) does for ITK's IO factories, scoped to one
# (imported) target instead of the consumer's whole directory. Every translation unit that links <target> and
# includes itkImageFileReader.h (or another IO reader/writer header) then registers the IO factories of the ITK
# modules found by the last find_package(ITK), so that reading a NRRD needs no ITK_USE_FILE.
#
# It writes ITK's own register-manager headers (ITK_CMAKE_DIR/itk<Factory>FactoryRegisterManager.h.in), filled as
# UseITK.cmake fills them, into <binary dir>/VesselReformationITKFactoryRegistration.
function(vr_register_itk_io_factories target)
  set(registration_dir ${CMAKE_CURRENT_BINARY_DIR}/VesselReformationITKFactoryRegistration)
  foreach(factory ${ITK_FACTORY_LIST})
    set(LIST_OF_FACTORIES_REGISTRATION "")
    set(LIST_OF_FACTORY_NAMES "")
    foreach(format ${ITK_${factory}})
      # The module providing <factory>::<format>, from ITK_FACTORY_NAMES entries <module>::<factory>::<format>.
      set(module "")
      foreach(entry ${ITK_FACTORY_NAMES})
        if(entry MATCHES "^(.*)::${factory}::${format}$")
          set(module ${CMAKE_MATCH_1})
          break()
        endif()
      endforeach()
      set(abi "")
      if(${module}_ENABLE_SHARED AND ITK_BUILD_SHARED)
        set(abi "ITK_ABI_IMPORT")
      endif()
      string(APPEND LIST_OF_FACTORIES_REGISTRATION "void ${abi} ${format}${factory}FactoryRegister__Private();")
      string(APPEND LIST_OF_FACTORY_NAMES "${format}${factory}FactoryRegister__Private,")
    endforeach()
    configure_file(${ITK_CMAKE_DIR}/itk${factory}FactoryRegisterManager.h.in
      ${registration_dir}/itk${factory}FactoryRegisterManager.h @ONLY)
  endforeach()
  set_property(TARGET ${target} APPEND PROPERTY INTERFACE_COMPILE_DEFINITIONS ITK_IO_FACTORY_REGISTER_MANAGER)
  set_property(TARGET ${target} APPEND PROPERTY INTERFACE_INCLUDE_DIRECTORIES ${registration_dir})
endfunction()
