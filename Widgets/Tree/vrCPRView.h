// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrCPRView_h
#define vrCPRView_h

#include "vrPixelReadout.h"
#include "vrReformationController.h"

#include <QPointF>
#include <QWidget>

#include <vtkNew.h>
#include <vtkSmartPointer.h>

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "itkPoint.h"

class QVTKOpenGLNativeWidget;
class vtkActor;
class vtkGenericOpenGLRenderWindow;
class vtkImageActor;
class vtkImageData;
class vtkPolyData;
class vtkRenderer;
class vtkTextActor;

namespace vr
{
/** Which CPR image the view shows: the paper's comparison of unfiltered and filtered reformations.
 * \ingroup VesselReformation
 */
enum class CPRComparison
{
  Filtered,
  Unfiltered,
  /** Unfiltered left of the middle column, filtered right of it, on the same grid. */
  Split,
  /** Unfiltered on the left, filtered on the right, each whole. */
  SideBySide
};

/** The overlays the CPR view can draw over the image.
 * \ingroup VesselReformation
 */
struct CPROverlays
{
  /** The centerlines projected into the view, one colour per branch. */
  bool Centerlines{ true };
  /** The fixed mask: centerline pixels and lumen (yellow). */
  bool FixedMask{ false };
  /** The owner labels: one colour per branch. */
  bool OwnerLabels{ false };
  /** The depth map (viridis: near dark, far yellow). */
  bool DepthMap{ false };

  bool
  operator==(const CPROverlays & other) const
  {
    return Centerlines == other.Centerlines && FixedMask == other.FixedMask && OwnerLabels == other.OwnerLabels &&
           DepthMap == other.DepthMap;
  }
};

/** \class CPRView
 * \brief The 2D view of a reformation: the CPR image through window/level (vr::WindowLevelToByte, the mapping of a
 * saved PNG; a VTK image actor draws the bytes), overlays, the unfiltered/filtered comparison, and a readout of the
 * pixel under the mouse. It displays the logic's outputs and computes nothing.
 *
 * Mouse:
 * - left-drag horizontally rotates the view about its up axis: rotationDragged() reports
 *   -DegreesPerPixel degrees per pixel to the right, so that dragging right turns the vessels nearest to the viewer
 *   to the right, as a 3D viewer's trackball turns an object (a 720-pixel drag is a full turn);
 * - right-drag sets window (horizontal: wider to the right, by the window's own size per 256 pixels) and level
 *   (vertical: higher upwards, by the window per 512 pixels);
 * - wheel zooms about the mouse (1.2 per notch), middle-drag pans, double-click fits the image;
 * - Ctrl+left-click picks the vessel under the mouse (vesselPicked(), the owner label's branch): the viewer opens
 *   its path (docs/viewer.md); a plain left-drag still turns the view;
 * - hovering reports the pixel's column and row, its RAS position, intensity, depth and branch (readoutChanged()).
 *
 * Pixel (i, j) (row 0 at the top) of a full-resolution image is drawn at world (i sx, j sy), the camera looking along
 * +z with -y up, so the image appears as the reformation defines it: screen-right u, screen-down -up. A preview (a
 * result at k times the spacing, docs/progressive-refinement.md) is drawn over the same millimetres of its full view,
 * with the overlays on its own grid, and labelled "preview (1/k resolution)" in the lower right corner until the full
 * image replaces it.
 *
 * \sa ReformationController, ThreeDView, ModulePanel
 * \ingroup VesselReformation
 */
class CPRView : public QWidget
{
  Q_OBJECT

public:
  /** Degrees the view turns per pixel of horizontal left-drag (negative: dragging right decreases the angle). */
  static constexpr double DegreesPerPixel = -0.5;

  explicit CPRView(QWidget * parent = nullptr);
  ~CPRView() override;

  /** Shows \a result (its images, overlays from its inputs); renders; imageDisplayed() follows once the frame is on
   * screen. The camera is kept unless the image's size changed. */
  void
  SetResult(std::shared_ptr<const ReformationResult> result);
  /** \return the result shown, or null. */
  std::shared_ptr<const ReformationResult>
  GetResult() const
  {
    return m_Result;
  }

  /** Window width and level, in the image's intensity unit (HU); display only. */
  void
  SetWindowLevel(double window, double level);
  double
  GetWindow() const
  {
    return m_Window;
  }
  double
  GetLevel() const
  {
    return m_Level;
  }

  void
  SetOverlays(const CPROverlays & overlays);
  const CPROverlays &
  GetOverlays() const
  {
    return m_Overlays;
  }
  void
  SetComparison(CPRComparison comparison);
  CPRComparison
  GetComparison() const
  {
    return m_Comparison;
  }

  /** Fits the whole image (both images side by side) into the view. */
  void
  FitImage();
  /** Zooms by \a factor about the widget point \a center. */
  void
  Zoom(double factor, const QPointF & center);

  /** \return what hovering over the widget point \a position shows. */
  PixelReadout
  ReadoutAt(const QPointF & position) const;
  /** \return the widget position (logical pixels) of the centre of image pixel (\a column, \a row) of the filtered or
   * the unfiltered image. */
  QPointF
  WidgetPositionOfPixel(double column, double row, bool unfiltered) const;
  /** \return the filtered (or unfiltered) image data shown: the logic's output's pixels, which the image actor draws
   * through window/level as vr::WindowLevelToByte maps them (the bytes a saved PNG holds). */
  vtkImageData *
  GetDisplayedImage(bool unfiltered) const;
  /** \return the widget that renders (mouse events go there). */
  QVTKOpenGLNativeWidget *
  GetRenderWidget() const
  {
    return m_Widget;
  }
  /** \return the latest readout. */
  const PixelReadout &
  GetReadout() const
  {
    return m_Readout;
  }
  /** \return the centerline overlay in the image's plane (one polyline per branch, in view mm). */
  vtkPolyData *
  GetCenterlineOverlay() const
  {
    return m_CenterlinePolyData;
  }
  /** \return the preview label on screen ("preview (1/2 resolution)"), or empty when the image is a full one. */
  QString
  GetPreviewLabel() const;
  /** \return the caption under the filtered (or unfiltered) image as drawn: the filter settings in the words of
   * vr::DescribeFilterSettings. */
  QString
  GetCaption(bool unfiltered) const;
  /** \return the upper left and upper right annotations' rectangles in the view's display pixels (x from the left, y
   * from the bottom, as VTK gives them: xmin, xmax, ymin, ymax). */
  std::array<std::array<double, 4>, 2>
  GetCornerTextBoxes() const;
  /** \return the filtered (or unfiltered) image's caption's rectangle, in the same display pixels. */
  std::array<double, 4>
  GetCaptionBox(bool unfiltered) const;
  /** \return seconds the latest vtkRenderWindow::Render() of a new image took. */
  double
  GetLastRenderSeconds() const
  {
    return m_LastRenderSeconds;
  }

  /** Shows a marker (a cross) at the patient point \a lps (LPS mm), projected into the view as the centerlines are;
   * nullopt hides it. The single-vessel reading's cross-section position (docs/viewer.md). */
  void
  SetPathMarker(const std::optional<itk::Point<double, 3>> & lps);
  /** \return the world position (view mm, the image plane) where the marker is drawn, or nullopt when hidden. */
  std::optional<std::array<double, 2>>
  GetPathMarkerWorldPosition() const
  {
    return m_PathMarkerWorld;
  }
  /** \return the world position of the centre of pixel (\a column, \a row) of the filtered image shown (a preview's
   * pixels for a preview). */
  std::array<double, 2>
  WorldPositionOfPixel(double column, double row) const
  {
    return { m_Origin[0] + column * m_Spacing[0], m_Origin[1] + row * m_Spacing[1] };
  }

  /** Renders now. */
  void
  Render();

signals:
  /** Ctrl+left-click on the image: \a readout is the pixel clicked (its Branch the owner label there). */
  void
  vesselPicked(const vr::PixelReadout & readout);
  /** A left-drag started. */
  void
  rotationStarted();
  /** The left-drag moved: \a degrees since it started (DegreesPerPixel per pixel); \a finished at the release. */
  void
  rotationDragged(double degrees, bool finished);
  /** Right-drag changed the window and level. */
  void
  windowLevelChanged(double window, double level);
  /** The pixel under the mouse changed. */
  void
  readoutChanged(const vr::PixelReadout & readout);
  /** The image of request \a requestId is on screen (the widget's frame was swapped). */
  void
  imageDisplayed(std::uint64_t requestId);

protected:
  bool
  eventFilter(QObject * watched, QEvent * event) override;

private:
  struct Pane;

  void
  UpdatePanes();
  /** Maps both images through the window and level into the bytes their actors draw. */
  void
  UpdateGrey();
  void
  UpdateOverlays();
  void
  UpdateAnnotation();
  void
  FitCornerTexts();
  void
  FitCaptions();
  /** A text actor's rectangle in the view's display pixels (as GetCornerTextBoxes gives them). */
  std::array<double, 4>
  TextBoxOf(vtkTextActor * text) const;
  void
  UpdateCenterlines();
  void
  UpdatePathMarker();
  /** World point (z = 0) under a widget point. */
  std::array<double, 2>
  WidgetToWorld(const QPointF & position) const;
  QPointF
  WorldToWidget(double x, double y) const;
  /** World x offset of the unfiltered image (negative in side-by-side mode). */
  double
  UnfilteredOffset() const;

  QVTKOpenGLNativeWidget *                      m_Widget{ nullptr };
  vtkSmartPointer<vtkGenericOpenGLRenderWindow> m_RenderWindow;
  vtkSmartPointer<vtkRenderer>                  m_Renderer;
  std::unique_ptr<Pane>                         m_Filtered;
  std::unique_ptr<Pane>                         m_Unfiltered;
  vtkSmartPointer<vtkTextActor>                 m_UpperLeftText;
  vtkSmartPointer<vtkTextActor>                 m_UpperRightText;
  vtkSmartPointer<vtkTextActor>                 m_PreviewText;
  vtkSmartPointer<vtkActor>                     m_SplitLine;
  vtkSmartPointer<vtkPolyData>                  m_CenterlinePolyData;
  vtkSmartPointer<vtkActor>                     m_PathMarkerActor;
  std::optional<itk::Point<double, 3>>          m_PathMarker;
  std::optional<std::array<double, 2>>          m_PathMarkerWorld;

  std::shared_ptr<const ReformationResult> m_Result;
  std::uint64_t                            m_PendingDisplay{ 0 };
  bool                                     m_HasPendingDisplay{ false };
  int                                      m_ImageSize[2]{ 0, 0 };
  double                                   m_Spacing[2]{ 1.0, 1.0 };
  /** World position of pixel (0, 0) of the image shown: 0 for a full image, the shift that lays a preview over its
   * full view's millimetres otherwise. */
  double m_Origin[2]{ 0.0, 0.0 };
  /** Size and spacing of the full view of the result shown (the image's own for a full image): what fitting and the
   * captions go by, so that a preview does not move the camera. */
  int           m_FrameSize[2]{ 0, 0 };
  double        m_FrameSpacing[2]{ 1.0, 1.0 };
  double        m_Window{ 900.0 };
  double        m_Level{ 200.0 };
  CPROverlays   m_Overlays;
  CPRComparison m_Comparison{ CPRComparison::Filtered };
  /** The filtered caption's texts, the first tried first (FitCaptions). */
  std::vector<std::string> m_CaptionForms;
  PixelReadout             m_Readout;
  double                   m_LastRenderSeconds{ 0.0 };

  // The drag in progress.
  Qt::MouseButton m_DragButton{ Qt::NoButton };
  /** Whether the wheel or a middle-drag moved the camera since the last FitImage() (then a resize keeps it). */
  bool    m_ZoomedByUser{ false };
  QPointF m_DragStart;
  double  m_DragWindow{ 0.0 };
  double  m_DragLevel{ 0.0 };
  double  m_DragFocal[3]{ 0.0, 0.0, 0.0 };
};
} // namespace vr

#endif
