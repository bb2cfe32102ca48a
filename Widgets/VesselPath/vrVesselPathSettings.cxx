// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrVesselPathSettings.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QRegularExpression>
#include <QSignalBlocker>

#include <algorithm>
#include <iterator>

namespace vr
{
namespace
{
QDoubleSpinBox *
MillimetreBox(double minimum, double maximum, const QString & tooltip)
{
  auto * box = new QDoubleSpinBox;
  box->setRange(minimum, maximum);
  box->setDecimals(1);
  box->setSingleStep(1.0);
  box->setSuffix(QStringLiteral(" mm"));
  box->setKeyboardTracking(false);
  box->setToolTip(tooltip);
  return box;
}

/** The scales in the order of the Scale box. */
constexpr StenosisScale    Scales[] = { StenosisScale::Automatic,
                                        StenosisScale::CADRADS,
                                        StenosisScale::Peripheral,
                                        StenosisScale::Carotid,
                                        StenosisScale::Aorta };
constexpr itk::CPRSlabMode SlabModes[] = { itk::CPRSlabMode::MIP, itk::CPRSlabMode::MinIP, itk::CPRSlabMode::Mean };
} // namespace

VesselPathSettings::VesselPathSettings(QWidget * parent)
  : QWidget(parent)
{
  m_Width =
    MillimetreBox(1.0,
                  300.0,
                  tr("Width of the straightened CPR across the vessel and of the cross-sections, mm. Wider than "
                     "twice the path's smallest radius of curvature, the CPR folds (the warning offers a width "
                     "that does not)."));
  m_HasRange = new QCheckBox(tr("Part"));
  m_HasRange->setToolTip(tr("Read only the part of the path between two arc lengths from its start (mm); off: the "
                            "whole path."));
  m_RangeStart = MillimetreBox(0.0, 1e5, tr("Where the part read starts: arc length from the path's start, mm."));
  m_RangeEnd = MillimetreBox(0.0, 1e5, tr("Where the part read ends: arc length from the path's start, mm."));
  auto * range = new QHBoxLayout;
  range->setContentsMargins(0, 0, 0, 0);
  range->addWidget(m_HasRange);
  range->addWidget(m_RangeStart, 1);
  range->addWidget(new QLabel(QStringLiteral("–")));
  range->addWidget(m_RangeEnd, 1);

  m_Slab = MillimetreBox(0.0,
                         50.0,
                         tr("Slab thickness across the image's plane, mm, combined by the slab mode; 0: the plane "
                            "alone."));
  m_SlabMode = new QComboBox;
  m_SlabMode->addItems({ tr("MIP"), tr("MinIP"), tr("mean") });
  m_SlabMode->setToolTip(tr("How the slab's samples are combined: maximum (MIP), minimum (MinIP) or mean."));
  auto * slab = new QHBoxLayout;
  slab->setContentsMargins(0, 0, 0, 0);
  slab->addWidget(m_Slab, 1);
  slab->addWidget(m_SlabMode);

  m_Method = new QComboBox;
  m_Method->addItems({ tr("interpolated"), tr("robust fit") });
  m_Method->setToolTip(tr("How the reference (healthy) diameter is found: interpolated between the reference points "
                          "(DICOM PS3.17 Annex T.4), or a robust line fitted to the profile (Tukey's biweight)."));
  m_Points = new QLineEdit;
  m_Points->setPlaceholderText(tr("each segment's own"));
  m_Points->setToolTip(tr("Your reference points: arc lengths in mm on the path read, separated by commas, one "
                          "reference through them over the whole path. Empty: each segment between junctions takes "
                          "its own, between its first and last section outside the margins. Enter applies."));
  auto * reference = new QHBoxLayout;
  reference->setContentsMargins(0, 0, 0, 0);
  reference->addWidget(m_Method);
  reference->addWidget(m_Points, 1);

  m_Scale = new QComboBox;
  for (const StenosisScale scale : Scales)
  {
    m_Scale->addItem(QString::fromUtf8(ToString(scale)));
  }
  m_Scale->setToolTip(tr("The clinical scale the % diameter stenosis is graded on. automatic: from each vessel's name "
                         "(CAD-RADS for a coronary artery only, NASCET for a carotid, the maximum diameter for the "
                         "aorta, the peripheral categories otherwise)."));

  auto * form = new QFormLayout(this);
  form->setContentsMargins(4, 4, 4, 4);
  form->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
  form->addRow(tr("Width"), m_Width);
  form->addRow(tr("Range"), range);
  form->addRow(tr("Slab"), slab);
  form->addRow(tr("Reference"), reference);
  form->addRow(tr("Scale"), m_Scale);

  for (QDoubleSpinBox * box : { m_Width, m_RangeStart, m_RangeEnd, m_Slab })
  {
    connect(box, QOverload<double>::of(&QDoubleSpinBox::valueChanged), this, &VesselPathSettings::edited);
  }
  connect(m_HasRange,
          &QCheckBox::toggled,
          this,
          [this](bool on)
          {
            m_RangeStart->setEnabled(on);
            m_RangeEnd->setEnabled(on);
            emit edited();
          });
  for (QComboBox * box : { m_SlabMode, m_Method, m_Scale })
  {
    connect(box, QOverload<int>::of(&QComboBox::activated), this, &VesselPathSettings::edited);
  }
  connect(m_Points,
          &QLineEdit::editingFinished,
          this,
          [this]
          {
            if (m_Points->isModified())
            {
              m_Points->setModified(false);
              emit edited();
            }
          });
}

void
VesselPathSettings::Show(const VesselPathParameters & parameters, double pathLength)
{
  const QSignalBlocker b0(m_Width), b1(m_HasRange), b2(m_RangeStart), b3(m_RangeEnd), b4(m_Slab), b5(m_SlabMode),
    b6(m_Method), b7(m_Points), b8(m_Scale);
  m_Width->setValue(parameters.Width);
  m_HasRange->setChecked(parameters.HasRange);
  m_PathLength = pathLength;
  m_RangeStart->setMaximum(pathLength);
  m_RangeEnd->setMaximum(pathLength);
  m_RangeStart->setValue(parameters.HasRange ? parameters.RangeStart : 0.0);
  m_RangeEnd->setValue(parameters.HasRange ? parameters.RangeEnd : pathLength);
  m_RangeStart->setEnabled(parameters.HasRange);
  m_RangeEnd->setEnabled(parameters.HasRange);
  m_Slab->setValue(parameters.SlabThickness);
  m_SlabMode->setCurrentIndex(static_cast<int>(
    std::find(std::begin(SlabModes), std::end(SlabModes), parameters.SlabMode) - std::begin(SlabModes)));
  m_Method->setCurrentIndex(parameters.ReferenceMethod == VesselReferenceMethod::RobustFit ? 1 : 0);
  QStringList points;
  for (const double s : parameters.ReferencePoints)
  {
    points << QString::number(s, 'g', 6);
  }
  m_Points->setText(points.join(QStringLiteral(", ")));
  m_Points->setModified(false);
  m_Scale->setCurrentIndex(
    static_cast<int>(std::find(std::begin(Scales), std::end(Scales), parameters.GradingScale) - std::begin(Scales)));
}

QString
VesselPathSettings::Apply(VesselPathParameters & parameters) const
{
  std::vector<double> points;
  for (const QString & item :
       m_Points->text().split(QRegularExpression(QStringLiteral("[,;\\s]+")), Qt::SkipEmptyParts))
  {
    bool         number = false;
    const double s = item.toDouble(&number);
    if (!number)
    {
      return tr("reference points: \"%1\" is not a number (arc lengths in mm, separated by commas)").arg(item);
    }
    points.push_back(s);
  }
  if (m_HasRange->isChecked() && !(m_RangeEnd->value() > m_RangeStart->value()))
  {
    return tr("range: the end (%1 mm) must come after the start (%2 mm)")
      .arg(m_RangeEnd->value())
      .arg(m_RangeStart->value());
  }
  parameters.Width = m_Width->value();
  parameters.HasRange = m_HasRange->isChecked();
  // The spin boxes show a tenth of a millimetre: their end may round past the path's own.
  parameters.RangeStart = parameters.HasRange ? m_RangeStart->value() : 0.0;
  parameters.RangeEnd = parameters.HasRange ? std::min(m_RangeEnd->value(), m_PathLength) : 0.0;
  parameters.SlabThickness = m_Slab->value();
  parameters.SlabMode = SlabModes[std::clamp(m_SlabMode->currentIndex(), 0, 2)];
  parameters.ReferenceMethod =
    m_Method->currentIndex() == 1 ? VesselReferenceMethod::RobustFit : VesselReferenceMethod::Interpolated;
  parameters.ReferencePoints = points;
  parameters.GradingScale = Scales[std::clamp(m_Scale->currentIndex(), 0, 4)];
  return QString();
}
} // namespace vr
