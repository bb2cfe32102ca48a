// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrStraightenedCPRView.h"

#include "vrGreyImage.h"
#include "vrSectionStepper.h"

#include <QMouseEvent>
#include <QPainter>

namespace vr
{
StraightenedCPRView::StraightenedCPRView(QWidget * parent)
  : GreyImageView(parent)
{
  setMinimumSize(100, 120);
  setToolTip(tr("The straightened CPR of the vessel path: left-drag rolls it about the path, right-click puts the "
                "cross-section at that row, %1.")
               .arg(SectionStepper::Help()));
  connect(new SectionStepper(this), &SectionStepper::stepped, this, &StraightenedCPRView::stepped);
}

void
StraightenedCPRView::SetImage(DepthImageType::ConstPointer image, double window, double level)
{
  m_Image = image;
  Refresh(window, level);
}

QImage
StraightenedCPRView::MakeGreyImage(double window, double level) const
{
  return GreyImage(m_Image.GetPointer(), window, level);
}

QSizeF
StraightenedCPRView::ImageExtent() const
{
  if (!m_Image)
  {
    return QSizeF();
  }
  const auto spacing = m_Image->GetSpacing();
  const auto size = m_Image->GetLargestPossibleRegion().GetSize();
  return QSizeF(size[0] * spacing[0], size[1] * spacing[1]);
}

void
StraightenedCPRView::SetPositionRow(double row)
{
  m_PositionRow = row;
  update();
}

double
StraightenedCPRView::WidgetYOfRow(double row) const
{
  const QRectF rect = ImageRect();
  const int    rows = GetDisplayedImage().height();
  return rows > 0 ? rect.top() + (row + 0.5) * rect.height() / rows : 0.0;
}

double
StraightenedCPRView::RowAtWidgetY(double y) const
{
  const QRectF rect = ImageRect();
  return rect.height() > 0.0 ? (y - rect.top()) * GetDisplayedImage().height() / rect.height() - 0.5 : 0.0;
}

void
StraightenedCPRView::PaintOverlay(QPainter & painter, const QRectF & target)
{
  if (m_PositionRow >= 0.0)
  {
    const double y = WidgetYOfRow(m_PositionRow);
    painter.setPen(QPen(QColor(255, 60, 255), 1.5));
    painter.drawLine(QPointF(target.left() - 3.0, y), QPointF(target.right() + 3.0, y));
  }
}

void
StraightenedCPRView::mousePressEvent(QMouseEvent * event)
{
  if (m_Drag != Qt::NoButton)
  {
    return;
  }
  m_Drag = event->button();
  m_DragStart = event->localPos();
  if (m_Drag == Qt::LeftButton)
  {
    emit rollStarted();
  }
  else if (m_Drag == Qt::RightButton)
  {
    emit rowPicked(RowAtWidgetY(event->localPos().y()));
  }
}

void
StraightenedCPRView::mouseMoveEvent(QMouseEvent * event)
{
  if (m_Drag == Qt::LeftButton)
  {
    emit rollDragged(DegreesPerPixel * (event->localPos().x() - m_DragStart.x()), false);
  }
  else if (m_Drag == Qt::RightButton)
  {
    emit rowPicked(RowAtWidgetY(event->localPos().y()));
  }
}

void
StraightenedCPRView::mouseReleaseEvent(QMouseEvent * event)
{
  if (event->button() != m_Drag)
  {
    return;
  }
  if (m_Drag == Qt::LeftButton)
  {
    emit rollDragged(DegreesPerPixel * (event->localPos().x() - m_DragStart.x()), true);
  }
  m_Drag = Qt::NoButton;
}
} // namespace vr
