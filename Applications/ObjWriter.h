// The `surfacemap` command line: triangles written as Wavefront OBJ, with
// per-corner texture coordinates and normals kept exact.
#pragma once

#include <string>

class vtkPolyData;

namespace surfacemap
{

/// Writes the triangles of `data` as Wavefront OBJ through
/// writeFileAtomically: `v` per point, and, from the cell arrays
/// "CornerTCoords" (6 components) and "CornerNormals" (9), one `vt` / `vn`
/// per distinct corner value with faces `f v/vt/vn` (`v/vt`, `v//vn`, `v`),
/// so texture seams and sharp normals stay exact; a face with a non-finite
/// corner value goes without that attribute. OBJ holds no other data: other
/// point and cell arrays are not written.
void writeObjAtomically(vtkPolyData* data, const std::string& path);

} // namespace surfacemap
