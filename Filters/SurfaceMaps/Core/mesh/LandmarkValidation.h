// SurfaceMaps engine: checks of landmark ids, per input and across inputs.
#pragma once

#include <string>
#include <vector>

namespace surfacemaps
{

/// Checks per-vertex landmark ids (-1 none) of one input: every id is >= -1
/// and on at most one vertex. One sentence per defect, without the input name.
std::vector<std::string> checkLandmarkIds(const std::vector<int>& landmarkIds);

/// Checks that the landmark ids of several inputs (each passing
/// checkLandmarkIds) correspond: the same set of ids on every input as on the
/// first. Per input, one sentence per defect naming both inputs by `names`
/// (the first input's list stays empty).
std::vector<std::vector<std::string>> checkLandmarkCorrespondence(
  const std::vector<std::vector<int>>& landmarkIds,
  const std::vector<std::string>& names);

} // namespace surfacemaps
