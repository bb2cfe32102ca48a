// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrThreeDView_h
#define vrThreeDView_h

#include "vrReformationController.h"

#include <QWidget>

#include <chrono>

#include <vtkSmartPointer.h>

#include <array>
#include <memory>
#include <optional>
#include <vector>

#include "itkPoint.h"

class QVTKOpenGLNativeWidget;
class vtkActor;
class vtkGenericOpenGLRenderWindow;
class vtkLookupTable;
class vtkPolyData;
class vtkPolyDataMapper;
class vtkRenderer;

namespace vr
{
/** \class ThreeDView
 * \brief The 3D view of a reformation: the cut surface coloured by intensity (through the CPR view's window and
 * level), the centerlines as tubes of their lumen radii (one colour per branch), the volume's outline and the view
 * direction as an arrow; orbit with the left mouse button, zoom with the wheel or the right button, pan with the
 * middle one (VTK's trackball camera). It displays the logic's outputs and computes nothing.
 *
 * So that it never holds a drag back (Mesa's software renderer draws the full 512 x 1024 surface in about 290 ms), it
 * draws the preview surface (every s-th pixel, vr::BuildPreviewSurface) while the user drags anything, in this view or
 * in the CPR view, and the full surface once the drag ends; and it renders at its own pace: render requests arriving
 * while a render is due are merged into one, which runs after the CPR view's frame is on screen.
 *
 * \sa CPRView, ReformationController
 * \ingroup VesselReformation
 */
class ThreeDView : public QWidget
{
  Q_OBJECT

public:
  explicit ThreeDView(QWidget * parent = nullptr);
  ~ThreeDView() override;

  /** Shows the outline and the centerline tubes of \a inputs, and points the camera at them. */
  void
  SetInputs(std::shared_ptr<const ReformationInputs> inputs);
  /** Shows \a result's surface (its full one when it has it, else the preview) and view direction. */
  void
  SetResult(std::shared_ptr<const ReformationResult> result);
  /** Window and level of the surface's colours (HU). */
  void
  SetWindowLevel(double window, double level);
  /** While true (a drag in either view), the preview surface stands in for the full one. */
  void
  SetInteracting(bool interacting);
  bool
  IsInteracting() const
  {
    return m_Interacting || m_Orbiting;
  }
  /** \return whether the full surface (rather than the preview) is what the next render draws. */
  bool
  IsShowingFullSurface() const;

  /** Asks for a render; requests made before it runs are merged into one. While the CPR view's drag turns the view
   * (SetInteracting), renders come at most every InteractiveRenderIntervalMilliseconds: a frame of this view costs
   * more than one of the CPR view on a software OpenGL, and the CPR view's images come first
   * (docs/progressive-refinement.md). */
  void
                       ScheduleRender();
  static constexpr int InteractiveRenderIntervalMilliseconds = 250;
  /** Shows a marker (a sphere) at the patient point \a lps (LPS mm; drawn in RAS as the whole scene), and
   * \a pathRAS, the vessel path read, as a line; nullopt hides the marker, an empty path the line. The
   * single-vessel reading's cross-section position (docs/viewer.md). Schedules a render. */
  void
  SetPathMarker(const std::optional<itk::Point<double, 3>> & lps);
  void
  SetPath(const std::vector<itk::Point<double, 3>> & lps);
  /** \return the marker's centre as drawn (RAS mm), or nullopt when hidden. */
  std::optional<std::array<double, 3>>
  GetPathMarkerPosition() const;

  /** Renders now. */
  void
  Render();
  /** \return seconds the latest render took, and the number of surface points it drew. */
  double
  GetLastRenderSeconds() const
  {
    return m_LastRenderSeconds;
  }
  long long
  GetLastRenderedSurfacePoints() const
  {
    return m_LastRenderedPoints;
  }
  /** Fits the camera to the outline, looking along the view direction from 30 degrees aside (azimuth 30 degrees about
   * up, elevation 10). */
  void
  ResetCamera();
  /** As ResetCamera, along the view direction of the view at \a angleInDegrees about up (the shown view turned by
   * the difference), before that view is computed: Home resets the angle and the camera together. */
  void
  ResetCameraForAngle(double angleInDegrees);
  /** The camera's direction of projection (RAS, unit). */
  std::array<double, 3>
  GetCameraDirection() const;
  /** \return the widget that renders. */
  QVTKOpenGLNativeWidget *
  GetRenderWidget() const
  {
    return m_Widget;
  }
  /** \return the centerline tubes drawn (cell data "BranchIds"), or null before any inputs. */
  vtkPolyData *
  GetTubes() const;
  /** The camera's focal point (RAS mm), for tests of how it is fitted. */
  std::array<double, 3>
  GetCameraFocalPoint() const;

signals:
  /** A render finished: its time in seconds and whether it drew the full surface. */
  void
  rendered(double seconds, bool fullSurface);

private:
  void
  ChooseSurface();
  void
  ResetCameraAlong(const std::array<double, 3> & v, const std::array<double, 3> & up);
  void
  UpdateViewDirection();

  QVTKOpenGLNativeWidget *                      m_Widget{ nullptr };
  vtkSmartPointer<vtkGenericOpenGLRenderWindow> m_RenderWindow;
  vtkSmartPointer<vtkRenderer>                  m_Renderer;
  vtkSmartPointer<vtkActor>                     m_Surface;
  vtkSmartPointer<vtkPolyDataMapper>            m_SurfaceMapper;
  vtkSmartPointer<vtkLookupTable>               m_Grey;
  vtkSmartPointer<vtkActor>                     m_Tubes;
  vtkSmartPointer<vtkActor>                     m_Outline;
  vtkSmartPointer<vtkActor>                     m_Arrow;
  vtkSmartPointer<vtkActor>                     m_Plane;
  vtkSmartPointer<vtkActor>                     m_PathMarker;
  vtkSmartPointer<vtkActor>                     m_Path;

  std::shared_ptr<const ReformationInputs> m_Inputs;
  std::shared_ptr<const ReformationResult> m_Result;
  bool                                     m_Interacting{ false };
  bool                                     m_Orbiting{ false };
  bool                                     m_RenderScheduled{ false };
  std::chrono::steady_clock::time_point    m_LastRenderTime;
  bool                                     m_CameraSet{ false };
  double                                   m_LastRenderSeconds{ 0.0 };
  long long                                m_LastRenderedPoints{ 0 };
};
} // namespace vr

#endif
