// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrLegacyVTKReader_h
#define vrLegacyVTKReader_h

#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <string>

namespace vr::detail
{
/** What a legacy .vtk polyline file holds. */
struct LegacyVTKPolyData
{
  vtkSmartPointer<vtkPolyData> PolyData;
  /** The second line of the file (3D Slicer writes "SPACE=RAS" or "SPACE=LPS" there). */
  std::string Header;
};

/** Reads the polyline subset of the legacy VTK format that centerline files use, and nothing else: file versions
 * 1.0 to 5.1, ASCII or BINARY (big-endian), DATASET POLYDATA with a dataset FIELD, one POINTS and one LINES
 * section (the count-and-ids form before version 5, OFFSETS and CONNECTIVITY from 5), then POINT_DATA and
 * CELL_DATA once each with SCALARS (and their LOOKUP_TABLE line), VECTORS, NORMALS, TENSORS, TENSORS6,
 * TEXTURE_COORDINATES, GLOBAL_IDS, PEDIGREE_IDS and FIELD arrays of numbers or strings, each optionally followed by
 * the METADATA block VTK writes (skipped). Every count is checked against limits and against the bytes that really
 * follow before anything is allocated, every point id against the points, every attribute count against the
 * points or cells. Anything else (another dataset, POLYGONS, VERTICES, a repeated section, an unknown keyword or
 * type) is refused by name. VTK's own vtkPolyDataReader is not used: it trusts the counts (fuzzing made it crash).
 *
 * \param path the file.
 * \param description how messages name it ("centerline file x.vtk").
 * Throws vr::InputError "<description>: <what is wrong> (legacy VTK, line N)".
 */
LegacyVTKPolyData
ReadLegacyVTKPolyData(const std::string & path, const std::string & description);
} // namespace vr::detail

#endif
