// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrViewerStatusBar.h"

#include <QPainter>
#include <QProgressBar>
#include <QStyleOption>

namespace vr
{
ElidedLabel::ElidedLabel(QWidget * parent)
  : QLabel(parent)
{
  setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);
  setTextFormat(Qt::PlainText);
}

void
ElidedLabel::SetText(const QString & text, const QString & tooltip)
{
  setText(text);
  setToolTip(tooltip.isEmpty() ? text : tooltip);
}

QSize
ElidedLabel::minimumSizeHint() const
{
  return QSize(40, QLabel::minimumSizeHint().height());
}

void
ElidedLabel::paintEvent(QPaintEvent *)
{
  QPainter    painter(this);
  const QRect area = contentsRect();
  painter.drawText(area,
                   static_cast<int>(alignment()) | Qt::TextSingleLine,
                   fontMetrics().elidedText(text(), Qt::ElideRight, area.width()));
}

ViewerStatusBar::ViewerStatusBar(QWidget * parent)
  : QStatusBar(parent)
  , m_Message(new ElidedLabel)
  , m_Readout(new ElidedLabel)
  , m_Times(new ElidedLabel)
  , m_Progress(new QProgressBar)
{
  m_Message->setObjectName(QStringLiteral("statusMessage"));
  m_Readout->setObjectName(QStringLiteral("statusReadout"));
  m_Times->setObjectName(QStringLiteral("statusTimes"));
  m_Times->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
  m_Progress->setRange(0, 1000);
  m_Progress->setMaximumWidth(160);
  m_Progress->setTextVisible(false);
  m_Progress->setVisible(false);
  // Permanent, so that a message hides none of them: it has its own field.
  addPermanentWidget(m_Message, 3);
  addPermanentWidget(m_Readout, 4);
  addPermanentWidget(m_Times, 3);
  addPermanentWidget(m_Progress);
  connect(this, &QStatusBar::messageChanged, m_Message, [this](const QString & text) { m_Message->SetText(text); });
}

void
ViewerStatusBar::paintEvent(QPaintEvent *)
{
  // The panel alone: the message is in its field, not drawn across the bar.
  QPainter     painter(this);
  QStyleOption option;
  option.initFrom(this);
  style()->drawPrimitive(QStyle::PE_PanelStatusBar, &option, &painter, this);
}
} // namespace vr
