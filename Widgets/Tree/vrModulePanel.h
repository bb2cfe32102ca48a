// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrModulePanel_h
#define vrModulePanel_h

#include "vrCPRView.h"
#include "vrReformationController.h"
#include "vrIntensityWindow.h"
#include "vrOutputWriter.h"
#include "vrReformationParameters.h"

#include <QWidget>

#include <memory>
#include <string>

namespace Ui
{
class ModulePanel;
}
class QSlider;
class QDoubleSpinBox;
class QLabel;

namespace vr
{
/** A window/level preset of the display section (intensities in HU).
 * \ingroup VesselReformation
 */
struct WindowLevelPreset
{
  const char * Name;
  double       Window;
  double       Level;
};
/** CTA (W 900, L 200: lumen, soft tissue and bone at once, as the demo's pictures), bone (W 2000, L 500) and soft
 * tissue (W 400, L 40). */
constexpr WindowLevelPreset CTAPreset{ "CTA", CTAWindow, CTALevel };
constexpr WindowLevelPreset BonePreset{ "Bone", 2000.0, 500.0 };
constexpr WindowLevelPreset SoftTissuePreset{ "Soft tissue", 400.0, 40.0 };
/** The preset whose window spans the volume's 1st to 99th intensity percentile (SetPercentileWindow): the default
 * for volumes without HU, whose intensities have no fixed scale (MR angiography). */
constexpr const char * PercentilePresetName = "1–99 %";

/** \class ModulePanel
 * \brief The module's parameter panel (layout in Resources/UI/vrModulePanel.ui): inputs, view, filter, display and
 * outputs. It collects vr::ReformationParameters and says when they change; it computes nothing.
 *
 * parametersChanged() carries how the change should be requested: Interactive while the angle slider is being
 * dragged, Final otherwise (spin boxes emit on Enter, on losing focus and on their arrows). Display settings
 * (window, level, overlays, comparison) change nothing the logic computes and come through displayChanged().
 *
 * \sa ReformationController, CPRView
 * \ingroup VesselReformation
 */
class ModulePanel : public QWidget
{
  Q_OBJECT

public:
  explicit ModulePanel(QWidget * parent = nullptr);
  ~ModulePanel() override;

  /** \return the parameters the controls show (view, filter, and the display window and level). The range kernel
   * is the one chosen in the panel: JumpThreshold (mm) or Anisotropy (mm^-2), never both. */
  ReformationParameters
  GetParameters() const;
  /** Shows \a parameters in the controls without emitting anything. */
  void
  SetParameters(const ReformationParameters & parameters);

  /** Sets the angle (degrees, wrapped into [-180, 180)) as a user would, emitting parametersChanged(\a kind). */
  void
  SetAngle(double degrees, RequestKind kind);
  double
  GetAngle() const;

  /** Sets the window and level controls; emits displayChanged(). \a byHand (a right-drag in the CPR view) shows the
   * preset as "Custom". */
  void
  SetWindowLevel(double window, double level, bool byHand = false);
  /** The window and level of the "1–99 %" preset, from the volume's intensity percentiles (ReformationInputs). */
  void
  SetPercentileWindow(double window, double level);
  /** \return the preset the panel shows ("CTA", "Custom", ...). */
  QString
  GetPresetName() const;
  /** Chooses a preset by name ("CTA", "Bone", "Soft tissue", "Full range"); \a fullRange gives the window and level of
   * "Full range". Emits displayChanged(). \return false for an unknown name. */
  bool
  ApplyPreset(const QString & name, double fullRangeWindow, double fullRangeLevel);

  CPROverlays
  GetOverlays() const;
  void
  SetOverlays(const CPROverlays & overlays);
  CPRComparison
  GetComparison() const;
  void
  SetComparison(CPRComparison comparison);
  OutputSelection
  GetOutputSelection() const;

  /** Chooses \a name in the phantom list (the phantom on screen), emitting nothing. */
  void
  ShowPhantom(const QString & name);
  /** Labels the window and level in \a unit ("HU"; empty for intensities without a unit). */
  void
  SetIntensityUnit(const QString & unit);
  /** Shows where the inputs came from: the volume, the centerlines, and the segmentation they were extracted from
   * (empty when they came from a file or a phantom). */
  void
  SetInputDescription(const QString & volume, const QString & centerlines, const QString & segmentation = QString());
  /** Marks the control of \a parameter (a vr::ParameterName) with \a message, or clears every mark when empty. */
  void
  MarkParameterError(const QString & parameter, const QString & message);

  /** Shows which backend relaxed the latest image and why (VesselReformationLogic's RelaxBackendUsed and
   * RelaxBackendReason) under the backend choice. */
  void
  SetRelaxBackendReport(const QString & backend, const QString & reason);
  QString
  GetRelaxBackendReport() const;

  /** The controls, for hosts and tests. */
  QSlider *
  GetAngleSlider() const;
  QDoubleSpinBox *
  GetAngleSpinBox() const;
  QDoubleSpinBox *
  GetWindowSpinBox() const;
  QDoubleSpinBox *
  GetLevelSpinBox() const;
  const Ui::ModulePanel &
  GetUi() const
  {
    return *m_Ui;
  }

protected:
  /** Elides the input labels again when their width changes. */
  bool
  eventFilter(QObject * watched, QEvent * event) override;

signals:
  /** A parameter the logic uses changed. */
  void
  parametersChanged(vr::RequestKind kind);
  /** Window, level, overlays or comparison changed: display only. */
  void
  displayChanged();
  /** "Full range" was chosen: the host answers with SetWindowLevel() from the logic's display range. */
  void
  fullRangeRequested();
  void
  openVolumeRequested();
  void
  openCenterlinesRequested();
  void
  openSegmentationRequested();
  void
  loadPhantomRequested(const QString & name);
  void
  saveOutputsRequested();

private:
  /** Captions, tooltips, combo entries and ranges of the reformation's controls from the parameter table
   * (vrParameterTable.h): the panel shows each parameter as the modules describe it. */
  void
  DescribeParameters();
  void
  Connect();
  QWidget *
  ControlOf(const QString & parameter) const;
  /** True when the range kernel is given as the jump threshold J (mm), false for the anisotropy a (mm^-2). */
  bool
  UsesJumpThreshold() const;
  /** Enables the kernel's chosen spin box, and N and w for the Jacobi solver only. */
  void
  EnableFilterControls();
  /** Shows \a text in an input label, with an ellipsis when it is wider than the label: in the middle of a file
   * name (\a fileName), at the end of a description. */
  void
  SetElidedText(QLabel * label, const QString & text, bool fileName);

  std::unique_ptr<Ui::ModulePanel> m_Ui;
  bool                             m_Updating{ false };
  /** The "1-99 %" preset's window and level (0: none known yet). */
  double m_PercentileWindow{ 0.0 };
  double m_PercentileLevel{ 0.0 };
};

/** \return \a degrees wrapped into [-180, 180). */
double
WrapAngle(double degrees);
} // namespace vr

#endif
