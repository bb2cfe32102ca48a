// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrCrossSectionView.h"

#include "vrGreyImage.h"
#include "vrSectionStepper.h"

#include <QPainter>

#include <cmath>

namespace vr
{
CrossSectionView::CrossSectionView(QWidget * parent)
  : GreyImageView(parent)
{
  setMinimumSize(110, 110);
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
  Refresh(window, level);
}

QImage
CrossSectionView::MakeGreyImage(double window, double level) const
{
  // The stack's v axis is the frame's up: drawn upwards, so row 0 of the slice goes to the bottom.
  return GreySlice(m_Stack.GetPointer(), m_Index, window, level).mirrored(false, true);
}

void
CrossSectionView::SetDiameter(double diameter)
{
  m_Diameter = diameter;
  update();
}

void
CrossSectionView::PaintOverlay(QPainter & painter, const QRectF & target)
{
  if (!m_Stack)
  {
    return;
  }
  const QPointF center = target.center();
  const double  perMillimetre = target.width() / (GetDisplayedImage().width() * m_Stack->GetSpacing()[0]);
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
} // namespace vr
