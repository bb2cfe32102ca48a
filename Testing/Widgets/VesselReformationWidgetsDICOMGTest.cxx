// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// The viewer opening DICOM folders (issue 37, docs/dicom-series.md), driven as a user would under a virtual X server:
// a folder of two series asks which (cancelling keeps the data on screen; the answer reads that series), and a series
// with a slice missing shows the reader's warning, whole, in the banner above the views.
#include "vrWidgetsTestSupport.h"
#include "vrWindowTestFixture.h"

#include "vrDICOMCampaign.h"
#include "vrDICOMTestSeries.h"
#include "vrNodeConversion.h"
#include "vrTestFiles.h"

#include <QInputDialog>
#include <QLabel>
#include <QMessageBox>

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

namespace
{
using namespace vr;
using namespace vr::test;

/** The small phantom rounded to whole HU, as a DICOM series would hold it. */
VolumeImageType::Pointer
PhantomAsCT()
{
  return QuantizedCT(ConvertVolumeNodeToItkImage(SmallPhantomInputs().Volume));
}

/** The series' folder written under \a folder. */
std::string
WriteFolder(const ScopedTemporaryFolder & folder, const std::string & name, const std::vector<DICOMTestFile> & files)
{
  const std::string path = folder.File(name);
  WriteDICOMTestFolder(path, files);
  return path;
}

QInputDialog *
SeriesDialog(ViewerWindow & window)
{
  auto * dialog = window.findChild<QInputDialog *>(QStringLiteral("dicomSeriesChoice"));
  return dialog != nullptr && dialog->isVisible() ? dialog : nullptr;
}
} // namespace

TEST_F(WidgetsTest, AFolderOfTwoSeriesAsksWhichAndReadsTheOneChosen)
{
  ScopedTemporaryFolder      folder;
  const auto                 volume = PhantomAsCT();
  std::vector<DICOMTestFile> files = MakeCTSeries(volume);
  for (int k = 1; k <= 2; ++k)
  {
    DICOMTestFile scout = files.front();
    scout.Name = "scout" + std::to_string(k) + ".dcm";
    scout.Values.assign(32 * 32, -1000.0);
    scout.Data.SetUS(0x0028, 0x0010, 32);
    scout.Data.SetUS(0x0028, 0x0011, 32);
    scout.Data.SetText(0x0020, 0x000E, "UI", "1.2.826.0.1.3680043.9.7731.37.8");
    scout.Data.SetText(0x0008, 0x0018, "UI", "1.2.826.0.1.3680043.9.7731.37.8." + std::to_string(k));
    scout.Data.SetText(0x0008, 0x103E, "LO", "Topogram");
    scout.Data.SetText(0x0020, 0x0011, "IS", "1");
    files.push_back(scout);
  }
  const std::string dicom = WriteFolder(folder, "two-series", files);
  const auto        inputsBefore = Controller().GetInputs();
  int               errors = 0;
  QObject::connect(&Window(), &ViewerWindow::errorShown, &Window(), [&] { ++errors; });

  // Asked; cancelled: nothing replaced, no error.
  Window().OpenVolume(QString::fromStdString(dicom));
  QInputDialog * dialog = nullptr;
  ASSERT_TRUE(WaitUntil([&] { return (dialog = SeriesDialog(Window())) != nullptr; }, 120.0));
  const QStringList items = dialog->comboBoxItems();
  ASSERT_EQ(items.size(), 2);
  EXPECT_TRUE(items[0].startsWith(QStringLiteral("1: series 1 \"Topogram\" (CT), 2 files of 32 x 32 pixels")))
    << items[0].toStdString();
  const auto size = volume->GetLargestPossibleRegion().GetSize();
  EXPECT_TRUE(items[1].startsWith(QStringLiteral("2: series 3 \"CTA 1.5 mm\" (CT), %1 files of %2 x %3 pixels")
                                    .arg(size[2])
                                    .arg(size[0])
                                    .arg(size[1])))
    << items[1].toStdString();
  EXPECT_TRUE(dialog->labelText().contains(QStringLiteral("holds 2 series"))) << dialog->labelText().toStdString();
  EXPECT_EQ(dialog->textValue(), items[1]) << "the series of the most files offered first";
  EXPECT_EQ(Controller().GetInputs(), inputsBefore) << "nothing is replaced while the question is open";
  std::filesystem::create_directories(VR_WIDGETS_PICTURES_DIR);
  EXPECT_TRUE(dialog->grab().save(QString::fromStdString(
    (std::filesystem::path(VR_WIDGETS_PICTURES_DIR) / "viewer-dicom-series-choice.png").string())));
  dialog->reject();
  ASSERT_TRUE(WaitUntilSettled(Window()));
  EXPECT_EQ(Controller().GetInputs(), inputsBefore);
  EXPECT_EQ(errors, 0);
  EXPECT_EQ(ErrorDialog(Window()), nullptr);

  // Asked again; the CT chosen: read, the phantom's voxels at the phantom's points.
  Window().OpenVolume(QString::fromStdString(dicom));
  ASSERT_TRUE(WaitUntil([&] { return (dialog = SeriesDialog(Window())) != nullptr; }, 120.0));
  dialog->setTextValue(dialog->comboBoxItems()[1]);
  dialog->accept();
  ASSERT_TRUE(WaitUntil([&] { return Controller().GetInputs() != inputsBefore; }, 120.0));
  ASSERT_TRUE(WaitUntilSettled(Window()));
  EXPECT_EQ(errors, 0);
  const auto read = ConvertVolumeNodeToItkImage(Controller().GetInputs()->Volume);
  EXPECT_EQ(read->GetLargestPossibleRegion().GetSize(), size);
  EXPECT_EQ(SlicesThatDiffer(read, volume, 0.0), std::vector<unsigned int>());
  EXPECT_TRUE(Window().GetShownWarnings().isEmpty());
  EXPECT_EQ(Window().GetCPRView()->GetResult()->Inputs, Controller().GetInputs()) << "the CT is reformed";
}

TEST_F(WidgetsTest, AFolderWithASliceMissingShowsTheGapInTheBanner)
{
  ScopedTemporaryFolder      folder;
  std::vector<DICOMTestFile> files = MakeCTSeries(PhantomAsCT());
  files.erase(
    std::find_if(files.begin(), files.end(), [](const DICOMTestFile & file) { return file.Name == "IM0040.dcm"; }));
  const std::string dicom = WriteFolder(folder, "gap", files);
  const auto        inputsBefore = Controller().GetInputs();
  Window().OpenVolume(QString::fromStdString(dicom));
  ASSERT_TRUE(WaitUntil([&] { return Controller().GetInputs() != inputsBefore; }, 120.0));
  ASSERT_TRUE(WaitUntilSettled(Window()));
  const std::string warnings = Window().GetShownWarnings().join(QStringLiteral("\n")).toStdString();
  const std::string files41 = (std::filesystem::path(dicom) / "IM0041.dcm").string();
  const std::string files39 = (std::filesystem::path(dicom) / "IM0039.dcm").string();
  EXPECT_NE(warnings.find("volume folder " + dicom + ": the DICOM series has a gap of 6 mm between the files " +
                          files41 + " and " + files39),
            std::string::npos)
    << warnings;
  EXPECT_NE(warnings.find("is interpolated linearly from those two files"), std::string::npos) << warnings;
  // The banner shows it whole on screen.
  const QLabel * banner = nullptr;
  for (const QLabel * label : Window().findChildren<QLabel *>())
  {
    if (label->isVisible() && label->wordWrap() && label->text().contains(QStringLiteral("has a gap of 6 mm")))
    {
      banner = label;
    }
  }
  ASSERT_NE(banner, nullptr) << "no visible banner holds the warning";
  EXPECT_TRUE(banner->text().contains(QStringLiteral("interpolated linearly from those two files")));
  const QString picture =
    QString::fromStdString((std::filesystem::path(VR_WIDGETS_PICTURES_DIR) / "viewer-dicom-gap-banner.png").string());
  std::filesystem::create_directories(VR_WIDGETS_PICTURES_DIR);
  EXPECT_TRUE(Window().grab().save(picture)) << picture.toStdString();
}
