// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrWindowKeyPolicy_h
#define vrWindowKeyPolicy_h

#include <QKeySequence>
#include <QObject>
#include <QPointer>

class QWidget;

namespace vr
{
/** \class WindowKeyPolicy
 * \brief Makes a window's shortcuts (its QActions: undo, turning the view, stepping the vessel path's
 * cross-section, the window presets) work wherever the focus is in it (docs/viewer.md, "Keys").
 *
 * Qt lets the focused widget claim a key before the window's shortcuts see it (QEvent::ShortcutOverride): a spin box
 * claims Up, Down, Page Up and Down, Left, Right, Home and Ctrl+Z, a list or tree view its arrows. This policy, an
 * application event filter, refuses those claims for keys that are one of the window's enabled shortcuts, except
 * while the user is typing in a text field (a line edit, a spin box, an editable combo box or text editor) of the
 * window: from the first character, Backspace or Delete typed there until Return, Enter, Escape or the focus leaves
 * it, the field keeps its keys (its cursor keys, its own Ctrl+Z). Keys that are no enabled shortcut of the window
 * (the section keys while no path is open) stay the focused widget's, as Qt has them.
 * \ingroup VesselReformation
 */
class WindowKeyPolicy : public QObject
{
  Q_OBJECT

public:
  /** Applies to \a window's widgets; installs itself on the application, and goes with \a window. */
  explicit WindowKeyPolicy(QWidget * window);
  ~WindowKeyPolicy() override;

  /** \return whether \a sequence is the shortcut of one of the window's enabled actions. */
  bool
  IsWindowShortcut(const QKeySequence & sequence) const;
  /** \return the text field the user is typing in, or null. */
  QWidget *
  GetTypingField() const
  {
    return m_Typing;
  }
  /** \return whether \a widget takes typed text (a line edit, spin box, editable combo box, text editor). */
  static bool
  IsTextField(const QWidget * widget);

protected:
  bool
  eventFilter(QObject * watched, QEvent * event) override;

private:
  QWidget *         m_Window;
  QPointer<QWidget> m_Typing;
};
} // namespace vr

#endif
