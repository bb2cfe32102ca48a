// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// vesselreformation._engine: the extension module the package re-exports (vesselreformation/__init__.py).
#include "itkCTAPhantom.h"
#include "vrPythonCenterlines.h"
#include "vrPythonErrors.h"
#include "vrPythonVolume.h"

#include <pybind11/stl.h>

#include <stdexcept>

namespace vr::python
{
void
RegisterReform(py::module_ & module);
void
RegisterVesselPath(py::module_ & module);
} // namespace vr::python

PYBIND11_MODULE(_engine, module)
{
  namespace py = pybind11;
  using namespace vr::python;
  module.doc() = "The VesselReformation engine (C++, ITK): the package vesselreformation re-exports what it defines.";
  RegisterErrors(module);
  RegisterVolumes(module);
  RegisterCenterlines(module);
  RegisterReform(module);
  RegisterVesselPath(module);

  module.def(
    "phantom",
    [](const std::string & name, double spacing)
    {
      itk::CTAPhantomKind kind{};
      try
      {
        kind = itk::ParseCTAPhantomKind(name);
      }
      catch (const std::invalid_argument & error)
      {
        RaiseValueError(std::string("name: ") + error.what());
      }
      if (!(spacing > 0.0 && spacing < 100.0))
      {
        RaiseValueError("spacing: " + std::to_string(spacing) + " mm: give a voxel spacing > 0");
      }
      auto phantom = itk::MakeCTAPhantom(kind, spacing);
      {
        const py::gil_scoped_release release;
        phantom.Source->Update();
      }
      Centerlines centerlines;
      centerlines.Tree = phantom.Tree;
      for (auto & branch : centerlines.Tree.GetBranches())
      {
        branch.Name = phantom.BranchName(branch.Id);
      }
      centerlines.Source = "phantom " + phantom.Name + " (exact)";
      vr::VolumeImageType::Pointer image = phantom.Source->GetOutput();
      image->DisconnectPipeline();
      return py::make_tuple(VolumeFromImage(image, phantom.Name), centerlines, phantom.DesignAngleInDegrees);
    },
    py::arg("name") = "runoff",
    py::arg("spacing") = 1.5,
    R"doc(A built-in synthetic CT angiography in Hounsfield units with its exact centerline tree (with radii and the
arteries' names): "runoff" (the legs) or "thorax" (the aortic arch), voxels of `spacing` mm.
Returns (volume, centerlines, design_angle): the view angle (degrees) the phantom was designed for.)doc");
}
