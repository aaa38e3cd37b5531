/**
 * @class   vtkSurfaceMapsMarkups
 * @brief   3D Slicer's markups JSON (.mrk.json) as landmark records.
 *
 * Private to the module: vtkSurfaceMeshReader's reader of landmark files in
 * Slicer's markups format, markups[0].controlPoints[i] with "position"
 * [x, y, z] and optional "id" and "label". Every problem is an InputError
 * naming the file and the line of the value concerned.
 */
#ifndef vtkSurfaceMapsMarkups_h
#define vtkSurfaceMapsMarkups_h

#include "io/LandmarkReader.h"

#include <string>
#include <vector>

namespace vtkSurfaceMapsMarkups
{
/// The control points of `text` (the contents of the file `path`), ids as
/// the landmark readers take them (surfacemaps::finishLandmarkIds).
std::vector<surfacemaps::LandmarkRecord> parse(const std::string& text, const std::string& path);
}

#endif
