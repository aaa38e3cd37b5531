// SurfaceMaps engine: plausibility of the counts in a VTK XML PolyData file.
#pragma once

#include <string>

namespace surfacemaps
{

/// Every data byte of a mesh file holds at most this many points or cells:
/// real geometry does not compress below an eighth of a byte per point.
constexpr double MaxItemsPerXmlByte = 8.0;

/// Components of one array at most (a 3x3 tensor has 9).
constexpr long long MaxXmlComponents = 1024;

/// Checks the counts of a .vtp file's bytes before VTK's XML reader
/// allocates or loops by them: <Piece> NumberOfPoints, NumberOfVerts,
/// NumberOfLines, NumberOfStrips, NumberOfPolys and <DataArray> / <Array>
/// NumberOfTuples must be non-negative integers no larger than
/// MaxItemsPerXmlByte times the file size, NumberOfComponents within 1 to
/// MaxXmlComponents. Throws InputError naming the file, the element and the
/// count.
void checkXmlPolyDataCounts(const std::string& bytes, const std::string& name);

} // namespace surfacemaps
