// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrBranchColors.h"

#include <vtkLookupTable.h>
#include <vtkMath.h>

#include <algorithm>
#include <cmath>

namespace vr
{
std::array<double, 3>
BranchColor(int id)
{
  // Hues a golden angle apart, so that consecutive ids (often neighbouring vessels) differ clearly; saturation and
  // value alternate a little for the same reason.
  const double          hue = std::fmod(0.08 + 0.618033988749895 * static_cast<double>(id), 1.0);
  const double          saturation = id % 2 == 0 ? 0.85 : 0.65;
  const double          value = id % 3 == 0 ? 0.85 : 1.0;
  std::array<double, 3> rgb{};
  vtkMath::HSVToRGB(hue, saturation, value, &rgb[0], &rgb[1], &rgb[2]);
  return rgb;
}

vtkSmartPointer<vtkLookupTable>
MakeBranchLookupTable(int maximumId, double opacity)
{
  maximumId = std::max(1, maximumId);
  auto table = vtkSmartPointer<vtkLookupTable>::New();
  table->SetNumberOfTableValues(maximumId + 1);
  table->SetTableRange(0.0, static_cast<double>(maximumId));
  table->SetTableValue(0, 0.0, 0.0, 0.0, 0.0);
  for (int id = 1; id <= maximumId; ++id)
  {
    const auto rgb = BranchColor(id);
    table->SetTableValue(id, rgb[0], rgb[1], rgb[2], opacity);
  }
  return table;
}

vtkSmartPointer<vtkLookupTable>
MakeDepthLookupTable(double nearest, double farthest, double opacity)
{
  // Viridis at nine points (matplotlib's, CC0), as the demo draws depth maps.
  static const double viridis[9][3] = { { 68, 1, 84 },    { 71, 44, 122 },  { 59, 81, 139 },
                                        { 44, 113, 142 }, { 33, 144, 141 }, { 39, 173, 129 },
                                        { 92, 200, 99 },  { 170, 220, 50 }, { 253, 231, 37 } };
  constexpr int       entries = 256;
  auto                table = vtkSmartPointer<vtkLookupTable>::New();
  table->SetNumberOfTableValues(entries);
  table->SetTableRange(nearest, farthest > nearest ? farthest : nearest + 1.0);
  for (int k = 0; k < entries; ++k)
  {
    const double t = 8.0 * k / (entries - 1);
    const int    low = std::min(7, static_cast<int>(t));
    const double f = t - low;
    double       rgb[3];
    for (int c = 0; c < 3; ++c)
    {
      rgb[c] = (viridis[low][c] + f * (viridis[low + 1][c] - viridis[low][c])) / 255.0;
    }
    table->SetTableValue(k, rgb[0], rgb[1], rgb[2], opacity);
  }
  return table;
}
} // namespace vr
