// SurfaceMaps engine: strict Stanford PLY reading (ASCII and binary).
#pragma once

#include "mesh/PolygonMesh.h"

#include <string>

namespace surfacemaps
{

/// Reads a PLY file: ASCII, binary_little_endian or binary_big_endian. Uses
/// the `vertex` element's x, y, z and the `face` element's vertex_indices (or
/// vertex_index) list; a face `texcoord` list (2 values per corner) becomes
/// per-corner texture coordinates. The vertex element's other scalar
/// properties become point arrays, named as VTK's PLY reader names them:
/// red, green, blue (alpha) -> "RGB" ("RGBA"; unsigned char when the file's
/// are), nx, ny, nz -> "Normals", u, v (or s, t, texture_u, texture_v,
/// texture_s, texture_t) -> "TCoords" (float); every other property (which
/// VTK's reader drops) -> a 1-component array of its own name and type
/// (uchar stays unsigned char, other integers int or, for uint, 64-bit int,
/// float and double stay). Other elements and list properties are skipped.
/// Strict: the declared element counts must be met and every index must be in
/// range. Throws InputError naming the file and the defect (a truncated file
/// says how far it got).
PolygonMesh readPly(const std::string& path);

/// Same, from bytes already in memory; `name` is used in messages.
PolygonMesh parsePly(const std::string& bytes, const std::string& name);

} // namespace surfacemaps
