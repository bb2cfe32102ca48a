// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrVesselPathPanel_h
#define vrVesselPathPanel_h

#include "vrReformationInputs.h"
#include "vrReformationParameters.h"
#include "vrStoredVolume.h"
#include "vrVesselPathLogic.h"

#include <QString>
#include <QUrl>
#include <QWidget>

#include <memory>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QTabWidget;
class QTextBrowser;

namespace vr
{
class CrossSectionView;
class LumenProfilePlot;
class StraightenedCPRView;
class VesselPathSettings;

/** \class VesselPathPanel
 * \brief The single-vessel reading in the viewer (docs/viewer.md): one path of the centerline tree as a
 * straightened (or stretched) CPR that left-drag rolls, the cross-section at a position along it that the mouse
 * and the arrow keys move, the lumen profile as a plot, and beside the cross-section two tabs: the report (the
 * grading by segment with its headline, the reference, the section shown, the fold warning with a width that does not
 * fold) and the settings (width, range, slab, reference, scale; vr::VesselPathSettings). Every text has its own area:
 * the panel's minimum size holds all its parts, and the report scrolls. vr::VesselPathLogic computes everything; the
 * panel holds one, sets its inputs and parameters and shows its results.
 *
 * The logic runs on the GUI thread: a roll reruns its resampling alone, which takes milliseconds at a vessel's size
 * (the viewer benchmark "VesselPathRoll" measures roll to picture on screen), so a worker thread would only add
 * latency and a copy of the results. Opening a path also converts the volume once per inputs.
 * \sa StraightenedCPRView, CrossSectionView, LumenProfilePlot
 * \ingroup VesselReformation
 */
class VesselPathPanel : public QWidget
{
  Q_OBJECT

public:
  explicit VesselPathPanel(QWidget * parent = nullptr);
  ~VesselPathPanel() override;

  /** New data: lists its branches, closes the path shown. The volume and the tree are handed to the logic when a
   * path is first opened. */
  void
  SetInputs(std::shared_ptr<const ReformationInputs> inputs);
  /** The tree view whose look the path's frame takes at roll 0 (its up axis and angle), used at the next open. */
  void
  SetViewParameters(const ReformationParameters & parameters);
  /** A segmentation to measure the lumen on (a label map, mask, level set or probability map node; null: the
   * inputs' own segmentation, else the centerline radii), named \a name in messages. \return an error message, or
   * empty. Remeasures an open path. */
  QString
  SetLumenSegmentation(vtkSmartPointer<VolumeNode> segmentation, const QString & name);

  /** Opens the path from the tree's root to branch \a branchId's far end (0: the longest path). \return false, with
   * GetLastError() and errorOccurred(), when the logic refuses it; the path shown stays. */
  bool
  OpenBranch(int branchId);
  bool
  HasPath() const
  {
    return m_HasPath;
  }
  QString
  GetLastError() const
  {
    return m_LastError;
  }

  /** Roll about the path, degrees (wrapped to (-180, 180]). */
  void
  SetRoll(double degrees);
  double
  GetRoll() const;
  void
  SetStretched(bool stretched);
  bool
  IsStretched() const;
  /** The image's width across the vessel, mm (the Width setting). */
  void
  SetWidth(double width);
  /** Applies the settings tab's values (what its edits do). \return false, with the error shown, when the logic
   * refuses them; the settings then show the parameters in use again. */
  bool
  ApplySettings();

  /** The cross-section position: a section of the logic's list (clamped), or the section nearest an arc length. */
  void
  SetSectionIndex(int index);
  void
  StepSections(int sections);
  void
  SetArcLength(double arcLength);
  int
  GetSectionIndex() const
  {
    return m_Section;
  }
  /** \return the arc length (mm) of the cross-section shown. */
  double
  GetArcLength() const;

  /** Window and level of the images (the CPR view's). */
  void
  SetWindowLevel(double window, double level);

  /** Writes the lumen table (vr::WriteLumenTable; CSV or TSV by the extension). \return an error, or empty. */
  QString
  WriteLumenTable(const QString & path) const;

  const VesselPathLogic &
  GetLogic() const
  {
    return *m_Logic;
  }
  const VesselPathParameters &
  GetParameters() const
  {
    return m_Parameters;
  }
  StraightenedCPRView *
  GetStraightenedView() const
  {
    return m_CPR;
  }
  CrossSectionView *
  GetCrossSectionView() const
  {
    return m_CrossSection;
  }
  LumenProfilePlot *
  GetProfilePlot() const
  {
    return m_Plot;
  }
  QComboBox *
  GetBranchList() const
  {
    return m_Branches;
  }
  /** \return the report as shown, as plain text. */
  QString
  GetMeasurementText() const;
  /** The report's area (a read-only text browser; its links are the fold warning's offers). */
  QTextBrowser *
  GetReportView() const
  {
    return m_Measurements;
  }
  VesselPathSettings *
  GetSettings() const
  {
    return m_Settings;
  }
  /** The tabs beside the cross-section: the report and the settings. */
  QTabWidget *
  GetTabs() const
  {
    return m_Tabs;
  }
  /** \return seconds the latest logic update took. */
  double
  GetLastUpdateSeconds() const
  {
    return m_LastUpdateSeconds;
  }

signals:
  /** A path was opened: \a branchId as asked (0: the longest). */
  void
  pathOpened(int branchId);
  /** The cross-section moved (or the path changed): its centre, LPS mm. */
  void
  positionChanged(const itk::Point<double, 3> & center);
  void
  errorOccurred(const QString & message);

private:
  /** Updates the logic and shows its results. \return false on an error (m_LastError), which \a report also emits. */
  bool
  Run(bool report = true);
  void
  ShowResults();
  void
  ShowPosition();
  void
  ShowMeasurements();
  bool
  PrepareLogic();
  /** Runs the logic with \a parameters; on a refusal puts the previous parameters back (and their results). */
  bool
  RunWith(const VesselPathParameters & parameters);
  void
  FollowReportLink(const QUrl & link);

  std::unique_ptr<VesselPathLogic>         m_Logic;
  std::shared_ptr<const ReformationInputs> m_Inputs;
  StoredVolume                             m_Volume;
  LabelMapVolumeType::Pointer              m_Mask;
  std::string                              m_MaskName;
  bool                                     m_LogicReady{ false };
  VesselPathParameters                     m_Parameters;
  ReformationParameters                    m_View;
  bool                                     m_HasPath{ false };
  int                                      m_Section{ 0 };
  double                                   m_DragStartRoll{ 0.0 };
  double                                   m_Window{ 400.0 };
  double                                   m_Level{ 200.0 };
  double                                   m_LastUpdateSeconds{ 0.0 };
  /** The whole path's length (without a range), the range's limit. */
  double  m_PathLength{ 0.0 };
  QString m_LastError;

  QComboBox *           m_Branches{ nullptr };
  QCheckBox *           m_Stretched{ nullptr };
  QDoubleSpinBox *      m_Roll{ nullptr };
  QTabWidget *          m_Tabs{ nullptr };
  QTextBrowser *        m_Measurements{ nullptr };
  QString               m_ReportHTML;
  VesselPathSettings *  m_Settings{ nullptr };
  StraightenedCPRView * m_CPR{ nullptr };
  CrossSectionView *    m_CrossSection{ nullptr };
  LumenProfilePlot *    m_Plot{ nullptr };
};
} // namespace vr

#endif
