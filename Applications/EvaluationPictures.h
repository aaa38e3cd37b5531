// surfacemap evaluate --pictures: a measured map drawn (see Pictures.h for
// the display they need).
#pragma once

#include <string>
#include <utility>
#include <vector>

class vtkPolyData;

namespace surfacemap
{

/// The two meshes of a map (identical connectivity) and their captions.
struct MapSides
{
  vtkPolyData* source;
  vtkPolyData* target;
  std::string sourceCaption, targetCaption;
};

/// Writes, each atomically, with source and target side by side:
///   <prefix>distortion.png    each triangle coloured by the distortion
///                             max(s1, 1/s2) that `result` (an output of
///                             vtkSurfaceMapEvaluation for these sides) holds
///                             as MaxStretch: 1 white to 3 dark red, above 3
///                             darkest
///   <prefix>checkerboard.png  a checkerboard of the source's positions
///                             (sourcePositions; 3 to 8 squares along the
///                             longest side, fewer on coarse meshes), the
///                             same on both sides: on the target it shows
///                             how the map carries it
/// Throws std::runtime_error naming a file that cannot be written.
void writeMapPictures(const MapSides& sides, vtkPolyData* result, const std::string& prefix);

/// The cumulative distortion curves (area fraction of the source below each
/// distortion) of evaluation results, one line per (label, result), as one
/// chart written atomically to `path`.
void writeDistortionCurvePicture(const std::vector<std::pair<std::string, vtkPolyData*>>& curves,
  const std::string& path);

} // namespace surfacemap
