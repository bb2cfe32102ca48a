// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// The viewer window's single-vessel reading (docs/viewer.md): opening a path (Ctrl+click in the CPR view, the
// panel's list or the Vessel menu), keeping the cross-section's marker in the CPR and 3D views, and the exports.
#include "vrViewerWindow.h"

#include "vrCrossSectionView.h"
#include "vrLumenProfilePlot.h"
#include "vrStraightenedCPRView.h"
#include "vrViewerLayout.h"

#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QMenu>
#include <QMenuBar>
#include <QSplitter>
#include <QStatusBar>

namespace vr
{
const QStringList &
ViewerWindow::VesselPathImageNames()
{
  static const QStringList names = { QStringLiteral("vessel-path-panel.png"),
                                     QStringLiteral("vessel-path-cpr.png"),
                                     QStringLiteral("vessel-path-cross-section.png"),
                                     QStringLiteral("vessel-path-profile.png") };
  return names;
}

void
ViewerWindow::BuildVesselPathMenu()
{
  QMenu * vessel = menuBar()->addMenu(tr("V&essel"));
  vessel->addAction(tr("Open the &longest path"), this, [this] { OpenVesselPath(0); })
    ->setObjectName(QStringLiteral("openLongestPath"));
  vessel->addAction(tr("Measure the lumen on a &segmentation…"), this, [this] { ChooseAndOpenLumenSegmentation(); });
  vessel->addSeparator();
  vessel->addAction(tr("Export the lumen &table…"), this, [this] { ChooseAndExportLumenTable(); })
    ->setObjectName(QStringLiteral("exportLumenTable"));
  vessel->addAction(tr("Export the path's &images…"), this, [this] { ChooseAndExportVesselPathImages(); })
    ->setObjectName(QStringLiteral("exportVesselPathImages"));
  vessel->addSeparator();
  vessel->addAction(tr("&Close the vessel path"), this, [this] { CloseVesselPath(); });
  BuildSectionKeys(vessel);
}

void
ViewerWindow::ConnectVesselPath()
{
  connect(m_CPRView,
          &CPRView::vesselPicked,
          this,
          [this](const PixelReadout & readout)
          {
            if (!readout.Inside || readout.Branch <= 0)
            {
              statusBar()->showMessage(tr("No vessel under the mouse: Ctrl+click a vessel to open its path"), 5000);
              return;
            }
            OpenVesselPath(readout.Branch);
          });
  connect(m_PathPanel,
          &VesselPathPanel::positionChanged,
          this,
          [this](const itk::Point<double, 3> & center)
          {
            m_CPRView->SetPathMarker(center);
            m_ThreeDView->SetPathMarker(center);
          });
  connect(
    m_PathPanel,
    &VesselPathPanel::pathOpened,
    this,
    [this](int branchId)
    {
      std::vector<itk::Point<double, 3>> points;
      for (const auto & section : m_PathPanel->GetOutputs().Sections)
      {
        points.push_back(section.Center);
      }
      m_ThreeDView->SetPath(points);
      m_Layout->ShowPathPanel();
      EnableSectionKeys(true);
      const QString name = branchId > 0 && m_CurrentInputs
                             ? QString::fromStdString(m_CurrentInputs->BranchName(branchId))
                             : tr("the longest path");
      statusBar()->showMessage(
        tr("Opened the path to %1 (%2 ms)").arg(name).arg(std::lround(1000.0 * m_PathPanel->GetLastUpdateSeconds())),
        5000);
    });
  connect(m_PathPanel,
          &VesselPathPanel::errorOccurred,
          this,
          [this](const QString & message) { ShowError(tr("Cannot read the vessel path"), message); });
}

bool
ViewerWindow::OpenVesselPath(int branchId)
{
  // Asked of the worker: pathOpened() shows it, errorOccurred() says why not.
  return m_PathPanel->OpenBranch(branchId);
}

void
ViewerWindow::CloseVesselPath()
{
  m_PathPanel->setVisible(false);
  EnableSectionKeys(false);
  m_CPRView->SetPathMarker(std::nullopt);
  m_ThreeDView->SetPathMarker(std::nullopt);
  m_ThreeDView->SetPath({});
}

bool
ViewerWindow::OpenLumenSegmentation(const QStringList & paths)
{
  try
  {
    std::vector<std::string> files;
    for (const QString & path : paths)
    {
      files.push_back(path.toStdString());
    }
    if (!paths.isEmpty())
    {
      RememberDataFolder(paths.front());
    }
    std::vector<std::string> warnings;
    std::vector<std::string> descriptions;
    const auto               node = ReadSegmentationNode(files, warnings, descriptions);
    // Measured on the worker: a refusal comes through errorOccurred() and the previous segmentation stays.
    m_PathPanel->SetLumenSegmentation(node);
    for (const auto & warning : warnings)
    {
      ShowWarning(QString::fromStdString(warning));
    }
    return true;
  }
  catch (const std::exception & error)
  {
    ShowError(tr("Cannot open %1").arg(paths.join(",")), QString::fromUtf8(error.what()));
    return false;
  }
}

bool
ViewerWindow::ExportLumenTable(const QString & path)
{
  const QString error = m_PathPanel->WriteLumenTable(path);
  if (!error.isEmpty())
  {
    ShowError(tr("Cannot export the lumen table"), error);
    return false;
  }
  statusBar()->showMessage(tr("Wrote the lumen table %1").arg(path), 10000);
  return true;
}

int
ViewerWindow::ExportVesselPathImages(const QString & folder)
{
  if (!m_PathPanel->HasPath())
  {
    ShowError(tr("Cannot export the path's images"), tr("no vessel path is open"));
    return 0;
  }
  const QDir target(folder);
  QWidget *  widgets[] = {
     m_PathPanel, m_PathPanel->GetStraightenedView(), m_PathPanel->GetCrossSectionView(), m_PathPanel->GetProfilePlot()
  };
  int written = 0;
  for (int i = 0; i < VesselPathImageNames().size(); ++i)
  {
    const QString error = WriteWidgetPNG(widgets[i], target.filePath(VesselPathImageNames()[i]));
    if (!error.isEmpty())
    {
      ShowError(tr("Cannot export the path's images"), error);
      return 0;
    }
    ++written;
  }
  statusBar()->showMessage(tr("Wrote %1 pictures of the vessel path to %2").arg(written).arg(folder), 10000);
  return written;
}

void
ViewerWindow::ChooseAndOpenLumenSegmentation()
{
  const QStringList paths =
    QFileDialog::getOpenFileNames(this,
                                  tr("Measure the lumen on a segmentation"),
                                  StartFolder(),
                                  tr("Images (*.nii *.nii.gz *.nrrd *.mha *.mhd);;All files (*)"));
  if (!paths.isEmpty())
  {
    OpenLumenSegmentation(paths);
  }
}

void
ViewerWindow::ChooseAndExportLumenTable()
{
  const QString path = QFileDialog::getSaveFileName(this,
                                                    tr("Export the lumen table"),
                                                    QDir(StartFolder()).filePath(QStringLiteral("lumen.csv")),
                                                    tr("CSV (*.csv);;TSV (*.tsv)"));
  if (!path.isEmpty())
  {
    ExportLumenTable(path);
  }
}

void
ViewerWindow::ChooseAndExportVesselPathImages()
{
  const QString folder = QFileDialog::getExistingDirectory(this, tr("Export the path's images to"), StartFolder());
  if (!folder.isEmpty())
  {
    ExportVesselPathImages(folder);
  }
}
} // namespace vr
