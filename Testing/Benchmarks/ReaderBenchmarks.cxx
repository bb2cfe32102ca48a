// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// The readers on VMTK's aorta (issue 25: no reader slower for its checks), each beside the library reading the same
// file alone in the same run:
// - Read_AortaVolume: vr::ReadVolume on aorta.mha (the file checks, the MetaImage header check, ITK's read, the
//   finite-voxel scan), beside Read_AortaVolume_ITKAlone (itk::ReadImage); Read_AortaVolume_HeaderCheck is the
//   MetaImage header check by itself;
// - Read_AortaCenterlines/vtp: vr::ReadCenterlines on aorta-centerline.vtp (VTK's XML reader with its arrays checked)
//   beside .../VTKAlone (vtkXMLPolyDataReader);
// - Read_AortaCenterlines/vtk: our own legacy .vtk reader on the same centerlines written as .vtk, beside
//   .../VTKAlone (vtkPolyDataReader).
#include "vrCenterlineIO.h"
#include "vrMetaImageHeaderCheck.h"
#include "vrVolumeIO.h"

#include "itkImageFileReader.h"

#include <vtkPolyData.h>
#include <vtkPolyDataReader.h>
#include <vtkSmartPointer.h>
#include <vtkXMLPolyDataReader.h>

#include <benchmark/benchmark.h>

#include <filesystem>

namespace
{
namespace fs = std::filesystem;

fs::path
AortaFile(const char * name)
{
  return fs::path(VR_SHARED_DATA_DIR) / "vmtk-aorta-mra" / name;
}

/** The aorta's centerlines as a legacy .vtk file, written once by our writer. */
std::string
AortaLegacyVTK()
{
  static const std::string path = []()
  {
    const std::string written = (fs::temp_directory_path() / "vr-reader-benchmark-aorta.vtk").string();
    vr::WriteCenterlines(vr::ReadCenterlines(AortaFile("aorta-centerline.vtp").string()), written);
    return written;
  }();
  return path;
}

void
Read_AortaVolume(benchmark::State & state)
{
  const std::string path = AortaFile("aorta.mha").string();
  for (auto _ : state) // NOLINT(clang-analyzer-deadcode.DeadStores): Google Benchmark's loop
  {
    benchmark::DoNotOptimize(vr::ReadVolume(path).GetPointer());
  }
}

void
Read_AortaVolume_ITKAlone(benchmark::State & state)
{
  const std::string path = AortaFile("aorta.mha").string();
  for (auto _ : state) // NOLINT(clang-analyzer-deadcode.DeadStores): Google Benchmark's loop
  {
    benchmark::DoNotOptimize(itk::ReadImage<vr::VolumeImageType>(path).GetPointer());
  }
}

void
Read_AortaVolume_HeaderCheck(benchmark::State & state)
{
  const std::string path = AortaFile("aorta.mha").string();
  for (auto _ : state) // NOLINT(clang-analyzer-deadcode.DeadStores): Google Benchmark's loop
  {
    vr::detail::CheckMetaImageHeader(path, "volume");
  }
}

void
Read_AortaCenterlines(benchmark::State & state)
{
  const std::string path = state.range(0) == 0 ? AortaFile("aorta-centerline.vtp").string() : AortaLegacyVTK();
  state.SetLabel(state.range(0) == 0 ? "vtp" : "vtk");
  for (auto _ : state) // NOLINT(clang-analyzer-deadcode.DeadStores): Google Benchmark's loop
  {
    benchmark::DoNotOptimize(vr::ReadCenterlines(path).GetNumberOfBranches());
  }
}

void
Read_AortaCenterlines_VTKAlone(benchmark::State & state)
{
  const std::string path = state.range(0) == 0 ? AortaFile("aorta-centerline.vtp").string() : AortaLegacyVTK();
  state.SetLabel(state.range(0) == 0 ? "vtp" : "vtk");
  for (auto _ : state) // NOLINT(clang-analyzer-deadcode.DeadStores): Google Benchmark's loop
  {
    if (state.range(0) == 0)
    {
      auto reader = vtkSmartPointer<vtkXMLPolyDataReader>::New();
      reader->SetFileName(path.c_str());
      reader->Update();
      benchmark::DoNotOptimize(reader->GetOutput()->GetNumberOfPoints());
    }
    else
    {
      auto reader = vtkSmartPointer<vtkPolyDataReader>::New();
      reader->SetFileName(path.c_str());
      reader->Update();
      benchmark::DoNotOptimize(reader->GetOutput()->GetNumberOfPoints());
    }
  }
}

BENCHMARK(Read_AortaVolume)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(Read_AortaVolume_ITKAlone)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(Read_AortaVolume_HeaderCheck)->Unit(benchmark::kMicrosecond)->UseRealTime();
BENCHMARK(Read_AortaCenterlines)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(Read_AortaCenterlines_VTKAlone)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime();
} // namespace
