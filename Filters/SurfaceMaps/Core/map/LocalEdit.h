// SurfaceMaps engine: one candidate edit of remeshing, evaluated locally.
// Owns the edit's local configuration (the triangles it replaces and those
// it creates over local vertices) and its gain from the phase's energy of
// the triangles it changes and the samples in them (DESIGN.md section 1.4).
#pragma once

#include "map/CommonTriangulation.h"
#include "map/MapEnergy.h"

#include <limits>
#include <vector>

namespace surfacemaps
{

/// The gain of an edit that is not possible.
constexpr double NoGain = -std::numeric_limits<double>::infinity();

/// The triangles an edit replaces and the ones it creates, over local
/// vertices (mesh vertices and the one new or moved vertex).
struct LocalEdit
{
  std::vector<OpenMesh::VertexHandle> handles;
  /// The vertices before the edit; evaluate() turns them into the vertices
  /// after it (the moved one moved, the split's new one appended).
  std::vector<MapVertex> vertices;
  std::vector<std::array<int, 3>> before;
  std::vector<double> beforeLengths;
  /// The faces the edit replaces, and their samples per input: gathered
  /// only for an edit that passes the cheaper checks (gatherSamples).
  std::vector<OpenMesh::FaceHandle> faces;
  std::vector<std::vector<int>> samples;
  /// The new vertex (split, appended) or the moved one (collapse: index).
  MapVertex moved;
  int movedIndex = -1;
  std::vector<std::array<int, 3>> after;
  std::vector<double> afterLengths;
  LocalAssignment assignment;
  /// Energy of each face the edit removes (from the cache, if valid), and of
  /// each triangle it creates.
  double cachedBefore = 0.0;
  bool beforeCached = true;
  std::vector<double> afterEnergies;
  /// evaluate()'s terms and energies of the triangles the edit creates
  /// (without their samples).
  std::vector<MapEnergy::TriangleTerms> afterTerms;
  std::vector<double> afterTriangleEnergies;

  /// Back to a new edit, keeping the vectors' storage: candidates are
  /// evaluated by the hundred thousand, each on one scratch edit per thread
  /// (a MapVertex is a few hundred bytes).
  void clear()
  {
    this->handles.clear();
    this->vertices.clear();
    this->before.clear();
    this->beforeLengths.clear();
    this->faces.clear();
    this->samples.clear();
    this->moved = MapVertex();
    this->movedIndex = -1;
    this->after.clear();
    this->afterLengths.clear();
    this->assignment.clear();
    this->cachedBefore = 0.0;
    this->beforeCached = true;
    this->afterEnergies.clear();
    this->afterTerms.clear();
    this->afterTriangleEnergies.clear();
  }
};

/// Local index of mesh vertex v in the edit, adding it (with its data) if new.
int localIndex(const CommonTriangulation& T, LocalEdit& edit, OpenMesh::VertexHandle v);

/// Adds face f to the faces the edit replaces: its triangle, target length
/// and cached energy.
void addFace(const CommonTriangulation& T, LocalEdit& edit, OpenMesh::FaceHandle f);

/// Energy before minus energy after; turns the edit's vertices into those
/// after it and fills its after lengths, energies and sample assignment.
/// With a finite minGain, an edit that cannot gain more than it (its new
/// triangles alone already cost as much as the old configuration, and
/// sample energies are >= 0) is answered with NoGain before its samples are
/// located: cheaper, same edits applied.
double evaluate(const MapEnergy& energy,
  LocalEdit& edit,
  double minGain = -std::numeric_limits<double>::infinity());

} // namespace surfacemaps
