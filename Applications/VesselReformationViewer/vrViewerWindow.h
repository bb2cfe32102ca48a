// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrViewerWindow_h
#define vrViewerWindow_h

#include "vrCPRView.h"
#include "vrDICOMSeriesChoice.h"
#include "vrModulePanel.h"
#include "vrOcclusionStrip.h"
#include "vrReformationController.h"
#include "vrRotationSeries.h"
#include "vrThreeDView.h"
#include "vrVesselPathPanel.h"

#include "vrViewerSettings.h"

#include <QElapsedTimer>
#include <QMainWindow>
#include <QString>
#include <QStringList>

#include <functional>
#include <optional>
#include <memory>
#include <vector>

class QAction;
class QCloseEvent;
class QLabel;
class QMenu;
class QSplitter;
class QProgressBar;
class QTimer;

namespace vr
{
class ViewerLayout;
class WindowKeyPolicy;

/** \class ViewerWindow
 * \brief The VesselReformationViewer's main window, a host for the module's widgets: the module panel, the CPR view
 * and the 3D view around one ReformationController, with menus to open files and phantoms, save outputs and show the
 * module description, and a status bar with the progress, each stage's time and the pixel readout.
 *
 * Bad files never crash it: the logic's message is shown in a dialog (or given to the error handler a host sets) and
 * the data on screen stays.
 *
 * \sa ModulePanel, CPRView, ThreeDView, ReformationController
 * \ingroup VesselReformation
 */
class ViewerWindow : public QMainWindow
{
  Q_OBJECT

public:
  /** Receives errors instead of a dialog: a title ("Cannot open aorta.mha") and the logic's message. */
  using ErrorHandler = std::function<void(const QString & title, const QString & message)>;

  explicit ViewerWindow(QWidget * parent = nullptr);
  ~ViewerWindow() override;

  /** Loads a built-in phantom (on the worker thread) and reforms it. */
  void
  LoadPhantom(const QString & name, double spacing = 1.5);
  /** Opens a volume and centerlines together. A DICOM folder that holds several series is read with \a series (its
   * number in the reader's list or its Series Instance UID); without one, a dialog asks which (objectName
   * "dicomSeriesChoice", one item a series, vr::DescribeDICOMSeries) and the open is made again with the answer. */
  void
  OpenFiles(const QString & volume, const QString & centerlines, const QString & series = QString());
  /** Opens a volume, keeping the centerlines; \a series as for OpenFiles(). */
  void
  OpenVolume(const QString & path, const QString & series = QString());
  /** Opens centerlines, keeping the volume. */
  void
  OpenCenterlines(const QString & path);
  /** Opens a vessel segmentation (one file, or several combined: label maps, masks, VMTK level sets) instead of
   * centerlines, keeping the volume: the logic extracts the centerlines (VesselReformationLogic::SetSegmentationNode),
   * and the overlays and tubes show them. A file the logic refuses leaves the data on screen as it was. */
  void
  OpenSegmentation(const QStringList & paths);
  /** Opens a volume and a segmentation together; \a series as for OpenFiles(). */
  void
  OpenFilesWithSegmentation(const QString &     volume,
                            const QStringList & segmentation,
                            const QString &     series = QString());

  /** Remembers and restores what ViewerSettings keeps (window geometry, panel split, overlays, the latest folder,
   * File > Open recent) in \a settings; without it (the default, and in scripted runs) nothing is remembered. Call
   * once, before show(). */
  void
  UseSettings(std::shared_ptr<ViewerSettings> settings);
  /** File > Open recent's entry \a index (0: the latest). */
  void
  OpenRecent(int index);
  /** The folder file dialogs start in: the data's on screen, else the latest of an earlier run, else the working
   * folder. */
  QString
  StartFolder() const;

  /** Edit > Undo open: loads again the inputs that were on screen before the latest successful open (several steps
   * back, up to MaximumUndoSteps), as they were: a volume and centerlines that looked wrong together are undone in
   * one step. Does nothing when there is nothing to undo. */
  void
  UndoOpen();
  /** \return whether UndoOpen() has inputs to go back to. */
  bool
  CanUndoOpen() const
  {
    return !m_UndoInputs.empty();
  }
  static constexpr std::size_t MaximumUndoSteps = 10;

  /** Sends the panel's parameters to the logic. */
  void
  RequestReformation(RequestKind kind);
  /** Sends the panel's parameters at \a angle (degrees) to the logic as a step of a drag, leaving the panel as it is.
   */
  void
  RequestTurn(double angle);
  /** Writes the outputs on screen into \a folder (WriteOutputs); errors go to the error handler or a dialog.
   * \return whether they were written. */
  bool
  SaveOutputs(const QString & folder);
  /** Renders the window into a PNG at \a path, atomically. \return an empty string, or what went wrong. */
  QString
  WriteScreenshot(const QString & path);
  /** Exports a rotation series of the reformation on screen (vr::RotationSeriesExport: its inputs and parameters, the
   * panel's window and level) into \a folder at \a angles, its pictures at least \a displayLongSide pixels long with
   * the angle and orientation letters burned in (0: the CPR's own size), on a thread of its own behind a modal progress
   * dialog whose Cancel stops it (nothing is then written). Errors go to the error handler or a dialog. \return the
   * number of views written, 0 when nothing was. */
  int
  ExportRotationSeries(const QString &        folder,
                       const RotationAngles & angles,
                       unsigned int           displayLongSide = RotationSeriesSettings::DefaultDisplayLongSide);

  /** Errors go to \a handler instead of a dialog (scripted mode); an empty handler restores dialogs. */
  void
  SetErrorHandler(ErrorHandler handler);
  /** \return the latest error shown: "title: message", or empty. */
  QString
  GetLastError() const
  {
    return m_LastError;
  }

  /** \return the help page F1 opens (HTML): mouse and keys, what each panel section does, the paper's citation. */
  static QString
  HelpText();
  /** Turns the view by \a degrees from the panel's angle (the arrow keys: 1°, with Shift 10°). */
  void
  TurnBy(double degrees);
  /** Home: angle 0, the image fitted, the 3D camera along the view direction at 0 degrees. */
  void
  ResetView();
  /** The split between the panel and the views, which keeps every view on screen (View > Reset layout). */
  ViewerLayout *
  GetLayout() const
  {
    return m_Layout;
  }

  /** \return the module description with the paper's citation, as the About box shows it (HTML). */
  static QString
  AboutText();

  /** Asks for the path from the tree's root to branch \a branchId (0: the longest) in the vessel path panel, which the
   * worker computes; once it comes, the panel and the markers are shown (docs/viewer.md). \return false, with an error
   * shown, when it cannot be asked; the logic's refusal comes later, shown as an error, the path shown staying. */
  bool
  OpenVesselPath(int branchId);
  /** Measures the open path's lumen on the segmentation file(s) \a paths (on the worker). \return false, with an
   * error shown, when they cannot be read; the logic's refusal comes later, shown as an error. */
  bool
  OpenLumenSegmentation(const QStringList & paths);
  /** Writes the vessel path's lumen table (CSV or TSV by the extension). \return false, with an error shown. */
  bool
  ExportLumenTable(const QString & path);
  /** Writes the vessel path's pictures as PNG into \a folder: the panel, the straightened CPR, the cross-section and
   * the profile plot (VesselPathImageNames). \return the number written (0, with an error shown, on failure). */
  int
  ExportVesselPathImages(const QString & folder);
  static const QStringList &
  VesselPathImageNames();
  VesselPathPanel *
  GetPathPanel() const
  {
    return m_PathPanel;
  }

  ModulePanel *
  GetPanel() const
  {
    return m_Panel;
  }
  CPRView *
  GetCPRView() const
  {
    return m_CPRView;
  }
  ThreeDView *
  GetThreeDView() const
  {
    return m_ThreeDView;
  }
  /** \return the strip under the CPR view: hidden fraction against the angle. */
  OcclusionStrip *
  GetOcclusionStrip() const
  {
    return m_OcclusionStrip;
  }
  /** View > Best view: turns to the angle of 0-179 degrees that hides the least of the tree (the occlusion profile's
   * minimum). \return false when no profile has come yet. */
  bool
  GoToBestView();
  ReformationController *
  GetController() const
  {
    return m_Controller;
  }
  /** \return whether the status bar shows the progress bar now. */
  bool
  IsProgressShown() const;
  /** \return the warnings the banner above the views shows now, each in full (empty when it is hidden). */
  QStringList
  GetShownWarnings() const;

  /** How long an update runs before the status bar shows its progress, in seconds. Showing the bar repaints the
   * window, which Qt composes again with its two OpenGL views: for the angle changes of a drag, which take about a
   * tenth of a second, those repaints took a third of the processor the logic ran on. */
  static constexpr int ProgressDelayMilliseconds = 400;

signals:
  /** An error was shown (dialog or handler). */
  void
  errorShown(const QString & title, const QString & message);

protected:
  void
  closeEvent(QCloseEvent * event) override;

private:
  void
  BuildMenus();
  void
  BuildVesselPathMenu();
  /** The View menu's keys (vrViewerWindowKeys.cxx): turns, Home, presets, Reset layout. */
  void
  BuildViewKeys(QMenu * view);
  /** The Vessel menu's keys that step the cross-section, enabled while a path is open. */
  void
  BuildSectionKeys(QMenu * vessel);
  void
  EnableSectionKeys(bool enabled);
  void
  ConnectVesselPath();
  void
  ChooseAndOpenLumenSegmentation();
  void
  ChooseAndExportLumenTable();
  void
  ChooseAndExportVesselPathImages();
  void
  CloseVesselPath();
  /** File > Open recent, from the settings. */
  void
  FillRecentMenu();
  /** Adds an opened pair to the settings' recent list once it has loaded. */
  void
  RememberWhenLoaded(const ViewerSettings::RecentEntry & entry);
  /** Reads the volume of a load, on the controller's worker. A DICOM folder of several series without \a series
   * puts the question to the GUI thread (AskForDICOMSeries, which calls \a again with the answer) and ends this load
   * quietly, with vr::Cancelled: nothing is replaced and no error is shown. */
  vtkSmartPointer<VolumeNode>
  ReadVolumeOrAsk(const std::string &                          path,
                  const QString &                              series,
                  VolumeReadReport &                           report,
                  const std::function<void(const QString &)> & again) const;
  /** Asks which of \a series of the folder \a path is the volume (a dialog that does not block) and calls \a again
   * with its number; nothing when the user cancels. */
  void
  AskForDICOMSeries(const QString &                              path,
                    const std::vector<DICOMSeriesSummary> &      series,
                    const QString &                              reason,
                    const std::function<void(const QString &)> & again);
  /** Remembers the folder of \a path (a file or folder opened) for the dialogs, and in the settings. */
  void
  RememberDataFolder(const QString & path);
  void
  ChooseAndOpenVolumeAndCenterlines();
  void
  ConnectParts();
  void
  ApplyDisplay();
  void
  ShowError(const QString & title, const QString & message);
  /** Adds \a message to the warning banner (whole, word-wrapped: the status bar cuts long text off) unless it shows
   * it already, and says so briefly in the status bar. */
  void
  ShowWarning(const QString & message);
  void
  ClearWarnings();
  void
  ShowResult(const std::shared_ptr<const ReformationResult> & result);
  void
  ShowTimes();
  /** Shows the backend that relaxed and why (the panel, the status bar when it changes, the times' tooltip). */
  void
  ShowRelaxBackend(const ReformationOutputs & outputs);
  /** Shows the backend message, elided to the room the stage times leave, for what is left of its 10 s. */
  void
  ShowBackendMessage();
  void
  ShowAbout();
  void
  ShowHelp();
  void
  ChooseAndOpenVolume(bool dicomFolder);
  void
  ChooseAndOpenCenterlines();
  void
  ChooseAndOpenSegmentation();
  /** The panel's parameters for a load's extraction, or none when the panel holds an invalid one. */
  std::optional<ReformationParameters>
  PanelParameters() const;
  void
  ChooseAndSaveOutputs();
  void
  ChooseAndSaveScreenshot();
  /** File > Export rotation series: a folder, then start,step,count. */
  void
  ChooseAndExportRotationSeries();

  ReformationController *                    m_Controller{ nullptr };
  ModulePanel *                              m_Panel{ nullptr };
  CPRView *                                  m_CPRView{ nullptr };
  OcclusionStrip *                           m_OcclusionStrip{ nullptr };
  ThreeDView *                               m_ThreeDView{ nullptr };
  VesselPathPanel *                          m_PathPanel{ nullptr };
  QLabel *                                   m_Readout{ nullptr };
  QWidget *                                  m_WarningBanner{ nullptr };
  QSplitter *                                m_Splitter{ nullptr };
  ViewerLayout *                             m_Layout{ nullptr };
  WindowKeyPolicy *                          m_KeyPolicy{ nullptr };
  std::vector<QAction *>                     m_SectionActions;
  QMenu *                                    m_RecentMenu{ nullptr };
  std::shared_ptr<ViewerSettings>            m_Settings;
  QString                                    m_DataFolder;
  std::optional<ViewerSettings::RecentEntry> m_PendingRecent;
  QAction *                                  m_UndoOpen{ nullptr };
  /** The inputs shown before each successful open, the latest last; and those shown now. */
  std::vector<std::shared_ptr<const ReformationInputs>> m_UndoInputs;
  std::shared_ptr<const ReformationInputs>              m_CurrentInputs;
  bool                                                  m_Undoing{ false };
  QLabel *                                              m_WarningText{ nullptr };
  QStringList                                           m_Warnings;
  QLabel *                                              m_Times{ nullptr };
  QProgressBar *                                        m_Progress{ nullptr };
  QTimer *                                              m_ProgressDelay{ nullptr };
  ErrorHandler                                          m_ErrorHandler;
  QString                                               m_LastError;
  double                                                m_DragStartAngle{ 0.0 };
  /** While a left-drag in the CPR view turns the view, its steps go to the controller directly and the panel shows
   * the angle of each image as it is shown: a change of the panel repaints the window, which Qt composes with its
   * OpenGL views, and at the mouse's 60 Hz those repaints took the processor the logic needs. */
  bool          m_Turning{ false };
  bool          m_FullRangeOnNextResult{ false };
  QString       m_ShownBackendReason;
  QString       m_BackendMessage;
  QElapsedTimer m_BackendMessageTime;
  /** The images on screen, and the full cut surface of the same request once it came. */
  std::shared_ptr<const ReformationResult> m_Shown;
  std::shared_ptr<const ReformationResult> m_ShownSurface;
};
/** Writes \a widget as drawn into the PNG \a path (opaque RGB, atomic). \return an error message, or empty. */
QString
WriteWidgetPNG(QWidget * widget, const QString & path);
} // namespace vr

#endif
