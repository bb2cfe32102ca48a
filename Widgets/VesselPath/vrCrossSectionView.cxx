// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrCrossSectionView.h"

#include "vrGreyImage.h"
#include "vrSectionStepper.h"

#include <QPainter>

#include <algorithm>
#include <cmath>

namespace vr
{
CrossSectionView::CrossSectionView(QWidget * parent)
  : QWidget(parent)
{
  setFocusPolicy(Qt::StrongFocus);
  setMinimumSize(110, 110);
  setAttribute(Qt::WA_OpaquePaintEvent);
  setToolTip(tr("The cross-section perpendicular to the path at the position shown on the straightened CPR; the "
                "circle has the section's lumen diameter; %1.")
               .arg(SectionStepper::Help()));
  connect(new SectionStepper(this), &SectionStepper::stepped, this, &CrossSectionView::stepped);
}

void
CrossSectionView::SetSlice(VolumeImageType::ConstPointer stack, unsigned int index, double window, double level)
{
  m_Stack = stack;
  m_Index = index;
  m_Window = window;
  m_Level = level;
  // The stack's v axis is the frame's up: drawn upwards, so row 0 of the slice goes to the bottom.
  m_Grey = GreySlice(m_Stack.GetPointer(), m_Index, m_Window, m_Level).mirrored(false, true);
  update();
}

void
CrossSectionView::SetWindowLevel(double window, double level)
{
  if (window == m_Window && level == m_Level)
  {
    return;
  }
  SetSlice(m_Stack, m_Index, window, level);
}

void
CrossSectionView::SetDiameter(double diameter)
{
  m_Diameter = diameter;
  update();
}

void
CrossSectionView::SetCaption(const QString & caption)
{
  m_Caption = caption;
  update();
}

QRectF
CrossSectionView::ImageRect() const
{
  if (m_Grey.isNull())
  {
    return QRectF();
  }
  const double top = 22.0;
  const double side = std::max(1.0, std::min(width() - 8.0, height() - top - 4.0));
  const double scale = side / std::max(m_Grey.width(), m_Grey.height());
  const QSizeF size(m_Grey.width() * scale, m_Grey.height() * scale);
  return QRectF(QPointF(0.5 * (width() - size.width()), top), size);
}

void
CrossSectionView::paintEvent(QPaintEvent *)
{
  QPainter painter(this);
  painter.fillRect(rect(), QColor(20, 20, 26));
  if (!m_Grey.isNull() && m_Stack)
  {
    const QRectF target = ImageRect();
    painter.drawImage(target, m_Grey);
    const QPointF center = target.center();
    const double  perMillimetre = target.width() / (m_Grey.width() * m_Stack->GetSpacing()[0]);
    painter.setRenderHint(QPainter::Antialiasing);
    painter.setPen(QPen(QColor(255, 60, 255), 1.5));
    painter.drawLine(center - QPointF(6.0, 0.0), center + QPointF(6.0, 0.0));
    painter.drawLine(center - QPointF(0.0, 6.0), center + QPointF(0.0, 6.0));
    if (std::isfinite(m_Diameter) && m_Diameter > 0.0)
    {
      const double radius = 0.5 * m_Diameter * perMillimetre;
      painter.setPen(QPen(QColor(80, 220, 120), 1.5));
      painter.drawEllipse(center, radius, radius);
    }
  }
  painter.setPen(Qt::white);
  painter.drawText(QRectF(4.0, 2.0, width() - 8.0, 18.0), Qt::AlignLeft | Qt::AlignVCenter, m_Caption);
}
} // namespace vr
