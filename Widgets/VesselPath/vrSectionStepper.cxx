// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrSectionStepper.h"

#include <QKeyEvent>
#include <QWheelEvent>
#include <QWidget>

namespace vr
{
SectionStepper::SectionStepper(QWidget * view)
  : QObject(view)
{
  view->installEventFilter(this);
}

int
SectionStepper::SectionsOfKey(int key)
{
  switch (key)
  {
    case Qt::Key_Up:
      return -1;
    case Qt::Key_Down:
      return 1;
    case Qt::Key_PageUp:
      return -PageSections;
    case Qt::Key_PageDown:
      return PageSections;
    default:
      return 0;
  }
}

QString
SectionStepper::Help()
{
  return tr("the wheel and the Up/Down keys move the cross-section by one section (Page Up/Down by %1)")
    .arg(PageSections);
}

bool
SectionStepper::eventFilter(QObject * watched, QEvent * event)
{
  if (event->type() == QEvent::KeyPress)
  {
    const int sections = SectionsOfKey(static_cast<QKeyEvent *>(event)->key());
    if (sections != 0)
    {
      emit stepped(sections);
      return true;
    }
  }
  else if (event->type() == QEvent::Wheel)
  {
    // Whole notches of 120 eighths of a degree; the event stops here either way, so no scroll area behind the view
    // moves as well.
    const int notches = -static_cast<QWheelEvent *>(event)->angleDelta().y() / 120;
    if (notches != 0)
    {
      emit stepped(notches);
    }
    return true;
  }
  return QObject::eventFilter(watched, event);
}
} // namespace vr
