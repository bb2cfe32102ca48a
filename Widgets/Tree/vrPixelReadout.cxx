// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrPixelReadout.h"

#include <vtkImageData.h>
#include <vtkMatrix4x4.h>

namespace vr
{
namespace
{
double
ScalarAt(VolumeNode * node, int column, int row)
{
  vtkImageData * data = node != nullptr ? node->GetImageData() : nullptr;
  return data != nullptr ? data->GetScalarComponentAsDouble(column, row, 0, 0) : 0.0;
}
} // namespace

QString
PixelReadout::ToText() const
{
  if (!Inside)
  {
    return QString();
  }
  const QString intensity =
    IntensityUnit.empty()
      ? QStringLiteral("value %1").arg(Intensity, 0, 'f', 0)
      : QStringLiteral("%1 %2").arg(Intensity, 0, 'f', 0).arg(QString::fromStdString(IntensityUnit));
  QString text = QStringLiteral("(%1, %2)  RAS (%3, %4, %5) mm  %6  depth %7 mm")
                   .arg(Column)
                   .arg(Row)
                   .arg(RAS[0], 0, 'f', 1)
                   .arg(RAS[1], 0, 'f', 1)
                   .arg(RAS[2], 0, 'f', 1)
                   .arg(intensity)
                   .arg(Depth, 0, 'f', 1);
  text += Branch > 0 ? QStringLiteral("  %1").arg(QString::fromStdString(BranchName)) : QStringLiteral("  no branch");
  if (HiddenBranch > 0)
  {
    text += HiddenBranch == Branch
              ? QStringLiteral(", in front of another part of itself")
              : QStringLiteral(", in front of the %1").arg(QString::fromStdString(HiddenBranchName));
  }
  if (Unfiltered)
  {
    text += QStringLiteral("  (unfiltered)");
  }
  return text;
}

PixelReadout
ReadPixel(const ReformationResult & result, bool unfiltered, int column, int row)
{
  PixelReadout readout;
  const auto & outputs = result.Outputs;
  VolumeNode * cpr = unfiltered ? outputs.UnfilteredCPR.GetPointer() : outputs.CPR.GetPointer();
  VolumeNode * depth = unfiltered ? outputs.Depth.GetPointer() : outputs.RelaxedDepth.GetPointer();
  if (cpr == nullptr || depth == nullptr || cpr->GetImageData() == nullptr)
  {
    return readout;
  }
  int dimensions[3];
  cpr->GetImageData()->GetDimensions(dimensions);
  if (column < 0 || row < 0 || column >= dimensions[0] || row >= dimensions[1])
  {
    return readout;
  }
  readout.Inside = true;
  readout.Unfiltered = unfiltered;
  readout.Column = column;
  readout.Row = row;
  readout.Intensity = ScalarAt(cpr, column, row);
  readout.Depth = ScalarAt(depth, column, row);
  readout.Branch = static_cast<int>(ScalarAt(outputs.OwnerLabels, column, row));
  readout.HiddenBranch = static_cast<int>(ScalarAt(outputs.HiddenLabels, column, row));
  if (readout.Branch > 0 && result.Inputs)
  {
    readout.BranchName = result.Inputs->BranchName(readout.Branch);
  }
  if (readout.HiddenBranch > 0 && result.Inputs)
  {
    readout.HiddenBranchName = result.Inputs->BranchName(readout.HiddenBranch);
  }
  if (result.Inputs)
  {
    readout.IntensityUnit = result.Inputs->IntensityUnit;
  }
  const double ijk[4] = { static_cast<double>(column), static_cast<double>(row), readout.Depth, 1.0 };
  double       ras[4];
  cpr->GetIJKToRASMatrix()->MultiplyPoint(ijk, ras);
  readout.RAS = { ras[0], ras[1], ras[2] };
  return readout;
}
} // namespace vr
