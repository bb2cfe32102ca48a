// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// vesselreformation.reform: the whole-tree reformation through vr::VesselReformationLogic, as the VesselReformation
// module runs it, on a volume the logic reads without a copy of its own.
#include "itkCPRVolumeSampler.h"
#include "vrCoordinateFrames.h"
#include "vrNodeConversion.h"
#include "vrOutputWriter.h"
#include "vrPythonCenterlines.h"
#include "vrPythonEngineRun.h"
#include "vrPythonErrors.h"
#include "vrPythonImages.h"
#include "vrPythonOptions.h"
#include "vrPythonVolume.h"
#include "vrVesselReformationLogic.h"

#include <pybind11/stl.h>

#include <cmath>
#include <map>

namespace vr::python
{
namespace
{
/** What reform() returns. */
struct ReformResult
{
  py::object CPR, UnfilteredCPR, Depth, RelaxedDepth, FixedMask, OwnerLabels;
  /** The tree as the logic reformed it: overlapping paths merged, a trunk split where a child leaves it; its ids are
   * the owner labels' values. */
  py::object                    Tree;
  itk::CPRViewGeometry          View;
  std::string                   Backend, BackendReason;
  std::vector<std::string>      Warnings;
  std::map<std::string, double> Times;
  double                        Window{ 0.0 }, Level{ 0.0 };
  std::vector<std::string>      Written;
  std::uintptr_t                EngineVolumeAddress{ 0 };
};

/** The outputs reform() writes, by the keys of its `outputs` argument. */
const std::map<std::string, ReformationOutput> OutputKeys = {
  { "cpr", ReformationOutput::CPR },
  { "cpr_png", ReformationOutput::CPRPNG },
  { "unfiltered_cpr", ReformationOutput::UnfilteredCPR },
  { "depth", ReformationOutput::Depth },
  { "relaxed_depth", ReformationOutput::RelaxedDepth },
  { "fixed_mask", ReformationOutput::FixedMask },
  { "owner_labels", ReformationOutput::OwnerLabels },
  { "surface", ReformationOutput::CutSurface },
};

py::dict
ViewOf(const itk::CPRViewGeometry & view)
{
  const auto vector = [](const auto & v) { return py::make_tuple(v[0], v[1], v[2]); };
  py::dict   result;
  result["angle"] = view.GetAngleInDegrees();
  result["up"] = vector(view.GetUp());
  result["u"] = vector(view.GetU());
  result["v"] = vector(view.GetV());
  result["center"] = vector(view.GetCenter());
  result["size"] = py::make_tuple(view.GetSize()[0], view.GetSize()[1]);
  result["spacing"] = py::make_tuple(view.GetSpacing()[0], view.GetSpacing()[1]);
  return result;
}

/** The patient points of CPR pixels (columns, rows), moved along v by \a depth or the relaxed depth (nearest
 * pixel), as an (..., 3) array in \a space. */
py::array_t<double>
SurfacePoints(const itk::CPRViewGeometry & view,
              const py::object &           relaxedDepth,
              const py::object &           columns,
              const py::object &           rows,
              const py::object &           depth,
              const std::string &          space)
{
  CoordinateSpace frame = CoordinateSpace::LPS;
  OnArguments([&] { frame = ParseCoordinateSpace(space, "space"); });
  const py::module_        numpy = py::module_::import("numpy");
  const py::tuple          arrays = numpy.attr("broadcast_arrays")(numpy.attr("asarray")(columns, "float64"),
                                                          numpy.attr("asarray")(rows, "float64"),
                                                          depth.is_none() ? numpy.attr("asarray")(0.0)
                                                                                   : numpy.attr("asarray")(depth, "float64"));
  const auto               i = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(arrays[0]);
  const auto               j = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(arrays[1]);
  const auto               d = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(arrays[2]);
  const auto               map = py::array_t<float, py::array::c_style | py::array::forcecast>::ensure(relaxedDepth);
  const long               width = static_cast<long>(view.GetSize()[0]);
  const long               height = static_cast<long>(view.GetSize()[1]);
  std::vector<py::ssize_t> shape(i.shape(), i.shape() + i.ndim());
  shape.push_back(3);
  py::array_t<double> points(shape);
  double *            target = points.mutable_data();
  for (py::ssize_t n = 0; n < i.size(); ++n)
  {
    double offset = d.data()[n];
    if (depth.is_none())
    {
      const long column = std::lround(i.data()[n]);
      const long row = std::lround(j.data()[n]);
      if (column < 0 || column >= width || row < 0 || row >= height)
      {
        RaiseValueError("i, j: pixel (" + std::to_string(i.data()[n]) + ", " + std::to_string(j.data()[n]) +
                        ") lies outside the " + std::to_string(width) + " x " + std::to_string(height) +
                        " view; give depth= for points off the image");
      }
      offset = map.data()[row * width + column];
    }
    auto point = view.SurfacePoint(i.data()[n], j.data()[n], offset);
    if (frame == CoordinateSpace::RAS)
    {
      point = LPSToRAS(point);
    }
    for (unsigned int c = 0; c < 3; ++c)
    {
      target[3 * n + c] = point[c];
    }
  }
  return points;
}

ReformResult
Reform(const py::object & volumeArgument, const py::object & centerlinesArgument, const py::kwargs & options)
{
  OptionReader              read(options);
  const Volume &            volume = VolumeOf(volumeArgument);
  const itk::CenterlineTree tree = TreeOf(centerlinesArgument, read.Text("space", "LPS"));

  ReformationParameters parameters;
  OnArguments(
    [&]
    {
      read.Up("up", parameters.AutomaticUp, parameters.Up);
      parameters.AngleInDegrees = read.Number("angle", 0.0);
      if (read.Has("center"))
      {
        const auto center = read.Numbers("center", 3);
        parameters.HasCenter = true;
        for (unsigned int k = 0; k < 3; ++k)
        {
          parameters.Center[k] = center[k];
        }
      }
      if (read.Has("size"))
      {
        const auto size = read.Whole("size", 2);
        parameters.ImageSize[0] = size[0];
        parameters.ImageSize[1] = size[1];
      }
      if (read.Has("spacing"))
      {
        const auto spacing = read.Spacing("spacing");
        parameters.PixelSpacing[0] = spacing[0];
        parameters.PixelSpacing[1] = spacing[1];
      }
      parameters.Mode = ParseDepthMode(read.Text("mode", "scanline"), "mode");
      parameters.FixLumen = read.Flag("fix_lumen", true);
      parameters.Relaxation = read.Number("relaxation", 1.0);
      if (read.Has("jump_threshold"))
      {
        parameters.JumpThreshold = read.Number("jump_threshold", 0.0);
      }
      if (read.Has("anisotropy"))
      {
        parameters.Anisotropy = read.Number("anisotropy", 0.0);
      }
      parameters.Iterations = read.Integer("iterations", 500);
      parameters.Solver = ParseRelaxSolver(read.Text("solver", "jacobi"), "solver");
      parameters.Backend = ParseRelaxBackend(read.Text("backend", "auto"), "backend");
      parameters.OpenCLDevice = read.Text("opencl_device", "");
      parameters.Interpolation = ParseInterpolation(read.Text("interpolation", "linear"), "interpolation");
      parameters.SlabThickness = read.Number("slab_thickness", 0.0);
      parameters.SlabMode = ParseSlabMode(read.Text("slab_mode", "mip"), "slab_mode");
      parameters.Window = read.Number("window", 0.0);
      parameters.Level = read.Number("level", 0.0);
      parameters.Validate();
    });
  const py::object progress = read.Object("progress");
  const py::object outputFiles = read.Object("outputs");
  read.CheckAllUsed("reform");

  // Every output path is reserved before the work; nothing lands until all are written (vr::OutputWriter).
  OutputWriter writer;
  AddOutputFiles(outputFiles, OutputKeys, writer);

  VesselReformationLogic logic;
  const auto             node = NodeOver(volume);
  logic.SetVolumeNode(node);
  logic.GetInputCache()->SetVolume(node, volume.Image);
  logic.SetCenterlineNode(ConvertTreeToCenterlineNode(tree, "centerlines"));
  logic.SetParameters(parameters);
  logic.SetSurfaceEnabled(writer.Has(ReformationOutput::CutSurface));
  ReformResult result;
  logic.SetWarningCallback(
    [&result](const std::string & message, const std::string & parameter)
    {
      const std::string keyword = KeywordOf(parameter);
      result.Warnings.push_back(message + (keyword.empty() ? "" : " (" + keyword + ")"));
    });
  OnArguments(
    [&]
    {
      RunEngine(
        progress,
        [&](ProgressSink & sink)
        {
          logic.SetProgressCallback([&sink](double fraction, const std::string & stage)
                                    { sink.Report(fraction, stage); });
          const ReformationOutputs & computed = logic.Update();
          logic.GetDisplayWindowLevel(result.Window, result.Level);
          if (!writer.Paths().empty())
          {
            try
            {
              writer.Write(computed, result.Window, result.Level);
            }
            catch (const InputError & error)
            {
              throw FileError(error.what());
            }
          }
        },
        [&logic] { logic.AbortUpdate(); });
    });
  OnFiles("", [&] { writer.CommitAll(); });
  result.Written = writer.Paths();

  const ReformationOutputs & outputs = logic.GetOutputs();
  OnArguments(
    [&]
    {
      result.CPR = ArrayOf(ConvertVolumeNodeToDepthImage(outputs.CPR).GetPointer());
      result.UnfilteredCPR = ArrayOf(ConvertVolumeNodeToDepthImage(outputs.UnfilteredCPR).GetPointer());
      result.Depth = ArrayOf(ConvertVolumeNodeToDepthImage(outputs.Depth).GetPointer());
      result.RelaxedDepth = ArrayOf(ConvertVolumeNodeToDepthImage(outputs.RelaxedDepth).GetPointer());
      result.FixedMask = ArrayOf(ConvertVolumeNodeToMaskImage(outputs.FixedMask).GetPointer());
      result.OwnerLabels = ArrayOf(ConvertVolumeNodeToLabelImage(outputs.OwnerLabels).GetPointer());
    });
  Centerlines reformed;
  reformed.Tree = logic.GetDepthFilter()->GetCenterlineTree();
  reformed.Source = "as reformed (ids: the owner labels)";
  result.Tree = py::cast(std::move(reformed));
  result.View = outputs.View;
  result.Backend = outputs.RelaxBackendUsed;
  result.BackendReason = outputs.RelaxBackendReason;
  result.Times = { { "conversion", outputs.Times.Conversion },
                   { "depth", outputs.Times.Depth },
                   { "relax", outputs.Times.Relax },
                   { "resample", outputs.Times.Resample },
                   { "surface", outputs.Times.Surface } };
  result.EngineVolumeAddress = itk::VisitStoredVolume(
    logic.GetResampleFilter()->GetVolume(),
    [](const auto * image) { return reinterpret_cast<std::uintptr_t>(image->GetBufferPointer()); });
  return result;
}
} // namespace

void
RegisterReform(py::module_ & module)
{
  py::class_<ReformResult>(module, "ReformResult", R"doc(
What reform() returns. Images are numpy arrays indexed (row, column) = (j, i) on the view: the CPR (float32, the
volume's intensities), the CPR on the unrelaxed depth, the depth maps (mm along the view direction), the fixed mask
(uint8, 1 = held fixed) and the owner labels (uint32, the branch id owning each pixel, 0 = none); `view` (LPS) says
where every pixel lies, and to_patient() maps pixels back to the patient.)doc")
    .def_readonly("cpr", &ReformResult::CPR)
    .def_readonly("unfiltered_cpr", &ReformResult::UnfilteredCPR)
    .def_readonly("depth", &ReformResult::Depth)
    .def_readonly("relaxed_depth", &ReformResult::RelaxedDepth)
    .def_readonly("fixed_mask", &ReformResult::FixedMask)
    .def_readonly("owner_labels", &ReformResult::OwnerLabels)
    .def_readonly("centerlines",
                  &ReformResult::Tree,
                  "The tree as reformed (overlapping paths merged, a trunk split where a child leaves it): its "
                  "branch ids are the values of owner_labels, its names the given ones.")
    .def_property_readonly(
      "view",
      [](const ReformResult & r) { return ViewOf(r.View); },
      "The resolved view (LPS): angle, up, u (screen right), v (view direction), center, size "
      "(W, H) and spacing (sx, sy) in mm.")
    .def_readonly("backend", &ReformResult::Backend, "\"cpu\" or \"opencl\": where the relaxation ran.")
    .def_readonly("backend_reason", &ReformResult::BackendReason)
    .def_readonly("warnings", &ReformResult::Warnings)
    .def_readonly("times", &ReformResult::Times, "Seconds per stage.")
    .def_readonly("window", &ReformResult::Window)
    .def_readonly("level", &ReformResult::Level)
    .def_readonly("written", &ReformResult::Written, "The files written (outputs), after all were.")
    .def_readonly("_engine_volume_address",
                  &ReformResult::EngineVolumeAddress,
                  "The address of the voxels the resampling read (for tests: the Volume's when it was viewed).")
    .def(
      "to_patient",
      [](const ReformResult & r,
         const py::object &   columns,
         const py::object &   rows,
         const py::object &   depth,
         const std::string &  space) { return SurfacePoints(r.View, r.RelaxedDepth, columns, rows, depth, space); },
      py::arg("i"),
      py::arg("j"),
      py::arg("depth") = py::none(),
      py::arg("space") = "LPS",
      R"doc(The patient position (mm) of CPR pixel (i, j) = (column, row): the view plane's point B(i, j) moved along
the view direction by the relaxed depth at the nearest pixel (or by `depth`, mm). i and j may be numbers or arrays
of one shape; returns (..., 3) in "LPS" or "RAS".)doc");

  module.def(
    "reform",
    &Reform,
    py::arg("volume"),
    py::arg("centerlines"),
    R"doc(reform(volume, centerlines, *, angle=0, up="S", center=None, size=None, spacing=None, mode="scanline",
       fix_lumen=True, relaxation=1.0, jump_threshold=None, anisotropy=None, iterations=500, solver="jacobi",
       backend="auto", opencl_device="", interpolation="linear", slab_thickness=0, slab_mode="mip", window=0,
       level=0, space="LPS", outputs=None, progress=None) -> ReformResult

The multipath CPR of a vessel tree with bilateral depth filtering: the VesselReformation module's job, on the same
engine (vr::VesselReformationLogic), with the same parameters under Python names:
    volume        a Volume (or a path read with read_volume); viewed, not copied, when float32 C-contiguous
    centerlines   a Centerlines, a path, or a list of branches (points in `space`, "LPS" or "RAS")
    angle         rotation about `up`, degrees; up: "S", "I", "A", "P", "L", "R", "auto" or an LPS vector
    center        view centre, LPS mm (default: the tree's bounding-box centre)
    size          (W, H) pixels; spacing: s or (sx, sy) mm (defaults fit the tree)
    mode          "scanline" (mpCPR) or "nearest"; fix_lumen: hold the lumen fixed as well as the centerline
    relaxation    w in [0, 1]; jump_threshold J in mm (default 3) or anisotropy a = 1/J^2 (the paper's)
    iterations    N Jacobi passes; solver "jacobi" (the paper's) or "steady" (the fixed point)
    backend       "auto", "cpu" or "opencl"
    interpolation "linear", "nearest" or "cubic"; slab_thickness mm with slab_mode "mip", "minip" or "mean"
    window, level the PNG's display window (0: the CPR's full range)
    outputs       {kind: path} to write, all or nothing (kinds: cpr, cpr_png, unfiltered_cpr, depth, relaxed_depth,
                  fixed_mask, owner_labels, surface); written like the module's, NRRD or any ITK 2D format
    progress      a callable (fraction, stage) called on this thread while the engine runs without the GIL;
                  returning False cancels (Cancelled), raising (or Ctrl-C) stops the engine and re-raises; a
                  stopped run writes nothing and leaves earlier files as they were.
Raises ValueError naming the argument (e.g. "iterations: ...") and OSError for files.)doc");
}
} // namespace vr::python
