// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrVesselPathSettings_h
#define vrVesselPathSettings_h

#include "vrVesselPathParameters.h"

#include <QString>
#include <QWidget>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLineEdit;

namespace vr
{
/** \class VesselPathSettings
 * \brief The vessel path panel's settings (docs/viewer.md, "Reading one vessel"), the controls the module has as
 * flags: the image's width, the part of the path read (range), the slab, the reference (method and the user's points)
 * and the grading scale. It edits a vr::VesselPathParameters and says when the user changed one (edited()); it
 * computes nothing. Every control has a tooltip with its unit.
 * \ingroup VesselReformation
 */
class VesselPathSettings : public QWidget
{
  Q_OBJECT

public:
  explicit VesselPathSettings(QWidget * parent = nullptr);

  /** Shows \a parameters in the controls (no edited() signal). \a pathLength: the whole path's length, the range's
   * limit (mm). */
  void
  Show(const VesselPathParameters & parameters, double pathLength);
  /** Writes the controls into \a parameters (the other fields stay). \return an error naming the control and what is
   * wrong (a reference point that is no number, a range whose end is not after its start), or empty. */
  QString
  Apply(VesselPathParameters & parameters) const;

  QDoubleSpinBox *
  GetWidthSpinBox() const
  {
    return m_Width;
  }
  QCheckBox *
  GetRangeCheckBox() const
  {
    return m_HasRange;
  }
  QDoubleSpinBox *
  GetRangeStartSpinBox() const
  {
    return m_RangeStart;
  }
  QDoubleSpinBox *
  GetRangeEndSpinBox() const
  {
    return m_RangeEnd;
  }
  QDoubleSpinBox *
  GetSlabSpinBox() const
  {
    return m_Slab;
  }
  QComboBox *
  GetSlabModeBox() const
  {
    return m_SlabMode;
  }
  QComboBox *
  GetReferenceMethodBox() const
  {
    return m_Method;
  }
  QLineEdit *
  GetReferencePointsField() const
  {
    return m_Points;
  }
  QComboBox *
  GetScaleBox() const
  {
    return m_Scale;
  }

signals:
  /** The user changed a setting (a spin box's value once typed or stepped, a choice, the points once entered). */
  void
  edited();

private:
  QDoubleSpinBox * m_Width{ nullptr };
  QCheckBox *      m_HasRange{ nullptr };
  QDoubleSpinBox * m_RangeStart{ nullptr };
  QDoubleSpinBox * m_RangeEnd{ nullptr };
  QDoubleSpinBox * m_Slab{ nullptr };
  QComboBox *      m_SlabMode{ nullptr };
  QComboBox *      m_Method{ nullptr };
  QLineEdit *      m_Points{ nullptr };
  QComboBox *      m_Scale{ nullptr };
  double           m_PathLength{ 0.0 };
};
} // namespace vr

#endif
