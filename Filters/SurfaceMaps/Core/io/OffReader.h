// SurfaceMaps engine: strict Object File Format (OFF) reading.
#pragma once

#include "mesh/PolygonMesh.h"

#include <string>

namespace surfacemaps
{

/// Reads an ASCII OFF file (headers OFF, COFF, NOFF, CNOFF; per-vertex and
/// per-face colours or normals are skipped). Strict: the declared vertex and
/// face counts must be met, every index must be in range, every number must
/// parse. Throws InputError "path:line: defect" otherwise.
PolygonMesh readOff(const std::string& path);

/// Same, from text already in memory; `name` is used in messages.
PolygonMesh parseOff(const std::string& text, const std::string& name);

} // namespace surfacemaps
