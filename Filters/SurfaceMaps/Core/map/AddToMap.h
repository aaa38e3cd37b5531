// SurfaceMaps engine: inputs added to a map computed earlier, without
// computing the existing inputs' maps again.
#pragma once

#include "map/MapInput.h"
#include "map/MapOptions.h"
#include "map/SurfaceMap.h"

#include <Eigen/Core>

#include <array>
#include <vector>

namespace surfacemaps
{

/// A map of M inputs computed earlier (SurfaceMapResult's members of the
/// same names): T's triangles, its embedding g_j on every sphere j < M, T
/// lifted onto every input j (original coordinates), T's landmark ids.
struct ExistingMap
{
  std::vector<std::array<int, 3>> triangles;
  std::vector<std::vector<Eigen::Vector3d>> spherePositions;
  std::vector<std::vector<Eigen::Vector3d>> lifted;
  std::vector<int> landmarks;
};

/// Adds inputs to `existing`, one after the other, and returns the map of
/// every input. `inputs` holds the M existing inputs first, each with the
/// embedding f_j the map used (SurfaceMapResult::inputSpherePositions, kept
/// as given), then the inputs to add (embedded; rotated here onto the map's
/// sphere frame through the landmarks).
///
/// Each added input is mapped against the existing inputs' mean shape (T
/// lifted onto every input, aligned by generalized Procrustes with scale
/// and averaged), first alone: computeSurfaceMap of the two with the whole
/// schedule of `options` (landmark phase, collapses, flips) on a
/// triangulation of their own. That map is composed onto T
/// (composeEmbedding): the new input's g(v) is its image of g_0(v), and T is
/// split where that would fold, each new vertex at the edge's midpoint on
/// every existing sphere, which is where the existing maps already send that
/// point: the existing inputs' maps keep their vertices and new vertices lie
/// on their triangles (a collapse or flip would change them). Should the
/// splits not remove every fold, the new input is optimised on T instead (a
/// warning says so): a two-input problem whose first input is the mean shape
/// with g_0 as its fixed embedding, the new input starting at g_0 (the same
/// sphere frame after the rotation), `options`' schedule with splits as the
/// only edits and only the new input's embedding moving. In both problems the
/// map weight is halved so that, as in the population preset's mean pairing
/// over N inputs, the new input's distortion weighs as much as each of its
/// per-input terms. Afterwards every existing g_j gets T's new vertices
/// through psi_0j = g_j o g_0^-1 of the existing map, and every embedding is
/// certified.
///
/// The result's energies are those of the last addition's two-input
/// problem (alone, or on T), its phases those of every addition in turn; baseDistance is
/// measured on the last added input only (NaN on the others), errorBound 0. Throws InputError when
/// the existing map or the inputs do not fit (sizes, embeddings that are not bijective, landmark
/// ids the new input lacks) or when `options` ask for what adding cannot keep (refinement rounds or
/// an error bound re-run on every input: set refinementRounds 0 and maxError 0), NoResultError when
/// an embedding of the result cannot be certified, Aborted through the progress callback.
SurfaceMapResult addToSurfaceMap(const ExistingMap& existing,
  const std::vector<MapInput>& inputs,
  const SurfaceMapOptions& options = SurfaceMapOptions());

} // namespace surfacemaps
