// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrOpenGLRenderer.h"

#include <QOffscreenSurface>
#include <QOpenGLContext>
#include <QOpenGLFunctions>
#include <vtkOpenGLRenderWindow.h>

#include <algorithm>
#include <array>
#include <cctype>

namespace vr
{
std::string
OpenGLRendererName()
{
  QOffscreenSurface surface;
  surface.create();
  QOpenGLContext context;
  if (!context.create() || !context.makeCurrent(&surface))
  {
    return "unknown";
  }
  const auto * renderer = context.functions()->glGetString(GL_RENDERER);
  const auto * version = context.functions()->glGetString(GL_VERSION);
  std::string  text = renderer ? reinterpret_cast<const char *>(renderer) : "unknown";
  text += version ? std::string(", OpenGL ") + reinterpret_cast<const char *>(version) : std::string();
  context.doneCurrent();
  return text;
}

bool
IsSoftwareRenderer(const std::string & rendererName)
{
  std::string lower = rendererName;
  std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return std::tolower(c); });
  constexpr std::array<const char *, 5> software{ "llvmpipe", "softpipe", "swrast", "swiftshader", "gdi generic" };
  return std::any_of(
    software.begin(), software.end(), [&](const char * name) { return lower.find(name) != std::string::npos; });
}

int
ViewMultiSamples()
{
  static const int samples =
    IsSoftwareRenderer(OpenGLRendererName()) ? 0 : vtkOpenGLRenderWindow::GetGlobalMaximumNumberOfMultiSamples();
  return samples;
}
} // namespace vr
