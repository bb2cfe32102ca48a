// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrCrossSectionView_h
#define vrCrossSectionView_h

#include "vrImageTypes.h"

#include <QImage>
#include <QRectF>
#include <QWidget>

namespace vr
{
/** \class CrossSectionView
 * \brief The plane perpendicular to the vessel path at the cross-section position: one slice of the logic's
 * cross-section stack (u = the frame's lateral axis to the right, v = its up axis upwards, the path point in the
 * middle), through window and level, with a cross at the path point and, when the lumen was measured, a circle of
 * the section's diameter (display only: the measurement is the logic's). QPainter draws it.
 *
 * The wheel, Up/Down and Page Up/Down step the position as in the straightened CPR (vr::SectionStepper; stepped()).
 * \sa VesselPathPanel
 * \ingroup VesselReformation
 */
class CrossSectionView : public QWidget
{
  Q_OBJECT

public:
  explicit CrossSectionView(QWidget * parent = nullptr);

  /** Shows slice \a index of \a stack (null: empty view) through \a window and \a level. */
  void
  SetSlice(VolumeImageType::ConstPointer stack, unsigned int index, double window, double level);
  void
  SetWindowLevel(double window, double level);
  /** The section's lumen diameter (mm), drawn as a circle about the path point; NaN draws none. */
  void
  SetDiameter(double diameter);
  /** A caption in the upper left corner ("s = 42.0 mm"). */
  void
  SetCaption(const QString & caption);

  unsigned int
  GetSliceIndex() const
  {
    return m_Index;
  }
  /** \return where the slice is drawn (widget pixels). */
  QRectF
  ImageRect() const;
  const QImage &
  GetDisplayedImage() const
  {
    return m_Grey;
  }

  QSize
  sizeHint() const override
  {
    return QSize(240, 240);
  }

signals:
  void
  stepped(int sections);

protected:
  void
  paintEvent(QPaintEvent * event) override;

private:
  VolumeImageType::ConstPointer m_Stack;
  unsigned int                  m_Index{ 0 };
  QImage                        m_Grey;
  double                        m_Window{ 400.0 };
  double                        m_Level{ 200.0 };
  double                        m_Diameter{ 0.0 };
  QString                       m_Caption;
};
} // namespace vr

#endif
