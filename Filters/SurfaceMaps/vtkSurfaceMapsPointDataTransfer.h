/**
 * @class   vtkSurfaceMapsPointDataTransfer
 * @brief   Point arrays sampled at surface points, continuous or categorical (private).
 *
 * Where vtkSurfaceMapFilter's outputs and vtkSurfaceMapTransfer read an
 * input's point arrays at points of its surface (a triangle and barycentric
 * coordinates): each array in the mode vtkSurfaceArrayTransferAlgorithm's rule
 * gives it, continuous (interpolated, integers rounded: VTK's
 * InterpolateTuple) or categorical (the tuple of the triangle's nearest
 * corner, surfacemaps::nearestCorner: never a value the source lacks).
 */
#ifndef vtkSurfaceMapsPointDataTransfer_h
#define vtkSurfaceMapsPointDataTransfer_h

#include "mesh/SurfacePoint.h"

#include "vtkSmartPointer.h"

#include <array>
#include <vector>

class vtkAbstractArray;
class vtkPointData;
class vtkSurfaceArrayTransferAlgorithm;

class vtkSurfaceMapsPointDataTransfer
{
public:
  /// `array` (one tuple per source point) at every surface point of the
  /// source's `triangles`, as a new array of the same type, name and
  /// components. Throws std::logic_error for a point on no triangle.
  static vtkSmartPointer<vtkAbstractArray> Sample(vtkAbstractArray* array,
    const std::vector<std::array<int, 3>>& triangles,
    const std::vector<surfacemaps::SurfacePoint>& points,
    bool categorical);

  /// Every one of `arrays` (arrays of `from`) sampled into `to` in the mode
  /// `modes` resolves for it, keeping its role as an active attribute of
  /// `from` (scalars, vectors, normals, texture coordinates, ...).
  static void SampleArrays(vtkPointData* from,
    const std::vector<vtkAbstractArray*>& arrays,
    vtkPointData* to,
    const std::vector<std::array<int, 3>>& triangles,
    const std::vector<surfacemaps::SurfacePoint>& points,
    vtkSurfaceArrayTransferAlgorithm* modes);
};

#endif
