// The `surfacemap` command line: a map measured with vtkSurfaceMapEvaluation
// and its summary figures (named, read, as JSON).
#pragma once

#include "vtkSmartPointer.h"

#include <string>
#include <vector>

class vtkPolyData;
namespace Json
{
class Value;
}

namespace surfacemap
{

/// Measures the map source -> target (equal connectivity) with
/// vtkSurfaceMapEvaluation; originals (for the Hausdorff figures) may be null.
/// Returns the evaluated source with the per-triangle arrays and the summary
/// field data; throws std::invalid_argument with the evaluation's message.
vtkSmartPointer<vtkPolyData> measureMap(vtkPolyData* source,
  vtkPolyData* target,
  vtkPolyData* sourceOriginal,
  vtkPolyData* targetOriginal);

/// "<what> has N zero-area triangles (the first is triangle t): ..." when
/// `mesh` has triangles of zero area at double precision, on which no map's
/// distortion is defined (its figures would be infinite); empty otherwise.
std::string zeroAreaTriangles(vtkPolyData* mesh, const std::string& what);

/// The names of measureMap's summary figures, in the order they are printed.
const std::vector<const char*>& evaluationSummaryNames();

/// A summary figure of measureMap's result, NaN if absent.
double summaryValue(vtkPolyData* result, const char* name);

/// The summary figures present in `result` as a JSON object { name: number }
/// (null for a figure that is not finite).
Json::Value summaryJson(vtkPolyData* result);

} // namespace surfacemap
