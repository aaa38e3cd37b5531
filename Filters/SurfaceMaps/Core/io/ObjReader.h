// SurfaceMaps engine: Wavefront OBJ reading that keeps the file's vertices.
#pragma once

#include "mesh/PolygonMesh.h"

#include <string>

namespace surfacemaps
{

/// Reads an OBJ file. Vertices are exactly the file's `v` lines, in order, so a
/// closed mesh with texture seams stays closed (unlike readers that make one
/// point per distinct v/vt/vn combination). Texture coordinates and normals of
/// `f` corners are kept per corner (cornerTexCoords, cornerNormals; each empty
/// when no corner of the file has one, NaN at corners without one). Lines and
/// points (`l`, `p`) are counted as non-polygon cells; materials, groups and
/// smoothing groups are ignored.
/// Throws InputError "path:line: defect" on malformed content.
PolygonMesh readObj(const std::string& path);

/// Same, from text already in memory; `name` is used in messages.
PolygonMesh parseObj(const std::string& text, const std::string& name);

} // namespace surfacemaps
