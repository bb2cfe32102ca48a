// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrVesselPathPanel.h"

#include "vrCrossSectionView.h"
#include "vrLumenProfilePlot.h"
#include "vrLumenMeasurement.h"
#include "vrNodeConversion.h"
#include "vrSegmentationIO.h"
#include "vrStraightenedCPRView.h"
#include "vrVesselPathReport.h"
#include "vrVesselPathSettings.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QHBoxLayout>
#include <QLabel>
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

VesselPathPanel::VesselPathPanel(QWidget * parent)
  : QWidget(parent)
  , m_Logic(std::make_unique<VesselPathLogic>())
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
            m_Logic->SetCrossSectionsEnabled(false);
          });
  connect(m_CPR,
          &StraightenedCPRView::rollDragged,
          this,
          [this](double degrees, bool finished)
          {
            if (finished)
            {
              m_Logic->SetCrossSectionsEnabled(true);
            }
            SetRoll(m_DragStartRoll + degrees);
            if (finished && m_HasPath && !m_Logic->GetResults().CrossSections)
            {
              Run();
            }
          });
  connect(m_CPR,
          &StraightenedCPRView::rowPicked,
          this,
          [this](double row)
          {
            if (!m_HasPath)
            {
              return;
            }
            // The section whose row lies nearest (rows need not be evenly spaced in arc length: stretched).
            const auto & sections = m_Logic->GetResults().Sections;
            int          best = 0;
            double       distance = std::numeric_limits<double>::infinity();
            for (std::size_t i = 0; i < sections.size(); ++i)
            {
              const double d = std::abs(m_Logic->RowOfArcLength(sections[i].ArcLength) - row);
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
VesselPathPanel::SetInputs(std::shared_ptr<const ReformationInputs> inputs)
{
  m_Inputs = std::move(inputs);
  m_Logic = std::make_unique<VesselPathLogic>();
  m_Volume = StoredVolume();
  m_LogicReady = false;
  m_HasPath = false;
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

QString
VesselPathPanel::SetLumenSegmentation(vtkSmartPointer<VolumeNode> segmentation, const QString & name)
{
  const LabelMapVolumeType::Pointer previousMask = m_Mask;
  const std::string                 previousName = m_MaskName;
  try
  {
    LabelMapVolumeType::Pointer mask;
    if (segmentation)
    {
      mask = MakeSegmentationMask(ConvertVolumeNodeToItkImage(segmentation).GetPointer(), {}, name.toStdString());
    }
    m_Mask = mask;
    m_MaskName = segmentation ? name.toStdString() : std::string();
  }
  catch (const std::exception & error)
  {
    m_LastError = QString::fromUtf8(error.what());
    return m_LastError;
  }
  m_LogicReady = false;
  if (m_HasPath && !Run(false))
  {
    // Refused (e.g. no section's centre inside it): the path goes back to what it was measured on.
    const QString error = m_LastError;
    m_Mask = previousMask;
    m_MaskName = previousName;
    m_LogicReady = false;
    Run();
    m_LastError = error;
    return error;
  }
  return QString();
}

bool
VesselPathPanel::PrepareLogic()
{
  if (m_LogicReady)
  {
    return true;
  }
  if (!m_Inputs || !m_Inputs->Volume)
  {
    m_LastError = tr("no volume to read a vessel path in");
    return false;
  }
  if (!m_Volume.Image)
  {
    // The node's voxels, shared: the panel reads the volume the tree view reads, in its stored type.
    m_Volume = ConvertVolumeNodeToStoredVolume(m_Inputs->Volume);
  }
  m_Logic->SetVolume(m_Volume.Image, m_Volume.Rescale);
  m_Logic->SetCenterlineTree(m_Inputs->Tree);
  LabelMapVolumeType::Pointer mask = m_Mask;
  std::string                 name = m_MaskName;
  if (!mask && m_Inputs->Segmentation)
  {
    name = "segmentation " + m_Inputs->Segmentation->GetName();
    mask = MakeSegmentationMask(ConvertVolumeNodeToItkImage(m_Inputs->Segmentation).GetPointer(), {}, name);
  }
  m_Logic->SetSegmentationMask(mask.GetPointer(), name);
  m_Logic->SetCrossSectionsEnabled(true);
  m_LogicReady = true;
  return true;
}

bool
VesselPathPanel::OpenBranch(int branchId)
{
  VesselPathParameters parameters = m_Parameters;
  parameters.BranchId = branchId;
  parameters.HasRange = false;
  parameters.ReferencePoints.clear();
  // At roll 0 the image looks as the tree view does at the path's start.
  parameters.AutomaticUp = m_View.AutomaticUp;
  parameters.Up = m_View.Up;
  parameters.ViewAngleInDegrees = m_View.AngleInDegrees;
  const VesselPathParameters previous = m_Parameters;
  const bool                 hadPath = m_HasPath;
  m_Parameters = parameters;
  if (!Run())
  {
    m_Parameters = previous;
    m_HasPath = hadPath;
    if (hadPath)
    {
      Run();
    }
    return false;
  }
  const QSignalBlocker block(m_Branches);
  m_Branches->setCurrentIndex(std::max(0, m_Branches->findData(branchId)));
  // Open on the headline: the MLD of a graded stenosis, the aorta's maximum diameter; else the path's middle.
  const auto & results = m_Logic->GetResults();
  m_PathLength = results.Path.GetLength();
  m_Settings->Show(m_Parameters, m_PathLength);
  const auto & stenosis = results.Stenosis;
  if (results.HasLumen && !stenosis.Grade.empty() && std::isfinite(stenosis.MinimalLumenDiameterArcLength))
  {
    SetArcLength(stenosis.MinimalLumenDiameterArcLength);
  }
  else if (results.HasLumen && std::isfinite(stenosis.MaximumDiameterArcLength))
  {
    SetArcLength(stenosis.MaximumDiameterArcLength);
  }
  else
  {
    SetSectionIndex(static_cast<int>(results.Sections.size() / 2));
  }
  emit pathOpened(branchId);
  return true;
}

bool
VesselPathPanel::RunWith(const VesselPathParameters & parameters)
{
  const VesselPathParameters previous = m_Parameters;
  const double               s = GetArcLength() + m_Logic->GetResults().Path.GetArcLengthOffset();
  m_Parameters = parameters;
  if (!Run())
  {
    m_Parameters = previous;
    Run(false);
    m_Settings->Show(m_Parameters, m_PathLength);
    return false;
  }
  m_Settings->Show(m_Parameters, m_PathLength);
  // The cross-section stays at the same place of the vessel when a range moves the path's start.
  SetArcLength(s - m_Logic->GetResults().Path.GetArcLengthOffset());
  return true;
}

bool
VesselPathPanel::ApplySettings()
{
  if (!m_HasPath)
  {
    return false;
  }
  VesselPathParameters parameters = m_Parameters;
  const QString        problem = m_Settings->Apply(parameters);
  if (!problem.isEmpty())
  {
    m_LastError = problem;
    emit errorOccurred(problem);
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
  if (!m_HasPath)
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

bool
VesselPathPanel::Run(bool report)
{
  try
  {
    if (!PrepareLogic())
    {
      if (report)
      {
        emit errorOccurred(m_LastError);
      }
      return false;
    }
    const auto start = std::chrono::steady_clock::now();
    m_Logic->SetParameters(m_Parameters);
    m_Logic->Update();
    m_LastUpdateSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
  catch (const std::exception & error)
  {
    m_LastError = QString::fromUtf8(error.what());
    if (report)
    {
      emit errorOccurred(m_LastError);
    }
    return false;
  }
  m_HasPath = true;
  m_LastError.clear();
  ShowResults();
  return true;
}

void
VesselPathPanel::ShowResults()
{
  const auto & results = m_Logic->GetResults();
  const bool   stretched = m_Parameters.Reformation == PathReformation::Stretched;
  m_CPR->SetImage(results.CPR.GetPointer(), m_Window, m_Level);
  m_CPR->SetCaption(tr("%1, roll %2°")
                      .arg(stretched ? tr("stretched") : tr("straightened"))
                      .arg(m_Parameters.RollInDegrees, 0, 'f', 1));
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
  m_Parameters.RollInDegrees = roll;
  if (m_HasPath)
  {
    Run();
    // The new picture goes on screen now, not at the next idle paint: what the roll's latency is measured on.
    m_CPR->repaint();
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
  m_Parameters.Reformation = reformation;
  if (m_HasPath)
  {
    Run();
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
  if (!m_HasPath)
  {
    return;
  }
  const int count = static_cast<int>(m_Logic->GetResults().Sections.size());
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
  if (!m_HasPath)
  {
    return;
  }
  const auto & sections = m_Logic->GetResults().Sections;
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
  const auto & sections = m_Logic->GetResults().Sections;
  return m_HasPath && !sections.empty() ? sections[static_cast<std::size_t>(m_Section)].ArcLength : 0.0;
}

void
VesselPathPanel::ShowPosition()
{
  const auto & results = m_Logic->GetResults();
  if (!m_HasPath || results.Sections.empty())
  {
    return;
  }
  const double s = GetArcLength();
  m_CPR->SetPositionRow(m_Logic->RowOfArcLength(s));
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
  emit positionChanged(m_Logic->SectionAt(s).Center);
}

void
VesselPathPanel::ShowMeasurements()
{
  const auto &  results = m_Logic->GetResults();
  const QString html = VesselPathReportHTML(results, static_cast<std::size_t>(m_Section), m_Parameters.Width);
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
  if (!m_HasPath || !m_Logic->GetResults().HasLumen)
  {
    return tr("no lumen measured: open a vessel path first");
  }
  try
  {
    const auto & results = m_Logic->GetResults();
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
