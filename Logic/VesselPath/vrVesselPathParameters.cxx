// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrVesselPathParameters.h"

#include "itkCPRVectorHelpers.h"
#include "vrInputError.h"

#include <cmath>
#include <sstream>

namespace vr
{
VesselPathParameters::VesselPathParameters()
  : Up(itk::detail::MakeVector3(0.0, 0.0, 1.0))
{
}

void
VesselPathParameters::Validate() const
{
  std::ostringstream problem;
  const char *       parameter = "";
  if (BranchId < 0)
  {
    parameter = ParameterName::Branch;
    problem << "branch = " << BranchId << ": must be a branch id (>= 1), or 0 for the longest path";
  }
  else if (HasRange &&
           !(std::isfinite(RangeStart) && std::isfinite(RangeEnd) && RangeStart >= 0.0 && RangeEnd > RangeStart))
  {
    parameter = ParameterName::PathRange;
    problem << "path range = " << RangeStart << "," << RangeEnd
            << " mm: must be two finite arc lengths, 0 <= start < end";
  }
  else if (!std::isfinite(RollInDegrees))
  {
    parameter = ParameterName::Roll;
    problem << "roll = " << RollInDegrees << " degrees: must be a finite number";
  }
  else if (!(std::isfinite(Width) && Width > 0.0))
  {
    parameter = ParameterName::Width;
    problem << "width = " << Width << " mm: must be finite and > 0";
  }
  else if (!(std::isfinite(PixelSpacing) && PixelSpacing >= 0.0))
  {
    parameter = ParameterName::PixelSpacing;
    problem << "pixel spacing = " << PixelSpacing << " mm: must be finite and > 0 (or unset)";
  }
  else if (!(std::isfinite(SectionSpacing) && SectionSpacing >= 0.0))
  {
    parameter = ParameterName::SectionSpacing;
    problem << "section spacing = " << SectionSpacing << " mm: must be finite and > 0 (or unset)";
  }
  else if (!AutomaticUp &&
           !(std::isfinite(Up[0]) && std::isfinite(Up[1]) && std::isfinite(Up[2]) && Up.GetNorm() > 1e-12))
  {
    parameter = ParameterName::UpAxis;
    problem << "up axis = " << Up[0] << "," << Up[1] << "," << Up[2]
            << ": must be a finite, non-zero LPS vector, or automatic";
  }
  else if (!std::isfinite(ViewAngleInDegrees))
  {
    parameter = ParameterName::Angle;
    problem << "angle = " << ViewAngleInDegrees << " degrees: must be a finite number";
  }
  else if (!(std::isfinite(SlabThickness) && SlabThickness >= 0.0))
  {
    parameter = ParameterName::SlabThickness;
    problem << "slab thickness = " << SlabThickness << " mm: must be finite and >= 0";
  }
  else
  {
    for (const double s : ReferencePoints)
    {
      if (!std::isfinite(s))
      {
        parameter = ParameterName::ReferencePoints;
        problem << "reference point = " << s << " mm: must be a finite arc length";
        break;
      }
    }
  }
  if (*parameter)
  {
    throw InputError(problem.str(), parameter);
  }
}

bool
VesselPathParameters::operator==(const VesselPathParameters & other) const
{
  return BranchId == other.BranchId && HasRange == other.HasRange && RangeStart == other.RangeStart &&
         RangeEnd == other.RangeEnd && Reformation == other.Reformation && RollInDegrees == other.RollInDegrees &&
         Width == other.Width && PixelSpacing == other.PixelSpacing && SectionSpacing == other.SectionSpacing &&
         AutomaticUp == other.AutomaticUp && (AutomaticUp || Up == other.Up) &&
         ViewAngleInDegrees == other.ViewAngleInDegrees && Interpolation == other.Interpolation &&
         SlabThickness == other.SlabThickness && SlabMode == other.SlabMode &&
         ReferencePoints == other.ReferencePoints && ReferenceMethod == other.ReferenceMethod &&
         GradingScale == other.GradingScale;
}
} // namespace vr
