// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// The viewer window's opening of files: volumes, centerlines, segmentations, phantoms, the recent files and undo.
#include "vrViewerWindow.h"

#include "itkCTAPhantom.h"
#include "vrInputError.h"
#include "vrReformationInputs.h"

#include <QAbstractItemView>
#include <QAction>
#include <QComboBox>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QInputDialog>
#include <QMetaObject>
#include <QMenu>
#include <QMessageBox>
#include <QStatusBar>

#include <algorithm>

namespace vr
{
namespace
{
/** The file dialogs' filters: the formats the volume and centerline readers take. */
QString
VolumeFileFilter()
{
  return ViewerWindow::tr("Volumes (*.nrrd *.nhdr *.nii *.nii.gz *.mha *.mhd);;All files (*)");
}

QString
CenterlineFileFilter()
{
  return ViewerWindow::tr("Centerlines (*.vtp *.vtk *.mrk.json *.json *.tre *.csv);;All files (*)");
}
} // namespace

void
ViewerWindow::LoadPhantom(const QString & name, double spacing)
{
  const std::string phantom = name.toStdString();
  m_Controller->LoadInputs([phantom, spacing] { return MakePhantomInputs(phantom, spacing); },
                           tr("the %1 phantom").arg(name));
}

void
ViewerWindow::OpenFiles(const QString & volume, const QString & centerlines, const QString & series)
{
  const std::string volumePath = volume.toStdString();
  const std::string centerlinePath = centerlines.toStdString();
  RememberDataFolder(volume);
  RememberWhenLoaded({ QFileInfo(volume).absoluteFilePath(), { QFileInfo(centerlines).absoluteFilePath() }, false });
  m_Controller->LoadInputs(
    [this, volumePath, centerlinePath, volume, centerlines, series]
    {
      VolumeReadReport  report;
      const auto        node = ReadVolumeOrAsk(volumePath,
                                        series,
                                        report,
                                        [this, volume, centerlines](const QString & chosen)
                                        { OpenFiles(volume, centerlines, chosen); });
      ReformationInputs inputs = MakeInputs(node, ReadCenterlineNode(centerlinePath));
      AddVolumeReport(inputs, report);
      return inputs;
    },
    tr("%1 and %2").arg(QFileInfo(volume).fileName(), QFileInfo(centerlines).fileName()));
}

void
ViewerWindow::OpenVolume(const QString & path, const QString & series)
{
  auto current = m_Controller->GetInputs();
  if (!current)
  {
    ShowError(tr("Cannot open %1").arg(path), tr("Open the centerlines as well: the viewer needs both."));
    return;
  }
  const std::string volumePath = path.toStdString();
  RememberDataFolder(path);
  m_Controller->LoadInputs(
    [this, volumePath, current, path, series]
    {
      VolumeReadReport report;
      const auto       node =
        ReadVolumeOrAsk(volumePath, series, report, [this, path](const QString & chosen) { OpenVolume(path, chosen); });
      ReformationInputs inputs;
      if (current->Segmentation)
      {
        // The segmentation stays: the logic extracts its centerlines again against the new volume.
        inputs = MakeSegmentationInputs(node, current->Segmentation);
      }
      else
      {
        inputs = MakeInputs(node, current->Centerlines);
      }
      inputs.CenterlineSource = current->CenterlineSource;
      AddVolumeReport(inputs, report);
      return inputs;
    },
    QFileInfo(path).fileName(),
    PanelParameters());
}

vtkSmartPointer<VolumeNode>
ViewerWindow::ReadVolumeOrAsk(const std::string &                          path,
                              const QString &                              series,
                              VolumeReadReport &                           report,
                              const std::function<void(const QString &)> & again) const
{
  VolumeReadOptions options;
  options.DICOMSeries = series.toStdString();
  try
  {
    return ReadVolumeNode(path, options, &report);
  }
  catch (const DICOMSeriesChoiceRequired & choice)
  {
    auto *        window = const_cast<ViewerWindow *>(this);
    const auto    listed = choice.GetSeries();
    const QString folder = QString::fromStdString(path);
    // The reason is said only where a choice was given and named none (the folder changed since).
    const QString reason = series.isEmpty() ? QString() : QString::fromStdString(choice.what());
    QMetaObject::invokeMethod(
      window,
      [window, folder, listed, reason, again] { window->AskForDICOMSeries(folder, listed, reason, again); },
      Qt::QueuedConnection);
    throw Cancelled("waiting for the choice of a DICOM series");
  }
}

void
ViewerWindow::AskForDICOMSeries(const QString &                              path,
                                const std::vector<DICOMSeriesSummary> &      series,
                                const QString &                              reason,
                                const std::function<void(const QString &)> & again)
{
  QStringList items;
  for (const DICOMSeriesSummary & summary : series)
  {
    items << QString::fromStdString(DescribeDICOMSeries(summary));
  }
  auto * dialog = new QInputDialog(this);
  dialog->setObjectName(QStringLiteral("dicomSeriesChoice"));
  dialog->setAttribute(Qt::WA_DeleteOnClose);
  dialog->setWindowTitle(tr("Which DICOM series?"));
  dialog->setLabelText((reason.isEmpty() ? QString() : reason + QStringLiteral("\n\n")) +
                       tr("The folder %1 holds %2 series. Which one is the volume to read?")
                         .arg(QDir::toNativeSeparators(path))
                         .arg(series.size()));
  dialog->setComboBoxItems(items);
  dialog->setComboBoxEditable(false);
  // The series with the most files first in view (the volume, most often; a scout has a few); the list shows each
  // line whole, the closed box a part of it.
  const auto largest =
    std::max_element(series.begin(),
                     series.end(),
                     [](const DICOMSeriesSummary & a, const DICOMSeriesSummary & b) { return a.Files < b.Files; });
  dialog->setTextValue(items[static_cast<int>(largest - series.begin())]);
  if (auto * box = dialog->findChild<QComboBox *>())
  {
    box->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    box->setMinimumContentsLength(72);
    box->view()->setMinimumWidth(box->view()->sizeHintForColumn(0));
  }
  dialog->setOkButtonText(tr("Read"));
  connect(dialog,
          &QInputDialog::textValueSelected,
          this,
          [items, series, again](const QString & text)
          {
            const int index = items.indexOf(text);
            if (index >= 0)
            {
              again(QString::number(series[static_cast<std::size_t>(index)].Number));
            }
          });
  dialog->open();
  statusBar()->showMessage(
    tr("%1 holds %2 DICOM series: choose one").arg(QFileInfo(path).fileName()).arg(series.size()), 10000);
}

void
ViewerWindow::OpenCenterlines(const QString & path)
{
  auto current = m_Controller->GetInputs();
  if (!current)
  {
    ShowError(tr("Cannot open %1").arg(path), tr("Open a volume as well: the viewer needs both."));
    return;
  }
  const std::string centerlinePath = path.toStdString();
  RememberDataFolder(path);
  m_Controller->LoadInputs(
    [centerlinePath, current]
    {
      ReformationInputs inputs = MakeInputs(current->Volume, ReadCenterlineNode(centerlinePath));
      inputs.VolumeSource = current->VolumeSource;
      inputs.IsPhantom = current->IsPhantom;
      return inputs;
    },
    QFileInfo(path).fileName());
}

std::optional<ReformationParameters>
ViewerWindow::PanelParameters() const
{
  try
  {
    return m_Panel->GetParameters();
  }
  catch (const InputError &)
  {
    return std::nullopt;
  }
}

void
ViewerWindow::OpenSegmentation(const QStringList & paths)
{
  auto current = m_Controller->GetInputs();
  if (!current)
  {
    ShowError(tr("Cannot open %1").arg(paths.join(QStringLiteral(", "))),
              tr("Open a volume as well: the viewer needs both."));
    return;
  }
  std::vector<std::string> files;
  QStringList              names;
  for (const QString & path : paths)
  {
    files.push_back(path.toStdString());
    names << QFileInfo(path).fileName();
  }
  RememberDataFolder(paths.front());
  m_Controller->LoadInputs(
    [files, current]
    {
      std::vector<std::string> warnings;
      std::vector<std::string> descriptions;
      ReformationInputs        inputs =
        MakeSegmentationInputs(current->Volume, ReadSegmentationNode(files, warnings, descriptions));
      inputs.VolumeSource = current->VolumeSource;
      inputs.IsPhantom = current->IsPhantom;
      inputs.PhantomName = current->PhantomName;
      inputs.Warnings = warnings;
      return inputs;
    },
    names.join(QStringLiteral(", ")),
    PanelParameters());
}

void
ViewerWindow::OpenFilesWithSegmentation(const QString &     volume,
                                        const QStringList & segmentation,
                                        const QString &     series)
{
  const std::string        volumePath = volume.toStdString();
  std::vector<std::string> files;
  QStringList              names;
  for (const QString & path : segmentation)
  {
    files.push_back(path.toStdString());
    names << QFileInfo(path).fileName();
  }
  QStringList absolute;
  for (const QString & path : segmentation)
  {
    absolute << QFileInfo(path).absoluteFilePath();
  }
  RememberDataFolder(volume);
  RememberWhenLoaded({ QFileInfo(volume).absoluteFilePath(), absolute, true });
  m_Controller->LoadInputs(
    [this, volumePath, files, volume, segmentation, series]
    {
      std::vector<std::string> warnings;
      std::vector<std::string> descriptions;
      VolumeReadReport         report;
      auto                     volumeNode = ReadVolumeOrAsk(volumePath,
                                        series,
                                        report,
                                        [this, volume, segmentation](const QString & chosen)
                                        { OpenFilesWithSegmentation(volume, segmentation, chosen); });
      ReformationInputs        inputs =
        MakeSegmentationInputs(volumeNode, ReadSegmentationNode(files, warnings, descriptions));
      inputs.Warnings = warnings;
      AddVolumeReport(inputs, report);
      return inputs;
    },
    tr("%1 and %2").arg(QFileInfo(volume).fileName(), names.join(QStringLiteral(", "))),
    PanelParameters());
}

QString
ViewerWindow::StartFolder() const
{
  // The folder of the data on screen; else the latest folder of an earlier run; else where the viewer was started.
  if (!m_DataFolder.isEmpty() && QFileInfo(m_DataFolder).isDir())
  {
    return m_DataFolder;
  }
  const QString remembered = m_Settings ? m_Settings->LastFolder() : QString();
  return !remembered.isEmpty() && remembered != QDir::homePath() ? remembered : QDir::currentPath();
}

void
ViewerWindow::RememberDataFolder(const QString & path)
{
  const QFileInfo info(path);
  m_DataFolder = info.isDir() ? info.absoluteFilePath() : info.absolutePath();
  if (m_Settings)
  {
    m_Settings->RememberFolderOf(path);
  }
}

void
ViewerWindow::RememberWhenLoaded(const ViewerSettings::RecentEntry & entry)
{
  m_PendingRecent = entry;
}

void
ViewerWindow::FillRecentMenu()
{
  m_RecentMenu->clear();
  const auto entries = m_Settings ? m_Settings->Recent() : std::vector<ViewerSettings::RecentEntry>();
  for (int k = 0; k < static_cast<int>(entries.size()); ++k)
  {
    QStringList names;
    for (const QString & path : entries[k].Centerlines)
    {
      names << QFileInfo(path).fileName();
    }
    QAction * action =
      m_RecentMenu->addAction(QStringLiteral("&%1 %2 + %3")
                                .arg(k + 1)
                                .arg(QFileInfo(entries[k].Volume).fileName(), names.join(QStringLiteral(", "))),
                              this,
                              [this, k] { OpenRecent(k); });
    action->setToolTip(entries[k].Volume + QStringLiteral(" + ") + entries[k].Centerlines.join(QStringLiteral(", ")));
  }
  if (entries.empty())
  {
    m_RecentMenu->addAction(tr("(nothing opened yet)"))->setEnabled(false);
  }
}

void
ViewerWindow::OpenRecent(int index)
{
  const auto entries = m_Settings ? m_Settings->Recent() : std::vector<ViewerSettings::RecentEntry>();
  if (index < 0 || index >= static_cast<int>(entries.size()))
  {
    return;
  }
  const auto & entry = entries[static_cast<std::size_t>(index)];
  if (entry.Segmentation)
  {
    OpenFilesWithSegmentation(entry.Volume, entry.Centerlines);
  }
  else
  {
    OpenFiles(entry.Volume, entry.Centerlines.front());
  }
}

void
ViewerWindow::ChooseAndOpenVolumeAndCenterlines()
{
  const QString volume =
    QFileDialog::getOpenFileName(this, tr("Open a volume (then its centerlines)"), StartFolder(), VolumeFileFilter());
  if (volume.isEmpty())
  {
    return;
  }
  const QString centerlines =
    QFileDialog::getOpenFileName(this,
                                 tr("Open the centerlines of %1").arg(QFileInfo(volume).fileName()),
                                 QFileInfo(volume).absolutePath(),
                                 CenterlineFileFilter());
  if (centerlines.isEmpty())
  {
    return;
  }
  if (m_Settings)
  {
    m_Settings->RememberFolderOf(centerlines);
  }
  OpenFiles(volume, centerlines);
}

void
ViewerWindow::UndoOpen()
{
  if (m_UndoInputs.empty())
  {
    return;
  }
  const std::shared_ptr<const ReformationInputs> previous = m_UndoInputs.back();
  m_UndoInputs.pop_back();
  m_UndoOpen->setEnabled(!m_UndoInputs.empty());
  m_Undoing = true;
  m_Controller->LoadInputs(
    [previous] { return *previous; },
    tr("the previous inputs (%1)").arg(QFileInfo(QString::fromStdString(previous->VolumeSource)).fileName()),
    PanelParameters());
}

void
ViewerWindow::ChooseAndOpenVolume(bool dicomFolder)
{
  const QString path = dicomFolder
                         ? QFileDialog::getExistingDirectory(this, tr("Open a DICOM series folder"), StartFolder())
                         : QFileDialog::getOpenFileName(this, tr("Open a volume"), StartFolder(), VolumeFileFilter());
  if (!path.isEmpty())
  {
    if (m_Settings)
    {
      m_Settings->RememberFolderOf(path);
    }
    OpenVolume(path);
  }
}

void
ViewerWindow::ChooseAndOpenCenterlines()
{
  const QString path =
    QFileDialog::getOpenFileName(this, tr("Open centerlines"), StartFolder(), CenterlineFileFilter());
  if (!path.isEmpty())
  {
    if (m_Settings)
    {
      m_Settings->RememberFolderOf(path);
    }
    OpenCenterlines(path);
  }
}

void
ViewerWindow::ChooseAndOpenSegmentation()
{
  const QStringList paths = QFileDialog::getOpenFileNames(
    this,
    tr("Open a vessel segmentation (several files are combined)"),
    StartFolder(),
    tr("Segmentations: label maps, masks, level sets (*.nii *.nii.gz *.nrrd *.nhdr *.mha *.mhd);;All files (*)"));
  if (!paths.isEmpty())
  {
    if (m_Settings)
    {
      m_Settings->RememberFolderOf(paths.front());
    }
    OpenSegmentation(paths);
  }
}
} // namespace vr
