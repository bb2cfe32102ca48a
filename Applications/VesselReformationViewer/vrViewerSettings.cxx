// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrViewerSettings.h"

#include <QDir>
#include <QFileInfo>
#include <QSettings>

namespace vr
{
ViewerSettings::ViewerSettings(const QString & iniFile)
  : m_Settings(iniFile.isEmpty() ? std::make_unique<QSettings>(QStringLiteral("VesselReformation"),
                                                               QStringLiteral("VesselReformationViewer"))
                                 : std::make_unique<QSettings>(iniFile, QSettings::IniFormat))
{
}

ViewerSettings::~ViewerSettings() = default;

QString
ViewerSettings::LastFolder() const
{
  const QString folder = m_Settings->value(QStringLiteral("files/lastFolder")).toString();
  return !folder.isEmpty() && QFileInfo(folder).isDir() ? folder : QDir::homePath();
}

void
ViewerSettings::RememberFolderOf(const QString & path)
{
  const QFileInfo info(path);
  m_Settings->setValue(QStringLiteral("files/lastFolder"),
                       info.isDir() ? info.absoluteFilePath() : info.absolutePath());
}

std::vector<ViewerSettings::RecentEntry>
ViewerSettings::Recent() const
{
  std::vector<RecentEntry> entries;
  const int                count = m_Settings->beginReadArray(QStringLiteral("recent"));
  for (int k = 0; k < count && k < MaximumRecent; ++k)
  {
    m_Settings->setArrayIndex(k);
    RecentEntry entry;
    entry.Volume = m_Settings->value(QStringLiteral("volume")).toString();
    entry.Centerlines = m_Settings->value(QStringLiteral("centerlines")).toStringList();
    entry.Segmentation = m_Settings->value(QStringLiteral("segmentation")).toBool();
    if (!entry.Volume.isEmpty() && !entry.Centerlines.isEmpty())
    {
      entries.push_back(entry);
    }
  }
  m_Settings->endArray();
  return entries;
}

void
ViewerSettings::AddRecent(const RecentEntry & entry)
{
  std::vector<RecentEntry> entries{ entry };
  for (const RecentEntry & old : Recent())
  {
    const bool same =
      old.Volume == entry.Volume && old.Centerlines == entry.Centerlines && old.Segmentation == entry.Segmentation;
    if (!same && static_cast<int>(entries.size()) < MaximumRecent)
    {
      entries.push_back(old);
    }
  }
  m_Settings->beginWriteArray(QStringLiteral("recent"), static_cast<int>(entries.size()));
  for (int k = 0; k < static_cast<int>(entries.size()); ++k)
  {
    m_Settings->setArrayIndex(k);
    m_Settings->setValue(QStringLiteral("volume"), entries[k].Volume);
    m_Settings->setValue(QStringLiteral("centerlines"), entries[k].Centerlines);
    m_Settings->setValue(QStringLiteral("segmentation"), entries[k].Segmentation);
  }
  m_Settings->endArray();
}

QByteArray
ViewerSettings::Value(const QString & key) const
{
  return m_Settings->value(key).toByteArray();
}

void
ViewerSettings::SetValue(const QString & key, const QByteArray & value)
{
  m_Settings->setValue(key, value);
}

void
ViewerSettings::Sync()
{
  m_Settings->sync();
}
} // namespace vr
