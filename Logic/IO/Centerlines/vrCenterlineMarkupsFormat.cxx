// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrCenterlineFormats.h"
#include "vrText.h"
#include "vrInputError.h"
#include "vrInputFileChecks.h"

#include <nlohmann/json.hpp>
#include <vtkCardinalSpline.h>
#include <vtkParametricSpline.h>
#include <vtkPoints.h>
#include <vtkSmartPointer.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>

namespace vr::detail
{
namespace
{
using PointType = itk::CenterlineBranch::PointType;
using Json = nlohmann::json;

/** The deepest nesting of JSON arrays and objects accepted; a 3D Slicer markups file has about 6 levels. */
constexpr std::size_t MaximumJSONNesting = 64;

/** Spacing of the points the reader puts along an interpolated curve, in mm. */
constexpr double CurveSampleSpacing = 0.5;
/** Steps per control-point interval when measuring arc length along the spline. */
constexpr int ArcLengthSteps = 64;

const char * const SchemaURL = "https://raw.githubusercontent.com/slicer/slicer/master/Modules/Loadable/Markups/"
                               "Resources/Schema/markups-schema-v1.0.3.json#";

/** A short rendering of a JSON value for messages. */
std::string
Shown(const Json & value)
{
  std::string text = value.dump();
  return text.size() > 60 ? text.substr(0, 57) + "..." : text;
}

/** The curve 3D Slicer draws through \a controls (vtkMRMLMarkupsCurveNode: a vtkCurveGenerator of type
 * CardinalSpline, i.e. one vtkCardinalSpline per coordinate over vtkParametricSpline with the control point index
 * as parameter, ParameterizeByLength off, open, VTK's default end constraints; see Slicer's
 * Modules/Loadable/Markups/MRML/vtkCurveGenerator.cxx and vtkMRMLMarkupsCurveNode.cxx). Each interval between
 * control points is sampled every CurveSampleSpacing mm of arc length, so every control point is a vertex of
 * the result. Radii are interpolated linearly in the parameter, as Slicer does for control-point measurements. */
void
InterpolateSlicerCurve(const std::vector<PointType> & controls,
                       const std::vector<double> &    controlRadii,
                       itk::CenterlineBranch &        branch)
{
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  for (const auto & control : controls)
  {
    points->InsertNextPoint(control.GetDataPointer());
  }
  auto spline = vtkSmartPointer<vtkParametricSpline>::New();
  spline->SetXSpline(vtkSmartPointer<vtkCardinalSpline>::New());
  spline->SetYSpline(vtkSmartPointer<vtkCardinalSpline>::New());
  spline->SetZSpline(vtkSmartPointer<vtkCardinalSpline>::New());
  spline->SetPoints(points);
  spline->SetClosed(false);
  spline->SetParameterizeByLength(false);

  const double intervals = static_cast<double>(controls.size() - 1);
  auto         evaluate = [&](double parameter)
  {
    double u[3] = { parameter / intervals, 0.0, 0.0 };
    double xyz[3];
    double derivatives[9];
    spline->Evaluate(u, xyz, derivatives);
    PointType point;
    point[0] = xyz[0];
    point[1] = xyz[1];
    point[2] = xyz[2];
    return point;
  };
  auto addSample = [&](double parameter, const PointType & point)
  {
    branch.Points.push_back(point);
    if (!controlRadii.empty())
    {
      const auto   interval = std::min(static_cast<std::size_t>(parameter), controls.size() - 2);
      const double t = parameter - static_cast<double>(interval);
      branch.Radii.push_back((1.0 - t) * controlRadii[interval] + t * controlRadii[interval + 1]);
    }
  };

  for (std::size_t interval = 0; interval + 1 < controls.size(); ++interval)
  {
    // Arc length along this interval, tabulated against the parameter.
    std::vector<double> parameters(ArcLengthSteps + 1);
    std::vector<double> arc(ArcLengthSteps + 1, 0.0);
    PointType           previous = controls[interval];
    for (int step = 0; step <= ArcLengthSteps; ++step)
    {
      parameters[step] = static_cast<double>(interval) + static_cast<double>(step) / ArcLengthSteps;
      const PointType point = step == 0 ? controls[interval] : evaluate(parameters[step]);
      arc[step] = step == 0 ? 0.0 : arc[step - 1] + point.EuclideanDistanceTo(previous);
      previous = point;
    }
    const double length = arc.back();
    const auto   samples = std::max<std::size_t>(1, static_cast<std::size_t>(std::ceil(length / CurveSampleSpacing)));
    addSample(static_cast<double>(interval), controls[interval]);
    for (std::size_t sample = 1; sample < samples; ++sample)
    {
      const double target = length * static_cast<double>(sample) / static_cast<double>(samples);
      const auto   above = static_cast<std::size_t>(std::lower_bound(arc.begin(), arc.end(), target) - arc.begin());
      const std::size_t upper = std::min<std::size_t>(std::max<std::size_t>(above, 1), ArcLengthSteps);
      const double      span = arc[upper] - arc[upper - 1];
      const double      t = span > 0.0 ? (target - arc[upper - 1]) / span : 0.0;
      const double      parameter = parameters[upper - 1] + t * (parameters[upper] - parameters[upper - 1]);
      addSample(parameter, evaluate(parameter));
    }
  }
  addSample(intervals, controls.back());
}

CoordinateSpace
MarkupSpace(const Json & markup, const std::string & where)
{
  if (!markup.contains("coordinateSystem"))
  {
    return CoordinateSpace::LPS; // the markups schema's default
  }
  const Json &      value = markup["coordinateSystem"];
  const std::string text = value.is_string() ? ToLower(value.get<std::string>()) : std::string();
  if (text == "lps")
  {
    return CoordinateSpace::LPS;
  }
  if (text == "ras")
  {
    return CoordinateSpace::RAS;
  }
  throw InputError(where + ".coordinateSystem is " + Shown(value) + "; it must be \"LPS\" or \"RAS\"");
}

double
MarkupUnitsInMillimetres(const Json & markup, const std::string & where)
{
  if (!markup.contains("coordinateUnits"))
  {
    return 1.0;
  }
  const Json &      value = markup["coordinateUnits"];
  const Json &      unit = value.is_array() && !value.empty() ? value[0] : value;
  const std::string text = unit.is_string() ? unit.get<std::string>() : std::string();
  if (text == "mm")
  {
    return 1.0;
  }
  if (text == "um")
  {
    return 1e-3;
  }
  throw InputError(where + ".coordinateUnits is " + Shown(value) + "; it must be \"mm\" or \"um\"");
}

/** The per-control-point radius measurement ("Radius", as 3D Slicer's Extract Centerline writes), or null. */
const Json *
RadiusValues(const Json & markup, const std::string & where, std::size_t controlPointCount, std::string & field)
{
  if (!markup.contains("measurements") || !markup["measurements"].is_array())
  {
    return nullptr;
  }
  const Json & measurements = markup["measurements"];
  for (std::size_t m = 0; m < measurements.size(); ++m)
  {
    const Json & measurement = measurements[m];
    if (!measurement.is_object() || !measurement.contains("name") || !measurement["name"].is_string())
    {
      continue;
    }
    const std::string name = ToLower(measurement["name"].get<std::string>());
    if ((name != "radius" && name != "maximuminscribedsphereradius") || !measurement.contains("controlPointValues"))
    {
      continue;
    }
    field = where + ".measurements[" + std::to_string(m) + "].controlPointValues";
    const Json & values = measurement["controlPointValues"];
    if (!values.is_array() || values.size() != controlPointCount)
    {
      throw InputError(field + " must be an array of one radius per control point (" +
                       std::to_string(controlPointCount) + "); it is " + Shown(values));
    }
    for (std::size_t k = 0; k < values.size(); ++k)
    {
      if (!values[k].is_number() || !std::isfinite(values[k].get<double>()) || values[k].get<double>() < 0.0)
      {
        throw InputError(field + "[" + std::to_string(k) + "] is " + Shown(values[k]) +
                         "; a radius must be a finite number >= 0 (mm)");
      }
    }
    return &values;
  }
  return nullptr;
}
} // namespace

itk::CenterlineTree
ReadMarkupsCurves(const std::string & path, CoordinateSpace space, CenterlineReadReport & report)
{
  report.Format = "3D Slicer markups (.mrk.json)";
  const std::string file = "centerline file " + path;
  // nlohmann::json builds and destroys nested values recursively: measure the nesting before it parses.
  const std::size_t depth = JSONNestingDepth(path, "centerline file");
  if (depth > MaximumJSONNesting)
  {
    throw InputError(file + ": arrays and objects nest " + std::to_string(depth) + " levels deep; a markups file " +
                     "needs about 6, and more than " + std::to_string(MaximumJSONNesting) + " are refused");
  }
  std::ifstream input(path);
  if (!input)
  {
    throw InputError(file + ": cannot be opened");
  }
  Json document;
  try
  {
    document = Json::parse(input);
  }
  catch (const Json::exception & exception)
  {
    throw InputError(file + ": not valid JSON (" + exception.what() + ")");
  }
  if (!document.is_object() || !document.contains("markups") || !document["markups"].is_array())
  {
    throw InputError(file + ": no \"markups\" array at the top level; not a 3D Slicer markups file");
  }

  itk::CenterlineTree      tree;
  std::vector<std::string> spaces;
  std::vector<std::string> otherTypes;
  const Json &             markups = document["markups"];
  for (std::size_t m = 0; m < markups.size(); ++m)
  {
    const Json & markup = markups[m];
    std::string  where = file + ": markups[" + std::to_string(m) + "]";
    if (!markup.is_object())
    {
      throw InputError(where + " is " + Shown(markup) + ", not an object");
    }
    const std::string type =
      markup.contains("type") && markup["type"].is_string() ? markup["type"].get<std::string>() : std::string();
    if (type != "Curve")
    {
      otherTypes.push_back(type.empty() ? "(no type)" : type);
      continue;
    }
    // Slicer names each markups node ("aorta"): the name is the vessel's.
    const std::string name =
      markup.contains("name") && markup["name"].is_string() ? markup["name"].get<std::string>() : std::string();
    if (!name.empty())
    {
      where += " (\"" + name + "\")";
    }
    const CoordinateSpace fileSpace = MarkupSpace(markup, where);
    const CoordinateSpace used = space == CoordinateSpace::Auto ? fileSpace : space;
    spaces.push_back(ToString(used));
    const double scale = MarkupUnitsInMillimetres(markup, where);
    if (!markup.contains("controlPoints") || !markup["controlPoints"].is_array())
    {
      throw InputError(where + ": no \"controlPoints\" array");
    }
    const Json & controlPoints = markup["controlPoints"];
    std::string  radiusField;
    const Json * radiusValues = RadiusValues(markup, where, controlPoints.size(), radiusField);
    if (radiusValues != nullptr)
    {
      report.RadiusArray = radiusField.substr(file.size() + 2); // "markups[0].measurements[1].controlPointValues"
    }

    std::vector<PointType> controls;
    std::vector<double>    controlRadii;
    for (std::size_t k = 0; k < controlPoints.size(); ++k)
    {
      const Json &      controlPoint = controlPoints[k];
      const std::string field = where + ".controlPoints[" + std::to_string(k) + "]";
      if (!controlPoint.is_object())
      {
        throw InputError(field + " is " + Shown(controlPoint) + ", not an object");
      }
      // Slicer keeps placeholders for points not placed yet; they are not part of the curve.
      if (controlPoint.contains("positionStatus") && controlPoint["positionStatus"] == "undefined")
      {
        continue;
      }
      const Json * position = controlPoint.contains("position") ? &controlPoint["position"] : nullptr;
      const bool   threeNumbers =
        position != nullptr && position->is_array() && position->size() == 3 &&
        std::all_of(position->begin(),
                    position->end(),
                    [](const Json & value) { return value.is_number() && std::isfinite(value.get<double>()); });
      if (!threeNumbers)
      {
        throw InputError(field + ".position is not three finite numbers: " +
                         (position == nullptr ? std::string("missing") : Shown(*position)));
      }
      PointType point;
      for (unsigned int axis = 0; axis < 3; ++axis)
      {
        point[axis] = scale * (*position)[axis].get<double>();
      }
      controls.push_back(used == CoordinateSpace::RAS ? RASToLPS(point) : point);
      if (radiusValues != nullptr)
      {
        controlRadii.push_back((*radiusValues)[k].get<double>());
      }
    }
    if (controls.size() < 2)
    {
      throw InputError(where + ": a curve needs at least 2 placed control points; it has " +
                       std::to_string(controls.size()));
    }
    itk::CenterlineBranch branch;
    branch.Id = static_cast<int>(tree.GetNumberOfBranches()) + 1;
    branch.Name = name;
    InterpolateSlicerCurve(controls, controlRadii, branch);
    tree.AddBranch(std::move(branch));
  }
  if (tree.GetNumberOfBranches() == 0)
  {
    std::string found;
    for (const auto & type : otherTypes)
    {
      found += (found.empty() ? "" : ", ") + type;
    }
    throw InputError(file + ": has no markup of type \"Curve\"" +
                     (found.empty() ? std::string(" (the markups array is empty)") : " (it holds: " + found + ")"));
  }

  report.InputPolylines = tree.GetNumberOfBranches();
  report.FileSpace = space == CoordinateSpace::Auto ? ParseCoordinateSpace(spaces.front(), "space") : space;
  if (space != CoordinateSpace::Auto)
  {
    report.SpaceSource = "override";
  }
  else
  {
    std::string list;
    for (const auto & name : spaces)
    {
      list += (list.empty() ? "" : ", ") + name;
    }
    report.SpaceSource = "each curve's coordinateSystem (" + list + ")";
  }
  return tree;
}

void
WriteMarkupsCurves(const itk::CenterlineTree & tree,
                   const std::string &         finalPath,
                   const std::string &         temporaryPath,
                   CoordinateSpace             space)
{
  const bool lps = space == CoordinateSpace::LPS;
  Json       markups = Json::array();
  for (const auto & branch : tree.GetBranches())
  {
    const std::string name = branch.Name.empty() ? "Branch " + std::to_string(branch.Id) : branch.Name;
    Json              controlPoints = Json::array();
    for (std::size_t k = 0; k < branch.Points.size(); ++k)
    {
      const PointType point = lps ? branch.Points[k] : LPSToRAS(branch.Points[k]);
      controlPoints.push_back({ { "id", std::to_string(k + 1) },
                                { "label", name + "-" + std::to_string(k + 1) },
                                { "position", { point[0], point[1], point[2] } },
                                { "positionStatus", "defined" } });
    }
    Json markup = { { "type", "Curve" },
                    { "name", name },
                    { "coordinateSystem", lps ? "LPS" : "RAS" },
                    { "coordinateUnits", "mm" },
                    { "controlPoints", controlPoints } };
    if (branch.HasRadii())
    {
      markup["measurements"] = Json::array(
        { { { "name", "Radius" }, { "enabled", false }, { "units", "mm" }, { "controlPointValues", branch.Radii } } });
    }
    markups.push_back(markup);
  }
  const Json    document = { { "@schema", SchemaURL }, { "markups", markups } };
  std::ofstream output(temporaryPath);
  if (!output)
  {
    throw InputError("centerline output " + finalPath + ": cannot be created");
  }
  output << document.dump(2) << '\n';
  output.close();
  if (!output)
  {
    throw InputError("centerline output " + finalPath + ": writing failed (disk full?)");
  }
}
} // namespace vr::detail
