// SurfaceMaps engine: plausibility of the counts in a VTK XML PolyData file.
#pragma once

#include <string>

namespace surfacemaps
{

/// Every data byte of a mesh file holds at most this many points or cells:
/// real geometry does not compress below an eighth of a byte per point.
constexpr double MaxItemsPerXmlByte = 8.0;

/// Checks the <Piece> counts (NumberOfPoints, NumberOfVerts, NumberOfLines,
/// NumberOfStrips, NumberOfPolys) of a .vtp file's bytes before VTK's XML
/// reader allocates by them: each must be a non-negative integer no larger
/// than MaxItemsPerXmlByte times the file size. Throws InputError naming the
/// file, the piece and the count.
void checkXmlPolyDataCounts(const std::string& bytes, const std::string& name);

} // namespace surfacemaps
