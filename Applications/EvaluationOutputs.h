// surfacemap evaluate: the files of one measured map (tables, summary, view).
#pragma once

#include "vtkSmartPointer.h"

#include <string>

class vtkDoubleArray;
class vtkPolyData;

namespace surfacemap
{

/// Writes <prefix>triangles.csv (per triangle s1, s2, distortion, unit areas)
/// and <prefix>distortion_curve.csv (area fraction below each distortion).
/// Throws std::runtime_error naming a file that cannot be written.
void writeEvaluationTables(vtkPolyData* result, const std::string& prefix);

/// The point array SourcePosition: the points of `source` centred on its
/// bounding box and scaled to a longest side of 2, so a checkerboard of them
/// drawn on any mesh of the same vertices shows how a map carries a regular
/// pattern across.
vtkSmartPointer<vtkDoubleArray> sourcePositions(vtkPolyData* source);

/// `target` with the evaluation's per-triangle figures and summary, and the
/// point array SourcePosition of `source` (sourcePositions).
vtkSmartPointer<vtkPolyData> targetWithFigures(vtkPolyData* target,
  vtkPolyData* source,
  vtkPolyData* result);

} // namespace surfacemap
