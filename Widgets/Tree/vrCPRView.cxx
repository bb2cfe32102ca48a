// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrCPRView.h"

#include "vrBranchColors.h"
#include "vrCenterlineOverlay.h"
#include "vrFilterSettingsText.h"
#include "vrOpenGLRenderer.h"
#include "vrWindowLevel.h"

#include <QEvent>
#include <QKeyEvent>
#include <QMouseEvent>
#include <QTimer>
#include <QVBoxLayout>
#include <QVTKOpenGLNativeWidget.h>
#include <QWheelEvent>

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkFloatArray.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkImageActor.h>
#include <vtkImageData.h>
#include <vtkImageProperty.h>
#include <vtkImageSliceMapper.h>
#include <vtkLookupTable.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkCoordinate.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>
#include <vtkUnsignedCharArray.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>

namespace vr
{
namespace
{
// Distances towards the camera (which looks along +z) that stack the layers over the image.
constexpr double DepthLayerZ = -0.1;
constexpr double LabelLayerZ = -0.2;
constexpr double MaskLayerZ = -0.3;
constexpr double LineLayerZ = -0.5;
constexpr double CameraDistance = 1000.0;
/** The upper corners' font size, and the smallest it shrinks to in a narrow view (FitCornerTexts). */
constexpr int CornerFontSize = 14;
constexpr int MinimumCornerFontSize = 9;
/** The caption's font size, and the smallest it shrinks to where moving it left is not enough (FitCaption). */
constexpr int CaptionFontSize = 15;
constexpr int MinimumCaptionFontSize = 10;
/** Display pixels kept free between a caption and the view's edges. */
constexpr double CaptionMargin = 4.0;

/** Shares the pixels of a one-slice output node, placed at world (origin + i sx, origin + j sy). */
void
Wrap(vtkImageData * target, VolumeNode * node, const double spacing[2], const double origin[2])
{
  if (node == nullptr || node->GetImageData() == nullptr)
  {
    target->Initialize();
    return;
  }
  target->ShallowCopy(node->GetImageData());
  target->SetOrigin(origin[0], origin[1], 0.0);
  target->SetSpacing(spacing[0], spacing[1], 1.0);
}

/** \a values through window/level into \a grey, on the same grid: the bytes vr::WindowLevelToByte makes, which a saved
 * PNG holds too. The image actor shows them as they are (window 255, level 127.5), so that the screen and the PNG
 * agree to the grey level; VTK's own window/level of the float image rounds otherwise. */
void
MapToGrey(vtkImageData * values, vtkImageData * grey, double window, double level)
{
  vtkDataArray * scalars = values->GetPointData() ? values->GetPointData()->GetScalars() : nullptr;
  if (scalars == nullptr)
  {
    grey->Initialize();
    return;
  }
  grey->SetExtent(values->GetExtent());
  grey->SetOrigin(values->GetOrigin());
  grey->SetSpacing(values->GetSpacing());
  grey->AllocateScalars(VTK_UNSIGNED_CHAR, 1);
  auto *          bytes = static_cast<unsigned char *>(grey->GetScalarPointer());
  const vtkIdType count = scalars->GetNumberOfTuples();
  if (auto * floats = vtkFloatArray::SafeDownCast(scalars))
  {
    WindowLevelToBytes(floats->GetPointer(0), static_cast<std::size_t>(count), window, level, bytes);
    return;
  }
  for (vtkIdType k = 0; k < count; ++k)
  {
    bytes[k] = WindowLevelToByte(scalars->GetComponent(k, 0), window, level);
  }
}

void
ConfigureOverlay(vtkImageActor * actor, vtkLookupTable * table, double opacity)
{
  vtkImageProperty * property = actor->GetProperty();
  property->SetLookupTable(table);
  property->UseLookupTableScalarRangeOn();
  property->SetInterpolationTypeToNearest();
  property->SetOpacity(opacity);
}

std::string
Format(double value, int decimals)
{
  std::ostringstream text;
  text.setf(std::ios::fixed);
  text.precision(decimals);
  text << value;
  // A component that rounds to zero is shown as 0, not "-0.00": a sign there reads as a direction.
  std::string shown = text.str();
  if (shown.front() == '-' && shown.find_first_not_of("-0.") == std::string::npos)
  {
    shown.erase(0, 1);
  }
  return shown;
}

} // namespace

/** One image of the comparison (filtered or unfiltered) with its overlays. */
struct CPRView::Pane
{
  /** The logic's CPR (its float pixels) and what the image actor draws: those pixels through window/level. */
  vtkNew<vtkImageData>  Image;
  vtkNew<vtkImageData>  Grey;
  vtkNew<vtkImageData>  Depth;
  vtkNew<vtkImageData>  Mask;
  vtkNew<vtkImageData>  Labels;
  vtkNew<vtkImageActor> ImageActor;
  vtkNew<vtkImageActor> DepthActor;
  vtkNew<vtkImageActor> MaskActor;
  vtkNew<vtkImageActor> LabelActor;
  vtkNew<vtkActor>      Lines;
  vtkNew<vtkTextActor>  Caption;
  double                Offset{ 0.0 };

  Pane()
  {
    ImageActor->GetMapper()->SetInputData(Grey);
    DepthActor->GetMapper()->SetInputData(Depth);
    MaskActor->GetMapper()->SetInputData(Mask);
    LabelActor->GetMapper()->SetInputData(Labels);
    // Edge pixels whole, as in a saved PNG (VTK otherwise draws from the first pixel's centre to the last one's).
    for (vtkImageActor * actor : { ImageActor.Get(), DepthActor.Get(), MaskActor.Get(), LabelActor.Get() })
    {
      actor->GetMapper()->BorderOn();
    }
    ImageActor->GetProperty()->SetInterpolationTypeToNearest();
    // The identity on bytes: the grey values are MapToGrey's.
    ImageActor->GetProperty()->SetColorWindow(255.0);
    ImageActor->GetProperty()->SetColorLevel(127.5);
    Caption->GetTextProperty()->SetFontSize(CaptionFontSize);
    Caption->GetTextProperty()->SetColor(1.0, 1.0, 1.0);
    Caption->GetTextProperty()->ShadowOn();
    Caption->GetTextProperty()->SetVerticalJustificationToTop();
    Caption->GetPositionCoordinate()->SetCoordinateSystemToWorld();
  }

  void
  AddTo(vtkRenderer * renderer)
  {
    for (vtkProp * prop :
         std::initializer_list<vtkProp *>{ ImageActor, DepthActor, LabelActor, MaskActor, Lines, Caption })
    {
      renderer->AddViewProp(prop);
    }
  }

  void
  Place(double offset)
  {
    Offset = offset;
    ImageActor->SetPosition(offset, 0.0, 0.0);
    DepthActor->SetPosition(offset, 0.0, DepthLayerZ);
    LabelActor->SetPosition(offset, 0.0, LabelLayerZ);
    MaskActor->SetPosition(offset, 0.0, MaskLayerZ);
    Lines->SetPosition(offset, 0.0, LineLayerZ);
  }

  void
  SetColumns(int first, int last)
  {
    for (vtkImageActor * actor :
         { ImageActor.GetPointer(), DepthActor.GetPointer(), LabelActor.GetPointer(), MaskActor.GetPointer() })
    {
      if (last < first)
      {
        actor->SetVisibility(false);
        continue;
      }
      int extent[6];
      Image->GetExtent(extent);
      actor->SetDisplayExtent(first, last, extent[2], extent[3], 0, 0);
    }
  }
};

CPRView::CPRView(QWidget * parent)
  : QWidget(parent)
  , m_Filtered(std::make_unique<Pane>())
  , m_Unfiltered(std::make_unique<Pane>())
{
  m_Widget = new QVTKOpenGLNativeWidget(this);
  auto * layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->addWidget(m_Widget);
  m_RenderWindow = vtkSmartPointer<vtkGenericOpenGLRenderWindow>::New();
  m_RenderWindow->SetMultiSamples(ViewMultiSamples());
  m_Widget->setRenderWindow(m_RenderWindow);
  m_Renderer = vtkSmartPointer<vtkRenderer>::New();
  m_Renderer->SetBackground(0.08, 0.08, 0.1);
  m_RenderWindow->AddRenderer(m_Renderer);
  vtkCamera * camera = m_Renderer->GetActiveCamera();
  camera->ParallelProjectionOn();
  camera->SetViewUp(0.0, -1.0, 0.0);

  m_Unfiltered->AddTo(m_Renderer);
  m_Filtered->AddTo(m_Renderer);
  m_CenterlinePolyData = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPolyDataMapper> lineMapper;
  lineMapper->SetInputData(m_CenterlinePolyData);
  lineMapper->SetScalarModeToUseCellData();
  for (Pane * pane : { m_Filtered.get(), m_Unfiltered.get() })
  {
    pane->Lines->SetMapper(lineMapper);
    pane->Lines->GetProperty()->SetLineWidth(1.5);
    pane->Lines->GetProperty()->SetOpacity(0.9);
  }

  m_PathMarkerActor = vtkSmartPointer<vtkActor>::New();
  vtkNew<vtkPolyDataMapper> markerMapper;
  m_PathMarkerActor->SetMapper(markerMapper);
  m_PathMarkerActor->GetProperty()->SetColor(1.0, 0.2, 1.0);
  m_PathMarkerActor->GetProperty()->SetLineWidth(2.5);
  m_PathMarkerActor->SetVisibility(false);
  m_Renderer->AddViewProp(m_PathMarkerActor);

  m_SplitLine = vtkSmartPointer<vtkActor>::New();
  m_SplitLine->GetProperty()->SetColor(1.0, 1.0, 1.0);
  m_SplitLine->GetProperty()->SetLineWidth(1.0);
  m_Renderer->AddViewProp(m_SplitLine);

  // Two text actors of one font size in the upper corners. (vtkCornerAnnotation fits its font size to the view
  // by rendering the text at several sizes whenever it changes: at every angle that took half the CPR view's frame.)
  for (auto * corner : { &m_UpperLeftText, &m_UpperRightText })
  {
    *corner = vtkSmartPointer<vtkTextActor>::New();
    vtkTextProperty * text = (*corner)->GetTextProperty();
    text->SetFontSize(CornerFontSize);
    text->SetColor(0.95, 0.95, 0.95);
    text->ShadowOn();
    text->SetVerticalJustificationToTop();
    (*corner)->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
    m_Renderer->AddViewProp(*corner);
  }
  m_UpperLeftText->GetTextProperty()->SetJustificationToLeft();
  m_UpperLeftText->GetPositionCoordinate()->SetValue(0.01, 0.99);
  m_UpperRightText->GetTextProperty()->SetJustificationToRight();
  m_UpperRightText->GetPositionCoordinate()->SetValue(0.99, 0.99);
  m_UpperLeftText->SetInput("No reformation yet");
  // A preview says so where the eye is (lower right, away from the captions under the image), in amber.
  m_PreviewText = vtkSmartPointer<vtkTextActor>::New();
  m_PreviewText->GetTextProperty()->SetFontSize(16);
  m_PreviewText->GetTextProperty()->SetColor(1.0, 0.75, 0.2);
  m_PreviewText->GetTextProperty()->BoldOn();
  m_PreviewText->GetTextProperty()->ShadowOn();
  m_PreviewText->GetTextProperty()->SetJustificationToRight();
  m_PreviewText->GetTextProperty()->SetVerticalJustificationToBottom();
  m_PreviewText->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
  m_PreviewText->GetPositionCoordinate()->SetValue(0.99, 0.01);
  m_PreviewText->SetVisibility(false);
  m_Renderer->AddViewProp(m_PreviewText);

  m_Widget->setMouseTracking(true);
  m_Widget->installEventFilter(this);
  connect(m_Widget,
          &QOpenGLWidget::frameSwapped,
          this,
          [this]
          {
            if (m_HasPendingDisplay)
            {
              m_HasPendingDisplay = false;
              emit imageDisplayed(m_PendingDisplay);
            }
          });
  setMinimumSize(200, 200);
  UpdatePanes();
}

CPRView::~CPRView() = default;

void
CPRView::SetResult(std::shared_ptr<const ReformationResult> result)
{
  if (!result || !result->Outputs.CPR)
  {
    return;
  }
  const auto & view = result->Outputs.View;
  // The frame is the full view's: a preview lies over the same millimetres and keeps the camera where it is.
  const auto & frame = result->IsPreview() ? result->FullView : view;
  const int    frameWidth = static_cast<int>(frame.GetSize()[0]);
  const int    frameHeight = static_cast<int>(frame.GetSize()[1]);
  const bool   refit = frameWidth != m_FrameSize[0] || frameHeight != m_FrameSize[1] ||
                     frame.GetSpacing()[0] != m_FrameSpacing[0] || frame.GetSpacing()[1] != m_FrameSpacing[1] ||
                     !m_Result;
  // Hidden stretches come with a new depth map (its hidden labels): the overlay follows.
  const bool newCenterlines = !m_Result || m_Result->Inputs != result->Inputs || m_Result->Outputs.View != view ||
                              m_Result->Outputs.HiddenLabels != result->Outputs.HiddenLabels;
  m_Result = std::move(result);
  m_ImageSize[0] = static_cast<int>(view.GetSize()[0]);
  m_ImageSize[1] = static_cast<int>(view.GetSize()[1]);
  m_Spacing[0] = view.GetSpacing()[0];
  m_Spacing[1] = view.GetSpacing()[1];
  m_FrameSize[0] = frameWidth;
  m_FrameSize[1] = frameHeight;
  m_FrameSpacing[0] = frame.GetSpacing()[0];
  m_FrameSpacing[1] = frame.GetSpacing()[1];
  for (int axis = 0; axis < 2; ++axis)
  {
    // Both grids are centred on the view's centre C (pixel i at (i - (W - 1) / 2) s mm from it).
    m_Origin[axis] =
      0.5 * (m_FrameSize[axis] - 1) * m_FrameSpacing[axis] - 0.5 * (m_ImageSize[axis] - 1) * m_Spacing[axis];
  }

  const auto & outputs = m_Result->Outputs;
  Wrap(m_Filtered->Image, outputs.CPR, m_Spacing, m_Origin);
  Wrap(m_Filtered->Depth, outputs.RelaxedDepth, m_Spacing, m_Origin);
  Wrap(m_Filtered->Mask, outputs.FixedMask, m_Spacing, m_Origin);
  Wrap(m_Filtered->Labels, outputs.OwnerLabels, m_Spacing, m_Origin);
  Wrap(m_Unfiltered->Image, outputs.UnfilteredCPR, m_Spacing, m_Origin);
  Wrap(m_Unfiltered->Depth, outputs.Depth, m_Spacing, m_Origin);
  Wrap(m_Unfiltered->Mask, outputs.FixedMask, m_Spacing, m_Origin);
  Wrap(m_Unfiltered->Labels, outputs.OwnerLabels, m_Spacing, m_Origin);
  UpdateGrey();
  if (newCenterlines)
  {
    UpdateCenterlines();
  }
  UpdatePathMarker();
  UpdateOverlays();
  UpdatePanes();
  if (refit)
  {
    FitImage();
  }
  m_PendingDisplay = m_Result->RequestId;
  m_HasPendingDisplay = true;
  Render();
  m_Widget->update();
}

void
CPRView::SetWindowLevel(double window, double level)
{
  if (!(window > 0.0) || !std::isfinite(window) || !std::isfinite(level))
  {
    return;
  }
  m_Window = window;
  m_Level = level;
  UpdateGrey();
  UpdateAnnotation();
  Render();
}

void
CPRView::UpdateGrey()
{
  for (Pane * pane : { m_Filtered.get(), m_Unfiltered.get() })
  {
    MapToGrey(pane->Image, pane->Grey, m_Window, m_Level);
  }
}

void
CPRView::SetOverlays(const CPROverlays & overlays)
{
  m_Overlays = overlays;
  UpdateOverlays();
  UpdatePanes();
  Render();
}

void
CPRView::SetComparison(CPRComparison comparison)
{
  const bool refit = (comparison == CPRComparison::SideBySide) != (m_Comparison == CPRComparison::SideBySide);
  m_Comparison = comparison;
  UpdatePanes();
  if (refit)
  {
    FitImage();
  }
  Render();
}

double
CPRView::UnfilteredOffset() const
{
  if (m_Comparison != CPRComparison::SideBySide)
  {
    return 0.0;
  }
  const double width = m_FrameSize[0] * m_FrameSpacing[0];
  return -(width + std::max(4.0 * m_FrameSpacing[0], 0.04 * width));
}

void
CPRView::UpdatePanes()
{
  const bool hasImage = m_Result != nullptr;
  const int  width = m_ImageSize[0];
  bool       showFiltered = hasImage && m_Comparison != CPRComparison::Unfiltered;
  bool       showUnfiltered = hasImage && m_Comparison != CPRComparison::Filtered;
  m_Filtered->Place(0.0);
  m_Unfiltered->Place(UnfilteredOffset());
  if (m_Comparison == CPRComparison::Split)
  {
    m_Unfiltered->SetColumns(0, width / 2 - 1);
    m_Filtered->SetColumns(width / 2, width - 1);
  }
  else
  {
    m_Unfiltered->SetColumns(0, width - 1);
    m_Filtered->SetColumns(0, width - 1);
  }
  auto show = [this](Pane * pane, bool visible, bool lines)
  {
    pane->ImageActor->SetVisibility(visible);
    pane->DepthActor->SetVisibility(visible && m_Overlays.DepthMap);
    pane->LabelActor->SetVisibility(visible && m_Overlays.OwnerLabels);
    pane->MaskActor->SetVisibility(visible && m_Overlays.FixedMask);
    pane->Lines->SetVisibility(visible && lines && m_Overlays.Centerlines);
    pane->Caption->SetVisibility(visible);
  };
  // In the split both images share one grid, so one set of centerlines serves both halves.
  show(m_Filtered.get(), showFiltered, true);
  show(m_Unfiltered.get(), showUnfiltered, m_Comparison != CPRComparison::Split);

  const double sx = m_Spacing[0];
  if (m_Comparison == CPRComparison::Split && hasImage)
  {
    vtkNew<vtkPolyData> line;
    vtkNew<vtkPoints>   points;
    const double        x = m_Origin[0] + (width / 2 - 0.5) * sx;
    points->InsertNextPoint(x, -0.5 * m_FrameSpacing[1], LineLayerZ);
    points->InsertNextPoint(x, (m_FrameSize[1] - 0.5) * m_FrameSpacing[1], LineLayerZ);
    vtkNew<vtkCellArray> cells;
    const vtkIdType      ids[2] = { 0, 1 };
    cells->InsertNextCell(2, ids);
    line->SetPoints(points);
    line->SetLines(cells);
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputData(line);
    m_SplitLine->SetMapper(mapper);
    m_SplitLine->SetVisibility(true);
  }
  else
  {
    m_SplitLine->SetVisibility(false);
  }

  if (hasImage)
  {
    // Two short lines, so that the caption fits under the image in the side-by-side comparison too.
    const std::string filtered = "bilateral: " + DescribeFilterSettings(m_Result->Parameters, "\n");
    m_CaptionForms = { filtered };
    if (m_Comparison == CPRComparison::Split)
    {
      // One caption for both halves: two captions side by side under half-images overlap. Each half's settings on a
      // line of its own where the view is too narrow for the shorter form (FitCaptions).
      const std::string halves = std::string("left: ") + UnfilteredSettingsText + ";";
      m_CaptionForms = { halves + " right: " + filtered, halves + "\nright: " + filtered };
    }
    m_Filtered->Caption->SetInput(m_CaptionForms.front().c_str());
    m_Unfiltered->Caption->SetInput(UnfilteredSettingsText);
    m_Unfiltered->Caption->SetVisibility(showUnfiltered && m_Comparison != CPRComparison::Split);
    // Below the image, where no corner annotation sits.
    const double below = (m_FrameSize[1] + 0.5) * m_FrameSpacing[1];
    m_Filtered->Caption->GetPositionCoordinate()->SetValue(0.0, below, 0.0);
    m_Unfiltered->Caption->GetPositionCoordinate()->SetValue(UnfilteredOffset(), below, 0.0);
    FitCaptions();
  }
  UpdateAnnotation();
}

void
CPRView::UpdateOverlays()
{
  if (!m_Result)
  {
    return;
  }
  int maximumId = 1;
  if (m_Result->Inputs)
  {
    for (const auto & branch : m_Result->Inputs->Tree.GetBranches())
    {
      maximumId = std::max(maximumId, branch.Id);
    }
  }
  // One depth colour range for both images, so that they compare.
  double range[2] = { 0.0, 1.0 };
  bool   first = true;
  for (vtkImageData * depth : { m_Filtered->Depth.GetPointer(), m_Unfiltered->Depth.GetPointer() })
  {
    if (depth->GetPointData() == nullptr || depth->GetPointData()->GetScalars() == nullptr)
    {
      continue;
    }
    double r[2];
    depth->GetScalarRange(r);
    range[0] = first ? r[0] : std::min(range[0], r[0]);
    range[1] = first ? r[1] : std::max(range[1], r[1]);
    first = false;
  }
  auto                   depthTable = MakeDepthLookupTable(range[0], range[1], 1.0);
  auto                   labelTable = MakeBranchLookupTable(maximumId, 1.0);
  vtkNew<vtkLookupTable> maskTable;
  maskTable->SetNumberOfTableValues(2);
  maskTable->SetTableRange(0.0, 1.0);
  maskTable->SetTableValue(0, 0.0, 0.0, 0.0, 0.0);
  maskTable->SetTableValue(1, 1.0, 0.85, 0.0, 1.0);
  for (Pane * pane : { m_Filtered.get(), m_Unfiltered.get() })
  {
    ConfigureOverlay(pane->DepthActor, depthTable, 0.6);
    ConfigureOverlay(pane->LabelActor, labelTable, 0.4);
    ConfigureOverlay(pane->MaskActor, maskTable, 0.55);
  }
}

void
CPRView::UpdateCenterlines()
{
  m_CenterlinePolyData->Initialize();
  if (!m_Result || !m_Result->Inputs)
  {
    return;
  }
  // Hidden stretches (Visibility mode) dashed: their own file draws them.
  m_CenterlinePolyData->ShallowCopy(BuildCenterlineOverlay(
    m_Result->Inputs->Tree, m_Result->Outputs.View, m_Result->Outputs.BranchOcclusions, m_Origin, m_Spacing));
}

void
CPRView::SetPathMarker(const std::optional<itk::Point<double, 3>> & lps)
{
  m_PathMarker = lps;
  UpdatePathMarker();
  Render();
}

void
CPRView::UpdatePathMarker()
{
  m_PathMarkerWorld.reset();
  if (!m_PathMarker || !m_Result)
  {
    m_PathMarkerActor->SetVisibility(false);
    return;
  }
  // Projected along the view direction as the centerline overlay is: the pixel whose sampling line passes nearest.
  const auto coordinates = m_Result->Outputs.View.ToView(*m_PathMarker);
  const auto world = WorldPositionOfPixel(coordinates.Column, coordinates.Row);
  m_PathMarkerWorld = world;
  const double         arm = 6.0 * std::max(m_FrameSpacing[0], m_FrameSpacing[1]);
  const double         gap = 0.35 * arm;
  vtkNew<vtkPoints>    points;
  vtkNew<vtkCellArray> lines;
  const double         directions[4][2] = { { 1.0, 0.0 }, { -1.0, 0.0 }, { 0.0, 1.0 }, { 0.0, -1.0 } };
  for (const auto & direction : directions)
  {
    const vtkIdType ids[2] = {
      points->InsertNextPoint(world[0] + gap * direction[0], world[1] + gap * direction[1], 1.5 * LineLayerZ),
      points->InsertNextPoint(world[0] + arm * direction[0], world[1] + arm * direction[1], 1.5 * LineLayerZ)
    };
    lines->InsertNextCell(2, ids);
  }
  vtkNew<vtkPolyData> marker;
  marker->SetPoints(points);
  marker->SetLines(lines);
  vtkPolyDataMapper::SafeDownCast(m_PathMarkerActor->GetMapper())->SetInputData(marker);
  m_PathMarkerActor->SetVisibility(true);
}

void
CPRView::UpdateAnnotation()
{
  if (!m_Result)
  {
    return;
  }
  const auto &       view = m_Result->Outputs.View;
  const auto &       up = view.GetUp();
  std::ostringstream upper;
  // Short lines: at 800 x 500 the CPR view is about 360 px wide and the upper right corner needs 110 of them.
  upper << "angle " << Format(view.GetAngleInDegrees(), 1) << " deg\n"
        << "up LPS " << Format(up[0], 2) << ", " << Format(up[1], 2) << ", " << Format(up[2], 2) << "\n"
        << "W " << Format(m_Window, 0) << "  L " << Format(m_Level, 0);
  m_UpperLeftText->SetInput(upper.str().c_str());
  std::ostringstream right;
  right << view.GetSize()[0] << " x " << view.GetSize()[1] << " px\n"
        << Format(view.GetSpacing()[0], 2) << " x " << Format(view.GetSpacing()[1], 2) << " mm";
  m_UpperRightText->SetInput(right.str().c_str());
  FitCornerTexts();
  const unsigned int factor = m_Result->PreviewFactor;
  m_PreviewText->SetVisibility(factor > 1);
  if (factor > 1)
  {
    m_PreviewText->SetInput(("preview (1/" + std::to_string(factor) + " resolution)").c_str());
  }
}

/** The upper corners' font: the largest size, from CornerFontSize down to MinimumCornerFontSize, at which the two
 * blocks fit side by side in the view's width. A narrow view (about 240 px at 800 x 500) would otherwise draw the
 * right block over the left one's widest line. */
void
CPRView::FitCornerTexts()
{
  if (!m_Renderer->GetRenderWindow())
  {
    return;
  }
  // Between the blocks' 1 % margins, and a gap of 8 px.
  const double room = 0.98 * m_Widget->width() * m_Widget->devicePixelRatioF() - 8.0;
  for (int size = CornerFontSize; size >= MinimumCornerFontSize; --size)
  {
    m_UpperLeftText->GetTextProperty()->SetFontSize(size);
    m_UpperRightText->GetTextProperty()->SetFontSize(size);
    const auto boxes = GetCornerTextBoxes();
    if ((boxes[0][1] - boxes[0][0]) + (boxes[1][1] - boxes[1][0]) <= room)
    {
      return;
    }
  }
}

/** The captions start under their images' left edges. Where they would leave the view or run into each other (a
 * narrow view: at 240 px the run-off phantom's caption lost "1" of "w = 1", and side by side the two captions
 * overlapped), they move left, as far as the view's left margin, and only then shrink their font, from
 * CaptionFontSize down to MinimumCaptionFontSize; the split view's caption then puts each half's settings on a line
 * of its own. The captions are placed from the right: each as far right as its image, the one to its right and the
 * view allow. */
void
CPRView::FitCaptions()
{
  if (!m_Renderer->GetRenderWindow() || m_FrameSize[1] == 0 || m_CaptionForms.empty())
  {
    return;
  }
  std::vector<Pane *> panes;
  if (m_Comparison == CPRComparison::SideBySide)
  {
    panes.push_back(m_Unfiltered.get());
  }
  panes.push_back(m_Filtered.get());
  const double below = (m_FrameSize[1] + 0.5) * m_FrameSpacing[1];
  const double right = m_Renderer->GetSize()[0] - CaptionMargin;
  // World units per display pixel along x (a parallel projection; world x runs to the right on screen).
  const double perPixel =
    2.0 * m_Renderer->GetActiveCamera()->GetParallelScale() / std::max(1, m_Renderer->GetSize()[1]);
  std::vector<double> start(panes.size());
  auto                place = [&](int size)
  {
    // Right to left: each caption ends before the next one (a gap of CaptionMargin) and before the view's edge.
    double limit = right;
    bool   fitsBelow = true;
    for (std::size_t k = panes.size(); k-- > 0;)
    {
      vtkTextActor * caption = panes[k]->Caption;
      caption->GetTextProperty()->SetFontSize(size);
      caption->GetPositionCoordinate()->SetValue(panes[k]->Offset, below, 0.0);
      const auto box = TextBoxOf(caption);
      start[k] = std::min(box[0], limit - (box[1] - box[0]));
      limit = start[k] - CaptionMargin;
      fitsBelow = fitsBelow && box[2] >= 0.0; // display y runs up from the view's bottom
    }
    return start.front() >= CaptionMargin && fitsBelow;
  };
  auto apply = [&]()
  {
    for (std::size_t k = 0; k < panes.size(); ++k)
    {
      vtkTextActor * caption = panes[k]->Caption;
      const double   natural = TextBoxOf(caption)[0];
      const double   moved = std::max(start[k], CaptionMargin);
      caption->GetPositionCoordinate()->SetValue(panes[k]->Offset + (moved - natural) * perPixel, below, 0.0);
    }
  };
  for (const std::string & form : m_CaptionForms)
  {
    m_Filtered->Caption->SetInput(form.c_str());
    for (int size = CaptionFontSize; size >= MinimumCaptionFontSize; --size)
    {
      if (place(size))
      {
        apply();
        return;
      }
    }
  }
  // Nothing fits: the last form at the smallest size, from the left margin.
  apply();
}

std::array<double, 4>
CPRView::TextBoxOf(vtkTextActor * text) const
{
  // The box about the text's anchor, moved to where the anchor is in the view.
  std::array<double, 4> box{};
  text->GetBoundingBox(m_Renderer, box.data());
  const int * anchor = text->GetPositionCoordinate()->GetComputedDisplayValue(m_Renderer);
  return { box[0] + anchor[0], box[1] + anchor[0], box[2] + anchor[1], box[3] + anchor[1] };
}

std::array<double, 4>
CPRView::GetCaptionBox(bool unfiltered) const
{
  return TextBoxOf((unfiltered ? m_Unfiltered : m_Filtered)->Caption);
}

std::array<std::array<double, 4>, 2>
CPRView::GetCornerTextBoxes() const
{
  return { TextBoxOf(m_UpperLeftText), TextBoxOf(m_UpperRightText) };
}

QString
CPRView::GetPreviewLabel() const
{
  return m_PreviewText->GetVisibility() ? QString::fromUtf8(m_PreviewText->GetInput()) : QString();
}

QString
CPRView::GetCaption(bool unfiltered) const
{
  const char * text = (unfiltered ? m_Unfiltered : m_Filtered)->Caption->GetInput();
  return text ? QString::fromUtf8(text) : QString();
}

void
CPRView::FitImage()
{
  if (m_FrameSize[0] == 0)
  {
    return;
  }
  const double sx = m_FrameSpacing[0];
  const double sy = m_FrameSpacing[1];
  const double left = std::min(0.0, UnfilteredOffset()) - 0.5 * sx;
  const double right = (m_FrameSize[0] - 0.5) * sx;
  const double top = -0.5 * sy;
  const double bottom = (m_FrameSize[1] - 0.5) * sy;
  // Room in screen pixels: above for the corner annotations, below for the captions, a little on the sides.
  const double widthPixels = std::max(50, m_Widget->width() - 16);
  const double heightPixels = std::max(50, m_Widget->height() - 2 * 44);
  const double perPixel = std::max((right - left) / widthPixels, (bottom - top) / heightPixels);
  const double halfHeight = 0.5 * perPixel * m_Widget->height();
  vtkCamera *  camera = m_Renderer->GetActiveCamera();
  const double cx = 0.5 * (left + right);
  const double cy = 0.5 * (top + bottom);
  camera->SetFocalPoint(cx, cy, 0.0);
  camera->SetPosition(cx, cy, -CameraDistance);
  camera->SetViewUp(0.0, -1.0, 0.0);
  camera->SetParallelScale(halfHeight);
  camera->SetClippingRange(1.0, 2.0 * CameraDistance);
  m_ZoomedByUser = false;
  FitCaptions();
}

void
CPRView::Zoom(double factor, const QPointF & center)
{
  if (!(factor > 0.0))
  {
    return;
  }
  const auto  before = WidgetToWorld(center);
  vtkCamera * camera = m_Renderer->GetActiveCamera();
  camera->SetParallelScale(camera->GetParallelScale() / factor);
  const auto after = WidgetToWorld(center);
  double     focal[3];
  camera->GetFocalPoint(focal);
  focal[0] += before[0] - after[0];
  focal[1] += before[1] - after[1];
  camera->SetFocalPoint(focal[0], focal[1], 0.0);
  camera->SetPosition(focal[0], focal[1], -CameraDistance);
  Render();
}

std::array<double, 2>
CPRView::WidgetToWorld(const QPointF & position) const
{
  vtkCamera * camera = m_Renderer->GetActiveCamera();
  double      focal[3];
  camera->GetFocalPoint(focal);
  const double height = std::max(1, m_Widget->height());
  const double perPixel = 2.0 * camera->GetParallelScale() / height;
  return { focal[0] + (position.x() - 0.5 * m_Widget->width()) * perPixel,
           focal[1] + (position.y() - 0.5 * height) * perPixel };
}

QPointF
CPRView::WorldToWidget(double x, double y) const
{
  vtkCamera * camera = m_Renderer->GetActiveCamera();
  double      focal[3];
  camera->GetFocalPoint(focal);
  const double height = std::max(1, m_Widget->height());
  const double perPixel = 2.0 * camera->GetParallelScale() / height;
  return QPointF(0.5 * m_Widget->width() + (x - focal[0]) / perPixel, 0.5 * height + (y - focal[1]) / perPixel);
}

QPointF
CPRView::WidgetPositionOfPixel(double column, double row, bool unfiltered) const
{
  const double offset = unfiltered ? UnfilteredOffset() : 0.0;
  return WorldToWidget(offset + m_Origin[0] + column * m_Spacing[0], m_Origin[1] + row * m_Spacing[1]);
}

PixelReadout
CPRView::ReadoutAt(const QPointF & position) const
{
  if (!m_Result)
  {
    return PixelReadout();
  }
  const auto world = WidgetToWorld(position);
  const int  row = static_cast<int>(std::floor((world[1] - m_Origin[1]) / m_Spacing[1] + 0.5));
  auto       columnIn = [&](double offset)
  { return static_cast<int>(std::floor((world[0] - offset - m_Origin[0]) / m_Spacing[0] + 0.5)); };
  bool unfiltered = false;
  int  column = columnIn(0.0);
  switch (m_Comparison)
  {
    case CPRComparison::Filtered:
      break;
    case CPRComparison::Unfiltered:
      unfiltered = true;
      break;
    case CPRComparison::Split:
      unfiltered = column < m_ImageSize[0] / 2;
      break;
    case CPRComparison::SideBySide:
    {
      const int inLeft = columnIn(UnfilteredOffset());
      if (inLeft >= 0 && inLeft < m_ImageSize[0])
      {
        unfiltered = true;
        column = inLeft;
      }
      break;
    }
  }
  return ReadPixel(*m_Result, unfiltered, column, row);
}

vtkImageData *
CPRView::GetDisplayedImage(bool unfiltered) const
{
  return unfiltered ? m_Unfiltered->Image.GetPointer() : m_Filtered->Image.GetPointer();
}

void
CPRView::Render()
{
  const auto start = std::chrono::steady_clock::now();
  m_RenderWindow->Render();
  m_LastRenderSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

bool
CPRView::eventFilter(QObject * watched, QEvent * event)
{
  if (watched != m_Widget)
  {
    return QWidget::eventFilter(watched, event);
  }
  switch (event->type())
  {
    case QEvent::MouseButtonPress:
    {
      auto * mouse = static_cast<QMouseEvent *>(event);
      if (m_DragButton != Qt::NoButton)
      {
        return true;
      }
      if (mouse->button() == Qt::LeftButton && (mouse->modifiers() & Qt::ControlModifier))
      {
        // Ctrl+click picks a vessel; the plain left-drag keeps turning the view.
        emit vesselPicked(ReadoutAt(mouse->localPos() + QPointF(0.5, 0.5)));
        return true;
      }
      m_DragButton = mouse->button();
      m_DragStart = mouse->localPos();
      m_DragWindow = m_Window;
      m_DragLevel = m_Level;
      m_Renderer->GetActiveCamera()->GetFocalPoint(m_DragFocal);
      if (m_DragButton == Qt::LeftButton)
      {
        emit rotationStarted();
      }
      return true;
    }
    case QEvent::MouseMove:
    {
      auto *        mouse = static_cast<QMouseEvent *>(event);
      const QPointF delta = mouse->localPos() - m_DragStart;
      switch (m_DragButton)
      {
        case Qt::LeftButton:
          emit rotationDragged(DegreesPerPixel * delta.x(), false);
          break;
        case Qt::RightButton:
        {
          const double window = std::max(1e-3, m_DragWindow * (1.0 + delta.x() / 256.0));
          const double level = m_DragLevel - m_DragWindow * delta.y() / 512.0;
          SetWindowLevel(window, level);
          emit windowLevelChanged(window, level);
          break;
        }
        case Qt::MiddleButton:
        {
          vtkCamera *  camera = m_Renderer->GetActiveCamera();
          const double perPixel = 2.0 * camera->GetParallelScale() / std::max(1, m_Widget->height());
          const double x = m_DragFocal[0] - delta.x() * perPixel;
          const double y = m_DragFocal[1] - delta.y() * perPixel;
          camera->SetFocalPoint(x, y, 0.0);
          camera->SetPosition(x, y, -CameraDistance);
          m_ZoomedByUser = true;
          Render();
          break;
        }
        default:
        {
          const PixelReadout readout = ReadoutAt(mouse->localPos() + QPointF(0.5, 0.5));
          if (readout.Inside != m_Readout.Inside || readout.Column != m_Readout.Column ||
              readout.Row != m_Readout.Row || readout.Unfiltered != m_Readout.Unfiltered)
          {
            m_Readout = readout;
            emit readoutChanged(m_Readout);
          }
          break;
        }
      }
      return true;
    }
    case QEvent::MouseButtonRelease:
    {
      auto * mouse = static_cast<QMouseEvent *>(event);
      if (mouse->button() != m_DragButton)
      {
        return true;
      }
      if (m_DragButton == Qt::LeftButton)
      {
        emit rotationDragged(DegreesPerPixel * (mouse->localPos().x() - m_DragStart.x()), true);
      }
      m_DragButton = Qt::NoButton;
      return true;
    }
    case QEvent::MouseButtonDblClick:
      FitImage();
      Render();
      return true;
    case QEvent::KeyPress:
      // VTK's own "r" would reset the camera to the actors' bounds, captions included: fit as a double-click does.
      if (static_cast<QKeyEvent *>(event)->key() == Qt::Key_R)
      {
        FitImage();
        Render();
        return true;
      }
      return false;
    case QEvent::Wheel:
    {
      auto * wheel = static_cast<QWheelEvent *>(event);
      Zoom(std::pow(1.2, wheel->angleDelta().y() / 120.0), wheel->position());
      m_ZoomedByUser = true;
      return true;
    }
    case QEvent::Leave:
      if (m_Readout.Inside)
      {
        m_Readout = PixelReadout();
        emit readoutChanged(m_Readout);
      }
      return false;
    case QEvent::Resize:
      // Keep the image fitted when the widget changes size, unless the user zoomed or panned since the last fit. The
      // render window takes the widget's new size in the widget's own handling of this event, after this filter: the
      // captions, measured in the render window's pixels, are fitted once that is done (fitted here, after a
      // maximised window they kept the old width's smallest font, away from the image's edge).
      QTimer::singleShot(0,
                         this,
                         [this]
                         {
                           if (!m_ZoomedByUser)
                           {
                             FitImage();
                           }
                           FitCornerTexts();
                           Render();
                         });
      return false;
    default:
      return false;
  }
}
} // namespace vr
