// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrWindowKeyPolicy.h"

#include <QAbstractSpinBox>
#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QKeyEvent>
#include <QLineEdit>
#include <QPlainTextEdit>
#include <QTextEdit>
#include <QWidget>

namespace vr
{
namespace
{
/** The key of \a event as a shortcut would name it (the keypad's flag dropped: Qt matches shortcuts without it). */
QKeySequence
SequenceOf(const QKeyEvent * event)
{
  const auto modifiers = event->modifiers() & ~Qt::KeypadModifier;
  return QKeySequence(static_cast<int>(event->key()) | static_cast<int>(modifiers));
}

/** A key that types into or edits a text field's text. */
bool
IsTypingKey(const QKeyEvent * event)
{
  if (event->key() == Qt::Key_Backspace || event->key() == Qt::Key_Delete)
  {
    return true;
  }
  const bool command = event->modifiers() & (Qt::ControlModifier | Qt::AltModifier | Qt::MetaModifier);
  return !command && !event->text().isEmpty() && event->text().at(0).isPrint();
}
} // namespace

WindowKeyPolicy::WindowKeyPolicy(QWidget * window)
  : QObject(window)
  , m_Window(window)
{
  qApp->installEventFilter(this);
}

WindowKeyPolicy::~WindowKeyPolicy()
{
  qApp->removeEventFilter(this);
}

bool
WindowKeyPolicy::IsTextField(const QWidget * widget)
{
  if (widget == nullptr)
  {
    return false;
  }
  if (qobject_cast<const QLineEdit *>(widget) || qobject_cast<const QAbstractSpinBox *>(widget))
  {
    return true;
  }
  if (const auto * combo = qobject_cast<const QComboBox *>(widget))
  {
    return combo->isEditable();
  }
  if (const auto * text = qobject_cast<const QTextEdit *>(widget))
  {
    return !text->isReadOnly();
  }
  if (const auto * text = qobject_cast<const QPlainTextEdit *>(widget))
  {
    return !text->isReadOnly();
  }
  return false;
}

bool
WindowKeyPolicy::IsWindowShortcut(const QKeySequence & sequence) const
{
  for (const QAction * action : m_Window->findChildren<QAction *>())
  {
    if (action->isEnabled() && action->shortcutContext() != Qt::WidgetShortcut &&
        action->shortcuts().contains(sequence))
    {
      return true;
    }
  }
  return false;
}

bool
WindowKeyPolicy::eventFilter(QObject * watched, QEvent * event)
{
  const QEvent::Type type = event->type();
  if (type != QEvent::KeyPress && type != QEvent::ShortcutOverride && type != QEvent::FocusOut)
  {
    return QObject::eventFilter(watched, event);
  }
  auto * widget = qobject_cast<QWidget *>(watched);
  if (widget == nullptr || widget->window() != m_Window)
  {
    return QObject::eventFilter(watched, event);
  }
  // The text field a key goes to: a spin box's or a combo box's own line edit counts as its owner (the owner has the
  // focus and forwards its keys to the line edit).
  QWidget * field = IsTextField(widget) ? widget : nullptr;
  QWidget * owner = widget->parentWidget();
  if (qobject_cast<QLineEdit *>(widget) &&
      (qobject_cast<QAbstractSpinBox *>(owner) || qobject_cast<QComboBox *>(owner)))
  {
    field = owner;
  }
  if (type == QEvent::FocusOut)
  {
    if (m_Typing && (widget == m_Typing || m_Typing->isAncestorOf(widget)))
    {
      m_Typing.clear();
    }
    return QObject::eventFilter(watched, event);
  }
  auto * key = static_cast<QKeyEvent *>(event);
  if (type == QEvent::KeyPress)
  {
    if (field != nullptr && IsTypingKey(key))
    {
      m_Typing = field;
    }
    else if (key->key() == Qt::Key_Return || key->key() == Qt::Key_Enter || key->key() == Qt::Key_Escape)
    {
      m_Typing.clear();
    }
    return QObject::eventFilter(watched, event);
  }
  // ShortcutOverride: the window's shortcut wins unless the user is typing in this field.
  const bool typing = field != nullptr && field == m_Typing;
  if (!typing && IsWindowShortcut(SequenceOf(key)))
  {
    key->ignore();
    return true;
  }
  return QObject::eventFilter(watched, event);
}
} // namespace vr
