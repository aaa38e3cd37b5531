// surfacemap evaluate SOURCE TARGET: the map between two meshes of identical
// connectivity.
#pragma once

#include <string>
#include <vector>

namespace surfacemap
{

/// Measures meshes[0] -> meshes[1] (with the surfaces they approximate when
/// `originals` names two), prints the figures and, with an output directory,
/// writes summary.json, triangles.csv, distortion_curve.csv and
/// evaluated.vtp there, with `pictures` also distortion.png,
/// checkerboard.png and distortion_curve.png (the caller has checked the
/// display). Returns the exit code.
int evaluateMeshPair(const std::vector<std::string>& meshes,
  const std::vector<std::string>& originals,
  const std::string& outputDir,
  bool pictures);

} // namespace surfacemap
