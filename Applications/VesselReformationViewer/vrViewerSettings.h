// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrViewerSettings_h
#define vrViewerSettings_h

#include <QByteArray>
#include <QString>
#include <QStringList>

#include <memory>
#include <vector>

class QSettings;

namespace vr
{
/** \class ViewerSettings
 * \brief What the viewer remembers from one run to the next (QSettings): the folder of the latest file opened, the
 * recently opened volume and centerline pairs, the window's geometry and the split between panel and views, and the
 * overlays shown. Nothing here changes a reformation: the parameters and the window of a new volume are the inputs'
 * own defaults each time.
 * \ingroup VesselReformation
 */
class ViewerSettings
{
public:
  /** \param iniFile an INI file to keep the settings in (tests); empty: the user's own settings of organisation
   * "VesselReformation", application "VesselReformationViewer" (~/.config on Linux). */
  explicit ViewerSettings(const QString & iniFile = QString());
  ~ViewerSettings();
  ViewerSettings(const ViewerSettings &) = delete;
  ViewerSettings &
  operator=(const ViewerSettings &) = delete;

  /** The folder file dialogs start in: the latest file's, else the home folder. */
  QString
  LastFolder() const;
  /** Remembers the folder of \a path (a file or a folder). */
  void
  RememberFolderOf(const QString & path);

  /** One entry of File > Open recent: a volume with its centerlines (or segmentation files). */
  struct RecentEntry
  {
    QString     Volume;
    QStringList Centerlines; // one file, or the segmentation files
    bool        Segmentation{ false };
  };
  /** \return the entries, the latest first (at most MaximumRecent). */
  std::vector<RecentEntry>
  Recent() const;
  /** Puts \a entry first, dropping an equal one further down and the oldest beyond MaximumRecent. */
  void
                       AddRecent(const RecentEntry & entry);
  static constexpr int MaximumRecent = 8;

  QByteArray
  Value(const QString & key) const;
  void
  SetValue(const QString & key, const QByteArray & value);

  /** Writes pending changes to permanent storage. */
  void
  Sync();

private:
  std::unique_ptr<QSettings> m_Settings;
};
} // namespace vr

#endif
