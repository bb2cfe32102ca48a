// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrOcclusionStrip_h
#define vrOcclusionStrip_h

#include "itkCPROcclusionProfile.h"

#include <QWidget>

#include <memory>

namespace vr
{
/** \class OcclusionStrip
 * \brief A thin strip under the CPR view: the hidden fraction of the tree's centerline against the view angle,
 * 0-179 degrees left to right (itk::CPROcclusionProfile, the logic's Outputs.OcclusionProfile), the current angle
 * marked with a line and the least occluded angle with a green tick. A click goes to the angle under the mouse
 * (angleClicked()); the tooltip reads the hidden length there. It draws what the logic computed and computes
 * nothing.
 *
 * Angles from 180 to 359 degrees look at the same overlaps from the other side: the mark stands at the angle less 180
 * and is drawn dashed.
 * \ingroup VesselReformation
 */
class OcclusionStrip : public QWidget
{
  Q_OBJECT

public:
  explicit OcclusionStrip(QWidget * parent = nullptr);

  /** The profile to draw (null: none yet, the strip says so). */
  void
  SetProfile(std::shared_ptr<const itk::CPROcclusionProfile> profile);
  std::shared_ptr<const itk::CPROcclusionProfile>
  GetProfile() const
  {
    return m_Profile;
  }
  /** The angle of the view on screen, degrees (any value; marked modulo 180). */
  void
  SetCurrentAngle(double degrees);
  double
  GetCurrentAngle() const
  {
    return m_Angle;
  }

  /** \return the angle (whole degrees, 0-179) under the widget x coordinate \a x. */
  int
  AngleAt(double x) const;
  /** \return the widget x coordinate of the middle of angle \a degrees (0-179). */
  double
  XOfAngle(double degrees) const;

  QSize
  sizeHint() const override;
  QSize
  minimumSizeHint() const override;

signals:
  /** A click on the strip: the angle there, whole degrees 0-179. */
  void
  angleClicked(double degrees);

protected:
  void
  paintEvent(QPaintEvent * event) override;
  void
  mousePressEvent(QMouseEvent * event) override;
  bool
  event(QEvent * event) override;

private:
  std::shared_ptr<const itk::CPROcclusionProfile> m_Profile;
  double                                          m_Angle{ 0.0 };
};
} // namespace vr

#endif
