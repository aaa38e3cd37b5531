// SurfaceMaps engine: edge splits, collapses and flips of the common
// triangulation that lower its energy (DESIGN.md section 1.4).
#pragma once

#include "map/CommonTriangulation.h"
#include "map/EditHandlers.h"
#include "map/MapEnergy.h"

namespace surfacemaps
{

struct RemeshingOptions
{
  bool split = true;
  bool collapse = true;
  bool flip = true;
  /// An edit must lower the energy by more than this.
  double minGain = 1e-12;
};

struct RemeshingResult
{
  int splits = 0;
  int collapses = 0;
  int flips = 0;
  /// Sum of the applied edits' gains: the energy decrease of the round.
  double gain = 0.0;
  double seconds = 0.0;
};

/// One remeshing round: all splits that lower `energy` (a phase's energy of
/// T), then all collapses, then all flips. Candidates of one kind are
/// evaluated in parallel from the energy of the triangles they change,
/// sorted by gain, re-evaluated and applied one after the other, T's own
/// bookkeeping (triangulationHandlers) run after each. Face target lengths
/// must be current.
RemeshingResult remesh(CommonTriangulation& T,
  const MapEnergy& energy,
  const RemeshingOptions& options = RemeshingOptions());

/// Energy decrease of one edit (-inf when the edit is not possible: topology,
/// landmarks, an inverted or degenerate triangle on some sphere, a sample
/// outside the new triangles), and the edit itself. Splits and flips act on
/// an edge; a collapse removes the halfedge's from-vertex and puts the kept
/// vertex at the edge's midpoint on every sphere.
double splitGain(const MapEnergy& energy, OpenMesh::EdgeHandle e);
double collapseGain(const MapEnergy& energy, OpenMesh::HalfedgeHandle h);
double flipGain(const MapEnergy& energy, OpenMesh::EdgeHandle e);
/// Apply the edit to T (energy's triangulation) if its gain exceeds
/// minGain, then the handlers of its kind; true if applied, and then the
/// gain in `applied` if given.
bool applySplit(CommonTriangulation& T,
  const MapEnergy& energy,
  const EditHandlers& handlers,
  OpenMesh::EdgeHandle e,
  double minGain,
  double* applied = nullptr);
bool applyCollapse(CommonTriangulation& T,
  const MapEnergy& energy,
  const EditHandlers& handlers,
  OpenMesh::HalfedgeHandle h,
  double minGain,
  double* applied = nullptr);
bool applyFlip(CommonTriangulation& T,
  const MapEnergy& energy,
  const EditHandlers& handlers,
  OpenMesh::EdgeHandle e,
  double minGain,
  double* applied = nullptr);

} // namespace surfacemaps
