// The command line: every input of a map on its own — how well T fits it
// (fit.csv, report.json's "specimens") and where T's vertices lie on it
// (correspondences.npz), for a population's per-specimen analysis.
#pragma once

#include "Json.h"

#include "vtkSmartPointer.h"

#include <string>
#include <vector>

class vtkPolyData;

namespace surfacemap
{

/// A name per input file: its stem, with "_<i>" appended where two inputs
/// have the same stem.
std::vector<std::string> specimenNames(const std::vector<std::string>& files);

/// The correspondences of a map as a .npz archive (NumpyArchive): "points"
/// (N x V x 3 float64: T's vertex v on input i, in input i's coordinates;
/// `common` holds the outputs common_<i>), "triangles" (F x 3 int64, T's
/// triangles, the same on every input), "names" (N strings).
std::string correspondencesArchive(
  const std::vector<std::string>& names, const std::vector<vtkPolyData*>& common);

/// Per input i, the largest distance between a landmark's vertex of T on
/// input i (common_<i>'s "Landmarks") and the same landmark on input i
/// (the input's "Landmarks"), in percent of input i's bounding-box
/// diagonal; NaN for an input without landmarks.
std::vector<double> landmarkErrors(const std::vector<vtkSmartPointer<vtkPolyData>>& inputs,
  const std::vector<vtkPolyData*>& common);

/// The fit table, one row per input i, from the report's
/// "approximating_map" and "exact_map" figures (maps 0 -> i): "input",
/// "name", "file", "hausdorff" (input i's vertices to T on input i) and
/// "two_sided_distance" (percent of input i's bounding-box diagonal),
/// "approximating_sd", "exact_sd", "exact_max_distortion",
/// "exact_area_below_1.5" (null on input 0 of a map of several inputs: it is
/// every map's source), "landmark_error" (landmarkErrors; null without
/// landmarks).
Json::Value specimenFit(const Json::Value& report,
  const std::vector<std::string>& names,
  const std::vector<double>& landmarkErrors);

/// The fit table as CSV (a header line, then one line per input; empty
/// fields for nulls).
std::string specimenFitCsv(const Json::Value& rows);

} // namespace surfacemap
