// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrOcclusionStrip.h"

#include <QHelpEvent>
#include <QMouseEvent>
#include <QPainter>
#include <QPainterPath>
#include <QToolTip>

#include <algorithm>
#include <cmath>

namespace vr
{
namespace
{
constexpr int Angles = static_cast<int>(itk::CPROcclusionProfile::NumberOfAngles);
// Room on the left for the scale's label, in pixels.
constexpr int LabelWidth = 64;
} // namespace

OcclusionStrip::OcclusionStrip(QWidget * parent)
  : QWidget(parent)
{
  setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
  setCursor(Qt::PointingHandCursor);
  setToolTip(tr("The part of the vessel tree hidden behind other vessels, against the view angle (0-179°). Click to "
                "go to that angle; the green tick marks the least hidden, View › Best view goes there."));
}

void
OcclusionStrip::SetProfile(std::shared_ptr<const itk::CPROcclusionProfile> profile)
{
  m_Profile = std::move(profile);
  update();
}

void
OcclusionStrip::SetCurrentAngle(double degrees)
{
  m_Angle = degrees;
  update();
}

int
OcclusionStrip::AngleAt(double x) const
{
  const double width = std::max(1, this->width() - LabelWidth);
  return std::clamp(static_cast<int>(std::floor((x - LabelWidth) / width * Angles)), 0, Angles - 1);
}

double
OcclusionStrip::XOfAngle(double degrees) const
{
  const double width = std::max(1, this->width() - LabelWidth);
  return LabelWidth + (degrees + 0.5) / Angles * width;
}

QSize
OcclusionStrip::sizeHint() const
{
  return QSize(400, 34);
}

QSize
OcclusionStrip::minimumSizeHint() const
{
  return QSize(LabelWidth + Angles / 2, 28);
}

void
OcclusionStrip::paintEvent(QPaintEvent *)
{
  QPainter painter(this);
  painter.fillRect(rect(), QColor(24, 24, 28));
  const QRectF plot(LabelWidth, 2.0, std::max(1, width() - LabelWidth - 1), height() - 4.0);
  painter.setPen(QColor(200, 200, 200));
  QFont font = painter.font();
  font.setPointSizeF(std::max(6.0, font.pointSizeF() - 1.5));
  painter.setFont(font);
  if (!m_Profile || m_Profile->HiddenLength.size() != static_cast<std::size_t>(Angles))
  {
    painter.drawText(rect().adjusted(6, 0, 0, 0), Qt::AlignVCenter | Qt::AlignLeft, tr("hidden vs angle: no profile"));
    return;
  }
  double largest = 0.0;
  for (int a = 0; a < Angles; ++a)
  {
    largest = std::max(largest, m_Profile->HiddenFraction(static_cast<unsigned int>(a)));
  }
  const double scale = largest > 0.0 ? largest : 1.0;
  painter.drawText(QRectF(2.0, 0.0, LabelWidth - 4.0, height()),
                   Qt::AlignVCenter | Qt::AlignRight,
                   tr("hidden\n≤ %1 %").arg(100.0 * largest, 0, 'f', largest < 0.1 ? 1 : 0));

  // The hidden fraction as a filled profile, 0 at the bottom.
  QPainterPath area;
  area.moveTo(plot.left(), plot.bottom());
  for (int a = 0; a < Angles; ++a)
  {
    const double y = plot.bottom() - plot.height() * m_Profile->HiddenFraction(static_cast<unsigned int>(a)) / scale;
    area.lineTo(plot.left() + plot.width() * a / Angles, y);
    area.lineTo(plot.left() + plot.width() * (a + 1) / Angles, y);
  }
  area.lineTo(plot.right(), plot.bottom());
  area.closeSubpath();
  painter.fillPath(area, QColor(230, 140, 60, 200));

  // Every 30 degrees a faint tick.
  painter.setPen(QColor(90, 90, 100));
  for (int a = 30; a < Angles; a += 30)
  {
    const double x = plot.left() + plot.width() * a / Angles;
    painter.drawLine(QPointF(x, plot.top()), QPointF(x, plot.bottom()));
  }

  // The least occluded angle, and the view on screen.
  const double best = XOfAngle(m_Profile->LeastOccludedAngle());
  painter.setPen(QPen(QColor(80, 220, 120), 2.0));
  painter.drawLine(QPointF(best, plot.bottom() - 6.0), QPointF(best, plot.bottom()));
  double wrapped = std::fmod(m_Angle, 360.0);
  wrapped = wrapped < 0.0 ? wrapped + 360.0 : wrapped;
  const bool   otherSide = wrapped >= 180.0;
  const double current = XOfAngle(std::floor(otherSide ? wrapped - 180.0 : wrapped));
  painter.setPen(QPen(QColor(255, 255, 255), 1.5, otherSide ? Qt::DashLine : Qt::SolidLine));
  painter.drawLine(QPointF(current, plot.top()), QPointF(current, plot.bottom()));
}

void
OcclusionStrip::mousePressEvent(QMouseEvent * event)
{
  if (event->button() == Qt::LeftButton && event->pos().x() >= LabelWidth)
  {
    emit angleClicked(static_cast<double>(AngleAt(event->pos().x())));
    event->accept();
    return;
  }
  QWidget::mousePressEvent(event);
}

bool
OcclusionStrip::event(QEvent * event)
{
  if (event->type() == QEvent::ToolTip && m_Profile && event != nullptr)
  {
    const auto * help = static_cast<QHelpEvent *>(event);
    if (help->pos().x() >= LabelWidth && !m_Profile->HiddenLength.empty())
    {
      const auto angle = static_cast<unsigned int>(AngleAt(help->pos().x()));
      QToolTip::showText(help->globalPos(),
                         tr("%1°: %2 mm hidden (%3 % of the tree)")
                           .arg(angle)
                           .arg(m_Profile->HiddenLength[angle], 0, 'f', 0)
                           .arg(100.0 * m_Profile->HiddenFraction(angle), 0, 'f', 1),
                         this);
      return true;
    }
  }
  return QWidget::event(event);
}
} // namespace vr
