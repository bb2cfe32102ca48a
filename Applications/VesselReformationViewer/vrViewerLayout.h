// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrViewerLayout_h
#define vrViewerLayout_h

#include <QByteArray>
#include <QList>
#include <QObject>

class QSplitter;

namespace vr
{
/** \class ViewerLayout
 * \brief The split of the viewer's window between the module panel, the CPR view, the 3D view and the vessel path
 * panel (docs/viewer.md, "Layout"), kept so that no view is ever lost:
 * - the CPR view is never narrower than MinimumCPRWidth and the path panel than MinimumPathPanelWidth; the module
 *   panel keeps its own minimum while there is room for it;
 * - when the window is too narrow for all, the 3D view gives way first (down to nothing: below MinimumThreeDWidth it
 *   is hidden rather than drawn as a strip), then the module panel, then the CPR view and the path panel share what
 *   is left down to their minimums; the 3D view comes back when the window has room again;
 * - sizes saved by an earlier run are checked when restored: a view narrower than its minimum (a split saved as
 *   [323, 0, 0, -1] shows only the panel) resets the layout;
 * - Reset() is View > Reset layout.
 *
 * It watches the splitter's resizes (an event filter) and sets its sizes; the window owns it. Sizes are in pixels of
 * the splitter's children, the order of Part.
 * \ingroup VesselReformation
 */
class ViewerLayout : public QObject
{
  Q_OBJECT

public:
  /** The splitter's children, in order. */
  enum Part
  {
    Panel = 0,
    CPR = 1,
    ThreeD = 2,
    Path = 3
  };
  static constexpr int MinimumCPRWidth = 240;
  static constexpr int MinimumPathPanelWidth = 300;
  static constexpr int MinimumThreeDWidth = 120;

  /** Takes \a splitter's four children in the order of Part, sets their minimum widths and which may collapse. */
  explicit ViewerLayout(QSplitter * splitter);

  /** The default split for the splitter's width: the module panel at its width, the rest to the CPR view, the 3D
   * view and (when shown) the path panel as 3 : 2 : 3, minimums kept in the give-way order. */
  void
  Reset();
  /** Restores a split saved by QSplitter::saveState, in proportion to the window's width now, or resets when the
   * saved split had the CPR view or the 3D view narrower than its minimum, or cannot be read. The path panel stays
   * hidden (it opens with a path). \return whether the saved split was kept. */
  bool
  Restore(const QByteArray & state);
  /** The sizes in a QSplitter::saveState, or an empty list when \a state is no such thing. */
  static QList<int>
  SavedSizes(const QByteArray & state);
  /** Shows the path panel beside the views, taking its room from the CPR and 3D views. */
  void
  ShowPathPanel();

  /** The sizes for \a total pixels: the module panel at its size, the views' sizes scaled to the rest, then minimums
   * kept in the give-way order above.
   * \param sizes the wanted sizes (any total), one per Part; a hidden part's size is ignored and returned as 0.
   * \param minimum the minimum width of each part (the module panel's included). \param shown which parts are shown.
   * \param total the pixels the shown parts share (the splitter's width less its handles). */
  static QList<int>
  Fit(const QList<int> & sizes, const QList<int> & minimum, const QList<bool> & shown, int total);
  /** The default sizes for \a total pixels (Reset's), with the module panel's preferred width \a panelWidth. */
  static QList<int>
  Defaults(int panelWidth, const QList<int> & minimum, const QList<bool> & shown, int total);

protected:
  bool
  eventFilter(QObject * watched, QEvent * event) override;

private:
  QList<int>
  Minimums() const;
  QList<bool>
  Shown() const;
  int
  Room() const;
  void
  Apply(const QList<int> & sizes);
  /** The splitter's own minimum width: the CPR view's and, while shown, the path panel's. */
  void
  UpdateMinimumWidth();
  /** Applies the restored sizes, or the defaults, waiting for the splitter's first size on screen. */
  void
  ApplyPending();

  QSplitter * m_Splitter;
  bool        m_Applying{ false };
  QList<int>  m_Pending;
  bool        m_PendingDefaults{ false };
};
} // namespace vr

#endif
