// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// The module panel shows each of the reformation's parameters as the one parameter table describes it
// (docs/parameters.md): caption, tooltip, values, range and default come from Resources/Parameters/vrParameters.json,
// so a value written into the panel's layout or code by hand, instead of the table, fails here.
#include "ui_vrModulePanel.h"
#include "vrModulePanel.h"
#include "vrParameterTable.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QSpinBox>

#include <gtest/gtest.h>

namespace
{
using namespace vr;

QString
Text(const std::string & text)
{
  return QString::fromStdString(text);
}

QStringList
Items(const QComboBox * combo)
{
  QStringList items;
  for (int k = 0; k < combo->count(); ++k)
  {
    items << combo->itemText(k);
  }
  return items;
}

TEST(ModulePanelParameterTable, CaptionsTooltipsValuesAndRangesComeFromTheTable)
{
  ModulePanel             panel;
  const Ui::ModulePanel & ui = panel.GetUi();
  const struct
  {
    const char * Key;
    QLabel *     Caption;
  } captions[] = { { "angle", ui.angleCaption },
                   { "up", ui.upCaption },
                   { "mode", ui.modeCaption },
                   { "size", ui.sizeCaption },
                   { "spacing", ui.spacingCaption },
                   { "interpolation", ui.interpolationCaption },
                   { "relaxation", ui.relaxationCaption },
                   { "jumpThreshold", ui.jumpThresholdCaption },
                   { "anisotropy", ui.anisotropyCaption },
                   { "solver", ui.solverCaption },
                   { "iterations", ui.iterationsCaption },
                   { "backend", ui.backendCaption },
                   { "window", ui.windowCaption },
                   { "level", ui.levelCaption } };
  for (const auto & caption : captions)
  {
    EXPECT_EQ(caption.Caption->text(), Text(Parameter(caption.Key).Label)) << caption.Key;
  }
  const struct
  {
    const char * Key;
    QComboBox *  Combo;
  } combos[] = { { "mode", ui.modeCombo },
                 { "interpolation", ui.interpolationCombo },
                 { "solver", ui.solverCombo },
                 { "backend", ui.backendCombo } };
  for (const auto & combo : combos)
  {
    const ParameterSpec & spec = Parameter(combo.Key);
    QStringList           values;
    for (const std::string & element : spec.Elements)
    {
      values << Text(element);
    }
    EXPECT_EQ(Items(combo.Combo), values) << combo.Key;
    EXPECT_EQ(combo.Combo->toolTip(), Text(spec.Description)) << combo.Key;
    EXPECT_EQ(combo.Combo->currentText(), Text(*spec.Default)) << combo.Key << ": the panel starts at the default";
  }
  const struct
  {
    const char *           Key;
    const QDoubleSpinBox * Spin;
  } spins[] = { { "relaxation", ui.relaxationSpin },
                { "jumpThreshold", ui.jumpThresholdSpin },
                { "anisotropy", ui.anisotropySpin },
                { "window", ui.windowSpin },
                { "level", ui.levelSpin } };
  for (const auto & spin : spins)
  {
    const ParameterSpec & spec = Parameter(spin.Key);
    EXPECT_EQ(spin.Spin->toolTip(), Text(spec.Description)) << spin.Key;
    ASSERT_TRUE(spec.Minimum && spec.Maximum && spec.Step) << spin.Key;
    EXPECT_DOUBLE_EQ(spin.Spin->minimum(), *spec.Minimum) << spin.Key;
    EXPECT_DOUBLE_EQ(spin.Spin->maximum(), *spec.Maximum) << spin.Key;
    EXPECT_DOUBLE_EQ(spin.Spin->singleStep(), *spec.Step) << spin.Key;
  }
  const ParameterSpec & iterations = Parameter("iterations");
  EXPECT_EQ(ui.iterationsSpin->toolTip(), Text(iterations.Description));
  EXPECT_EQ(ui.iterationsSpin->minimum(), static_cast<int>(*iterations.Minimum));
  EXPECT_EQ(ui.iterationsSpin->maximum(), static_cast<int>(*iterations.Maximum));
  EXPECT_EQ(ui.iterationsSpin->value(), std::stoi(*iterations.Default)) << "the panel starts at the default";
  EXPECT_DOUBLE_EQ(ui.relaxationSpin->value(), std::stod(*Parameter("relaxation").Default));
  EXPECT_EQ(ui.fixLumenCheck->text(), Text(Parameter("fixLumen").Label));
  EXPECT_EQ(ui.fixLumenCheck->toolTip(), Text(Parameter("fixLumen").Description));
  EXPECT_EQ(ui.fixLumenCheck->isChecked(), *Parameter("fixLumen").Default == "on");
  // Controls the panel shapes its own way still carry the table's words first.
  for (const QWidget * widget : std::initializer_list<const QWidget *>{ ui.angleSpin, ui.angleSlider })
  {
    EXPECT_TRUE(widget->toolTip().startsWith(Text(Parameter("angle").Description)))
      << widget->objectName().toStdString();
  }
  EXPECT_EQ(ui.upCombo->toolTip(), Text(Parameter("up").Description));
  EXPECT_TRUE(ui.spacingSpin->toolTip().startsWith(Text(Parameter("spacing").Description)));
  EXPECT_TRUE(ui.widthSpin->toolTip().startsWith(Text(Parameter("size").Description)));
}
} // namespace
