// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrViewerStatusBar_h
#define vrViewerStatusBar_h

#include <QLabel>
#include <QStatusBar>

class QProgressBar;

namespace vr
{
/** \class ElidedLabel
 * \brief A one-line label that shows as much of its text as its width allows, ending in "…", the whole text in its
 * tooltip; it takes any width a layout gives it, so it never pushes into its neighbours.
 * \ingroup VesselReformation
 */
class ElidedLabel : public QLabel
{
  Q_OBJECT

public:
  explicit ElidedLabel(QWidget * parent = nullptr);
  /** Sets the text and the tooltip (the whole text, or \a tooltip when given). */
  void
  SetText(const QString & text, const QString & tooltip = QString());
  QSize
  minimumSizeHint() const override;

protected:
  void
  paintEvent(QPaintEvent * event) override;
};

/** \class ViewerStatusBar
 * \brief The viewer's status bar: each thing it says in a field of its own, side by side, none drawn over another
 * (docs/viewer.md): the latest message (QStatusBar::showMessage's, with its timeout), the pixel readout, the stage
 * times and the progress bar. QStatusBar draws a message over its widgets; here every field is a permanent widget and
 * the message goes to its own field instead.
 * \ingroup VesselReformation
 */
class ViewerStatusBar : public QStatusBar
{
  Q_OBJECT

public:
  explicit ViewerStatusBar(QWidget * parent = nullptr);

  ElidedLabel *
  GetMessageField() const
  {
    return m_Message;
  }
  ElidedLabel *
  GetReadoutField() const
  {
    return m_Readout;
  }
  ElidedLabel *
  GetTimesField() const
  {
    return m_Times;
  }
  QProgressBar *
  GetProgressBar() const
  {
    return m_Progress;
  }

protected:
  void
  paintEvent(QPaintEvent * event) override;

private:
  ElidedLabel *  m_Message;
  ElidedLabel *  m_Readout;
  ElidedLabel *  m_Times;
  QProgressBar * m_Progress;
};
} // namespace vr

#endif
