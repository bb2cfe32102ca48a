// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// Full-size volumes (issue 40; docs/benchmarks.md "Full-size volumes"): a clinical run-off CTA of 512 x 512 x N int16
// voxels made from the run-off phantom (vr::test::MakeClinicalVolume), beside the phantom itself in the same run:
//   FullSize_Read/slices:N                    vr::ReadStoredVolume of it as a raw NRRD (written once to the temporary
//                                             folder), beside FullSize_Read_Plain/slices:N, the same bytes read with
//                                             read() into one buffer: what the disk or the page cache costs
//   FullSize_DepthResample/512/1024/slices:N  depth + resample for a new angle, the volume sampled as int16 through
//                                             itk::ImageBase<3> as the logic samples it; slices:0 is the phantom
//                                             (float, 1.5 mm voxels, 254 x 160 x 680): the reference of the ratio
//   FullSize_Resample/512/1024/slices:N       the resampling alone, of one depth map at the design angle, again and
//                                             again: how the volume's size and layout weigh on the sampling
//   FullSize_Pipeline_CPU/512/1024/slices:N   depth + 500 Jacobi passes + resample: the logic's work for a settled
//                                             angle change, the rest of which (drawing) does not depend on the volume
// The volumes are runoff-N.nrrd of the folder VR_FULL_SIZE_STUDIES where it names one (WriteClinicalVolume's files),
// else drawn in the process. Each iteration turns the view by a quarter degree from the phantom's design angle; the
// volumes are made once per process, outside any timing (about 10 s per 1 000 slices on 2 cores).
#include "vrBenchmarkScene.h"
#include "vrClinicalVolume.h"
#include "vrVolumeIO.h"

#include "itkBilateralDepthRelaxFilter.h"
#include "itkCPRDepthImageFilter.h"
#include "itkCPRResampleImageFilter.h"
#include "itkImageFileWriter.h"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdlib>
#include <fcntl.h>
#include <filesystem>
#include <map>
#include <unistd.h>
#include <vector>

namespace
{
using vr::benchmarks::DepthImage;
using DepthFilter = itk::CPRDepthImageFilter<DepthImage>;
using RelaxFilter = itk::BilateralDepthRelaxFilter<DepthImage>;
using ResampleFilter = itk::CPRResampleImageFilter<itk::ImageBase<3>, DepthImage>;
using ShortVolume = itk::Image<short, 3>;

/** The 512 x 512 x slices int16 volume (0: the run-off phantom), made once. */
const itk::ImageBase<3> *
VolumeOf(long slices)
{
  static std::map<long, ShortVolume::Pointer> volumes;
  if (slices == 0)
  {
    return vr::benchmarks::PhantomScene::Instance().GetVolume();
  }
  auto & volume = volumes[slices];
  if (!volume)
  {
    // runoff-N.nrrd as WriteClinicalVolume writes it, where VR_FULL_SIZE_STUDIES names a folder that holds it:
    // read in a second where drawing it takes a minute.
    const char * folder = std::getenv("VR_FULL_SIZE_STUDIES");
    const auto   file =
      std::filesystem::path(folder != nullptr ? folder : "") / ("runoff-" + std::to_string(slices) + ".nrrd");
    if (folder != nullptr && *folder != '\0' && std::filesystem::exists(file))
    {
      volume = dynamic_cast<ShortVolume *>(vr::ReadStoredVolume(file.string()).Image.GetPointer());
    }
  }
  if (!volume)
  {
    volume = vr::test::MakeClinicalVolume<short>(itk::CTAPhantomKind::Runoff,
                                                 { { 512, 512, static_cast<itk::SizeValueType>(slices) } });
  }
  return volume;
}

/** The volume as a raw NRRD in the temporary folder, written once and removed when the process ends. */
const std::string &
FileOf(long slices)
{
  struct Files
  {
    std::map<long, std::string> Paths;
    ~Files()
    {
      for (const auto & entry : Paths)
      {
        std::error_code error;
        std::filesystem::remove(entry.second, error);
      }
    }
  };
  static Files files;
  auto &       path = files.Paths[slices];
  if (path.empty())
  {
    path = (std::filesystem::temp_directory_path() /
            ("vr-fullsize-benchmark-" + std::to_string(getpid()) + "-" + std::to_string(slices) + ".nrrd"))
             .string();
    auto writer = itk::ImageFileWriter<ShortVolume>::New();
    writer->SetInput(dynamic_cast<const ShortVolume *>(VolumeOf(slices)));
    writer->SetFileName(path);
    writer->Update();
  }
  return path;
}

double
AngleOfIteration(std::size_t iteration)
{
  return vr::benchmarks::DesignAngle + 0.25 * static_cast<double>(iteration % 40);
}

void
FullSize_Read(benchmark::State & state)
{
  const std::string & path = FileOf(state.range(0));
  for (auto _ : state) // NOLINT(clang-analyzer-deadcode.DeadStores): Google Benchmark's loop
  {
    benchmark::DoNotOptimize(vr::ReadStoredVolume(path).Image.GetPointer());
  }
  state.SetBytesProcessed(static_cast<int64_t>(state.iterations()) *
                          static_cast<int64_t>(std::filesystem::file_size(path)));
}

void
FullSize_Read_Plain(benchmark::State & state)
{
  const std::string & path = FileOf(state.range(0));
  const auto          bytes = static_cast<std::size_t>(std::filesystem::file_size(path));
  for (auto _ : state) // NOLINT(clang-analyzer-deadcode.DeadStores): Google Benchmark's loop
  {
    std::unique_ptr<char[]> buffer(new char[bytes]);
    const int               file = open(path.c_str(), O_RDONLY);
    std::size_t             done = 0;
    while (done < bytes)
    {
      const ssize_t read = ::read(file, buffer.get() + done, bytes - done);
      if (read <= 0)
      {
        break;
      }
      done += static_cast<std::size_t>(read);
    }
    close(file);
    benchmark::DoNotOptimize(buffer.get());
  }
  state.SetBytesProcessed(static_cast<int64_t>(state.iterations()) * static_cast<int64_t>(bytes));
}

DepthFilter::Pointer
MakeDepthFilter(const itk::ImageBase<3> * volume, long width, long height)
{
  auto filter = DepthFilter::New();
  filter->SetCenterlineTree(vr::benchmarks::PhantomScene::Instance().GetCenterlineTree());
  filter->SetReferenceVolume(volume);
  filter->SetViewSpecification(vr::benchmarks::PaperView(width, height));
  return filter;
}

void
FullSize_DepthResample(benchmark::State & state)
{
  const itk::ImageBase<3> * volume = VolumeOf(state.range(2));
  auto                      depth = MakeDepthFilter(volume, state.range(0), state.range(1));
  auto                      resample = ResampleFilter::New();
  resample->SetVolume(volume);
  resample->SetDepth(depth->GetDepthOutput());
  resample->Update(); // not timed: the volume's minimum, once per volume
  std::size_t iteration = 0;
  for (auto _ : state) // NOLINT(clang-analyzer-deadcode.DeadStores): Google Benchmark's loop
  {
    depth->SetViewSpecification(
      vr::benchmarks::PaperView(state.range(0), state.range(1), AngleOfIteration(++iteration)));
    resample->Update();
    benchmark::DoNotOptimize(resample->GetOutput()->GetBufferPointer());
  }
}

void
FullSize_Resample(benchmark::State & state)
{
  const itk::ImageBase<3> * volume = VolumeOf(state.range(2));
  auto                      depth = MakeDepthFilter(volume, state.range(0), state.range(1));
  depth->Update();
  auto resample = ResampleFilter::New();
  resample->SetVolume(volume);
  resample->SetDepth(depth->GetDepthOutput());
  resample->Update();  // not timed: the volume's minimum, once per volume
  for (auto _ : state) // NOLINT(clang-analyzer-deadcode.DeadStores): Google Benchmark's loop
  {
    resample->Modified();
    resample->Update();
    benchmark::DoNotOptimize(resample->GetOutput()->GetBufferPointer());
  }
  // The share of the view's pixels that sample the volume (the others take the default value at once): a square
  // field of view holds more of a view than the phantom's box around the body.
  constexpr float Outside = -12345.0F;
  auto            marked = ResampleFilter::New();
  marked->SetVolume(volume);
  marked->SetDepth(depth->GetDepthOutput());
  marked->SetDefaultValue(Outside);
  marked->Update();
  const auto * values = marked->GetOutput()->GetBufferPointer();
  const auto   pixels = marked->GetOutput()->GetBufferedRegion().GetNumberOfPixels();
  const auto   inside = pixels - static_cast<std::size_t>(std::count(values, values + pixels, Outside));
  state.counters["inside_fraction"] = static_cast<double>(inside) / static_cast<double>(pixels);
  state.counters["inside_samples_per_s"] = benchmark::Counter(
    static_cast<double>(state.iterations()) * static_cast<double>(inside), benchmark::Counter::kIsRate);
}

void
FullSize_Pipeline_CPU(benchmark::State & state)
{
  const itk::ImageBase<3> * volume = VolumeOf(state.range(2));
  auto                      depth = MakeDepthFilter(volume, state.range(0), state.range(1));
  auto                      relax = RelaxFilter::New();
  relax->SetDepthInput(depth->GetDepthOutput());
  relax->SetFixedMask(depth->GetFixedMaskOutput());
  relax->SetRelaxation(1.0);
  relax->SetAnisotropy(0.5);
  relax->SetNumberOfIterations(500);
  auto resample = ResampleFilter::New();
  resample->SetVolume(volume);
  resample->SetDepth(relax->GetOutput());
  resample->Update();
  std::size_t iteration = 0;
  for (auto _ : state) // NOLINT(clang-analyzer-deadcode.DeadStores): Google Benchmark's loop
  {
    depth->SetViewSpecification(
      vr::benchmarks::PaperView(state.range(0), state.range(1), AngleOfIteration(++iteration)));
    resample->Update();
    benchmark::DoNotOptimize(resample->GetOutput()->GetBufferPointer());
  }
}

const bool Registered = []
{
  for (const long slices : { 1200L, 2400L })
  {
    benchmark::RegisterBenchmark("FullSize_Read", FullSize_Read)
      ->ArgName("slices")
      ->Arg(slices)
      ->Unit(benchmark::kMillisecond)
      ->UseRealTime()
      ->Repetitions(5)
      ->ReportAggregatesOnly();
    benchmark::RegisterBenchmark("FullSize_Read_Plain", FullSize_Read_Plain)
      ->ArgName("slices")
      ->Arg(slices)
      ->Unit(benchmark::kMillisecond)
      ->UseRealTime()
      ->Repetitions(5)
      ->ReportAggregatesOnly();
  }
  for (const long slices : { 0L, 1200L, 2400L })
  {
    benchmark::RegisterBenchmark("FullSize_DepthResample", FullSize_DepthResample)
      ->ArgNames({ "", "", "slices" })
      ->Args({ 512, 1024, slices })
      ->Unit(benchmark::kMillisecond)
      ->UseRealTime()
      ->Repetitions(5)
      ->ReportAggregatesOnly();
    benchmark::RegisterBenchmark("FullSize_Resample", FullSize_Resample)
      ->ArgNames({ "", "", "slices" })
      ->Args({ 512, 1024, slices })
      ->Unit(benchmark::kMillisecond)
      ->UseRealTime()
      ->Repetitions(9)
      ->ComputeStatistics(
        "min", [](const std::vector<double> & values) { return *std::min_element(values.begin(), values.end()); })
      ->ReportAggregatesOnly();
    benchmark::RegisterBenchmark("FullSize_Pipeline_CPU", FullSize_Pipeline_CPU)
      ->ArgNames({ "", "", "slices" })
      ->Args({ 512, 1024, slices })
      ->Unit(benchmark::kMillisecond)
      ->UseRealTime()
      ->Repetitions(5)
      ->ReportAggregatesOnly();
  }
  return true;
}();
} // namespace
