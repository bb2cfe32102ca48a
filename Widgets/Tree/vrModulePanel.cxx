// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrModulePanel.h"

#include "ui_vrModulePanel.h"
#include "vrParameterName.h"
#include "vrParameterTable.h"
#include "vrRelaxBackend.h"

#include <QFileInfo>
#include <QEvent>
#include <QLabel>
#include <QSignalBlocker>

#include <cmath>

namespace vr
{
namespace
{
constexpr double SliderStepsPerDegree = 10.0;

const char * const UpChoices[] = { "S", "I", "A", "P", "L", "R" };

/** The combo entry of an up vector (a patient axis), or -1. */
int
UpIndex(const ReformationParameters & parameters, int autoIndex)
{
  if (parameters.AutomaticUp)
  {
    return autoIndex;
  }
  for (int k = 0; k < 6; ++k)
  {
    const UpAxisChoice choice = ParseUpAxis(UpChoices[k], "up axis");
    if ((choice.Vector - parameters.Up).GetNorm() < 1e-9)
    {
      return k;
    }
  }
  return -1;
}

/** The table's label as a control's caption. */
void
Caption(QLabel * caption, const ParameterSpec & spec)
{
  caption->setText(QString::fromStdString(spec.Label));
}

/** The table's values of a string-enumeration as a combo box's entries, its description as the tooltip. */
void
Describe(QComboBox * combo, const ParameterSpec & spec)
{
  if (!spec.Elements.empty())
  {
    combo->clear();
    for (const std::string & element : spec.Elements)
    {
      combo->addItem(QString::fromStdString(element));
    }
  }
  combo->setToolTip(QString::fromStdString(spec.Description));
}

/** The table's range and step (where it gives them) and description on a spin box. */
template<typename TSpin>
void
Describe(TSpin * spin, const ParameterSpec & spec)
{
  if (spec.Minimum)
  {
    spin->setMinimum(*spec.Minimum);
  }
  if (spec.Maximum)
  {
    spin->setMaximum(*spec.Maximum);
  }
  if (spec.Step)
  {
    spin->setSingleStep(*spec.Step);
  }
  spin->setToolTip(QString::fromStdString(spec.Description));
}

void
SelectText(QComboBox * combo, const char * text)
{
  const int index = combo->findText(QString::fromLatin1(text));
  if (index >= 0)
  {
    combo->setCurrentIndex(index);
  }
}
} // namespace

double
WrapAngle(double degrees)
{
  double wrapped = std::fmod(degrees + 180.0, 360.0);
  if (wrapped < 0.0)
  {
    wrapped += 360.0;
  }
  return wrapped - 180.0;
}

ModulePanel::ModulePanel(QWidget * parent)
  : QWidget(parent)
  , m_Ui(std::make_unique<Ui::ModulePanel>())
{
  m_Ui->setupUi(this);
  DescribeParameters();
  for (QLabel * label : { m_Ui->volumeLabel, m_Ui->centerlineLabel, m_Ui->segmentationLabel })
  {
    label->setSizePolicy(QSizePolicy::Ignored, label->sizePolicy().verticalPolicy());
    label->installEventFilter(this);
  }
  m_Ui->presetCombo->setCurrentText(QString::fromLatin1(CTAPreset.Name));
  // Every phantom the factory makes (itk::MakeCTAPhantom).
  m_Ui->phantomCombo->clear();
  for (const auto & name : PhantomNames())
  {
    m_Ui->phantomCombo->addItem(QString::fromStdString(name));
  }
  Connect();
  // The table's defaults, as every other front end starts with them.
  SetParameters(ReformationParameters());
}

void
ModulePanel::DescribeParameters()
{
  Ui::ModulePanel & ui = *m_Ui;
  const auto        caption = [](QLabel * label, const char * key) { Caption(label, Parameter(key)); };
  caption(ui.angleCaption, "angle");
  caption(ui.upCaption, "up");
  caption(ui.modeCaption, "mode");
  caption(ui.sizeCaption, "size");
  caption(ui.spacingCaption, "spacing");
  caption(ui.interpolationCaption, "interpolation");
  caption(ui.relaxationCaption, "relaxation");
  caption(ui.jumpThresholdCaption, "jumpThreshold");
  caption(ui.anisotropyCaption, "anisotropy");
  caption(ui.solverCaption, "solver");
  caption(ui.iterationsCaption, "iterations");
  caption(ui.backendCaption, "backend");
  caption(ui.windowCaption, "window");
  caption(ui.levelCaption, "level");
  Describe(ui.modeCombo, Parameter("mode"));
  Describe(ui.interpolationCombo, Parameter("interpolation"));
  Describe(ui.solverCombo, Parameter("solver"));
  Describe(ui.backendCombo, Parameter("backend"));
  Describe(ui.relaxationSpin, Parameter("relaxation"));
  Describe(ui.jumpThresholdSpin, Parameter("jumpThreshold"));
  Describe(ui.anisotropySpin, Parameter("anisotropy"));
  Describe(ui.iterationsSpin, Parameter("iterations"));
  Describe(ui.windowSpin, Parameter("window"));
  Describe(ui.levelSpin, Parameter("level"));
  // The panel's own choices, with the table's words: the angle wraps at +-180 degrees and its slider counts tenths;
  // the up axis offers the patient directions and auto; one spacing for both axes.
  const QString angle = QString::fromStdString(Parameter("angle").Description);
  ui.angleSpin->setToolTip(angle + tr(" Here it wraps at plus/minus 180 degrees."));
  ui.angleSlider->setToolTip(angle + tr(" The slider counts tenths of a degree; dragging it shows new images as fast "
                                        "as they are computed, and a left-drag in the CPR view turns it too (0.5 "
                                        "degrees per pixel)."));
  ui.upCombo->setToolTip(QString::fromStdString(Parameter("up").Description));
  ui.widthSpin->setToolTip(QString::fromStdString(Parameter("size").Description) + tr(" Here: the width W; 0 fits."));
  ui.heightSpin->setToolTip(QString::fromStdString(Parameter("size").Description) + tr(" Here: the height H; 0 fits."));
  ui.spacingSpin->setToolTip(QString::fromStdString(Parameter("spacing").Description) +
                             tr(" Here one value for both axes; 0 takes the default."));
  ui.fixLumenCheck->setText(QString::fromStdString(Parameter("fixLumen").Label));
  ui.fixLumenCheck->setToolTip(QString::fromStdString(Parameter("fixLumen").Description));
}

ModulePanel::~ModulePanel() = default;

void
ModulePanel::Connect()
{
  Ui::ModulePanel & ui = *m_Ui;
  auto              final = [this]
  {
    if (!m_Updating)
    {
      emit parametersChanged(RequestKind::Final);
    }
  };
  auto display = [this]
  {
    if (!m_Updating)
    {
      emit displayChanged();
    }
  };

  connect(ui.angleSlider,
          &QSlider::valueChanged,
          this,
          [this](int value)
          {
            {
              const QSignalBlocker block(m_Ui->angleSpin);
              m_Ui->angleSpin->setValue(value / SliderStepsPerDegree);
            }
            if (!m_Updating)
            {
              emit parametersChanged(m_Ui->angleSlider->isSliderDown() ? RequestKind::Interactive : RequestKind::Final);
            }
          });
  connect(ui.angleSlider, &QSlider::sliderReleased, this, final);
  connect(ui.angleSpin,
          QOverload<double>::of(&QDoubleSpinBox::valueChanged),
          this,
          [this, final](double value)
          {
            {
              const QSignalBlocker block(m_Ui->angleSlider);
              m_Ui->angleSlider->setValue(static_cast<int>(std::lround(value * SliderStepsPerDegree)));
            }
            final();
          });
  for (QComboBox * combo : { ui.upCombo, ui.modeCombo, ui.interpolationCombo, ui.backendCombo, ui.solverCombo })
  {
    connect(combo, QOverload<int>::of(&QComboBox::currentIndexChanged), this, final);
  }
  for (QSpinBox * spin : { ui.widthSpin, ui.heightSpin, ui.iterationsSpin })
  {
    connect(spin, QOverload<int>::of(&QSpinBox::valueChanged), this, final);
  }
  for (QDoubleSpinBox * spin : { ui.spacingSpin, ui.relaxationSpin, ui.jumpThresholdSpin, ui.anisotropySpin })
  {
    connect(spin, QOverload<double>::of(&QDoubleSpinBox::valueChanged), this, final);
  }
  connect(ui.fixLumenCheck, &QCheckBox::toggled, this, final);
  // The other spin box takes the same kernel (a = 1/J^2), so that switching alone changes nothing in the picture.
  connect(ui.kernelCombo,
          QOverload<int>::of(&QComboBox::currentIndexChanged),
          this,
          [this, final]
          {
            if (!m_Updating)
            {
              m_Updating = true;
              if (UsesJumpThreshold())
              {
                if (m_Ui->anisotropySpin->value() > 0.0)
                {
                  m_Ui->jumpThresholdSpin->setValue(1.0 / std::sqrt(m_Ui->anisotropySpin->value()));
                }
              }
              else
              {
                const double J = m_Ui->jumpThresholdSpin->value();
                m_Ui->anisotropySpin->setValue(1.0 / (J * J));
              }
              m_Updating = false;
            }
            EnableFilterControls();
            final();
          });
  connect(
    ui.solverCombo, QOverload<int>::of(&QComboBox::currentIndexChanged), this, [this] { EnableFilterControls(); });

  for (QDoubleSpinBox * spin : { ui.windowSpin, ui.levelSpin })
  {
    connect(spin,
            QOverload<double>::of(&QDoubleSpinBox::valueChanged),
            this,
            [this, display]
            {
              if (!m_Updating)
              {
                const QSignalBlocker block(m_Ui->presetCombo);
                m_Ui->presetCombo->setCurrentIndex(0); // Custom
              }
              display();
            });
  }
  connect(ui.presetCombo,
          QOverload<int>::of(&QComboBox::currentIndexChanged),
          this,
          [this]
          {
            if (m_Updating)
            {
              return;
            }
            const QString name = m_Ui->presetCombo->currentText();
            if (name == QLatin1String("Full range"))
            {
              emit fullRangeRequested();
            }
            else if (name != QLatin1String("Custom"))
            {
              ApplyPreset(name, 0.0, 0.0);
            }
          });
  for (QCheckBox * check : { ui.centerlinesCheck, ui.maskCheck, ui.labelsCheck, ui.depthCheck })
  {
    connect(check, &QCheckBox::toggled, this, display);
  }
  connect(ui.comparisonCombo, QOverload<int>::of(&QComboBox::currentIndexChanged), this, display);

  connect(ui.openVolumeButton, &QPushButton::clicked, this, &ModulePanel::openVolumeRequested);
  connect(ui.openCenterlinesButton, &QPushButton::clicked, this, &ModulePanel::openCenterlinesRequested);
  connect(ui.openSegmentationButton, &QPushButton::clicked, this, &ModulePanel::openSegmentationRequested);
  connect(ui.loadPhantomButton,
          &QPushButton::clicked,
          this,
          [this] { emit loadPhantomRequested(m_Ui->phantomCombo->currentText()); });
  connect(ui.saveButton, &QPushButton::clicked, this, &ModulePanel::saveOutputsRequested);
}

ReformationParameters
ModulePanel::GetParameters() const
{
  const Ui::ModulePanel & ui = *m_Ui;
  ReformationParameters   parameters;
  const UpAxisChoice      up = ParseUpAxis(ui.upCombo->currentText().toStdString(), ParameterName::UpAxis);
  parameters.AutomaticUp = up.Automatic;
  if (!up.Automatic)
  {
    parameters.Up = up.Vector;
  }
  parameters.AngleInDegrees = ui.angleSpin->value();
  parameters.ImageSize[0] = static_cast<itk::SizeValueType>(ui.widthSpin->value());
  parameters.ImageSize[1] = static_cast<itk::SizeValueType>(ui.heightSpin->value());
  parameters.PixelSpacing[0] = ui.spacingSpin->value();
  parameters.PixelSpacing[1] = ui.spacingSpin->value();
  parameters.Mode = ParseDepthMode(ui.modeCombo->currentText().toStdString(), ParameterName::DepthMode);
  parameters.Interpolation =
    ParseInterpolation(ui.interpolationCombo->currentText().toStdString(), ParameterName::Interpolation);
  parameters.FixLumen = ui.fixLumenCheck->isChecked();
  parameters.Relaxation = ui.relaxationSpin->value();
  if (UsesJumpThreshold())
  {
    parameters.JumpThreshold = ui.jumpThresholdSpin->value();
  }
  else
  {
    parameters.Anisotropy = ui.anisotropySpin->value();
  }
  parameters.Solver = ParseRelaxSolver(ui.solverCombo->currentText().toStdString(), ParameterName::Solver);
  parameters.Iterations = ui.iterationsSpin->value();
  parameters.Backend = ParseRelaxBackend(ui.backendCombo->currentText().toStdString(), ParameterName::Backend);
  parameters.Window = ui.windowSpin->value();
  parameters.Level = ui.levelSpin->value();
  return parameters;
}

void
ModulePanel::SetParameters(const ReformationParameters & parameters)
{
  Ui::ModulePanel & ui = *m_Ui;
  m_Updating = true;
  const int upIndex = UpIndex(parameters, ui.upCombo->findText(QStringLiteral("auto")));
  if (upIndex >= 0)
  {
    ui.upCombo->setCurrentIndex(upIndex);
  }
  else
  {
    // An oblique up axis given as a vector: offered as its own entry.
    const QString text = QStringLiteral("%1,%2,%3").arg(parameters.Up[0]).arg(parameters.Up[1]).arg(parameters.Up[2]);
    if (ui.upCombo->findText(text) < 0)
    {
      ui.upCombo->addItem(text);
    }
    ui.upCombo->setCurrentText(text);
  }
  ui.angleSpin->setValue(WrapAngle(parameters.AngleInDegrees));
  ui.angleSlider->setValue(static_cast<int>(std::lround(ui.angleSpin->value() * SliderStepsPerDegree)));
  ui.widthSpin->setValue(static_cast<int>(parameters.ImageSize[0]));
  ui.heightSpin->setValue(static_cast<int>(parameters.ImageSize[1]));
  ui.spacingSpin->setValue(parameters.PixelSpacing[0]);
  SelectText(ui.modeCombo, ToString(parameters.Mode));
  SelectText(ui.interpolationCombo, ToString(parameters.Interpolation));
  ui.fixLumenCheck->setChecked(parameters.FixLumen);
  ui.relaxationSpin->setValue(parameters.Relaxation);
  // The kernel as given; the other spin box shows the same kernel in its own terms.
  const double anisotropy = parameters.EffectiveAnisotropy();
  ui.kernelCombo->setCurrentIndex(parameters.Anisotropy ? 1 : 0);
  ui.anisotropySpin->setValue(anisotropy);
  if (parameters.Anisotropy)
  {
    if (anisotropy > 0.0)
    {
      ui.jumpThresholdSpin->setValue(1.0 / std::sqrt(anisotropy));
    }
  }
  else
  {
    ui.jumpThresholdSpin->setValue(parameters.JumpThreshold.value_or(ReformationParameters::DefaultJumpThreshold));
  }
  SelectText(ui.solverCombo, ToString(parameters.Solver));
  ui.iterationsSpin->setValue(static_cast<int>(parameters.Iterations));
  SelectText(ui.backendCombo, ToString(parameters.Backend));
  if (parameters.Window > 0.0)
  {
    ui.windowSpin->setValue(parameters.Window);
    ui.levelSpin->setValue(parameters.Level);
  }
  m_Updating = false;
  EnableFilterControls();
}

bool
ModulePanel::UsesJumpThreshold() const
{
  return m_Ui->kernelCombo->currentIndex() == 0;
}

void
ModulePanel::EnableFilterControls()
{
  Ui::ModulePanel & ui = *m_Ui;
  ui.jumpThresholdSpin->setEnabled(UsesJumpThreshold());
  ui.anisotropySpin->setEnabled(!UsesJumpThreshold());
  // N and w belong to the Jacobi passes; the steady solver's fixed point depends on neither.
  const bool jacobi = ui.solverCombo->currentText() == QLatin1String(ToString(itk::BilateralDepthRelaxSolver::Jacobi));
  ui.iterationsSpin->setEnabled(jacobi);
  ui.relaxationSpin->setEnabled(jacobi);
}

void
ModulePanel::SetRelaxBackendReport(const QString & backend, const QString & reason)
{
  m_Ui->backendReasonLabel->setText(backend.isEmpty() ? tr("Backend used: (not run yet)")
                                                      : tr("Backend used: %1 (%2)").arg(backend, reason));
}

QString
ModulePanel::GetRelaxBackendReport() const
{
  return m_Ui->backendReasonLabel->text();
}

void
ModulePanel::SetAngle(double degrees, RequestKind kind)
{
  const double wrapped = WrapAngle(degrees);
  {
    const QSignalBlocker blockSpin(m_Ui->angleSpin);
    const QSignalBlocker blockSlider(m_Ui->angleSlider);
    m_Ui->angleSpin->setValue(wrapped);
    m_Ui->angleSlider->setValue(static_cast<int>(std::lround(wrapped * SliderStepsPerDegree)));
  }
  emit parametersChanged(kind);
}

double
ModulePanel::GetAngle() const
{
  return m_Ui->angleSpin->value();
}

void
ModulePanel::SetWindowLevel(double window, double level, bool byHand)
{
  if (byHand)
  {
    const QSignalBlocker block(m_Ui->presetCombo);
    m_Ui->presetCombo->setCurrentIndex(0); // Custom
  }
  {
    const QSignalBlocker blockWindow(m_Ui->windowSpin);
    const QSignalBlocker blockLevel(m_Ui->levelSpin);
    m_Ui->windowSpin->setValue(window);
    m_Ui->levelSpin->setValue(level);
  }
  emit displayChanged();
}

void
ModulePanel::SetPercentileWindow(double window, double level)
{
  m_PercentileWindow = window;
  m_PercentileLevel = level;
}

QString
ModulePanel::GetPresetName() const
{
  return m_Ui->presetCombo->currentText();
}

bool
ModulePanel::ApplyPreset(const QString & name, double fullRangeWindow, double fullRangeLevel)
{
  double window = 0.0;
  double level = 0.0;
  if (name.compare(QLatin1String("Full range"), Qt::CaseInsensitive) == 0)
  {
    window = fullRangeWindow;
    level = fullRangeLevel;
  }
  else if (name == QString::fromUtf8(PercentilePresetName))
  {
    if (!(m_PercentileWindow > 0.0))
    {
      return false;
    }
    window = m_PercentileWindow;
    level = m_PercentileLevel;
  }
  else
  {
    bool found = false;
    for (const WindowLevelPreset & preset : { CTAPreset, BonePreset, SoftTissuePreset })
    {
      if (name.compare(QLatin1String(preset.Name), Qt::CaseInsensitive) == 0)
      {
        window = preset.Window;
        level = preset.Level;
        found = true;
      }
    }
    if (!found)
    {
      return false;
    }
  }
  {
    const QSignalBlocker block(m_Ui->presetCombo);
    const int            index = m_Ui->presetCombo->findText(name, Qt::MatchFixedString);
    m_Ui->presetCombo->setCurrentIndex(index);
  }
  SetWindowLevel(window, level);
  return true;
}

CPROverlays
ModulePanel::GetOverlays() const
{
  CPROverlays overlays;
  overlays.Centerlines = m_Ui->centerlinesCheck->isChecked();
  overlays.FixedMask = m_Ui->maskCheck->isChecked();
  overlays.OwnerLabels = m_Ui->labelsCheck->isChecked();
  overlays.DepthMap = m_Ui->depthCheck->isChecked();
  return overlays;
}

void
ModulePanel::SetOverlays(const CPROverlays & overlays)
{
  m_Updating = true;
  m_Ui->centerlinesCheck->setChecked(overlays.Centerlines);
  m_Ui->maskCheck->setChecked(overlays.FixedMask);
  m_Ui->labelsCheck->setChecked(overlays.OwnerLabels);
  m_Ui->depthCheck->setChecked(overlays.DepthMap);
  m_Updating = false;
  emit displayChanged();
}

CPRComparison
ModulePanel::GetComparison() const
{
  return static_cast<CPRComparison>(m_Ui->comparisonCombo->currentIndex());
}

void
ModulePanel::SetComparison(CPRComparison comparison)
{
  m_Ui->comparisonCombo->setCurrentIndex(static_cast<int>(comparison));
}

OutputSelection
ModulePanel::GetOutputSelection() const
{
  OutputSelection selection;
  selection.CPR = m_Ui->saveCPRCheck->isChecked();
  selection.CPRPNG = m_Ui->savePNGCheck->isChecked();
  selection.UnfilteredCPR = m_Ui->saveUnfilteredCheck->isChecked();
  selection.DepthMaps = m_Ui->saveDepthCheck->isChecked();
  selection.FixedMask = m_Ui->saveMaskCheck->isChecked();
  selection.OwnerLabels = m_Ui->saveLabelsCheck->isChecked();
  selection.CutSurface = m_Ui->saveSurfaceCheck->isChecked();
  // What lies hidden exists only in the visibility mode; it goes with the owner labels.
  const bool visibility = m_Ui->modeCombo->currentText() == QString(ToString(itk::CPRDepthMode::Visibility));
  selection.HiddenLabels = selection.OwnerLabels && visibility;
  selection.HiddenLengths = selection.OwnerLabels && visibility;
  return selection;
}

void
ModulePanel::ShowPhantom(const QString & name)
{
  const QSignalBlocker block(m_Ui->phantomCombo);
  const int            index = m_Ui->phantomCombo->findText(name);
  if (index >= 0)
  {
    m_Ui->phantomCombo->setCurrentIndex(index);
  }
}

void
ModulePanel::SetIntensityUnit(const QString & unit)
{
  const QString suffix = unit.isEmpty() ? QString() : QLatin1Char(' ') + unit;
  m_Ui->windowSpin->setSuffix(suffix);
  m_Ui->levelSpin->setSuffix(suffix);
}

void
ModulePanel::SetInputDescription(const QString & volume, const QString & centerlines, const QString & segmentation)
{
  // A file by its name (the whole path in the status tip), a phantom by its description; the label shows what fits and
  // never widens the panel (its size policy is Ignored), so that the captions beside it stay whole.
  auto shortName = [](const QString & text)
  {
    const QFileInfo file(text);
    return text.contains(QLatin1Char('/')) && !file.fileName().isEmpty() ? file.fileName() : text;
  };
  auto isFile = [](const QString & text) { return text.contains(QLatin1Char('/')); };
  SetElidedText(m_Ui->volumeLabel, shortName(volume), isFile(volume));
  SetElidedText(m_Ui->centerlineLabel, shortName(centerlines), isFile(centerlines));
  m_Ui->volumeLabel->setStatusTip(volume);
  m_Ui->centerlineLabel->setStatusTip(centerlines);
  SetElidedText(
    m_Ui->segmentationLabel, segmentation.isEmpty() ? tr("(none)") : shortName(segmentation), isFile(segmentation));
  m_Ui->segmentationLabel->setStatusTip(segmentation);
}

void
ModulePanel::SetElidedText(QLabel * label, const QString & text, bool fileName)
{
  label->setProperty("fullText", text);
  label->setProperty("fileName", fileName);
  // A file name keeps its end (the extension, a series number); a description (a phantom's) its beginning.
  label->setText(
    label->fontMetrics().elidedText(text, fileName ? Qt::ElideMiddle : Qt::ElideRight, std::max(label->width(), 1)));
}

bool
ModulePanel::eventFilter(QObject * watched, QEvent * event)
{
  auto * label = qobject_cast<QLabel *>(watched);
  if (event->type() == QEvent::Resize && label != nullptr && label->property("fullText").isValid())
  {
    SetElidedText(label, label->property("fullText").toString(), label->property("fileName").toBool());
  }
  return QWidget::eventFilter(watched, event);
}

QWidget *
ModulePanel::ControlOf(const QString & parameter) const
{
  const Ui::ModulePanel & ui = *m_Ui;
  const std::string       name = parameter.toStdString();
  if (name == ParameterName::UpAxis)
    return ui.upCombo;
  if (name == ParameterName::Angle)
    return ui.angleSpin;
  if (name == ParameterName::ViewSize)
    return ui.widthSpin;
  if (name == ParameterName::PixelSpacing)
    return ui.spacingSpin;
  if (name == ParameterName::DepthMode)
    return ui.modeCombo;
  if (name == ParameterName::FixLumen)
    return ui.fixLumenCheck;
  if (name == ParameterName::Relaxation)
    return ui.relaxationSpin;
  if (name == ParameterName::Anisotropy)
    return UsesJumpThreshold() ? ui.jumpThresholdSpin : ui.anisotropySpin;
  if (name == ParameterName::JumpThreshold)
    return ui.jumpThresholdSpin;
  if (name == ParameterName::Solver)
    return ui.solverCombo;
  if (name == ParameterName::Iterations)
    return ui.iterationsSpin;
  if (name == ParameterName::Backend || name == ParameterName::OpenCLDevice)
    return ui.backendCombo;
  if (name == ParameterName::Interpolation)
    return ui.interpolationCombo;
  if (name == ParameterName::Window)
    return ui.windowSpin;
  if (name == ParameterName::Level)
    return ui.levelSpin;
  return nullptr;
}

void
ModulePanel::MarkParameterError(const QString & parameter, const QString & message)
{
  const Ui::ModulePanel & ui = *m_Ui;
  for (QWidget * control : std::initializer_list<QWidget *>{ ui.upCombo,
                                                             ui.angleSpin,
                                                             ui.widthSpin,
                                                             ui.heightSpin,
                                                             ui.spacingSpin,
                                                             ui.modeCombo,
                                                             ui.fixLumenCheck,
                                                             ui.relaxationSpin,
                                                             ui.jumpThresholdSpin,
                                                             ui.anisotropySpin,
                                                             ui.solverCombo,
                                                             ui.iterationsSpin,
                                                             ui.backendCombo,
                                                             ui.interpolationCombo,
                                                             ui.windowSpin,
                                                             ui.levelSpin })
  {
    control->setStyleSheet(QString());
    control->setStatusTip(QString());
  }
  if (parameter.isEmpty())
  {
    return;
  }
  QWidget * control = ControlOf(parameter);
  if (control == nullptr)
  {
    return;
  }
  control->setStyleSheet(QStringLiteral("background-color: #ffd6d6;"));
  control->setStatusTip(message);
  if (control == ui.widthSpin)
  {
    ui.heightSpin->setStyleSheet(control->styleSheet());
    ui.heightSpin->setStatusTip(message);
  }
}

QSlider *
ModulePanel::GetAngleSlider() const
{
  return m_Ui->angleSlider;
}

QDoubleSpinBox *
ModulePanel::GetAngleSpinBox() const
{
  return m_Ui->angleSpin;
}

QDoubleSpinBox *
ModulePanel::GetWindowSpinBox() const
{
  return m_Ui->windowSpin;
}

QDoubleSpinBox *
ModulePanel::GetLevelSpinBox() const
{
  return m_Ui->levelSpin;
}
} // namespace vr
