// SurfaceMaps engine: strict Stanford PLY reading (ASCII and binary).
#pragma once

#include "mesh/PolygonMesh.h"

#include <string>

namespace surfacemaps
{

/// Reads a PLY file: ASCII, binary_little_endian or binary_big_endian. Uses
/// the `vertex` element's x, y, z and the `face` element's vertex_indices (or
/// vertex_index) list; a face `texcoord` list (2 values per corner) becomes
/// per-corner texture coordinates; other elements and properties are skipped.
/// Strict: the declared element counts must be met and every index must be in
/// range. Throws InputError naming the file and the defect (a truncated file
/// says how far it got).
PolygonMesh readPly(const std::string& path);

/// Same, from bytes already in memory; `name` is used in messages.
PolygonMesh parsePly(const std::string& bytes, const std::string& name);

} // namespace surfacemaps
