/**
 * @class   vtkSurfaceMapInputs
 * @brief   vtkSurfaceMapFilter's inputs as the engine needs them (private).
 *
 * The one place where the map's inputs are validated: meshes (closed,
 * manifold, genus 0, ...), "Landmarks" (shape, ids, correspondence across
 * inputs), "Sizing" (shape, positive lengths) and "SpherePosition"
 * (certified bijective); then the missing sphere embeddings are computed.
 * Errors are surfacemaps::InputError naming the input, the defect and where.
 */
#ifndef vtkSurfaceMapInputs_h
#define vtkSurfaceMapInputs_h

#include "map/AddToMap.h"
#include "map/MapInput.h"

#include <functional>
#include <string>
#include <vector>

class vtkPolyData;

class vtkSurfaceMapInputs
{
public:
  /// "input 1", or "input 1 (a.obj)" when the input carries a file name.
  static std::string Name(vtkPolyData* input, int index);

  /// Every input as an engine input (mesh, landmarks, sizing when
  /// `useSizing`), validated; throws InputError listing every defect of
  /// every input. `warnings` receives what is valid but suspect: landmarks
  /// that are the mirror image of input 0's (checkLandmarkMirroring).
  static std::vector<surfacemaps::MapInput> Read(const std::vector<vtkPolyData*>& inputs,
    bool useSizing,
    std::vector<std::string>& warnings);

  /// Sets every input's sphere embedding: a given "SpherePosition" array
  /// (certified; InputError if it is no bijective embedding), else computed,
  /// all missing ones at once. `progress(fraction, text)` returns false to
  /// abort (Aborted). Returns the seconds each computed embedding took (0
  /// for given ones). Throws std::runtime_error naming the input whose
  /// embedding failed.
  static std::vector<double> Embed(const std::vector<vtkPolyData*>& inputs,
    std::vector<surfacemaps::MapInput>& mapInputs,
    const std::function<bool(double, const std::string&)>& progress);

  /// An existing map from its T lifted onto each of its inputs (outputs in
  /// COMMON_TRIANGULATION mode: points, triangles, "SpherePosition",
  /// "Landmarks"). Throws InputError naming the one that lacks an array or
  /// differs from the first in points or triangles.
  static surfacemaps::ExistingMap Existing(const std::vector<vtkPolyData*>& common);
};

#endif
