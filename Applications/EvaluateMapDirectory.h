// surfacemap evaluate MAPDIR: every map in an output directory of
// 'surfacemap map'.
#pragma once

#include <string>
#include <vector>

namespace surfacemap
{

/// Measures, for each input j > 0 (j = 0 for a single input), the
/// approximating map common_0 -> common_j, the exact map input 0 -> mapped_j
/// and the certificate; prints them and writes summary.json and each map's
/// tables and view into `outputDir` (default: `directory`), with `pictures`
/// also each map's distortion and checkerboard pictures and each j's
/// distortion curves (the caller has checked the display). The inputs are
/// `inputFiles`, or those report.json names when it is empty. Returns the
/// exit code; throws UsageError for --inputs of the wrong count.
int evaluateMapDirectory(const std::string& directory,
  std::vector<std::string> inputFiles,
  std::string outputDir,
  bool pictures);

} // namespace surfacemap
