// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrViewerLayout.h"

#include <QDataStream>
#include <QEvent>
#include <QSplitter>

#include <algorithm>
#include <numeric>

namespace vr
{
namespace
{
constexpr int Parts = 4;

/** Adds \a pixels to the shown parts among \a takers in proportion to \a weights (the last one takes the rounding). */
void
Share(QList<int> & sizes, int pixels, const QList<bool> & shown, const std::vector<int> & takers, const int * weights)
{
  int total = 0;
  for (std::size_t k = 0; k < takers.size(); ++k)
  {
    total += shown[takers[k]] ? weights[k] : 0;
  }
  if (total == 0 || pixels == 0)
  {
    return;
  }
  int given = 0;
  int last = -1;
  for (std::size_t k = 0; k < takers.size(); ++k)
  {
    if (!shown[takers[k]])
    {
      continue;
    }
    const int share = pixels * weights[k] / total;
    sizes[takers[k]] += share;
    given += share;
    last = takers[k];
  }
  sizes[last] += pixels - given;
}
} // namespace

ViewerLayout::ViewerLayout(QSplitter * splitter)
  : QObject(splitter)
  , m_Splitter(splitter)
{
  // The 3D view and the module panel may give way to nothing; the CPR view and the path panel never do.
  m_Splitter->setChildrenCollapsible(false);
  m_Splitter->setCollapsible(Panel, true);
  m_Splitter->setCollapsible(ThreeD, true);
  m_Splitter->widget(CPR)->setMinimumWidth(MinimumCPRWidth);
  m_Splitter->widget(ThreeD)->setMinimumWidth(MinimumThreeDWidth);
  m_Splitter->widget(Path)->setMinimumWidth(MinimumPathPanelWidth);
  m_Splitter->installEventFilter(this);
  m_Splitter->widget(Path)->installEventFilter(this);
  UpdateMinimumWidth();
}

void
ViewerLayout::UpdateMinimumWidth()
{
  // A splitter is as narrow as the sum of its shown children's minimums unless told otherwise; the parts that give
  // way (the 3D view, the module panel) must not count, or the window could not be narrower than all of them.
  const bool path = !m_Splitter->widget(Path)->isHidden();
  m_Splitter->setMinimumWidth(MinimumCPRWidth + (path ? std::max(MinimumPathPanelWidth, Minimums()[Path]) : 0) +
                              3 * m_Splitter->handleWidth());
}

QList<int>
ViewerLayout::Minimums() const
{
  QList<int> minimum;
  for (int k = 0; k < Parts; ++k)
  {
    const QWidget * widget = m_Splitter->widget(k);
    minimum << std::max(widget->minimumWidth(), widget->minimumSizeHint().width());
  }
  return minimum;
}

QList<bool>
ViewerLayout::Shown() const
{
  QList<bool> shown;
  for (int k = 0; k < Parts; ++k)
  {
    shown << !m_Splitter->widget(k)->isHidden();
  }
  return shown;
}

int
ViewerLayout::Room() const
{
  const QList<bool> shown = Shown();
  const int         count = static_cast<int>(std::count(shown.begin(), shown.end(), true));
  return std::max(0, m_Splitter->width() - std::max(0, count - 1) * m_Splitter->handleWidth());
}

QList<int>
ViewerLayout::Fit(const QList<int> & sizes, const QList<int> & minimum, const QList<bool> & shown, int total)
{
  QList<int> out;
  long long  sum = 0;
  for (int k = 0; k < Parts; ++k)
  {
    out << (shown[k] ? std::max(0, sizes.value(k)) : 0);
    sum += out[k];
  }
  if (sum <= 0)
  {
    return Defaults(minimum[Panel], minimum, shown, total);
  }
  // The views scaled to the room the module panel leaves (it keeps its width: a panel, not a view).
  const long long views = sum - out[Panel];
  const long long room = std::max<long long>(0, total - out[Panel]);
  for (const int k : { static_cast<int>(CPR), static_cast<int>(ThreeD), static_cast<int>(Path) })
  {
    out[k] = views > 0 ? static_cast<int>(static_cast<long long>(out[k]) * room / views) : 0;
  }
  // Parts that must stay shown get their minimum (a collapsed module panel stays collapsed).
  for (const int k : { static_cast<int>(Panel), static_cast<int>(CPR), static_cast<int>(Path) })
  {
    if (shown[k] && (k != Panel || out[k] > 0))
    {
      out[k] = std::max(out[k], minimum[k]);
    }
  }
  if (out[ThreeD] > 0 && out[ThreeD] < MinimumThreeDWidth)
  {
    out[ThreeD] = 0; // hidden rather than a strip
  }
  int excess = std::accumulate(out.begin(), out.end(), 0) - total;
  // Giving way: the 3D view to its minimum first, then the module panel to its minimum, then the CPR view and the
  // path panel to theirs; then the 3D view altogether, then the module panel.
  const auto take = [&](int part, int floor)
  {
    const int given = std::clamp(out[part] - floor, 0, std::max(0, excess));
    out[part] -= given;
    excess -= given;
  };
  if (excess > 0 && out[ThreeD] > 0)
  {
    take(ThreeD, MinimumThreeDWidth);
  }
  if (excess > 0 && out[Panel] > 0)
  {
    take(Panel, minimum[Panel]);
  }
  if (excess > 0)
  {
    // The CPR view and the path panel in proportion to what each has above its minimum.
    const int above = (shown[CPR] ? out[CPR] - minimum[CPR] : 0) + (shown[Path] ? out[Path] - minimum[Path] : 0);
    if (above > 0)
    {
      const int pixels = std::min(excess, above);
      const int fromCPR = shown[Path] ? pixels * (out[CPR] - minimum[CPR]) / above : pixels;
      out[CPR] -= fromCPR;
      out[Path] -= pixels - fromCPR;
      excess -= pixels;
    }
  }
  for (const int part : { static_cast<int>(ThreeD), static_cast<int>(Panel) })
  {
    if (excess > 0 && out[part] > 0)
    {
      excess -= out[part];
      out[part] = 0;
    }
  }
  if (excess < 0)
  {
    // Room left (a part hidden rather than squeezed): to the views, the 3D view's share while it is shown.
    static const int weights[] = { 3, 2, 3 };
    QList<bool>      takers = shown;
    takers[ThreeD] = shown[ThreeD] && out[ThreeD] > 0;
    Share(out, -excess, takers, { CPR, ThreeD, Path }, weights);
  }
  return out;
}

QList<int>
ViewerLayout::Defaults(int panelWidth, const QList<int> & minimum, const QList<bool> & shown, int total)
{
  QList<int> sizes = { 0, 0, 0, 0 };
  sizes[Panel] = shown[Panel] ? std::max(panelWidth, minimum[Panel]) : 0;
  const int        rest = std::max(0, total - sizes[Panel]);
  static const int weights[] = { 3, 2, 3 };
  Share(sizes, rest, shown, { CPR, ThreeD, Path }, weights);
  // Only the module panel's and the views' shares: Fit keeps the minimums.
  QList<int> wanted = sizes;
  if (std::accumulate(wanted.begin(), wanted.end(), 0) <= 0)
  {
    wanted[CPR] = 1;
  }
  return Fit(wanted, minimum, shown, total);
}

void
ViewerLayout::Apply(const QList<int> & sizes)
{
  m_Applying = true;
  m_Splitter->setSizes(sizes);
  m_Applying = false;
}

void
ViewerLayout::Reset()
{
  // Before the window is shown the splitter's width is not the window's: the layout waits for it.
  m_Pending.clear();
  m_PendingDefaults = true;
  if (m_Splitter->isVisible())
  {
    ApplyPending();
  }
}

QList<int>
ViewerLayout::SavedSizes(const QByteArray & state)
{
  // QSplitter::saveState's layout: a marker, a version, then the sizes as a count and the values (and more the
  // layout does not need). The count is checked against the bytes there before anything is read: a settings file is
  // input like any other.
  QDataStream stream(state);
  qint32      marker = 0;
  qint32      version = -1;
  qint32      count = -1;
  stream >> marker >> version >> count;
  if (stream.status() != QDataStream::Ok || marker != 0xff || version < 0 || version > 1 || count < 0 || count > 64 ||
      state.size() < 12 + 4 * count)
  {
    return QList<int>();
  }
  QList<int> sizes;
  for (qint32 k = 0; k < count; ++k)
  {
    qint32 size = 0;
    stream >> size;
    sizes << size;
  }
  return stream.status() == QDataStream::Ok ? sizes : QList<int>();
}

bool
ViewerLayout::Restore(const QByteArray & state)
{
  // Every view shown at the start but the path panel, which opens with a path.
  for (const int part : { static_cast<int>(Panel), static_cast<int>(CPR), static_cast<int>(ThreeD) })
  {
    m_Splitter->widget(part)->setVisible(true);
  }
  m_Splitter->widget(Path)->setVisible(false);
  const QList<int> sizes = SavedSizes(state);
  const bool usable = sizes.size() == Parts && sizes[CPR] >= MinimumCPRWidth && sizes[ThreeD] >= MinimumThreeDWidth;
  if (!usable)
  {
    Reset();
    return false;
  }
  m_Pending = sizes;
  if (m_Splitter->isVisible())
  {
    ApplyPending();
  }
  return true;
}

void
ViewerLayout::ApplyPending()
{
  const QList<int>  minimum = Minimums();
  const QList<bool> shown = Shown();
  const int         room = Room();
  const QList<int>  sizes = m_Pending.isEmpty() ? Defaults(minimum[Panel], minimum, shown, room) : m_Pending;
  m_Pending.clear();
  m_PendingDefaults = false;
  Apply(Fit(sizes, minimum, shown, room));
}

void
ViewerLayout::ShowPathPanel()
{
  if (!m_Splitter->widget(Path)->isHidden())
  {
    return;
  }
  // Room for the panel, taken from the CPR and 3D views (the module panel keeps its width).
  QList<int> sizes = m_Splitter->sizes();
  const int  room = sizes[CPR] + sizes[ThreeD];
  sizes[CPR] = room * 36 / 100;
  sizes[ThreeD] = sizes[ThreeD] > 0 ? room * 22 / 100 : 0;
  sizes[Path] = room - sizes[CPR] - sizes[ThreeD];
  m_Splitter->widget(Path)->setVisible(true);
  Apply(Fit(sizes, Minimums(), Shown(), Room()));
}

bool
ViewerLayout::eventFilter(QObject * watched, QEvent * event)
{
  const QEvent::Type type = event->type();
  if (type != QEvent::Show && type != QEvent::Hide && type != QEvent::Resize)
  {
    return QObject::eventFilter(watched, event); // nothing of the layout's: the splitter is not asked
  }
  if (watched == m_Splitter->widget(Path) && (type == QEvent::Show || type == QEvent::Hide))
  {
    UpdateMinimumWidth();
  }
  if (watched == m_Splitter && event->type() == QEvent::Resize && !m_Applying)
  {
    const QList<int>  minimum = Minimums();
    const QList<bool> shown = Shown();
    const int         room = Room();
    if (m_PendingDefaults || !m_Pending.isEmpty())
    {
      ApplyPending();
      return QObject::eventFilter(watched, event);
    }
    QList<int> sizes = m_Splitter->sizes();
    // The 3D view comes back when its default share fits again.
    const QList<int> defaults = Defaults(minimum[Panel], minimum, shown, room);
    if (shown[ThreeD] && sizes.value(ThreeD) == 0 && defaults[ThreeD] >= MinimumThreeDWidth)
    {
      sizes = defaults;
    }
    Apply(Fit(sizes, minimum, shown, room));
  }
  return QObject::eventFilter(watched, event);
}
} // namespace vr
