// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrLumenProfilePlot_h
#define vrLumenProfilePlot_h

#include "itkVesselLumenMeasurement.h"
#include "vrVesselStenosis.h"

#include <QPointF>
#include <QRectF>
#include <QWidget>

#include <optional>
#include <utility>
#include <vector>

namespace vr
{
/** \class LumenProfilePlot
 * \brief The lumen profile of a vessel path as a plot: the diameter against arc length (the segmentation's
 * circle-equivalent diameter, or 2r from the centerline radii), the centerline's inscribed diameter 2r beside it
 * when both exist, each segment's reference diameter as a dashed line (broken at the junctions, drawn dotted), the
 * sections the grading's margins exclude shaded, the graded stenosis's minimal lumen diameter (MLD) marked, the
 * aorta's maximum diameter marked, and the cross-section position as a vertical line. Every value is the logic's; the
 * plot draws them with QPainter (a plain widget: VTK's chart context would need a GL context of its own for a few
 * hundred points).
 *
 * A left click or drag puts the cross-section at the arc length under the mouse (arcLengthPicked()).
 * \sa VesselPathPanel
 * \ingroup VesselReformation
 */
class LumenProfilePlot : public QWidget
{
  Q_OBJECT

public:
  explicit LumenProfilePlot(QWidget * parent = nullptr);

  /** Plots \a profile with \a summary's segments and margins; marks its MLD when a stenosis is graded, and its
   * maximum diameter when the path has aortic segments. */
  void
  SetProfile(const itk::VesselLumenProfile & profile, const vr::VesselStenosisSummary & summary);
  /** Clears the plot. */
  void
  Clear();
  /** The cross-section position, mm of arc length. */
  void
  SetPosition(double arcLength);

  /** \return the point the plot marks as the MLD: x arc length (mm), y diameter (mm); nullopt when none. */
  std::optional<QPointF>
  GetMarkedMinimum() const
  {
    return m_Minimum;
  }
  /** \return the point marked as the aorta's maximum diameter (x arc length, y diameter); nullopt when none. */
  std::optional<QPointF>
  GetMarkedMaximum() const
  {
    return m_Maximum;
  }
  /** \return the shaded stretches (arc lengths, mm) the grading's margins exclude, and the junctions drawn. */
  const std::vector<std::pair<double, double>> &
  GetExcludedStretches() const
  {
    return m_Excluded;
  }
  const std::vector<double> &
  GetJunctions() const
  {
    return m_Junctions;
  }
  /** \return the widget point of (\a arcLength, \a diameter), and the arc length at widget x. */
  QPointF
  WidgetPoint(double arcLength, double diameter) const;
  double
  ArcLengthAtWidgetX(double x) const;
  /** \return the plotting area (widget pixels). */
  QRectF
  PlotRect() const;

  QSize
  sizeHint() const override
  {
    return QSize(480, 220);
  }

signals:
  void
  arcLengthPicked(double arcLength);

protected:
  void
  paintEvent(QPaintEvent * event) override;
  void
  mousePressEvent(QMouseEvent * event) override;
  void
  mouseMoveEvent(QMouseEvent * event) override;

private:
  std::vector<QPointF>                   m_Diameter;
  std::vector<QPointF>                   m_Inscribed;
  std::vector<QPointF>                   m_Reference;
  std::optional<QPointF>                 m_Minimum;
  std::optional<QPointF>                 m_Maximum;
  std::vector<std::pair<double, double>> m_Excluded;
  std::vector<double>                    m_Junctions;
  QString                                m_DiameterLabel;
  double                                 m_Position{ -1.0 };
  double                                 m_Range[4]{ 0.0, 1.0, 0.0, 1.0 };
};
} // namespace vr

#endif
