// SurfaceMaps engine: per-vertex sizing (target edge length) files.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace surfacemaps
{

/// Parses a sizing file: one target edge length per vertex, one per line, in
/// vertex order and in the mesh's own units (the form of the paper's
/// user-sizing experiment). Blank lines and `#` comments are skipped. Every
/// value must be a finite positive number, and there must be exactly
/// `numberOfVertices` of them. Throws InputError "name:line: defect" (or
/// "name: defect" for a count that falls short).
std::vector<double> parseSizing(const std::string& text,
  const std::string& name,
  std::size_t numberOfVertices);

/// Reads and parses a sizing file (parseSizing).
std::vector<double> readSizing(const std::string& path, std::size_t numberOfVertices);

} // namespace surfacemaps
