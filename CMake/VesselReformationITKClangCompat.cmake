# Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
# Lets Clang compile against an ITK whose itk_compiler_detection.h was generated for GCC alone (Debian's ITK 5.2:
# "#error Unsupported compiler" for anything but GCC). With GCC, or where ITK's header already knows Clang, the
# functions do nothing.
#
# vr_itk_clang_compat(<folder variable>) mirrors ITK's include folder into
# <binary dir>/VesselReformationITKClangCompat/<name of ITK's folder>: a tree of symbolic links to ITK's headers,
# except two patched copies:
# - itk_compiler_detection.h: Clang (and AppleClang) take the GCC feature table instead of reaching the #error.
# - compilers/ITK_COMPILER_INFO_GNU_CXX.h: its GCC version tests ((__GNUC__ * 100 + __GNUC_MINOR__) >= 408, ...)
#   are evaluated as for GCC 12 under Clang, which calls itself GCC 4.2 but has every feature in the table (C++11 to
#   C++17 language features, all in Clang 14).
# A whole mirror rather than the two files alone, because ITK's headers include each other with quotes, which
# searches the including header's own folder first: the patched header must sit beside the ones that include it.
# It sets <folder variable> to the mirror ("" when not needed) and VR_ITK_CLANG_COMPAT_ORIGINAL to ITK's folder.
#
# vr_itk_clang_compat_retarget(<targets>...) replaces ITK's folder (and folders beneath it) by the mirror in the
# INTERFACE_INCLUDE_DIRECTORIES of the given targets (ITK's imported ones, or a target that hands ITK's folders on)
# and in the current folder's INCLUDE_DIRECTORIES (what ITK_USE_FILE added), so no compile line names ITK's own.
function(vr_itk_clang_compat folder_variable)
  set(${folder_variable} "" PARENT_SCOPE)
  if(NOT CMAKE_CXX_COMPILER_ID MATCHES "Clang")
    return()
  endif()
  set(itk_folder "")
  foreach(dir ${ITK_INCLUDE_DIRS})
    if(EXISTS ${dir}/itk_compiler_detection.h AND EXISTS ${dir}/compilers/ITK_COMPILER_INFO_GNU_CXX.h)
      set(itk_folder ${dir})
      break()
    endif()
  endforeach()
  if(NOT itk_folder)
    return()
  endif()
  file(READ ${itk_folder}/itk_compiler_detection.h header)
  set(gnu_only "#  if ITK_COMPILER_IS_GNU\n\n#    include \"compilers/ITK_COMPILER_INFO_GNU_CXX.h\"\n\n#  else")
  string(FIND "${header}" "${gnu_only}" at)
  if(at EQUAL -1)
    return() # ITK's header covers Clang itself (or looks unlike 5.2's): leave it alone
  endif()
  string(REPLACE "#  if ITK_COMPILER_IS_GNU\n\n#    include"
    "#  if ITK_COMPILER_IS_GNU || ITK_COMPILER_IS_Clang || ITK_COMPILER_IS_AppleClang\n\n#    include" header "${header}")
  file(READ ${itk_folder}/compilers/ITK_COMPILER_INFO_GNU_CXX.h table)
  string(REPLACE "(__GNUC__ * 100 + __GNUC_MINOR__)" "VR_ITK_GNU_VERSION" table "${table}")
  string(REPLACE "(__GNUC__ * 10000 + __GNUC_MINOR__ * 100 + __GNUC_PATCHLEVEL__)" "(VR_ITK_GNU_VERSION * 100)"
    table "${table}")
  string(CONCAT table
    "/* Patched by VesselReformation (CMake/VesselReformationITKClangCompat.cmake): under Clang the GCC version\n"
    "   tests below are evaluated as for GCC 12. */\n"
    "#if defined(__clang__)\n#  define VR_ITK_GNU_VERSION 1200\n#else\n"
    "#  define VR_ITK_GNU_VERSION (__GNUC__ * 100 + __GNUC_MINOR__)\n#endif\n" "${table}")

  get_filename_component(itk_name ${itk_folder} NAME)
  set(mirror ${CMAKE_CURRENT_BINARY_DIR}/VesselReformationITKClangCompat/${itk_name})
  set(stamp ${mirror}/.vr-mirror-of)
  set(previous "")
  if(EXISTS ${stamp})
    file(READ ${stamp} previous)
  endif()
  if(NOT previous STREQUAL itk_folder)
    file(REMOVE_RECURSE ${mirror})
    file(GLOB_RECURSE entries RELATIVE ${itk_folder} LIST_DIRECTORIES false ${itk_folder}/*)
    foreach(entry ${entries})
      get_filename_component(entry_folder ${mirror}/${entry} DIRECTORY)
      file(MAKE_DIRECTORY ${entry_folder})
      file(CREATE_LINK ${itk_folder}/${entry} ${mirror}/${entry} SYMBOLIC)
    endforeach()
    file(REMOVE ${mirror}/itk_compiler_detection.h ${mirror}/compilers/ITK_COMPILER_INFO_GNU_CXX.h)
    file(WRITE ${stamp} "${itk_folder}")
  endif()
  # Written only when changed, so that a reconfigure does not rebuild everything.
  file(CONFIGURE OUTPUT ${mirror}/itk_compiler_detection.h CONTENT "${header}" @ONLY)
  file(CONFIGURE OUTPUT ${mirror}/compilers/ITK_COMPILER_INFO_GNU_CXX.h CONTENT "${table}" @ONLY)
  set(${folder_variable} ${mirror} PARENT_SCOPE)
  set(VR_ITK_CLANG_COMPAT_ORIGINAL ${itk_folder} PARENT_SCOPE)
endfunction()

# Replaces ITK's folder by the mirror in one list of folders.
function(_vr_itk_clang_compat_replace list_variable mirror original)
  set(replaced "")
  foreach(dir ${${list_variable}})
    string(FIND "${dir}/" "${original}/" at)
    if(at EQUAL 0)
      string(LENGTH "${original}" length)
      string(SUBSTRING "${dir}" ${length} -1 rest)
      set(dir "${mirror}${rest}")
    endif()
    list(APPEND replaced "${dir}")
  endforeach()
  set(${list_variable} "${replaced}" PARENT_SCOPE)
endfunction()

function(vr_itk_clang_compat_retarget mirror original)
  foreach(target ${ARGN})
    if(TARGET ${target})
      get_property(dirs TARGET ${target} PROPERTY INTERFACE_INCLUDE_DIRECTORIES)
      if(dirs)
        _vr_itk_clang_compat_replace(dirs ${mirror} ${original})
        set_property(TARGET ${target} PROPERTY INTERFACE_INCLUDE_DIRECTORIES "${dirs}")
      endif()
    endif()
  endforeach()
  get_property(dirs DIRECTORY PROPERTY INCLUDE_DIRECTORIES)
  _vr_itk_clang_compat_replace(dirs ${mirror} ${original})
  set_property(DIRECTORY PROPERTY INCLUDE_DIRECTORIES "${dirs}")
endfunction()
