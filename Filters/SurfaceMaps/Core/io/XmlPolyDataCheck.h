// SurfaceMaps engine: what of a VTK XML PolyData file is handed to VTK's reader.
#pragma once

#include <string>

namespace surfacemaps
{

/// Every data byte of a mesh file holds at most this many points or cells:
/// real geometry does not compress below an eighth of a byte per point.
constexpr double MaxItemsPerXmlByte = 8.0;

/// Uncompressed bytes per byte of the file at most (zlib compresses no
/// better than about 1 032 to 1).
constexpr double MaxUncompressedPerXmlByte = 1100.0;

/// Components of one array at most (a 3x3 tensor has 9).
constexpr long long MaxXmlComponents = 1024;

/// Checks the counts of a .vtp file's bytes before VTK's XML reader
/// allocates or loops by them: <Piece> NumberOfPoints, NumberOfVerts,
/// NumberOfLines, NumberOfStrips, NumberOfPolys and <DataArray> / <Array>
/// NumberOfTuples must be non-negative integers no larger than
/// MaxItemsPerXmlByte times the file size, NumberOfComponents within 1 to
/// MaxXmlComponents; the data blocks of appended raw and inline binary
/// arrays (their headers: byte counts, compressed block counts and sizes)
/// must lie within the data and expand to at most MaxUncompressedPerXmlByte
/// times the file size. Throws InputError naming the file, the element and
/// the count.
void checkXmlPolyDataCounts(const std::string& bytes, const std::string& name);

/// The bytes of a .vtp file without its String arrays (<Array> and
/// <DataArray> elements of type String, with their inline data; appended
/// blocks stay, unreferenced). VTK 9.1's XML reader corrupts memory on a
/// String array whose content does not match its NumberOfTuples, and
/// checking that would mean decompressing the data; no mesh reader here
/// needs a String array (the file name is added anew).
std::string withoutStringArrays(const std::string& bytes);

} // namespace surfacemaps
