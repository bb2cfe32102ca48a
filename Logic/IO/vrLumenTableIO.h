// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrLumenTableIO_h
#define vrLumenTableIO_h

#include "itkVesselLumenMeasurement.h"

#include <cstddef>
#include <string>
#include <vector>

namespace vr
{
/** The lumen table's columns, in order (docs/lumen-measurement.md, "The table"): the section's arc length, its
 * centre in RAS mm (r = -L, a = -P, s = S), the measured area and diameters, the reference diameter, then the
 * profile's diameter, the centerline's 2r, the reference area, the local % diameter stenosis 100 (1 - d / reference),
 * the source, whether the path point lies inside the segmentation, whether the region was clipped, and the branch id.
 */
constexpr const char * LumenTableColumns[] = { "arc_length_mm",
                                               "r_mm",
                                               "a_mm",
                                               "s_mm",
                                               "area_mm2",
                                               "equivalent_diameter_mm",
                                               "min_diameter_mm",
                                               "max_diameter_mm",
                                               "reference_diameter_mm",
                                               "diameter_mm",
                                               "inscribed_diameter_mm",
                                               "reference_area_mm2",
                                               "diameter_stenosis_percent",
                                               "source",
                                               "in_segmentation",
                                               "region_clipped",
                                               "branch_id" };

/** The position of the one text column, "source", among LumenTableColumns. */
constexpr std::size_t LumenTableSourceColumn = 13;

/** \class LumenTable
 * \brief The lumen table's cells as WriteLumenTable writes them and the Python package returns them: per column of
 * LumenTableColumns but "source", one number per section, NaN where the cell is empty (areas without a segmentation,
 * sections outside it, in_segmentation and region_clipped without a segmentation); the source as text.
 * \ingroup VesselReformation
 */
struct LumenTable
{
  /** Numbers[c][k]: column c of LumenTableColumns (Numbers[LumenTableSourceColumn] is empty), section k. */
  std::vector<std::vector<double>> Numbers;
  /** The lumen source, the same in every row ("segmentation" or "centerline radius"). */
  std::string Source;
  std::size_t Rows{ 0 };
};

/** \return the cells of \a profile's table: the section's centre in RAS, the local % stenosis and the rest. */
LumenTable
MakeLumenTable(const itk::VesselLumenProfile & profile);

/** The separator a lumen table at \a path is written with: ',' for .csv, '\t' for .tsv (any case). Call it before
 * the work to fail early. Throws vr::InputError naming \a path for any other extension. */
char
LumenTableSeparator(const std::string & path);

/** Writes \a profile as a table, one row per section after a header row (LumenTableColumns), CSV or TSV by the
 * extension. Empty cells where a value is not measured (NaN: areas without a segmentation, sections outside it).
 * Atomic (vr::AtomicOutput): on any error nothing appears and an existing file is left as it was. Throws
 * vr::InputError naming \a path on an unknown extension, a folder that cannot be written, or a failed write. */
void
WriteLumenTable(const itk::VesselLumenProfile & profile, const std::string & path);
} // namespace vr

#endif
