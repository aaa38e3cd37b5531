// SurfaceMaps engine: the map's energy of one phase over a common
// triangulation (DESIGN.md section 1.3). Owns what remeshing asks for gains
// (per-triangle terms, local energies of candidate edits, the per-face energy
// cache) and the objective of the Newton step, all under the phase's weights,
// fixed at construction. T itself holds no weights.
#pragma once

#include "map/CommonTriangulation.h"
#include "map/MapEnergyWeights.h"
#include "optimisation/Objective.h"

#include <Eigen/Core>

#include <array>
#include <map>
#include <vector>

namespace surfacemaps
{

class MapEnergy
{
public:
  MapEnergy(CommonTriangulation& T, MapEnergyWeights weights);

  const MapEnergyWeights& weights() const { return this->Weights; }
  const CommonTriangulation& triangulation() const { return this->T; }

  /// The weighted per-triangle terms of one triangle that do not depend on
  /// its target length, and its lifted triangles' Gram entries (which the
  /// mesh-quality term needs with the length). Remeshing computes them once
  /// and asks two questions: triangleEnergyBound before it walks on the
  /// spheres for the length, triangleEnergy after.
  struct TriangleTerms
  {
    bool valid = true; ///< false: a barrier term is infinite
    PerInput<double> barrier, coverage;
    PerInput<std::array<double, 3>> lifted;
    /// Per pair of the map distortion term (per input with mapToMean).
    PerInput<double> map;
  };
  TriangleTerms triangleTerms(const MapVertex& a, const MapVertex& b, const MapVertex& c) const;

  /// Energy of the per-triangle terms (barrier, mesh quality, coverage, map
  /// distortion) of one triangle, weighted; +inf if invalid.
  double triangleEnergy(const TriangleTerms& terms, double length) const;
  double triangleEnergy(const MapVertex& a,
    const MapVertex& b,
    const MapVertex& c,
    double length) const
  {
    return this->triangleEnergy(this->triangleTerms(a, b, c), length);
  }
  /// A lower bound of triangleEnergy(terms, length) over every length, with
  /// the same terms summed in the same order (so it holds in floating point
  /// as well): the mesh-quality term at its smallest value over lengths
  /// (meshQualityBound). Every term is >= 0, so a sum of bounds that already
  /// exceeds what an edit may cost rejects it without any target length.
  double triangleEnergyBound(const TriangleTerms& terms) const;
  /// Weighted approximation energy of sample s of input i in a triangle.
  double sampleEnergy(int i,
    int s,
    const MapVertex& a,
    const MapVertex& b,
    const MapVertex& c) const;

  /// Energy of a local configuration: triangles over `vertices` whose
  /// triangleEnergy values are `triangleEnergies`, plus the samples of each
  /// input (which must lie in the union of the triangles on that input's
  /// sphere). `assignment`, if given, receives the local triangle of each
  /// sample; a sample in no triangle makes the configuration invalid (+inf).
  /// `perTriangle`, if given, receives each triangle's energy with its
  /// samples'.
  double localEnergy(const std::vector<MapVertex>& vertices,
    const std::vector<std::array<int, 3>>& triangles,
    const std::vector<double>& triangleEnergies,
    const std::vector<std::vector<int>>& samples,
    LocalAssignment* assignment,
    std::vector<double>* perTriangle = nullptr) const;

  /// Fills T's per-face energy cache (CommonTriangulation::faceEnergy) and
  /// marks it valid.
  void updateFaceEnergies() const;

  /// Builds the objective over a snapshot of T (the snapshot must outlive
  /// the objective's use), each term in the group of its MapTerm. Landmark
  /// targets per input.
  void buildObjective(const CommonTriangulation::Snapshot& snapshot,
    const std::vector<std::map<int, Eigen::Vector3d>>& landmarkTargets,
    Objective& objective) const;

  /// Total energy (weighted) of T as it is, for tests of local changes.
  double total() const;

private:
  /// The terms of input i (barrier, mesh quality, coverage, approximation,
  /// landmarks) in that order.
  void addInputTerms(const CommonTriangulation::Snapshot& snapshot,
    int i,
    const std::vector<std::map<int, Eigen::Vector3d>>& landmarkTargets,
    Objective& objective) const;

  CommonTriangulation& T;
  MapEnergyWeights Weights;
};

} // namespace surfacemaps
