// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrThreeDView.h"

#include "vrBranchColors.h"
#include "vrCoordinateFrames.h"
#include "vrCutSurface.h"
#include "vrOpenGLRenderer.h"

#include <QTimer>
#include <QVBoxLayout>
#include <QVTKOpenGLNativeWidget.h>

#include <vtkActor.h>
#include <vtkArrowSource.h>
#include <vtkCallbackCommand.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkCommand.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkImageData.h>
#include <vtkInteractorStyleTrackballCamera.h>
#include <vtkLookupTable.h>
#include <vtkMatrix4x4.h>
#include <vtkNew.h>
#include <vtkOutlineSource.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderWindowInteractor.h>
#include <vtkRenderer.h>
#include <vtkSphereSource.h>
#include <vtkTubeFilter.h>

#include <algorithm>
#include <chrono>
#include <cmath>

namespace vr
{
namespace
{
itk::Point<double, 3>
ToRAS(const itk::Point<double, 3> & lps)
{
  return LPSToRAS(lps);
}

std::array<double, 3>
DirectionToRAS(const itk::Vector<double, 3> & lps)
{
  return { -lps[0], -lps[1], lps[2] };
}
} // namespace

ThreeDView::ThreeDView(QWidget * parent)
  : QWidget(parent)
{
  m_Widget = new QVTKOpenGLNativeWidget(this);
  auto * layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->addWidget(m_Widget);
  m_RenderWindow = vtkSmartPointer<vtkGenericOpenGLRenderWindow>::New();
  m_RenderWindow->SetMultiSamples(ViewMultiSamples());
  m_Widget->setRenderWindow(m_RenderWindow);
  m_Renderer = vtkSmartPointer<vtkRenderer>::New();
  m_Renderer->SetBackground(0.12, 0.12, 0.15);
  m_Renderer->SetBackground2(0.3, 0.3, 0.36);
  m_Renderer->GradientBackgroundOn();
  m_RenderWindow->AddRenderer(m_Renderer);

  m_Grey = vtkSmartPointer<vtkLookupTable>::New();
  m_Grey->SetHueRange(0.0, 0.0);
  m_Grey->SetSaturationRange(0.0, 0.0);
  m_Grey->SetValueRange(0.0, 1.0);
  m_Grey->SetRampToLinear();
  m_Grey->SetTableRange(-250.0, 650.0);
  m_Grey->Build();

  m_SurfaceMapper = vtkSmartPointer<vtkPolyDataMapper>::New();
  m_SurfaceMapper->SetScalarModeToUsePointFieldData();
  m_SurfaceMapper->SelectColorArray(CutSurfaceIntensityArrayName);
  m_SurfaceMapper->SetLookupTable(m_Grey);
  m_SurfaceMapper->UseLookupTableScalarRangeOn();
  m_SurfaceMapper->ScalarVisibilityOn();
  m_Surface = vtkSmartPointer<vtkActor>::New();
  m_Surface->SetMapper(m_SurfaceMapper);
  m_Surface->GetProperty()->SetAmbient(0.45);
  m_Surface->GetProperty()->SetDiffuse(0.55);
  m_Surface->GetProperty()->SetSpecular(0.0);
  m_Surface->SetVisibility(false);
  m_Renderer->AddActor(m_Surface);

  m_Tubes = vtkSmartPointer<vtkActor>::New();
  m_Tubes->SetVisibility(false);
  m_Renderer->AddActor(m_Tubes);
  m_Outline = vtkSmartPointer<vtkActor>::New();
  m_Outline->GetProperty()->SetColor(0.8, 0.8, 0.8);
  m_Outline->SetVisibility(false);
  m_Renderer->AddActor(m_Outline);
  m_Arrow = vtkSmartPointer<vtkActor>::New();
  m_Arrow->GetProperty()->SetColor(1.0, 0.55, 0.1);
  m_Arrow->SetVisibility(false);
  m_Renderer->AddActor(m_Arrow);
  m_PathMarker = vtkSmartPointer<vtkActor>::New();
  vtkNew<vtkSphereSource> sphere;
  sphere->SetRadius(3.0);
  sphere->SetThetaResolution(16);
  sphere->SetPhiResolution(12);
  vtkNew<vtkPolyDataMapper> sphereMapper;
  sphereMapper->SetInputConnection(sphere->GetOutputPort());
  m_PathMarker->SetMapper(sphereMapper);
  m_PathMarker->GetProperty()->SetColor(1.0, 0.2, 1.0);
  m_PathMarker->SetVisibility(false);
  // The path and its marker lie inside the centerline tubes: a layer of their own draws them over the scene.
  vtkNew<vtkRenderer> overlay;
  overlay->SetLayer(1);
  overlay->InteractiveOff();
  overlay->SetActiveCamera(m_Renderer->GetActiveCamera());
  m_RenderWindow->SetNumberOfLayers(2);
  m_RenderWindow->AddRenderer(overlay);
  overlay->AddActor(m_PathMarker);
  m_Path = vtkSmartPointer<vtkActor>::New();
  vtkNew<vtkPolyDataMapper> pathMapper;
  m_Path->SetMapper(pathMapper);
  m_Path->GetProperty()->SetColor(1.0, 0.9, 0.2);
  m_Path->GetProperty()->SetLineWidth(3.0);
  m_Path->SetVisibility(false);
  overlay->AddActor(m_Path);
  m_Plane = vtkSmartPointer<vtkActor>::New();
  m_Plane->GetProperty()->SetColor(0.35, 0.75, 1.0);
  m_Plane->GetProperty()->SetLineWidth(1.5);
  m_Plane->SetVisibility(false);
  m_Renderer->AddActor(m_Plane);

  vtkNew<vtkInteractorStyleTrackballCamera> style;
  m_Widget->interactor()->SetInteractorStyle(style);
  vtkNew<vtkCallbackCommand> onStart;
  onStart->SetClientData(this);
  onStart->SetCallback(
    [](vtkObject *, unsigned long, void * self, void *)
    {
      auto * view = static_cast<ThreeDView *>(self);
      view->m_Orbiting = true;
      view->ChooseSurface();
    });
  vtkNew<vtkCallbackCommand> onEnd;
  onEnd->SetClientData(this);
  onEnd->SetCallback(
    [](vtkObject *, unsigned long, void * self, void *)
    {
      auto * view = static_cast<ThreeDView *>(self);
      view->m_Orbiting = false;
      view->ChooseSurface();
      view->ScheduleRender();
    });
  style->AddObserver(vtkCommand::StartInteractionEvent, onStart);
  style->AddObserver(vtkCommand::EndInteractionEvent, onEnd);
  setMinimumSize(200, 200);
}

ThreeDView::~ThreeDView() = default;

void
ThreeDView::SetInputs(std::shared_ptr<const ReformationInputs> inputs)
{
  m_Inputs = std::move(inputs);
  // The result on screen belongs to the old data: the camera is fitted to the new data now and again to the new
  // data's first result (its view direction), not to the old one's.
  m_Result.reset();
  m_CameraSet = false;
  if (!m_Inputs)
  {
    return;
  }
  // The volume's outline: the corners of its voxel grid through the node's IJK->RAS matrix.
  vtkImageData * image = m_Inputs->Volume->GetImageData();
  int            extent[6];
  image->GetExtent(extent);
  vtkMatrix4x4 * ijkToRAS = m_Inputs->Volume->GetIJKToRASMatrix();
  double         corners[24];
  for (int corner = 0; corner < 8; ++corner)
  {
    const double ijk[4] = { (corner & 1 ? extent[1] + 0.5 : extent[0] - 0.5),
                            (corner & 2 ? extent[3] + 0.5 : extent[2] - 0.5),
                            (corner & 4 ? extent[5] + 0.5 : extent[4] - 0.5),
                            1.0 };
    double       ras[4];
    ijkToRAS->MultiplyPoint(ijk, ras);
    std::copy(ras, ras + 3, corners + 3 * corner);
  }
  vtkNew<vtkOutlineSource> outline;
  outline->SetBoxTypeToOriented();
  outline->SetCorners(corners);
  outline->Update();
  vtkNew<vtkPolyDataMapper> outlineMapper;
  outlineMapper->SetInputData(outline->GetOutput());
  m_Outline->SetMapper(outlineMapper);
  m_Outline->SetVisibility(true);

  // Tubes of the lumen radius along the centerlines (radius 1 mm where the centerlines carry none).
  vtkNew<vtkPolyData> lines;
  if (m_Inputs->Centerlines)
  {
    lines->ShallowCopy(m_Inputs->Centerlines->GetPolyData());
  }
  vtkNew<vtkTubeFilter> tubes;
  tubes->SetInputData(lines);
  tubes->SetNumberOfSides(10);
  tubes->SetRadius(1.0);
  tubes->CappingOn();
  if (vtkDataArray * radius = lines->GetPointData()->GetArray("Radius"))
  {
    lines->GetPointData()->SetScalars(radius);
    tubes->SetVaryRadiusToVaryRadiusByAbsoluteScalar();
  }
  tubes->Update();
  int maximumId = 1;
  for (const auto & branch : m_Inputs->Tree.GetBranches())
  {
    maximumId = std::max(maximumId, branch.Id);
  }
  vtkNew<vtkPolyDataMapper> tubeMapper;
  tubeMapper->SetInputData(tubes->GetOutput());
  tubeMapper->SetLookupTable(MakeBranchLookupTable(maximumId, 1.0));
  tubeMapper->UseLookupTableScalarRangeOn();
  tubeMapper->SetScalarModeToUseCellFieldData();
  tubeMapper->SelectColorArray("BranchIds");
  tubeMapper->ScalarVisibilityOn();
  m_Tubes->SetMapper(tubeMapper);
  m_Tubes->SetVisibility(true);
  m_Surface->SetVisibility(false);
  m_Arrow->SetVisibility(false);
  m_Plane->SetVisibility(false);
  ResetCamera();
}

vtkPolyData *
ThreeDView::GetTubes() const
{
  auto * mapper = vtkPolyDataMapper::SafeDownCast(m_Tubes->GetMapper());
  return mapper != nullptr ? mapper->GetInput() : nullptr;
}

void
ThreeDView::SetResult(std::shared_ptr<const ReformationResult> result)
{
  if (!result)
  {
    return;
  }
  if (result->Inputs != m_Inputs)
  {
    SetInputs(result->Inputs);
  }
  m_Result = std::move(result);
  ChooseSurface();
  UpdateViewDirection();
  if (!m_CameraSet)
  {
    ResetCamera();
  }
}

void
ThreeDView::SetWindowLevel(double window, double level)
{
  if (!(window > 0.0) || !std::isfinite(level))
  {
    return;
  }
  m_Grey->SetTableRange(level - 0.5 * window, level + 0.5 * window);
  m_Grey->Build();
}

void
ThreeDView::SetInteracting(bool interacting)
{
  if (interacting == m_Interacting)
  {
    return;
  }
  m_Interacting = interacting;
  ChooseSurface();
}

bool
ThreeDView::IsShowingFullSurface() const
{
  return m_Result && m_Result->Outputs.Surface && m_SurfaceMapper->GetInput() == m_Result->Outputs.Surface.GetPointer();
}

void
ThreeDView::ChooseSurface()
{
  if (!m_Result)
  {
    return;
  }
  vtkPolyData * surface = m_Result->Outputs.Surface;
  if (surface == nullptr || IsInteracting())
  {
    surface = m_Result->PreviewSurface;
  }
  if (surface == nullptr)
  {
    m_Surface->SetVisibility(false);
    return;
  }
  if (m_SurfaceMapper->GetInput() != surface)
  {
    m_SurfaceMapper->SetInputData(surface);
  }
  m_Surface->SetVisibility(true);
}

void
ThreeDView::UpdateViewDirection()
{
  const auto & view = m_Result->Outputs.View;
  // The view plane's edges (the CPR's border at depth 0) and an arrow along the view direction v towards the centre.
  const double      W = static_cast<double>(view.GetSize()[0]);
  const double      H = static_cast<double>(view.GetSize()[1]);
  vtkNew<vtkPoints> points;
  const double      corners[4][2] = { { -0.5, -0.5 }, { W - 0.5, -0.5 }, { W - 0.5, H - 0.5 }, { -0.5, H - 0.5 } };
  for (const auto & corner : corners)
  {
    const auto ras = ToRAS(view.PlanePoint(corner[0], corner[1]));
    points->InsertNextPoint(ras[0], ras[1], ras[2]);
  }
  vtkNew<vtkCellArray> loop;
  const vtkIdType      ids[5] = { 0, 1, 2, 3, 0 };
  loop->InsertNextCell(5, ids);
  vtkNew<vtkPolyData> plane;
  plane->SetPoints(points);
  plane->SetLines(loop);
  vtkNew<vtkPolyDataMapper> planeMapper;
  planeMapper->SetInputData(plane);
  m_Plane->SetMapper(planeMapper);
  m_Plane->SetVisibility(true);

  const double length = 0.3 * std::max(W * view.GetSpacing()[0], H * view.GetSpacing()[1]);
  const auto   v = DirectionToRAS(view.GetV());
  const auto   up = DirectionToRAS(view.GetUp());
  const auto   center = ToRAS(view.GetCenter());
  // The arrow's own frame: x along v, y along up, z = x cross y; it ends a little before the plane's centre.
  const double         z[3] = { v[1] * up[2] - v[2] * up[1], v[2] * up[0] - v[0] * up[2], v[0] * up[1] - v[1] * up[0] };
  const double         start[3] = { center[0] - 2.0 * length * v[0],
                                    center[1] - 2.0 * length * v[1],
                                    center[2] - 2.0 * length * v[2] };
  vtkNew<vtkMatrix4x4> matrix;
  for (int r = 0; r < 3; ++r)
  {
    matrix->SetElement(r, 0, length * v[r]);
    matrix->SetElement(r, 1, length * up[r]);
    matrix->SetElement(r, 2, length * z[r]);
    matrix->SetElement(r, 3, start[r]);
  }
  if (m_Arrow->GetMapper() == nullptr)
  {
    vtkNew<vtkArrowSource> arrow;
    arrow->SetTipResolution(24);
    arrow->SetShaftResolution(24);
    arrow->SetShaftRadius(0.04);
    arrow->SetTipRadius(0.1);
    arrow->SetTipLength(0.3);
    vtkNew<vtkPolyDataMapper> arrowMapper;
    arrowMapper->SetInputConnection(arrow->GetOutputPort());
    m_Arrow->SetMapper(arrowMapper);
  }
  m_Arrow->SetUserMatrix(matrix);
  m_Arrow->SetVisibility(true);
}

void
ThreeDView::ResetCamera()
{
  // Look along the view direction (anterior to posterior before a result).
  std::array<double, 3> v = { 0.0, 1.0, 0.0 };
  std::array<double, 3> up = { 0.0, 0.0, 1.0 };
  if (m_Result)
  {
    v = DirectionToRAS(m_Result->Outputs.View.GetV());
    up = DirectionToRAS(m_Result->Outputs.View.GetUp());
    m_CameraSet = true;
  }
  ResetCameraAlong(v, up);
}

void
ThreeDView::ResetCameraForAngle(double angleInDegrees)
{
  if (!m_Result)
  {
    ResetCamera();
    return;
  }
  // The view direction at that angle: the shown view's v turned about up by the difference (docs/design.md, "View":
  // the angle turns u and v about up by the right-hand rule), before the view at that angle is computed.
  const auto & view = m_Result->Outputs.View;
  const auto   v = view.GetV();
  const auto   up = view.GetUp();
  const double turn = (angleInDegrees - view.GetAngleInDegrees()) * 3.14159265358979323846 / 180.0;
  const auto   across = itk::CrossProduct(up, v);
  const auto   turned = v * std::cos(turn) + across * std::sin(turn) + up * ((up * v) * (1.0 - std::cos(turn)));
  m_CameraSet = true;
  ResetCameraAlong(DirectionToRAS(turned), DirectionToRAS(up));
}

std::array<double, 3>
ThreeDView::GetCameraDirection() const
{
  std::array<double, 3> direction{};
  m_Renderer->GetActiveCamera()->GetDirectionOfProjection(direction.data());
  return direction;
}

void
ThreeDView::ResetCameraAlong(const std::array<double, 3> & v, const std::array<double, 3> & up)
{
  if (!m_Inputs)
  {
    return;
  }
  double bounds[6];
  m_Outline->GetBounds(bounds);
  const double center[3] = { 0.5 * (bounds[0] + bounds[1]),
                             0.5 * (bounds[2] + bounds[3]),
                             0.5 * (bounds[4] + bounds[5]) };
  // Turned 30 degrees about up and raised 10, so that the cut surface's relief shows.
  vtkCamera * camera = m_Renderer->GetActiveCamera();
  camera->SetFocalPoint(center);
  camera->SetPosition(center[0] - v[0], center[1] - v[1], center[2] - v[2]);
  camera->SetViewUp(up.data());
  camera->Azimuth(30.0);
  camera->Elevation(10.0);
  camera->OrthogonalizeViewUp();
  m_Renderer->ResetCamera(bounds);
  camera->Zoom(1.1);
}

std::array<double, 3>
ThreeDView::GetCameraFocalPoint() const
{
  std::array<double, 3> focal{};
  m_Renderer->GetActiveCamera()->GetFocalPoint(focal.data());
  return focal;
}

void
ThreeDView::ScheduleRender()
{
  if (m_RenderScheduled)
  {
    return;
  }
  m_RenderScheduled = true;
  int delay = 0;
  if (m_Interacting)
  {
    const auto since =
      std::chrono::duration_cast<std::chrono::milliseconds>(std::chrono::steady_clock::now() - m_LastRenderTime)
        .count();
    delay = static_cast<int>(std::max<long long>(0, InteractiveRenderIntervalMilliseconds - since));
  }
  QTimer::singleShot(delay,
                     this,
                     [this]
                     {
                       m_RenderScheduled = false;
                       Render();
                     });
}

void
ThreeDView::Render()
{
  m_Renderer->ResetCameraClippingRange();
  const auto start = std::chrono::steady_clock::now();
  m_RenderWindow->Render();
  m_LastRenderTime = std::chrono::steady_clock::now();
  m_LastRenderSeconds = std::chrono::duration<double>(m_LastRenderTime - start).count();
  vtkPolyData * drawn = m_Surface->GetVisibility() ? vtkPolyData::SafeDownCast(m_SurfaceMapper->GetInput()) : nullptr;
  m_LastRenderedPoints = drawn != nullptr ? drawn->GetNumberOfPoints() : 0;
  emit rendered(m_LastRenderSeconds, IsShowingFullSurface());
}
void
ThreeDView::SetPathMarker(const std::optional<itk::Point<double, 3>> & lps)
{
  if (lps)
  {
    const auto ras = ToRAS(*lps);
    m_PathMarker->SetPosition(ras[0], ras[1], ras[2]);
  }
  m_PathMarker->SetVisibility(lps.has_value());
  ScheduleRender();
}

void
ThreeDView::SetPath(const std::vector<itk::Point<double, 3>> & lps)
{
  vtkNew<vtkPoints>      points;
  std::vector<vtkIdType> ids;
  for (const auto & point : lps)
  {
    const auto ras = ToRAS(point);
    ids.push_back(points->InsertNextPoint(ras[0], ras[1], ras[2]));
  }
  vtkNew<vtkCellArray> lines;
  if (ids.size() >= 2)
  {
    lines->InsertNextCell(static_cast<vtkIdType>(ids.size()), ids.data());
  }
  vtkNew<vtkPolyData> path;
  path->SetPoints(points);
  path->SetLines(lines);
  vtkPolyDataMapper::SafeDownCast(m_Path->GetMapper())->SetInputData(path);
  m_Path->SetVisibility(ids.size() >= 2);
  ScheduleRender();
}

std::optional<std::array<double, 3>>
ThreeDView::GetPathMarkerPosition() const
{
  if (!m_PathMarker->GetVisibility())
  {
    return std::nullopt;
  }
  const double * position = m_PathMarker->GetPosition();
  return std::array<double, 3>{ { position[0], position[1], position[2] } };
}
} // namespace vr
