// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrStraightenedCPRView_h
#define vrStraightenedCPRView_h

#include "vrGreyImageView.h"
#include "vrImageTypes.h"

#include <QPointF>

namespace vr
{
/** \class StraightenedCPRView
 * \brief One vessel's straightened (or stretched) CPR as the logic made it (x across the vessel, y along the path,
 * row 0 at the top), through window and level, with the cross-section position as a line across it. It displays
 * and computes nothing; QPainter draws it (a few hundred rows: cheaper than a GL context of its own under Mesa), as
 * vr::GreyImageView lays out its image, caption and window/level.
 *
 * - left-drag horizontally rolls the image about the path: rollDragged() reports DegreesPerPixel per pixel;
 * - right-click or right-drag puts the cross-section at the row under the mouse (rowPicked());
 * - the wheel and the Up/Down keys step the cross-section by one section, Page Up/Down by ten (vr::SectionStepper,
 *   as in the cross-section view; stepped()).
 * \sa VesselPathPanel
 * \ingroup VesselReformation
 */
class StraightenedCPRView : public GreyImageView
{
  Q_OBJECT

public:
  /** Degrees the image rolls per pixel of horizontal left-drag. */
  static constexpr double DegreesPerPixel = 0.5;

  explicit StraightenedCPRView(QWidget * parent = nullptr);

  /** Shows \a image (may be null: empty view) through \a window and \a level. */
  void
  SetImage(DepthImageType::ConstPointer image, double window, double level);
  /** The cross-section's continuous row (the logic's RowOfArcLength), drawn as a line across the image. */
  void
  SetPositionRow(double row);
  double
  GetPositionRow() const
  {
    return m_PositionRow;
  }

  /** \return the widget y of the centre of continuous row \a row, and the row at widget y. */
  double
  WidgetYOfRow(double row) const;
  double
  RowAtWidgetY(double y) const;
  QSize
  sizeHint() const override
  {
    return QSize(220, 420);
  }

signals:
  void
  rollStarted();
  /** \a degrees since the drag started; \a finished at the release. */
  void
  rollDragged(double degrees, bool finished);
  void
  rowPicked(double row);
  void
  stepped(int sections);

protected:
  QImage
  MakeGreyImage(double window, double level) const override;
  /** Millimetres: the image's own spacing sets the aspect. */
  QSizeF
  ImageExtent() const override;
  void
  PaintOverlay(QPainter & painter, const QRectF & target) override;
  void
  mousePressEvent(QMouseEvent * event) override;
  void
  mouseMoveEvent(QMouseEvent * event) override;
  void
  mouseReleaseEvent(QMouseEvent * event) override;

private:
  DepthImageType::ConstPointer m_Image;
  double                       m_PositionRow{ -1.0 };
  Qt::MouseButton              m_Drag{ Qt::NoButton };
  QPointF                      m_DragStart;
};
} // namespace vr

#endif
