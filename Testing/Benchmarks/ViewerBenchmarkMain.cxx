// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// VesselReformationViewerBenchmarks' main: a QApplication with VTK's OpenGL format (run it under a display, e.g.
// xvfb-run -a -s "-screen 0 1920x1080x24"), then Google Benchmark. The JSON context names the processor, the thread
// count, the build flags and the OpenGL renderer.
#include "itkMultiThreaderBase.h"
#include "vrOpenGLRenderer.h"

#include <QApplication>
#include <QSurfaceFormat>
#include <QVTKOpenGLNativeWidget.h>

#include <benchmark/benchmark.h>

#include <fstream>
#include <string>

namespace
{
std::string
ProcessorModel()
{
  std::ifstream cpuinfo("/proc/cpuinfo");
  std::string   line;
  while (std::getline(cpuinfo, line))
  {
    if (line.rfind("model name", 0) == 0)
    {
      const auto colon = line.find(':');
      return colon == std::string::npos ? line : line.substr(line.find_first_not_of(' ', colon + 1));
    }
  }
  return "unknown";
}
} // namespace

int
main(int argc, char ** argv)
{
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv))
  {
    return 1;
  }
  QSurfaceFormat::setDefaultFormat(QVTKOpenGLNativeWidget::defaultFormat());
  QApplication application(argc, argv);
  benchmark::AddCustomContext("cpu_model", ProcessorModel());
  benchmark::AddCustomContext("itk_threads", std::to_string(itk::MultiThreaderBase::GetGlobalDefaultNumberOfThreads()));
  benchmark::AddCustomContext("build_type", VR_BENCHMARK_BUILD_TYPE);
  benchmark::AddCustomContext("cxx_flags", VR_BENCHMARK_CXX_FLAGS);
  benchmark::AddCustomContext("opengl_renderer", vr::OpenGLRendererName());
  benchmark::AddCustomContext("view_multisamples", std::to_string(vr::ViewMultiSamples()));
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
