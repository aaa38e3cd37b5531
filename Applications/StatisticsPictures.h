// surfacemap statistics --pictures: PNG charts and a heat map (see
// Pictures.h for the display they need).
#pragma once

#include <string>
#include <vector>

class vtkPolyData;

namespace surfacemap
{

/// Bar chart of the explained variance per mode (in %), written atomically.
void writeExplainedVariancePicture(const std::vector<double>& fractions, const std::string& path);

/// Scatter plot of the specimens' scores on modes 1 and 2 (with one mode:
/// mode 1 against the specimen number), written atomically. `scores` holds
/// k values per specimen, row by row.
void writeScoresPicture(const std::vector<double>& scores, int modes, const std::string& path);

/// The mean shape coloured by its "StandardDeviation" point array, with a
/// colour bar, written atomically.
void writeSpreadPicture(vtkPolyData* mean, const std::string& path);

} // namespace surfacemap
