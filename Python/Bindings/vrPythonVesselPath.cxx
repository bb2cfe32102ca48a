// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// vesselreformation.vessel_path: one vessel's reading through vr::VesselPathLogic, as the VesselPathReformation
// module runs it.
#include "vrLumenMeasurement.h"
#include "vrLumenTableIO.h"
#include "vrPythonCenterlines.h"
#include "vrPythonEngineRun.h"
#include "vrPythonErrors.h"
#include "vrPythonImages.h"
#include "vrPythonOptions.h"
#include "vrPythonVolume.h"
#include "vrReformationParameters.h"
#include "vrText.h"
#include "vrNodeConversion.h"
#include "vrVesselPathLogic.h"
#include "vrVesselPathOutputWriter.h"

#include <pybind11/stl.h>

#include <map>

namespace vr::python
{
namespace
{
/** What vessel_path() returns. */
struct VesselPathResult
{
  py::object               CPR, CrossSections, Points, FoldMask;
  py::object               Lumen;
  py::dict                 Summary;
  double                   PathLength{ 0.0 };
  std::vector<int>         BranchChain;
  double                   PixelSpacing{ 0.0 }, SectionSpacing{ 0.0 };
  std::size_t              FoldedPixels{ 0 };
  std::vector<std::string> Warnings;
  std::vector<std::string> Written;
  std::string              CenterlineSource;
};

const std::map<std::string, VesselPathOutput> OutputKeys = {
  { "cpr", VesselPathOutput::CPR },
  { "cross_sections", VesselPathOutput::CrossSections },
  { "points", VesselPathOutput::Points },
  { "fold_mask", VesselPathOutput::FoldMask },
  { "lumen_table", VesselPathOutput::LumenTable },
};

/** The lumen table as the CSV has it: {column: numpy array}, NaN where the CSV cell is empty. */
py::dict
LumenColumns(const itk::VesselLumenProfile & profile)
{
  const LumenTable table = MakeLumenTable(profile);
  py::dict         columns;
  std::size_t      c = 0;
  for (const char * name : LumenTableColumns)
  {
    if (c == LumenTableProfileColumns)
    {
      break; // the grading's marks are the summary's, not the profile's
    }
    if (c == LumenTableSourceColumn)
    {
      columns[name] = py::module_::import("numpy").attr("array")(std::vector<std::string>(table.Rows, table.Source));
    }
    else if (std::string(name) == "branch_id")
    {
      std::vector<long long> ids(table.Numbers[c].begin(), table.Numbers[c].end());
      columns[name] = py::array_t<long long>(ids.size(), ids.data());
    }
    else
    {
      columns[name] = py::array_t<double>(table.Numbers[c].size(), table.Numbers[c].data());
    }
    ++c;
  }
  return columns;
}

/** The module's returned values (vr::LumenSummaryValues) with numbers as numbers, lists as tuples, nothing as None. */
py::dict
SummaryOf(const VesselPathOutputs & results)
{
  py::dict summary;
  for (const auto & [name, value] : LumenSummaryValues({ results.Lumen, results.Stenosis }))
  {
    if (!results.HasLumen || value.empty())
    {
      summary[name.c_str()] = name == "lumenSource" && !results.HasLumen ? py::object(py::str("none")) : py::none();
      continue;
    }
    std::vector<double> numbers;
    bool                numeric = true;
    for (const std::string & item : SplitAndTrim(value, ','))
    {
      double number = 0.0;
      numeric = numeric && ParseWholeDouble(item, number);
      numbers.push_back(number);
    }
    if (!numeric)
    {
      summary[name.c_str()] = value;
    }
    else if (numbers.size() == 1 && name != "referencePoints")
    {
      summary[name.c_str()] = name == "cadRads" || name == "sectionsOutsideSegmentation"
                                ? py::object(py::int_(static_cast<long long>(numbers[0])))
                                : py::object(py::float_(numbers[0]));
    }
    else
    {
      summary[name.c_str()] = py::tuple(py::cast(numbers));
    }
  }
  summary["pathLength"] = results.Path.GetLength();
  return summary;
}

VesselPathResult
VesselPath(const py::object & volumeArgument, const py::object & centerlinesArgument, const py::kwargs & options)
{
  OptionReader   read(options);
  const Volume & volume = VolumeOf(volumeArgument);

  VesselPathParameters parameters;
  OnArguments(
    [&]
    {
      parameters.BranchId = static_cast<int>(read.Integer("branch", 0));
      if (read.Has("path_range"))
      {
        const auto range = read.Numbers("path_range", 2);
        parameters.HasRange = true;
        parameters.RangeStart = range[0];
        parameters.RangeEnd = range[1];
      }
      const std::string reformation = read.Text("reformation", "straightened");
      if (reformation != "straightened" && reformation != "stretched")
      {
        RaiseValueError("reformation: \"" + reformation + "\": use straightened or stretched");
      }
      parameters.Reformation = reformation == "stretched" ? PathReformation::Stretched : PathReformation::Straightened;
      parameters.RollInDegrees = read.Number("roll", 0.0);
      parameters.Width = read.Number("width", 40.0);
      parameters.PixelSpacing = read.Number("spacing", 0.0);
      parameters.SectionSpacing = read.Number("section_spacing", 0.0);
      read.Up("up", parameters.AutomaticUp, parameters.Up);
      parameters.ViewAngleInDegrees = read.Number("angle", 0.0);
      parameters.Interpolation = ParseInterpolation(read.Text("interpolation", "linear"), "interpolation");
      parameters.SlabThickness = read.Number("slab_thickness", 0.0);
      parameters.SlabMode = ParseSlabMode(read.Text("slab_mode", "mip"), "slab_mode");
      if (read.Has("reference_points"))
      {
        const py::object points = read.Object("reference_points");
        parameters.ReferencePoints = read.Numbers("reference_points", py::len(points));
      }
      const std::string method = read.Text("reference_method", "interpolated");
      if (method != "interpolated" && method != "robust")
      {
        RaiseValueError("reference_method: \"" + method + "\": use interpolated or robust");
      }
      parameters.ReferenceMethod =
        method == "robust" ? VesselReferenceMethod::RobustFit : VesselReferenceMethod::Interpolated;
      parameters.Validate();
    });
  const bool        crossSections = read.Flag("cross_sections", true);
  const bool        pointImage = read.Flag("points", false);
  const py::object  segmentationArgument = read.Object("segmentation");
  const py::object  progress = read.Object("progress");
  const py::object  outputs = read.Object("outputs");
  const std::string space = read.Text("space", "LPS");
  read.CheckAllUsed("vessel_path");

  const Segmentation * segmentation =
    segmentationArgument.is_none() ? nullptr : &SegmentationOf(segmentationArgument, "segmentation");
  const std::string   segmentationName = segmentation ? "segmentation " + segmentation->Name : std::string();
  VesselPathResult    result;
  itk::CenterlineTree tree;
  const bool          extract = centerlinesArgument.is_none();
  if (extract && segmentation == nullptr)
  {
    RaiseValueError("centerlines: give centerlines, or a segmentation to extract them from (centerlines=None)");
  }
  if (!extract)
  {
    tree = TreeOf(centerlinesArgument, space);
    result.CenterlineSource = py::isinstance<Centerlines>(centerlinesArgument)
                                ? centerlinesArgument.cast<const Centerlines &>().Source
                                : std::string("given");
  }

  VesselPathOutputWriter writer;
  AddOutputFiles(outputs, OutputKeys, writer);

  VesselPathLogic logic;
  OnArguments(
    [&]
    {
      RunEngine(
        progress,
        [&](ProgressSink & sink)
        {
          // A stop is honoured between the steps here, and within the logic's update through its AbortUpdate().
          const auto stopIfAsked = [&sink](const char * stage)
          {
            if (sink.StopRequested())
            {
              throw Cancelled(std::string(stage) + ": cancelled");
            }
          };
          if (extract)
          {
            tree = ExtractCenterlineTree(
              segmentation->Mask,
              segmentationName,
              CenterlineExtractionParameters(),
              [&](double fraction, const std::string & stage)
              {
                stopIfAsked("centerlines");
                sink.Report(0.1 + 0.4 * fraction, stage);
              },
              result.Warnings);
          }
          stopIfAsked("reading");
          sink.Report(0.5, "reformation");
          // Nodes, as reform() hands them: the volume's node over the array's voxels, given ready-made.
          const auto node = NodeOver(volume);
          logic.SetVolumeNode(node);
          logic.GetInputCache()->SetVolume(node, volume.Image);
          const auto centerlines = ConvertTreeToCenterlineNode(tree, "centerlines");
          logic.GetInputCache()->SetCenterlines(centerlines, tree);
          logic.SetCenterlineNode(centerlines);
          if (segmentation)
          {
            logic.SetSegmentationNode(MakeSegmentationNode(*segmentation));
          }
          logic.SetParameters(parameters);
          logic.SetCrossSectionsEnabled(crossSections || writer.Has(VesselPathOutput::CrossSections));
          logic.SetPointImageEnabled(pointImage || writer.Has(VesselPathOutput::Points));
          const VesselPathOutputs & results = logic.Update();
          stopIfAsked("reformation");
          sink.Report(0.9, "writing");
          try
          {
            writer.Write(results);
          }
          catch (const InputError & error)
          {
            throw FileError(error.what());
          }
        },
        [&logic] { logic.AbortUpdate(); });
    });
  OnFiles("", [&] { writer.CommitAll(); });
  result.Written = writer.Paths();

  const VesselPathOutputs & results = logic.GetOutputs();
  result.CPR = ArrayOf(results.CPR.GetPointer());
  result.CrossSections = crossSections ? ArrayOf(results.CrossSections.GetPointer()) : py::object(py::none());
  result.Points = pointImage ? ArrayOfPoints(results.Points.GetPointer()) : py::object(py::none());
  result.FoldMask = ArrayOf(results.FoldMask.GetPointer());
  result.Lumen = results.HasLumen ? py::object(LumenColumns(results.Lumen)) : py::object(py::none());
  result.Summary = SummaryOf(results);
  result.PathLength = results.Path.GetLength();
  result.BranchChain = results.Path.GetBranchChain();
  result.PixelSpacing = results.PixelSpacing;
  result.SectionSpacing = results.SectionSpacing;
  result.FoldedPixels = results.FoldedPixels;
  result.Warnings.insert(result.Warnings.end(), results.Warnings.begin(), results.Warnings.end());
  if (extract)
  {
    result.CenterlineSource = "extracted from " + segmentationName;
  }
  return result;
}
} // namespace

void
RegisterVesselPath(py::module_ & module)
{
  py::class_<VesselPathResult>(module, "VesselPathResult", R"doc(
What vessel_path() returns: the straightened (or stretched) CPR, float32 indexed (row along the path, column across
it); the cross-sections, float32 (section, v, u), or None; the LPS point of every CPR pixel (row, column, 3) when
asked (points=True); the fold mask; `lumen`, the lumen table as {column: numpy array} with the CSV's column names
(NaN where the CSV's cell is empty), or None when no lumen was measured; `summary`, the module's returned values
(minimalLumenDiameter (MLD, mm), minimalLumenArea (MLA, mm^2), diameterStenosis (%), cadRads, ...).)doc")
    .def_readonly("cpr", &VesselPathResult::CPR)
    .def_readonly("cross_sections", &VesselPathResult::CrossSections)
    .def_readonly("points", &VesselPathResult::Points)
    .def_readonly("fold_mask", &VesselPathResult::FoldMask)
    .def_readonly("lumen", &VesselPathResult::Lumen)
    .def_readonly("summary", &VesselPathResult::Summary)
    .def_readonly("path_length", &VesselPathResult::PathLength, "mm")
    .def_readonly("branch_chain", &VesselPathResult::BranchChain, "The branch ids from the root to the path's end.")
    .def_readonly("pixel_spacing", &VesselPathResult::PixelSpacing)
    .def_readonly("section_spacing", &VesselPathResult::SectionSpacing)
    .def_readonly("folded_pixels", &VesselPathResult::FoldedPixels)
    .def_readonly("warnings", &VesselPathResult::Warnings)
    .def_readonly("written", &VesselPathResult::Written)
    .def_readonly("centerline_source", &VesselPathResult::CenterlineSource);

  module.def("vessel_path",
             &VesselPath,
             py::arg("volume"),
             py::arg("centerlines") = py::none(),
             R"doc(vessel_path(volume, centerlines=None, *, branch=0, segmentation=None, path_range=None,
            reformation="straightened", roll=0, width=40, spacing=0, section_spacing=0, up="S", angle=0,
            interpolation="linear", slab_thickness=0, slab_mode="mip", reference_points=None,
            reference_method="interpolated", cross_sections=True, points=False, space="LPS", outputs=None,
            progress=None) -> VesselPathResult

One vessel read along its length: the VesselPathReformation module's job on the same engine (vr::VesselPathLogic).
    branch           the branch whose far end the path runs to from the root; 0: the longest root-to-leaf path
    segmentation     a Segmentation to measure the lumen on (else the centerline radii); with centerlines=None,
                     the centerlines are extracted from it
    path_range       (start, end) arc lengths (mm) to read
    width, spacing   mm across the vessel and per pixel (0: the volume's smallest spacing); section_spacing mm
    roll, up, angle  the frame's turn about the path, and the tree view whose look it takes at roll 0
    reference_points arc lengths (mm) of the reference sections; reference_method "interpolated" or "robust"
    outputs          {kind: path} written all or nothing (cpr, cross_sections, points, fold_mask, lumen_table (.csv
                     or .tsv)), as the module writes them
    progress         a callable (fraction, stage); False cancels (Cancelled), raising stops; a stopped run writes
                     nothing. The reading stops at the next stage boundary.
Raises ValueError naming the argument (an unknown branch: "branch: ...") and OSError for files.)doc");
}
} // namespace vr::python
