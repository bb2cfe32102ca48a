# Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
# What the widgets need beyond the logic: Qt 5 Widgets and VTK's Qt support with the rendering modules the views
# use. Found here (and by the widgets' tests, which include this file), never at the top level, so that the filters
# and the logic gain no dependency. Sets VR_WIDGETS_DEPENDENCIES_FOUND, and VR_WIDGETS_MISSING to what is missing.
set(VR_WIDGETS_VTK_COMPONENTS
  GUISupportQt         # QVTKOpenGLNativeWidget
  RenderingOpenGL2
  RenderingFreeType    # text in the views
  RenderingAnnotation  # corner annotations
  InteractionStyle     # the 3D view's trackball
  ImagingColor         # lookup tables for labels and depth
  ImagingCore
  FiltersSources       # outline, arrow
  FiltersCore          # tubes along the centerlines
  FiltersGeneral
  CommonTransforms)
set(VR_WIDGETS_MISSING "")
# The top level's find_package(VTK) already made every VTK target, in its own directory scope; the packages VTK's
# rendering and Qt modules link (Qt5, X11, OpenGL, GLEW) are found only here, so they must be global imported targets
# for those VTK targets to resolve them (CMake 3.24).
if(CMAKE_VERSION VERSION_LESS 3.24)
  list(APPEND VR_WIDGETS_MISSING "CMake 3.24 or newer (this is ${CMAKE_VERSION})")
  set(VR_WIDGETS_DEPENDENCIES_FOUND FALSE)
  return()
endif()
set(CMAKE_FIND_PACKAGE_TARGETS_GLOBAL ON)
find_package(Qt5 5.12 QUIET COMPONENTS Widgets Test)
if(NOT Qt5Widgets_FOUND)
  list(APPEND VR_WIDGETS_MISSING "Qt 5 Widgets (Debian: qtbase5-dev)")
endif()
find_package(VTK 9.1 QUIET COMPONENTS ${VR_WIDGETS_VTK_COMPONENTS})
foreach(component IN LISTS VR_WIDGETS_VTK_COMPONENTS)
  if(NOT TARGET VTK::${component} OR NOT VTK_${component}_FOUND)
    list(APPEND VR_WIDGETS_MISSING "VTK::${component} (Debian: libvtk9-qt-dev)")
  endif()
endforeach()
list(REMOVE_DUPLICATES VR_WIDGETS_MISSING)
if(VR_WIDGETS_MISSING)
  set(VR_WIDGETS_DEPENDENCIES_FOUND FALSE)
else()
  set(VR_WIDGETS_DEPENDENCIES_FOUND TRUE)
endif()
