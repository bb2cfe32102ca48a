// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrCrossSectionView_h
#define vrCrossSectionView_h

#include "vrGreyImageView.h"
#include "vrImageTypes.h"

namespace vr
{
/** \class CrossSectionView
 * \brief The plane perpendicular to the vessel path at the cross-section position: one slice of the logic's
 * cross-section stack (u = the frame's lateral axis to the right, v = its up axis upwards, the path point in the
 * middle), through window and level, with a cross at the path point and, when the lumen was measured, a circle of
 * the section's diameter (display only: the measurement is the logic's). QPainter draws it, as vr::GreyImageView lays
 * out its image, caption and window/level.
 *
 * The wheel, Up/Down and Page Up/Down step the position as in the straightened CPR (vr::SectionStepper; stepped()).
 * \sa VesselPathPanel
 * \ingroup VesselReformation
 */
class CrossSectionView : public GreyImageView
{
  Q_OBJECT

public:
  explicit CrossSectionView(QWidget * parent = nullptr);

  /** Shows slice \a index of \a stack (null: empty view) through \a window and \a level. */
  void
  SetSlice(VolumeImageType::ConstPointer stack, unsigned int index, double window, double level);
  /** The section's lumen diameter (mm), drawn as a circle about the path point; NaN draws none. */
  void
  SetDiameter(double diameter);
  unsigned int
  GetSliceIndex() const
  {
    return m_Index;
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
  QImage
  MakeGreyImage(double window, double level) const override;
  void
  PaintOverlay(QPainter & painter, const QRectF & target) override;

private:
  VolumeImageType::ConstPointer m_Stack;
  unsigned int                  m_Index{ 0 };
  double                        m_Diameter{ 0.0 };
};
} // namespace vr

#endif
