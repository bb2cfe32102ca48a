// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrLumenProfilePlot.h"

#include <QMouseEvent>
#include <QPainter>
#include <QPainterPath>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>

namespace vr
{
namespace
{
/** A tick step of 1, 2 or 5 times a power of ten that gives about \a count ticks over \a span. */
double
TickStep(double span, int count)
{
  const double raw = span / std::max(1, count);
  const double power = std::pow(10.0, std::floor(std::log10(std::max(raw, 1e-9))));
  for (const double factor : { 1.0, 2.0, 5.0 })
  {
    if (factor * power >= raw)
    {
      return factor * power;
    }
  }
  return 10.0 * power;
}

/** Polylines through the finite points of \a points, broken where a value is missing. */
QPainterPath
Polyline(const std::vector<QPointF> & points, const std::function<QPointF(const QPointF &)> & toWidget)
{
  QPainterPath path;
  bool         drawing = false;
  for (const QPointF & point : points)
  {
    if (!std::isfinite(point.y()))
    {
      drawing = false;
      continue;
    }
    if (drawing)
    {
      path.lineTo(toWidget(point));
    }
    else
    {
      path.moveTo(toWidget(point));
      drawing = true;
    }
  }
  return path;
}
} // namespace

LumenProfilePlot::LumenProfilePlot(QWidget * parent)
  : QWidget(parent)
{
  setMinimumSize(200, 100);
  setAttribute(Qt::WA_OpaquePaintEvent);
  setToolTip(tr("The lumen diameter along the path (mm against mm of arc length), each segment's reference diameter "
                "(dashed; junctions dotted), the sections no MLD is taken from (shaded: near the path's ends and "
                "branch origins), the minimal lumen diameter (MLD, red) and the aorta's maximum diameter (orange). "
                "Click or drag to move the cross-section."));
}

void
LumenProfilePlot::Clear()
{
  m_Diameter.clear();
  m_Inscribed.clear();
  m_Reference.clear();
  m_Minimum.reset();
  m_Maximum.reset();
  m_Excluded.clear();
  m_Junctions.clear();
  m_Position = -1.0;
  update();
}

void
LumenProfilePlot::SetProfile(const itk::VesselLumenProfile & profile, const vr::VesselStenosisSummary & summary)
{
  Clear();
  const bool fromSegmentation = profile.Source == itk::VesselLumenSource::Segmentation;
  m_DiameterLabel = fromSegmentation ? tr("diameter 2\u221a(A/\u03c0)") : tr("diameter 2r (centerline)");
  double       top = 0.0;
  const auto & marks = summary.Sections;
  for (std::size_t k = 0; k < profile.Sections.size(); ++k)
  {
    const auto & section = profile.Sections[k];
    m_Diameter.emplace_back(section.ArcLength, section.Diameter);
    // Each segment's reference on its own: a break where the segment changes.
    if (k > 0 && k < marks.size() && marks[k].Segment != marks[k - 1].Segment)
    {
      m_Reference.emplace_back(section.ArcLength, std::numeric_limits<double>::quiet_NaN());
    }
    m_Reference.emplace_back(section.ArcLength, section.ReferenceDiameter);
    // The margins' stretches (a section not measured is no margin: the gap in the curve shows it).
    const bool excluded = k < marks.size() && !marks[k].Candidate && marks[k].ExcludedBecause != "not measured";
    if (excluded)
    {
      const double half =
        0.5 * (k + 1 < profile.Sections.size() ? profile.Sections[k + 1].ArcLength - section.ArcLength
                                               : section.ArcLength - profile.Sections[k - 1].ArcLength);
      if (!m_Excluded.empty() && std::abs(m_Excluded.back().second - (section.ArcLength - half)) < 1e-6)
      {
        m_Excluded.back().second = section.ArcLength + half;
      }
      else
      {
        m_Excluded.emplace_back(section.ArcLength - half, section.ArcLength + half);
      }
    }
    if (fromSegmentation)
    {
      m_Inscribed.emplace_back(section.ArcLength, section.InscribedDiameter);
    }
    for (const double value : { section.Diameter, section.ReferenceDiameter, section.InscribedDiameter })
    {
      if (std::isfinite(value))
      {
        top = std::max(top, value);
      }
    }
  }
  for (std::size_t g = 1; g < summary.Segments.size(); ++g)
  {
    m_Junctions.push_back(summary.Segments[g].Segment.Begin);
  }
  // The MLD of a graded stenosis; the aorta's maximum diameter.
  if (!summary.Grade.empty() && std::isfinite(summary.MinimalLumenDiameter) &&
      std::isfinite(summary.MinimalLumenDiameterArcLength))
  {
    m_Minimum = QPointF(summary.MinimalLumenDiameterArcLength, summary.MinimalLumenDiameter);
  }
  if (std::isfinite(summary.MaximumDiameter) && std::isfinite(summary.MaximumDiameterArcLength))
  {
    m_Maximum = QPointF(summary.MaximumDiameterArcLength, summary.MaximumDiameter);
  }
  m_Range[0] = profile.Sections.empty() ? 0.0 : profile.Sections.front().ArcLength;
  m_Range[1] = profile.Sections.empty() ? 1.0 : std::max(profile.Sections.back().ArcLength, m_Range[0] + 1e-3);
  m_Range[2] = 0.0;
  m_Range[3] = top > 0.0 ? 1.1 * top : 1.0;
  update();
}

void
LumenProfilePlot::SetPosition(double arcLength)
{
  m_Position = arcLength;
  update();
}

QRectF
LumenProfilePlot::PlotRect() const
{
  return QRectF(QPointF(48.0, 24.0), QPointF(width() - 12.0, height() - 30.0));
}

QPointF
LumenProfilePlot::WidgetPoint(double arcLength, double diameter) const
{
  const QRectF area = PlotRect();
  return QPointF(area.left() + (arcLength - m_Range[0]) / (m_Range[1] - m_Range[0]) * area.width(),
                 area.bottom() - (diameter - m_Range[2]) / (m_Range[3] - m_Range[2]) * area.height());
}

double
LumenProfilePlot::ArcLengthAtWidgetX(double x) const
{
  const QRectF area = PlotRect();
  return m_Range[0] + (x - area.left()) / std::max(1.0, area.width()) * (m_Range[1] - m_Range[0]);
}

void
LumenProfilePlot::paintEvent(QPaintEvent *)
{
  QPainter painter(this);
  painter.fillRect(rect(), QColor(250, 250, 250));
  const QRectF area = PlotRect();
  painter.setPen(QColor(120, 120, 120));
  painter.drawRect(area);
  if (m_Diameter.empty())
  {
    painter.drawText(area, Qt::AlignCenter, tr("no lumen measured"));
    return;
  }
  // Axes: mm of arc length across, mm of diameter up.
  const QFontMetrics metrics(painter.font());
  const double       xStep = TickStep(m_Range[1] - m_Range[0], 8);
  for (double x = std::ceil(m_Range[0] / xStep) * xStep; x <= m_Range[1] + 1e-9; x += xStep)
  {
    const QPointF at = WidgetPoint(x, m_Range[2]);
    painter.setPen(QColor(225, 225, 225));
    painter.drawLine(QPointF(at.x(), area.top()), at);
    painter.setPen(QColor(60, 60, 60));
    const QString text = QString::number(x, 'g', 4);
    painter.drawText(QPointF(at.x() - 0.5 * metrics.horizontalAdvance(text), area.bottom() + 14.0), text);
  }
  const double yStep = TickStep(m_Range[3] - m_Range[2], 4);
  for (double y = 0.0; y <= m_Range[3] + 1e-9; y += yStep)
  {
    const QPointF at = WidgetPoint(m_Range[0], y);
    painter.setPen(QColor(225, 225, 225));
    painter.drawLine(at, QPointF(area.right(), at.y()));
    painter.setPen(QColor(60, 60, 60));
    const QString text = QString::number(y, 'g', 3);
    painter.drawText(QPointF(area.left() - 6.0 - metrics.horizontalAdvance(text), at.y() + 4.0), text);
  }
  painter.drawText(QPointF(area.left(), height() - 4.0), tr("arc length (mm)"));
  painter.drawText(QPointF(4.0, 14.0), tr("diameter (mm)"));

  // The margins' stretches shaded, the junctions dotted.
  for (const auto & [begin, end] : m_Excluded)
  {
    const double left = std::max(area.left(), WidgetPoint(begin, 0.0).x());
    const double right = std::min(area.right(), WidgetPoint(end, 0.0).x());
    painter.fillRect(QRectF(QPointF(left, area.top() + 1.0), QPointF(right, area.bottom())), QColor(232, 232, 232));
  }
  painter.setPen(QPen(QColor(110, 110, 110), 1.0, Qt::DotLine));
  for (const double s : m_Junctions)
  {
    const double x = WidgetPoint(s, 0.0).x();
    painter.drawLine(QPointF(x, area.top()), QPointF(x, area.bottom()));
  }

  painter.setRenderHint(QPainter::Antialiasing);
  const auto toWidget = [this](const QPointF & point) { return WidgetPoint(point.x(), point.y()); };
  painter.setClipRect(area.adjusted(-1.0, -1.0, 1.0, 1.0));
  painter.setPen(QPen(QColor(150, 150, 150), 1.2));
  painter.drawPath(Polyline(m_Inscribed, toWidget));
  painter.setPen(QPen(QColor(30, 110, 200), 1.3, Qt::DashLine));
  painter.drawPath(Polyline(m_Reference, toWidget));
  painter.setPen(QPen(QColor(20, 20, 20), 1.8));
  painter.drawPath(Polyline(m_Diameter, toWidget));
  if (m_Position >= 0.0)
  {
    const double x = WidgetPoint(m_Position, 0.0).x();
    painter.setPen(QPen(QColor(220, 40, 220), 1.5));
    painter.drawLine(QPointF(x, area.top()), QPointF(x, area.bottom()));
  }
  if (m_Maximum)
  {
    // The aorta's maximum diameter: an orange triangle pointing down at it, its value beside.
    const QPointF at = toWidget(*m_Maximum);
    painter.setPen(QPen(QColor(220, 120, 0), 1.5));
    painter.setBrush(QColor(220, 120, 0));
    const QPointF triangle[] = { at, at + QPointF(-5.0, -8.0), at + QPointF(5.0, -8.0) };
    painter.drawPolygon(triangle, 3);
    painter.setClipping(false);
    const QString label = tr("max %1 mm").arg(m_Maximum->y(), 0, 'f', 1);
    const double  labelWidth = metrics.horizontalAdvance(label);
    const double  x = at.x() + 8.0 + labelWidth < width() - 2.0 ? at.x() + 8.0 : at.x() - 8.0 - labelWidth;
    painter.drawText(QPointF(x, at.y() - 2.0), label);
    painter.setClipRect(area.adjusted(-1.0, -1.0, 1.0, 1.0));
  }
  if (m_Minimum)
  {
    const QPointF at = toWidget(*m_Minimum);
    painter.setPen(QPen(QColor(210, 30, 30), 2.0));
    painter.setBrush(QColor(210, 30, 30));
    painter.drawEllipse(at, 4.0, 4.0);
    painter.setClipping(false);
    // The label beside the dot, on the side with room for it.
    const QString label = tr("MLD %1 mm").arg(m_Minimum->y(), 0, 'f', 2);
    const double  labelWidth = metrics.horizontalAdvance(label);
    const double  x = at.x() + 6.0 + labelWidth < width() - 2.0 ? at.x() + 6.0 : at.x() - 6.0 - labelWidth;
    painter.drawText(QPointF(x, at.y() + 16.0), label);
  }
  painter.setClipping(false);
  // The legend, in a row above the plot.
  double x = area.left() + 100.0;
  auto   legend = [&](const QString & text, const QColor & color)
  {
    // An entry that does not fit whole is left out rather than cut (the tooltip names them all).
    const double advance = metrics.horizontalAdvance(text);
    if (x + advance > width() - 4.0)
    {
      x = width();
      return;
    }
    painter.setPen(color);
    painter.drawText(QPointF(x, 14.0), text);
    x += advance + 16.0;
  };
  legend(m_DiameterLabel, QColor(20, 20, 20));
  legend(tr("reference"), QColor(30, 110, 200));
  if (!m_Excluded.empty())
  {
    legend(tr("excluded (margins)"), QColor(150, 150, 150));
  }
  if (!m_Inscribed.empty())
  {
    legend(tr("2r (centerline)"), QColor(130, 130, 130));
  }
}

void
LumenProfilePlot::mousePressEvent(QMouseEvent * event)
{
  if (event->button() == Qt::LeftButton && !m_Diameter.empty())
  {
    emit arcLengthPicked(ArcLengthAtWidgetX(event->localPos().x()));
  }
}

void
LumenProfilePlot::mouseMoveEvent(QMouseEvent * event)
{
  if ((event->buttons() & Qt::LeftButton) && !m_Diameter.empty())
  {
    emit arcLengthPicked(ArcLengthAtWidgetX(event->localPos().x()));
  }
}
} // namespace vr
