// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrStraightenedCPRView.h"

#include "vrGreyImage.h"
#include "vrSectionStepper.h"

#include <QMouseEvent>
#include <QPainter>

#include <algorithm>

namespace vr
{
StraightenedCPRView::StraightenedCPRView(QWidget * parent)
  : QWidget(parent)
{
  setFocusPolicy(Qt::StrongFocus);
  setMinimumSize(100, 120);
  setAttribute(Qt::WA_OpaquePaintEvent);
  setToolTip(tr("The straightened CPR of the vessel path: left-drag rolls it about the path, right-click puts the "
                "cross-section at that row, %1.")
               .arg(SectionStepper::Help()));
  connect(new SectionStepper(this), &SectionStepper::stepped, this, &StraightenedCPRView::stepped);
}

void
StraightenedCPRView::SetImage(DepthImageType::ConstPointer image, double window, double level)
{
  m_Image = image;
  m_Window = window;
  m_Level = level;
  m_Grey = GreyImage(m_Image.GetPointer(), m_Window, m_Level);
  update();
}

void
StraightenedCPRView::SetWindowLevel(double window, double level)
{
  if (window == m_Window && level == m_Level)
  {
    return;
  }
  SetImage(m_Image, window, level);
}

void
StraightenedCPRView::SetPositionRow(double row)
{
  m_PositionRow = row;
  update();
}

void
StraightenedCPRView::SetCaption(const QString & caption)
{
  m_Caption = caption;
  update();
}

QRectF
StraightenedCPRView::ImageRect() const
{
  if (!m_Image)
  {
    return QRectF();
  }
  // Square millimetres on screen: the image's own spacing sets the aspect.
  const auto   spacing = m_Image->GetSpacing();
  const double width = m_Grey.width() * spacing[0];
  const double height = m_Grey.height() * spacing[1];
  const double margin = 4.0;
  const double top = 22.0;
  const double scale = std::min((this->width() - 2.0 * margin) / width, (this->height() - top - margin) / height);
  const QSizeF size(width * scale, height * scale);
  return QRectF(QPointF(0.5 * (this->width() - size.width()), top), size);
}

double
StraightenedCPRView::WidgetYOfRow(double row) const
{
  const QRectF rect = ImageRect();
  return m_Grey.height() > 0 ? rect.top() + (row + 0.5) * rect.height() / m_Grey.height() : 0.0;
}

double
StraightenedCPRView::RowAtWidgetY(double y) const
{
  const QRectF rect = ImageRect();
  return rect.height() > 0.0 ? (y - rect.top()) * m_Grey.height() / rect.height() - 0.5 : 0.0;
}

void
StraightenedCPRView::paintEvent(QPaintEvent *)
{
  QPainter painter(this);
  painter.fillRect(rect(), QColor(20, 20, 26));
  if (m_Grey.isNull())
  {
    return;
  }
  const QRectF target = ImageRect();
  painter.drawImage(target, m_Grey);
  if (m_PositionRow >= 0.0)
  {
    const double y = WidgetYOfRow(m_PositionRow);
    painter.setPen(QPen(QColor(255, 60, 255), 1.5));
    painter.drawLine(QPointF(target.left() - 3.0, y), QPointF(target.right() + 3.0, y));
  }
  painter.setPen(Qt::white);
  painter.drawText(QRectF(4.0, 2.0, width() - 8.0, 18.0), Qt::AlignLeft | Qt::AlignVCenter, m_Caption);
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
