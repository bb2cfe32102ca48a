// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// The viewer window's keys (docs/viewer.md, "Keys"): every one an action of the window (its menus), so that it works
// wherever the focus is (vr::WindowKeyPolicy): turning the view, Home, the window presets, the layout, stepping the
// vessel path's cross-section.
#include "vrViewerWindow.h"

#include "vrIntensityWindow.h"
#include "vrSectionStepper.h"
#include "vrViewerLayout.h"

#include <QAction>
#include <QKeySequence>
#include <QMenu>

namespace vr
{
void
ViewerWindow::BuildViewKeys(QMenu * view)
{
  // Keys that turn the view and choose a window, as a reader works with the other hand on the mouse.
  view->addSeparator();
  const struct
  {
    const char * Name;
    QString      Text;
    double       Degrees;
    QKeySequence Key;
  } turns[] = { { "turnLeft1", tr("Turn left 1°"), -1.0, QKeySequence(Qt::Key_Left) },
                { "turnRight1", tr("Turn right 1°"), 1.0, QKeySequence(Qt::Key_Right) },
                { "turnLeft10", tr("Turn left 10°"), -10.0, QKeySequence(Qt::SHIFT | Qt::Key_Left) },
                { "turnRight10", tr("Turn right 10°"), 10.0, QKeySequence(Qt::SHIFT | Qt::Key_Right) } };
  for (const auto & turn : turns)
  {
    QAction * action = view->addAction(
      turn.Text, this, [this, degrees = turn.Degrees] { TurnBy(degrees); }, turn.Key);
    action->setObjectName(QString::fromLatin1(turn.Name));
    action->setShortcutContext(Qt::WindowShortcut);
  }
  QAction * home = view->addAction(
    tr("Reset the view"), this, [this] { ResetView(); }, QKeySequence(Qt::Key_Home));
  home->setObjectName(QStringLiteral("resetView"));
  view
    ->addAction(
      tr("&Best view (least hidden)"), this, [this] { GoToBestView(); }, QKeySequence(Qt::CTRL | Qt::Key_B))
    ->setObjectName(QStringLiteral("bestView"));
  QMenu *       presets = view->addMenu(tr("Window &preset"));
  const QString presetNames[] = { QString::fromLatin1(CTAPreset.Name),
                                  QString::fromLatin1(BonePreset.Name),
                                  QString::fromLatin1(SoftTissuePreset.Name),
                                  QString::fromUtf8(PercentilePresetName) };
  for (int k = 0; k < 4; ++k)
  {
    const QString name = presetNames[k];
    presets
      ->addAction(
        name, this, [this, name] { m_Panel->ApplyPreset(name, 0.0, 0.0); }, QKeySequence(Qt::CTRL | (Qt::Key_1 + k)))
      ->setObjectName(QStringLiteral("preset%1").arg(k + 1));
  }
  view->addSeparator();
  view->addAction(tr("Reset the &layout"), this, [this] { m_Layout->Reset(); })
    ->setObjectName(QStringLiteral("resetLayout"));
}

void
ViewerWindow::ResetView()
{
  m_Panel->SetAngle(0.0, RequestKind::Final);
  m_CPRView->FitImage();
  m_CPRView->Render();
  // Along the direction of the view at 0 degrees, not the one shown until its image comes.
  m_ThreeDView->ResetCameraForAngle(0.0);
  m_ThreeDView->ScheduleRender();
}

void
ViewerWindow::BuildSectionKeys(QMenu * vessel)
{
  // The cross-section's keys (vr::SectionStepper's, as its views take them), for the whole window while a path is
  // open; without a path they are no shortcut and stay the focused widget's.
  const struct
  {
    const char * Name;
    QString      Text;
    int          Key;
  } steps[] = { { "previousSection", tr("Previous section"), Qt::Key_Up },
                { "nextSection", tr("Next section"), Qt::Key_Down },
                { "previousSections", tr("%1 sections back").arg(SectionStepper::PageSections), Qt::Key_PageUp },
                { "nextSections", tr("%1 sections on").arg(SectionStepper::PageSections), Qt::Key_PageDown } };
  vessel->addSeparator();
  for (const auto & step : steps)
  {
    QAction * action = vessel->addAction(
      step.Text,
      this,
      [this, sections = SectionStepper::SectionsOfKey(step.Key)] { m_PathPanel->StepSections(sections); },
      QKeySequence(step.Key));
    action->setObjectName(QString::fromLatin1(step.Name));
    action->setShortcutContext(Qt::WindowShortcut);
    action->setEnabled(false);
    m_SectionActions.push_back(action);
  }
}

void
ViewerWindow::EnableSectionKeys(bool enabled)
{
  for (QAction * action : m_SectionActions)
  {
    action->setEnabled(enabled);
  }
}
} // namespace vr
