// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrSectionStepper_h
#define vrSectionStepper_h

#include <QObject>
#include <QString>

class QWidget;

namespace vr
{
/** \class SectionStepper
 * \brief The one handler of the keys and the wheel that move a vessel path's cross-section (docs/viewer.md), for
 * every view that moves it (vr::StraightenedCPRView, vr::CrossSectionView): an event filter on the view, which turns
 * - Up / Down into one section back / forward,
 * - Page Up / Page Down into PageSections back / forward,
 * - each notch of the wheel into one section (down: towards the path's end),
 *
 * and reports them by stepped(). Other keys and events go on to the view.
 * \ingroup VesselReformation
 */
class SectionStepper : public QObject
{
  Q_OBJECT

public:
  /** The sections Page Up / Page Down move by. */
  static constexpr int PageSections = 10;

  /** Watches \a view's keys and wheel; \a view owns the stepper. */
  explicit SectionStepper(QWidget * view);

  /** \return the sections key \a key moves by (Qt::Key): negative towards the path's start, 0 for any other key. */
  static int
  SectionsOfKey(int key);

  /** The keys and the wheel in words, for the views' tooltips. */
  static QString
  Help();

signals:
  void
  stepped(int sections);

protected:
  bool
  eventFilter(QObject * watched, QEvent * event) override;
};
} // namespace vr

#endif
