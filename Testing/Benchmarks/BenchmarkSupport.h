// Helpers shared by the benchmark programs (not part of the library).
#pragma once

#include "io/ObjReader.h"
#include "io/OffReader.h"
#include "io/PlyReader.h"
#include "mesh/PolygonMesh.h"

#include <sys/resource.h>

#include <stdexcept>
#include <string>

namespace surfacemaps::benchmark
{

inline PolygonMesh read(const std::string& path)
{
  const std::string ext = path.substr(path.find_last_of('.') + 1);
  if (ext == "obj")
  {
    return readObj(path);
  }
  if (ext == "off")
  {
    return readOff(path);
  }
  if (ext == "ply")
  {
    return readPly(path);
  }
  throw std::runtime_error(path + ": the benchmarks read .obj, .off and .ply");
}

inline double peakMegabytes()
{
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss / 1024.0;
}

} // namespace surfacemaps::benchmark
