// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrGreyImageView_h
#define vrGreyImageView_h

#include <QImage>
#include <QRectF>
#include <QString>
#include <QWidget>

class QPainter;

namespace vr
{
/** \class GreyImageView
 * \brief What the one-vessel views that QPainter draws share: a grey image of the logic's pixels through window and
 * level (vr::GreyImage, the mapping of a saved PNG), fitted under a caption in the upper left corner, and the
 * overlays a subclass draws over it. A subclass says what the image is (MakeGreyImage()) and how wide and high it is
 * on screen (ImageExtent()); it calls Refresh() when its data changes.
 * \sa StraightenedCPRView, CrossSectionView
 * \ingroup VesselReformation
 */
class GreyImageView : public QWidget
{
  Q_OBJECT

public:
  /** Window width and level (display only); a change remakes the grey image. */
  void
  SetWindowLevel(double window, double level);
  double
  GetWindow() const
  {
    return m_Window;
  }
  double
  GetLevel() const
  {
    return m_Level;
  }
  /** A caption in the upper left corner, drawn while the view shows an image. */
  void
  SetCaption(const QString & caption);
  const QString &
  GetCaption() const
  {
    return m_Caption;
  }
  /** \return where the image is drawn (widget pixels): as large as fits below the caption, centred, its aspect kept;
   * empty without an image. */
  QRectF
  ImageRect() const;
  /** \return the image drawn (8-bit grey). */
  const QImage &
  GetDisplayedImage() const
  {
    return m_Grey;
  }

protected:
  explicit GreyImageView(QWidget * parent = nullptr);

  /** Remakes the grey image through \a window and \a level (MakeGreyImage()) and repaints. */
  void
  Refresh(double window, double level);
  /** \return the subclass's pixels through \a window and \a level, row 0 at the top; null when it shows none. */
  virtual QImage
  MakeGreyImage(double window, double level) const = 0;
  /** \return the image's width and height on screen in any unit (ImageRect() keeps their ratio): its pixels by
   * default. */
  virtual QSizeF
  ImageExtent() const;
  /** Draws over the image, which lies at \a target. */
  virtual void
  PaintOverlay(QPainter & painter, const QRectF & target);

  void
  paintEvent(QPaintEvent * event) override;

private:
  QImage  m_Grey;
  double  m_Window{ 400.0 };
  double  m_Level{ 200.0 };
  QString m_Caption;
};
} // namespace vr

#endif
