// SurfaceMaps engine: per-face bookkeeping of remeshing edits, registered
// beside the edits instead of written into them. Owns what an applied edit
// tells its handlers (EditedFaces) and the handlers of each kind of edit.
#pragma once

#include "map/CommonTriangulation.h"

#include <functional>
#include <vector>

namespace surfacemaps
{

/// The faces an applied edit made, each with what the edit's evaluation
/// found for its triangle.
struct EditedFaces
{
  std::vector<OpenMesh::FaceHandle> faces;
  /// Per face: its triangle in the edit's evaluation.
  std::vector<int> triangle;
  /// Per evaluated triangle: target length and energy (its samples' with).
  const std::vector<double>* lengths = nullptr;
  const std::vector<double>* energies = nullptr;
  /// Per input: the samples of the faces the edit replaced (empty when T
  /// tracks none), and per sample the evaluated triangle it lies in now.
  const std::vector<std::vector<int>>* samples = nullptr;
  const LocalAssignment* assignment = nullptr;
};

using EditHandler = std::function<void(const EditedFaces&)>;

/// Handlers run after every applied edit of their kind, in registration
/// order.
struct EditHandlers
{
  std::vector<EditHandler> split, collapse, flip;
  /// Registers `handler` for every kind of edit.
  void onEveryEdit(const EditHandler& handler);
};

/// T's own bookkeeping: the new faces' target lengths, barrier raises
/// (cleared) and cached energies, and the samples of the replaced faces
/// handed to the new faces they lie in (while T tracks samples).
EditHandlers triangulationHandlers(CommonTriangulation& T);

} // namespace surfacemaps
