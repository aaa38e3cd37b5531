// SurfaceMaps engine: structural check of legacy VTK POLYDATA files.
#pragma once

#include <string>

namespace surfacemaps
{

/// Checks the bytes of a legacy VTK POLYDATA file (ASCII or BINARY, file
/// versions 1 to 5) before VTK's reader sees them: every declared count fits
/// in the rest of the file, every cell's point index is within the POINTS
/// count, the cell layouts add up (sizes, OFFSETS / CONNECTIVITY), and
/// POINT_DATA / CELL_DATA match the points and cells. VTK 9.1's reader
/// trusts all of these: a POLYGONS index 2^32 + k crashes it, a huge count is
/// allocated before any data is read. Throws InputError "name:line: what"
/// (ASCII) or "name: byte N: what" (BINARY) on the first defect.
void checkLegacyVtkPolyData(const std::string& bytes, const std::string& name);

} // namespace surfacemaps
