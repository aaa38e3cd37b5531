// surfacemap evaluate --pictures: a measured map drawn (see Pictures.h).
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
///                             (sourcePositions; 8 squares along the
///                             longest side), the same on both sides: each
///                             triangle cut along the squares' edges in
///                             those positions, so on the source the edges
///                             are straight and on the target they are the
///                             map's image of them
/// Both pictures show the two sides through one camera (writeSurfacePicture).
/// Throws std::runtime_error naming a file that cannot be written.
void writeMapPictures(const MapSides& sides, vtkPolyData* result, const std::string& prefix);

/// The cumulative distortion curves (area fraction of the source below each
/// distortion) of evaluation results, one line per (label, result), as one
/// chart written atomically to `path`.
void writeDistortionCurvePicture(const std::vector<std::pair<std::string, vtkPolyData*>>& curves,
  const std::string& path);

} // namespace surfacemap
