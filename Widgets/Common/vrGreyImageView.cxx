// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrGreyImageView.h"

#include <QPainter>

#include <algorithm>

namespace vr
{
namespace
{
// Room for the caption above the image, and around it.
constexpr double CaptionHeight = 22.0;
constexpr double Margin = 4.0;
} // namespace

GreyImageView::GreyImageView(QWidget * parent)
  : QWidget(parent)
{
  setFocusPolicy(Qt::StrongFocus);
  setAttribute(Qt::WA_OpaquePaintEvent);
}

void
GreyImageView::SetWindowLevel(double window, double level)
{
  if (window == m_Window && level == m_Level)
  {
    return;
  }
  Refresh(window, level);
}

void
GreyImageView::Refresh(double window, double level)
{
  m_Window = window;
  m_Level = level;
  m_Grey = MakeGreyImage(m_Window, m_Level);
  update();
}

void
GreyImageView::SetCaption(const QString & caption)
{
  m_Caption = caption;
  update();
}

QSizeF
GreyImageView::ImageExtent() const
{
  return QSizeF(m_Grey.size());
}

QRectF
GreyImageView::ImageRect() const
{
  const QSizeF extent = ImageExtent();
  if (m_Grey.isNull() || !(extent.width() > 0.0) || !(extent.height() > 0.0))
  {
    return QRectF();
  }
  const double scale = std::max(
    0.0, std::min((width() - 2.0 * Margin) / extent.width(), (height() - CaptionHeight - Margin) / extent.height()));
  const QSizeF size(extent.width() * scale, extent.height() * scale);
  return QRectF(QPointF(0.5 * (width() - size.width()), CaptionHeight), size);
}

void
GreyImageView::PaintOverlay(QPainter &, const QRectF &)
{
}

void
GreyImageView::paintEvent(QPaintEvent *)
{
  QPainter painter(this);
  painter.fillRect(rect(), QColor(20, 20, 26));
  // An empty view shows nothing, not the caption of the image it no longer has.
  if (m_Grey.isNull())
  {
    return;
  }
  const QRectF target = ImageRect();
  painter.drawImage(target, m_Grey);
  painter.save();
  PaintOverlay(painter, target);
  painter.restore();
  painter.setPen(Qt::white);
  painter.drawText(
    QRectF(Margin, 2.0, width() - 2.0 * Margin, CaptionHeight - Margin), Qt::AlignLeft | Qt::AlignVCenter, m_Caption);
}
} // namespace vr
