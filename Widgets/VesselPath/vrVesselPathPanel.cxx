// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrVesselPathPanel.h"

#include "vrCrossSectionView.h"
#include "vrLumenProfilePlot.h"
#include "vrInputError.h"
#include "vrLumenMeasurement.h"
#include "vrStraightenedCPRView.h"
#include "vrVesselPathReport.h"
#include "vrVesselPathSettings.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QPointer>
#include <QScrollArea>
#include <QScrollBar>
#include <QSignalBlocker>
#include <QTabWidget>
#include <QTextBrowser>
#include <QVBoxLayout>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <limits>

namespace vr
{
namespace
{
double
WrapDegrees(double degrees)
{
  double wrapped = std::fmod(degrees, 360.0);
  if (wrapped <= -180.0)
  {
    wrapped += 360.0;
  }
  else if (wrapped > 180.0)
  {
    wrapped -= 360.0;
  }
  return wrapped;
}
} // namespace

/** The logic of one inputs' reading: made with the inputs, then touched by the worker's tasks only. */
struct VesselPathPanel::Session
{
  VesselPathLogic Logic;
};

VesselPathPanel::VesselPathPanel(QWidget * parent)
  : QWidget(parent)
  , m_Session(std::make_shared<Session>())
{
  m_Branches = new QComboBox;
  m_Branches->setToolTip(tr("The path shown: from the tree's root to this branch's far end. Ctrl+click a vessel in the "
                            "CPR view opens its path too."));
  // Long vessel names must not widen the panel beyond the window: the list shows them whole when it opens.
  m_Branches->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
  m_Branches->setMinimumContentsLength(12);
  m_Stretched = new QCheckBox(tr("Stretched"));
  m_Stretched->setToolTip(tr("Stretched CPR: sampling lines along the tree view's horizontal, distances along the "
                             "projected path kept; off: straightened, the path as the middle column."));
  m_Roll = new QDoubleSpinBox;
  m_Roll->setRange(-180.0, 180.0);
  m_Roll->setDecimals(1);
  m_Roll->setSuffix(QStringLiteral("°"));
  m_Roll->setWrapping(true);
  m_Roll->setKeyboardTracking(false);
  m_Roll->setToolTip(tr("Rotation of the image about the path, degrees (left-drag on the image rolls it)."));
  auto * title = new QHBoxLayout;
  title->addWidget(new QLabel(tr("<b>Vessel path</b>")));
  title->addWidget(m_Branches, 1);
  auto * view = new QHBoxLayout;
  view->addWidget(m_Stretched);
  view->addStretch(1);
  view->addWidget(new QLabel(tr("Roll")));
  view->addWidget(m_Roll);

  m_CPR = new StraightenedCPRView;
  m_CrossSection = new CrossSectionView;
  m_Plot = new LumenProfilePlot;
  // The report in an area of its own that scrolls: never drawn over an image, whatever the panel's size.
  m_Measurements = new QTextBrowser;
  m_Measurements->setObjectName(QStringLiteral("vesselPathReport"));
  m_Measurements->setOpenLinks(false);
  m_Measurements->setMinimumSize(120, 60);
  m_Settings = new VesselPathSettings;
  auto * settings = new QScrollArea;
  settings->setWidget(m_Settings);
  settings->setWidgetResizable(true);
  settings->setMinimumSize(120, 60);
  m_Tabs = new QTabWidget;
  m_Tabs->addTab(m_Measurements, tr("Report"));
  m_Tabs->addTab(settings, tr("Settings"));

  auto * right = new QVBoxLayout;
  right->addWidget(m_CrossSection, 2);
  right->addWidget(m_Tabs, 3);
  auto * images = new QHBoxLayout;
  images->addWidget(m_CPR, 2);
  images->addLayout(right, 3);
  auto * layout = new QVBoxLayout(this);
  layout->setContentsMargins(4, 4, 4, 4);
  layout->addLayout(title);
  layout->addLayout(view);
  layout->addLayout(images, 3);
  layout->addWidget(m_Plot, 2);

  connect(m_Settings, &VesselPathSettings::edited, this, [this] { ApplySettings(); });
  connect(m_Measurements, &QTextBrowser::anchorClicked, this, [this](const QUrl & link) { FollowReportLink(link); });
  connect(m_Branches,
          QOverload<int>::of(&QComboBox::activated),
          this,
          [this](int index) { OpenBranch(m_Branches->itemData(index).toInt()); });
  connect(m_Stretched, &QCheckBox::toggled, this, [this](bool on) { SetStretched(on); });
  connect(m_Roll, QOverload<double>::of(&QDoubleSpinBox::valueChanged), this, [this](double v) { SetRoll(v); });
  // While a drag rolls the image, the logic resamples the CPR alone: the cross-section stack (one plane per row,
  // tens of times the CPR's samples) follows at the release.
  connect(m_CPR,
          &StraightenedCPRView::rollStarted,
          this,
          [this]
          {
            m_DragStartRoll = GetRoll();
            m_CrossSections = false;
          });
  connect(m_CPR,
          &StraightenedCPRView::rollDragged,
          this,
          [this](double degrees, bool finished)
          {
            if (finished)
            {
              m_CrossSections = true;
            }
            SetRoll(m_DragStartRoll + degrees);
            if (finished && HasPath() && !m_RequestedCrossSections)
            {
              Request(Purpose::Look, m_Parameters);
            }
          });
  connect(m_CPR,
          &StraightenedCPRView::rowPicked,
          this,
          [this](double row)
          {
            if (!HasPath())
            {
              return;
            }
            // The section whose row lies nearest (rows need not be evenly spaced in arc length: stretched).
            const auto & rows = m_Shown->SectionRows;
            int          best = 0;
            double       distance = std::numeric_limits<double>::infinity();
            for (std::size_t i = 0; i < rows.size(); ++i)
            {
              const double d = std::abs(rows[i] - row);
              if (d < distance)
              {
                distance = d;
                best = static_cast<int>(i);
              }
            }
            SetSectionIndex(best);
          });
  connect(m_CPR, &StraightenedCPRView::stepped, this, [this](int n) { StepSections(n); });
  connect(m_CrossSection, &CrossSectionView::stepped, this, [this](int n) { StepSections(n); });
  connect(m_Plot, &LumenProfilePlot::arcLengthPicked, this, [this](double s) { SetArcLength(s); });
  setEnabled(false);
}

VesselPathPanel::~VesselPathPanel() = default;

void
VesselPathPanel::SetWorker(LogicWorker * worker)
{
  m_Worker = worker;
}

const VesselPathOutputs &
VesselPathPanel::GetOutputs() const
{
  static const VesselPathOutputs none{};
  return m_Shown ? m_Shown->Outputs : none;
}

void
VesselPathPanel::SetInputs(std::shared_ptr<const ReformationInputs> inputs)
{
  m_Inputs = std::move(inputs);
  // A logic of their own for new inputs: a task still running for the old ones keeps the old session and is not shown.
  m_Session = std::make_shared<Session>();
  m_Shown = nullptr;
  m_AnsweredId = m_RequestedId;
  m_Section = 0;
  m_Branches->clear();
  m_CPR->SetImage(nullptr, m_Window, m_Level);
  m_CrossSection->SetSlice(nullptr, 0, m_Window, m_Level);
  m_Plot->Clear();
  m_Measurements->clear();
  m_ReportHTML.clear();
  if (!m_Inputs)
  {
    setEnabled(false);
    return;
  }
  m_Branches->addItem(tr("longest path"), 0);
  for (const auto & branch : m_Inputs->Tree.GetBranches())
  {
    m_Branches->addItem(
      QStringLiteral("%1: %2").arg(branch.Id).arg(QString::fromStdString(m_Inputs->BranchName(branch.Id))), branch.Id);
  }
  setEnabled(true);
}

void
VesselPathPanel::SetViewParameters(const ReformationParameters & parameters)
{
  m_View = parameters;
}

void
VesselPathPanel::SetLumenSegmentation(vtkSmartPointer<VolumeNode> segmentation)
{
  const vtkSmartPointer<VolumeNode> previous = m_Segmentation;
  m_Segmentation = segmentation;
  if (HasPath())
  {
    // The answer brings the previous segmentation back on a refusal.
    Request(Purpose::Segmentation, m_Parameters, 0.0, previous);
  }
}

void
VesselPathPanel::ReportError(const QString & message)
{
  m_LastError = message;
  emit errorOccurred(message);
}

bool
VesselPathPanel::Request(Purpose                      purpose,
                         const VesselPathParameters & previous,
                         double                       keepArcLength,
                         vtkSmartPointer<VolumeNode>  previousSegmentation)
{
  if (!m_Worker)
  {
    ReportError(tr("no worker to read the vessel path on"));
    return false;
  }
  if (!m_Inputs || !m_Inputs->Volume || !m_Inputs->Centerlines)
  {
    ReportError(tr("no volume and centerlines to read a vessel path in"));
    return false;
  }
  const std::uint64_t id = ++m_RequestedId;
  // What the task hands the logic, copied now: the worker never reads the panel.
  auto                              session = m_Session;
  const auto                        inputs = m_Inputs;
  const vtkSmartPointer<VolumeNode> segmentation = m_Segmentation ? m_Segmentation : m_Inputs->Segmentation;
  const VesselPathParameters        parameters = m_Parameters;
  const bool                        crossSections = m_CrossSections;
  m_RequestedCrossSections = crossSections;
  LogicWorker * const worker = m_Worker;
  auto                result = std::make_shared<VesselPathResult>();
  auto                error = std::make_shared<QString>();
  LogicWorker::Task   task;
  task.Run = [session, inputs, segmentation, parameters, crossSections, worker, result, error, id]
  {
    VesselPathLogic & logic = session->Logic;
    try
    {
      logic.SetProgressCallback([worker](double fraction, const std::string & stage)
                                { worker->ReportTaskProgress(fraction, "vessel path: " + stage); });
      logic.SetVolumeNode(inputs->Volume);
      logic.SetCenterlineNode(inputs->Centerlines);
      logic.SetSegmentationNode(segmentation);
      logic.SetCrossSectionsEnabled(crossSections);
      logic.SetParameters(parameters);
      const VesselPathStageCounts before = logic.GetStageCounts();
      const auto                  start = std::chrono::steady_clock::now();
      const VesselPathOutputs &   outputs = logic.Update();
      result->UpdateSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      result->RequestId = id;
      result->Parameters = parameters;
      result->Outputs = outputs;
      for (const auto & section : outputs.Sections)
      {
        result->SectionRows.push_back(logic.RowOfArcLength(section.ArcLength));
      }
      const VesselPathStageCounts & after = logic.GetStageCounts();
      result->StagesRun = { after.Path - before.Path,
                            after.Frame - before.Frame,
                            after.Resampling - before.Resampling,
                            after.Measurement - before.Measurement };
    }
    catch (const std::exception & failure)
    {
      *error = QString::fromUtf8(failure.what());
    }
  };
  QPointer<VesselPathPanel> panel(this);
  task.Done = [panel, id, purpose, result, error, previous, keepArcLength, previousSegmentation]
  {
    if (panel)
    {
      panel->Answer(
        id, purpose, error->isEmpty() ? result : nullptr, *error, previous, keepArcLength, previousSegmentation);
    }
  };
  m_Worker->RunTask(WorkerLane, std::move(task));
  return true;
}

void
VesselPathPanel::Answer(std::uint64_t                           id,
                        Purpose                                 purpose,
                        std::shared_ptr<const VesselPathResult> result,
                        const QString &                         error,
                        const VesselPathParameters &            previous,
                        double                                  keepArcLength,
                        vtkSmartPointer<VolumeNode>             previousSegmentation)
{
  if (id <= m_AnsweredId)
  {
    return; // for inputs replaced since (SetInputs answers every request made before)
  }
  // Tasks run in order: a request answered after this one was superseded while it waited, never ran.
  const bool latest = id == m_RequestedId;
  m_AnsweredId = id;
  if (!result)
  {
    if (!latest)
    {
      return;
    }
    // Refused: what is shown stays, and so do the parameters and the segmentation it was computed with.
    m_Parameters = m_Shown ? m_Shown->Parameters : previous;
    if (purpose == Purpose::Segmentation)
    {
      m_Segmentation = previousSegmentation;
    }
    if (HasPath())
    {
      m_Settings->Show(m_Parameters, m_PathLength);
      const QSignalBlocker blockRoll(m_Roll);
      m_Roll->setValue(m_Parameters.RollInDegrees);
      const QSignalBlocker blockStretched(m_Stretched);
      m_Stretched->setChecked(m_Parameters.Reformation == PathReformation::Stretched);
    }
    ReportError(error);
    return;
  }
  m_Shown = std::move(result);
  m_LastError.clear();
  ShowResults();
  m_CPR->repaint();
  if (!latest)
  {
    return; // a step of a drag: shown; what the request was for waits for the latest
  }
  const auto & outputs = m_Shown->Outputs;
  switch (purpose)
  {
    case Purpose::Open:
    {
      const int            branchId = m_Shown->Parameters.BranchId;
      const QSignalBlocker block(m_Branches);
      m_Branches->setCurrentIndex(std::max(0, m_Branches->findData(branchId)));
      // Open on the headline: the MLD of a graded stenosis, the aorta's maximum diameter; else the path's middle.
      m_PathLength = outputs.Path.GetLength();
      m_Settings->Show(m_Parameters, m_PathLength);
      const auto & stenosis = outputs.Stenosis;
      if (outputs.HasLumen && !stenosis.Grade.empty() && std::isfinite(stenosis.MinimalLumenDiameterArcLength))
      {
        SetArcLength(stenosis.MinimalLumenDiameterArcLength);
      }
      else if (outputs.HasLumen && std::isfinite(stenosis.MaximumDiameterArcLength))
      {
        SetArcLength(stenosis.MaximumDiameterArcLength);
      }
      else
      {
        SetSectionIndex(static_cast<int>(outputs.Sections.size() / 2));
      }
      emit pathOpened(branchId);
      break;
    }
    case Purpose::Change:
      m_Settings->Show(m_Parameters, m_PathLength);
      // The cross-section stays at the same place of the vessel when a range moves the path's start.
      SetArcLength(keepArcLength - outputs.Path.GetArcLengthOffset());
      break;
    case Purpose::Look:
    case Purpose::Segmentation:
      break;
  }
}

bool
VesselPathPanel::OpenBranch(int branchId)
{
  const VesselPathParameters previous = m_Parameters;
  VesselPathParameters       parameters = m_Parameters;
  parameters.BranchId = branchId;
  parameters.HasRange = false;
  parameters.ReferencePoints.clear();
  // At roll 0 the image looks as the tree view does at the path's start.
  parameters.AutomaticUp = m_View.AutomaticUp;
  parameters.Up = m_View.Up;
  parameters.ViewAngleInDegrees = m_View.AngleInDegrees;
  m_Parameters = parameters;
  if (!Request(Purpose::Open, previous))
  {
    m_Parameters = previous;
    return false;
  }
  return true;
}

bool
VesselPathPanel::RunWith(const VesselPathParameters & parameters)
{
  const VesselPathParameters previous = m_Parameters;
  const double               s = GetArcLength() + GetOutputs().Path.GetArcLengthOffset();
  m_Parameters = parameters;
  if (!Request(Purpose::Change, previous, s))
  {
    m_Parameters = previous;
    m_Settings->Show(m_Parameters, m_PathLength);
    return false;
  }
  return true;
}

bool
VesselPathPanel::ApplySettings()
{
  if (!HasPath())
  {
    return false;
  }
  VesselPathParameters parameters = m_Parameters;
  const QString        problem = m_Settings->Apply(parameters);
  if (!problem.isEmpty())
  {
    ReportError(problem);
    m_Settings->Show(m_Parameters, m_PathLength);
    return false;
  }
  return parameters == m_Parameters || RunWith(parameters);
}

void
VesselPathPanel::SetWidth(double width)
{
  VesselPathParameters parameters = m_Parameters;
  parameters.Width = width;
  if (!HasPath())
  {
    m_Parameters = parameters;
    m_Settings->Show(m_Parameters, m_PathLength);
    return;
  }
  RunWith(parameters);
}

void
VesselPathPanel::FollowReportLink(const QUrl & link)
{
  const QString text = link.toString();
  if (text.startsWith(QString::fromLatin1(ReportLink::Width)))
  {
    bool         number = false;
    const double width = text.mid(static_cast<int>(std::strlen(ReportLink::Width))).toDouble(&number);
    if (number && width > 0.0)
    {
      SetWidth(width);
    }
  }
  else if (text == QString::fromLatin1(ReportLink::Stretched))
  {
    SetStretched(true);
  }
}

void
VesselPathPanel::ShowResults()
{
  const auto &                 results = GetOutputs();
  const VesselPathParameters & shown = m_Shown->Parameters;
  const bool                   stretched = shown.Reformation == PathReformation::Stretched;
  m_CPR->SetImage(results.CPR.GetPointer(), m_Window, m_Level);
  m_CPR->SetCaption(
    tr("%1, roll %2°").arg(stretched ? tr("stretched") : tr("straightened")).arg(shown.RollInDegrees, 0, 'f', 1));
  if (results.HasLumen)
  {
    m_Plot->SetProfile(results.Lumen, results.Stenosis);
  }
  else
  {
    m_Plot->Clear();
  }
  m_Section = std::clamp(m_Section, 0, std::max(0, static_cast<int>(results.Sections.size()) - 1));
  ShowPosition();
}

void
VesselPathPanel::SetRoll(double degrees)
{
  const double roll = WrapDegrees(degrees);
  {
    const QSignalBlocker block(m_Roll);
    m_Roll->setValue(roll);
  }
  if (roll == m_Parameters.RollInDegrees)
  {
    return;
  }
  const VesselPathParameters previous = m_Parameters;
  m_Parameters.RollInDegrees = roll;
  if (HasPath())
  {
    // The new picture goes on screen as soon as it comes (Answer repaints at once: what the roll's latency is
    // measured on).
    Request(Purpose::Look, previous);
  }
}

double
VesselPathPanel::GetRoll() const
{
  return m_Parameters.RollInDegrees;
}

void
VesselPathPanel::SetStretched(bool stretched)
{
  {
    const QSignalBlocker block(m_Stretched);
    m_Stretched->setChecked(stretched);
  }
  const PathReformation reformation = stretched ? PathReformation::Stretched : PathReformation::Straightened;
  if (reformation == m_Parameters.Reformation)
  {
    return;
  }
  const VesselPathParameters previous = m_Parameters;
  m_Parameters.Reformation = reformation;
  if (HasPath())
  {
    Request(Purpose::Look, previous);
  }
}

bool
VesselPathPanel::IsStretched() const
{
  return m_Parameters.Reformation == PathReformation::Stretched;
}

void
VesselPathPanel::SetSectionIndex(int index)
{
  if (!HasPath())
  {
    return;
  }
  const int count = static_cast<int>(GetOutputs().Sections.size());
  m_Section = std::clamp(index, 0, std::max(0, count - 1));
  ShowPosition();
}

void
VesselPathPanel::StepSections(int sections)
{
  SetSectionIndex(m_Section + sections);
}

void
VesselPathPanel::SetArcLength(double arcLength)
{
  if (!HasPath())
  {
    return;
  }
  const auto & sections = GetOutputs().Sections;
  const auto   nearest = std::min_element(sections.begin(),
                                        sections.end(),
                                        [arcLength](const auto & a, const auto & b) {
                                          return std::abs(a.ArcLength - arcLength) < std::abs(b.ArcLength - arcLength);
                                        });
  if (nearest != sections.end())
  {
    SetSectionIndex(static_cast<int>(nearest - sections.begin()));
  }
}

double
VesselPathPanel::GetArcLength() const
{
  const auto & sections = GetOutputs().Sections;
  return HasPath() && !sections.empty() ? sections[static_cast<std::size_t>(m_Section)].ArcLength : 0.0;
}

void
VesselPathPanel::ShowPosition()
{
  const auto & results = GetOutputs();
  if (!HasPath() || results.Sections.empty())
  {
    return;
  }
  const double s = GetArcLength();
  m_CPR->SetPositionRow(m_Shown->SectionRows[static_cast<std::size_t>(m_Section)]);
  m_Plot->SetPosition(s);
  double diameter = std::numeric_limits<double>::quiet_NaN();
  if (results.HasLumen && static_cast<std::size_t>(m_Section) < results.Lumen.Sections.size())
  {
    diameter = results.Lumen.Sections[static_cast<std::size_t>(m_Section)].Diameter;
  }
  if (results.CrossSections)
  {
    m_CrossSection->SetSlice(
      results.CrossSections.GetPointer(), static_cast<unsigned int>(m_Section), m_Window, m_Level);
  }
  m_CrossSection->SetDiameter(diameter);
  m_CrossSection->SetCaption(tr("cross-section at s = %1 mm").arg(s, 0, 'f', 1));
  ShowMeasurements();
  emit positionChanged(SectionAt(results, s).Center);
}

void
VesselPathPanel::ShowMeasurements()
{
  const auto &  results = GetOutputs();
  const QString html = VesselPathReportHTML(results, static_cast<std::size_t>(m_Section), m_Shown->Parameters.Width);
  // Laid out again only when it changed (a roll changes nothing in it), and where it was scrolled to.
  if (html != m_ReportHTML)
  {
    m_ReportHTML = html;
    const int scrolled = m_Measurements->verticalScrollBar()->value();
    m_Measurements->setHtml(html);
    m_Measurements->verticalScrollBar()->setValue(scrolled);
  }
  std::string all;
  for (const auto & warning : results.Warnings)
  {
    all += (all.empty() ? "" : "\n") + warning;
  }
  m_Measurements->setToolTip(QString::fromStdString(all));
}

QString
VesselPathPanel::GetMeasurementText() const
{
  return m_Measurements->toPlainText();
}

void
VesselPathPanel::SetWindowLevel(double window, double level)
{
  m_Window = window;
  m_Level = level;
  m_CPR->SetWindowLevel(window, level);
  m_CrossSection->SetWindowLevel(window, level);
}

QString
VesselPathPanel::WriteLumenTable(const QString & path) const
{
  if (!HasPath() || !GetOutputs().HasLumen)
  {
    return tr("no lumen measured: open a vessel path first");
  }
  try
  {
    const auto & results = GetOutputs();
    vr::WriteLumenTable(
      results.Lumen, path.toStdString(), LumenTableNotesOf({ results.Lumen, results.Stenosis }, DescribePath(results)));
  }
  catch (const std::exception & error)
  {
    return QString::fromUtf8(error.what());
  }
  return QString();
}
} // namespace vr
