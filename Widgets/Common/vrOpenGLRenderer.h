// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrOpenGLRenderer_h
#define vrOpenGLRenderer_h

#include <string>

namespace vr
{
/** The OpenGL renderer and version of the platform's default context, e.g. "llvmpipe (LLVM 15.0.6, 256 bits),
 * OpenGL 4.5 (Core Profile) Mesa 22.3.6"; "unknown" where no context can be made. Needs a QGuiApplication. */
std::string
OpenGLRendererName();

/** Whether a renderer name (as above) is a software rasteriser: Mesa's llvmpipe, softpipe and swrast, Google's
 * SwiftShader, Microsoft's GDI Generic. */
bool
IsSoftwareRenderer(const std::string & rendererName);

/** The multisampling the CPR and 3D views ask of their render windows: none on a software rasteriser, where VTK's
 * default of 8 samples makes every frame about three times as dear (measured here under Mesa llvmpipe: the 3D view's
 * full cut surface 1033 ms against 331 ms a frame, a drag's images 1.8-3.2 against 5.1-7.6 a second), VTK's default
 * elsewhere, where a GPU resolves the samples in hardware. Decided once per process. */
int
ViewMultiSamples();
} // namespace vr

#endif
