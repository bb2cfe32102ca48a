// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrLumenTableIO_h
#define vrLumenTableIO_h

#include "itkVesselLumenMeasurement.h"

#include <cstddef>
#include <string>
#include <vector>

namespace vr
{
/** The lumen table's columns, in order (docs/lumen-measurement.md, "The table"): the section's arc length along the
 * path, its centre in RAS mm (ras_r = -L, ras_a = -P, ras_s = S), the measured area and diameters, the reference
 * diameter, then the profile's diameter, the centerline's 2r, the reference area, the local % diameter stenosis
 * 100 (1 - d / reference), the source, whether the path point lies inside the segmentation, whether the region was
 * clipped, the branch id, and the grading's marks: the segment (1, 2, ...), whether the section may hold the MLD,
 * and why not. */
constexpr const char * LumenTableColumns[] = { "arc_length_mm",
                                               "ras_r_mm",
                                               "ras_a_mm",
                                               "ras_s_mm",
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
                                               "branch_id",
                                               "segment",
                                               "mld_candidate",
                                               "excluded_because" };

/** \class LumenTableNotes
 * \brief What the grading adds to a lumen table: comment lines before the header (the summary a reader signs: the
 * reference method, the segments, the scales, why a value is not given), written as "# " + line, and the marks of
 * each row (the last three columns; empty cells where there is no mark).
 * \ingroup VesselReformation
 */
struct LumenTableNotes
{
  struct RowMarks
  {
    /** The segment, from 1; 0 leaves the cell empty. */
    int         Segment{ 0 };
    bool        Candidate{ false };
    std::string ExcludedBecause;
  };
  std::vector<std::string> Comments;
  /** One per profile section, or none. */
  std::vector<RowMarks> Rows;
};

/** The position of the one text column, "source", among LumenTableColumns. */
constexpr std::size_t LumenTableSourceColumn = 13;
/** How many of LumenTableColumns the profile fills (MakeLumenTable), up to branch_id; the last three are the grading's
 * marks (LumenTableNotes). */
constexpr std::size_t LumenTableProfileColumns = 17;
static_assert(sizeof(LumenTableColumns) / sizeof(LumenTableColumns[0]) == LumenTableProfileColumns + 3,
              "the profile's columns, then the grading's three marks");

/** \class LumenTable
 * \brief The lumen table's cells as WriteLumenTable writes them and the Python package returns them: per column of
 * LumenTableColumns but "source", one number per section, NaN where the cell is empty (areas without a segmentation,
 * sections outside it, in_segmentation and region_clipped without a segmentation); the source as text.
 * \ingroup VesselReformation
 */
struct LumenTable
{
  /** Numbers[c][k]: column c < LumenTableProfileColumns of LumenTableColumns (Numbers[LumenTableSourceColumn] is
   * empty), section k. */
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

/** Writes \a profile as a table: \a notes' comment lines ("# ..."), then a header row (LumenTableColumns), then one
 * row per section; CSV or TSV by the extension. Empty cells where a value is not measured (NaN: areas without a
 * segmentation, sections outside it). Atomic (vr::AtomicOutput): on any error nothing appears and an existing file
 * is left as it was. Throws vr::InputError naming \a path on an unknown extension, marks for another number of rows
 * than sections, a folder that cannot be written, or a failed write. */
void
WriteLumenTable(const itk::VesselLumenProfile & profile, const std::string & path, const LumenTableNotes & notes = {});
} // namespace vr

#endif
