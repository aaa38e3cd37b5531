// SurfaceMaps engine: checks of landmark ids, per input and across inputs.
#pragma once

#include "mesh/PolygonMesh.h"

#include <string>
#include <vector>

namespace surfacemaps
{

/// Checks per-vertex landmark ids (-1 none) of one input: every id is >= -1
/// and on at most one vertex. One sentence per defect, without the input name.
std::vector<std::string> checkLandmarkIds(const std::vector<int>& landmarkIds);

/// Checks that the landmark ids of several inputs (each passing
/// checkLandmarkIds) correspond: the same set of ids on every input as on the
/// first. Per input, one sentence per defect naming both inputs by `names`
/// (the first input's list stays empty).
std::vector<std::vector<std::string>> checkLandmarkCorrespondence(
  const std::vector<std::vector<int>>& landmarkIds,
  const std::vector<std::string>& names);

/// How the landmarks of one input are oriented against another's: over
/// triples of landmarks (a, b, c), the sign of det[a - o, b - o, c - o] with
/// o the input's area-weighted centroid, i.e. whether a, b, c turn
/// counter-clockwise seen from the inside. Rotation, translation, scale and
/// moderate bending keep most signs; a mirror image flips every one.
struct LandmarkOrientation
{
  /// Triples decisive on both inputs (|det| at least 1e-3 of the cube of
  /// the input's size, so nearly flat triples do not vote).
  int triples = 0;
  /// Decisive triples whose sign differs.
  int opposite = 0;
};

/// Compares the landmark triples (ids common to both, at most the first 60
/// ids: 34 220 triples) of two validated triangle meshes with per-vertex
/// landmark ids (-1 none).
LandmarkOrientation compareLandmarkOrientation(const PolygonMesh& first,
  const std::vector<int>& firstIds,
  const PolygonMesh& other,
  const std::vector<int>& otherIds);

/// One warning per input whose landmarks are the mirror image of the first
/// input's (more than half of the decisive triples opposite), naming both
/// inputs by `names`: such landmarks can only be met by a map that turns
/// the surface inside out locally, with huge distortion (a mirrored mesh or
/// a landmark list of the other side). Empty when none is.
std::vector<std::string> checkLandmarkMirroring(const std::vector<const PolygonMesh*>& meshes,
  const std::vector<std::vector<int>>& landmarkIds,
  const std::vector<std::string>& names);

} // namespace surfacemaps
