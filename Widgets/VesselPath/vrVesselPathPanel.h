// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrVesselPathPanel_h
#define vrVesselPathPanel_h

#include "vrLogicWorker.h"
#include "vrReformationInputs.h"
#include "vrReformationParameters.h"
#include "vrVesselPathLogic.h"

#include <QString>
#include <QUrl>
#include <QWidget>

#include <cstdint>
#include <memory>
#include <vector>

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

/** What the panel shows of one request: the logic's outputs (images the logic no longer writes to), the rows of the
 * sections in the CPR, and the parameters they were computed with. Made on the worker, read on the GUI thread.
 * \ingroup VesselReformation
 */
struct VesselPathResult
{
  std::uint64_t        RequestId{ 0 };
  VesselPathParameters Parameters;
  VesselPathOutputs    Outputs;
  /** The continuous CPR row of each of Outputs.Sections (VesselPathLogic::RowOfArcLength). */
  std::vector<double>   SectionRows;
  VesselPathStageCounts StagesRun;
  /** Wall time of VesselPathLogic::Update(), seconds. */
  double UpdateSeconds{ 0.0 };
};

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

  /** The worker the logic runs on (not owned; it must outlive the panel's use of it, or be set to null first). Without
   * one, nothing is computed and opening a path says so. */
  void
  SetWorker(LogicWorker * worker);
  /** New data: lists its branches, closes the path shown. The nodes are handed to the logic with the next request. */
  void
  SetInputs(std::shared_ptr<const ReformationInputs> inputs);
  /** The tree view whose look the path's frame takes at roll 0 (its up axis and angle), used at the next open. */
  void
  SetViewParameters(const ReformationParameters & parameters);
  /** A segmentation to measure the lumen on (a label map, mask, level set or probability map node; null: the
   * inputs' own segmentation, else the centerline radii), named in messages by its node's name. Remeasures an open
   * path; when the logic refuses it, the segmentation measured before comes back and errorOccurred() says why. */
  void
  SetLumenSegmentation(vtkSmartPointer<VolumeNode> segmentation);

  /** Asks for the path from the tree's root to branch \a branchId's far end (0: the longest path); pathOpened() when
   * it is shown. \return false, with GetLastError() and errorOccurred(), when it cannot even be asked (no inputs, no
   * worker); a refusal of the logic comes later through errorOccurred(), and the path shown stays. */
  bool
  OpenBranch(int branchId);
  bool
  HasPath() const
  {
    return m_Shown != nullptr;
  }
  /** \return true while a request is still to be answered. */
  bool
  IsUpdating() const
  {
    return m_RequestedId > m_AnsweredId;
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

  /** \return the result shown (null before a path is open). */
  std::shared_ptr<const VesselPathResult>
  GetResult() const
  {
    return m_Shown;
  }
  /** \return the outputs shown (empty before a path is open). */
  const VesselPathOutputs &
  GetOutputs() const;
  /** \return the parameters asked for (the result shown was computed with GetResult()->Parameters). */
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
  /** \return seconds the logic's update of the result shown took. */
  double
  GetLastUpdateSeconds() const
  {
    return m_Shown ? m_Shown->UpdateSeconds : 0.0;
  }
  /** The worker's lane of the panel's tasks. */
  static constexpr const char * WorkerLane = "vessel path";

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
  /** What a request does once answered, beyond showing its result. */
  enum class Purpose
  {
    /** Opening a path: the branch list, the settings, the cross-section at the headline. */
    Open,
    /** A change of the settings: the cross-section kept at the same place of the vessel. */
    Change,
    /** A roll or the stretched mode: the same section. */
    Look,
    /** Another segmentation: on a refusal, the previous one comes back. */
    Segmentation
  };
  struct Session;
  /** Sends the parameters asked for to the worker. \return false (with m_LastError) when there is no worker or no
   * volume. */
  bool
  Request(Purpose                      purpose,
          const VesselPathParameters & previous,
          double                       keepArcLength = 0.0,
          vtkSmartPointer<VolumeNode>  previousSegmentation = nullptr);
  /** The answer to a request, on the GUI thread. */
  void
  Answer(std::uint64_t                           id,
         Purpose                                 purpose,
         std::shared_ptr<const VesselPathResult> result,
         const QString &                         error,
         const VesselPathParameters &            previous,
         double                                  keepArcLength,
         vtkSmartPointer<VolumeNode>             previousSegmentation);
  void
  ReportError(const QString & message);
  void
  ShowResults();
  void
  ShowPosition();
  void
  ShowMeasurements();
  /** Changes the parameters (a settings edit or a width): the request, with the cross-section kept. */
  bool
  RunWith(const VesselPathParameters & parameters);
  void
  FollowReportLink(const QUrl & link);

  LogicWorker * m_Worker{ nullptr };
  /** The logic and what it was last given, touched by the worker's tasks only (shared with them). */
  std::shared_ptr<Session>                 m_Session;
  std::shared_ptr<const ReformationInputs> m_Inputs;
  /** The segmentation chosen for the lumen (null: the inputs' own, if any). */
  vtkSmartPointer<VolumeNode>             m_Segmentation;
  std::shared_ptr<const VesselPathResult> m_Shown;
  std::uint64_t                           m_RequestedId{ 0 };
  std::uint64_t                           m_AnsweredId{ 0 };
  /** Whether requests compute the cross-section stack (off while a drag rolls the image). */
  bool m_CrossSections{ true };
  /** Whether the latest request computes them. */
  bool                  m_RequestedCrossSections{ true };
  VesselPathParameters  m_Parameters;
  ReformationParameters m_View;
  int                   m_Section{ 0 };
  double                m_DragStartRoll{ 0.0 };
  double                m_Window{ 400.0 };
  double                m_Level{ 200.0 };
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
