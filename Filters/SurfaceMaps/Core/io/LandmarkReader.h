// SurfaceMaps engine: landmark (vertex correspondence) files.
#pragma once

#include <string>
#include <vector>

namespace surfacemaps
{

/// Reads a landmark file: one 0-based vertex index per line, optionally
/// prefixed by `lk ` (`.pinned`, `.txt`), or SHREC `.vts` lines `index x y z`
/// (coordinates ignored). Blank lines and `#` comments are skipped. The k-th
/// index carries landmark id k. Throws InputError "path:line: defect".
std::vector<int> readLandmarks(const std::string& path);

/// Same, from text already in memory; `name` is used in messages.
std::vector<int> parseLandmarks(const std::string& text, const std::string& name);

/// Per-vertex landmark ids (-1 none) from a list of vertex indices (id = position
/// in the list). Throws InputError naming `name` when an index is out of range
/// or a vertex is listed twice.
std::vector<int> landmarkIdsFromIndices(const std::vector<int>& indices,
  std::size_t numberOfVertices,
  const std::string& name);

} // namespace surfacemaps
