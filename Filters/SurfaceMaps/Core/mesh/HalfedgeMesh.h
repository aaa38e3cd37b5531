// SurfaceMaps engine: the half-edge triangle mesh the algorithms work on.
#pragma once

#include "mesh/PolygonMesh.h"

#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>

namespace surfacemaps
{

struct HalfedgeMeshTraits : public OpenMesh::DefaultTraits
{
  using Point = OpenMesh::Vec3d;
  using Normal = OpenMesh::Vec3d;
  // Status flags make edge collapses and garbage collection possible.
  VertexAttributes(OpenMesh::Attributes::Status);
  EdgeAttributes(OpenMesh::Attributes::Status);
  HalfedgeAttributes(OpenMesh::Attributes::Status);
  FaceAttributes(OpenMesh::Attributes::Status);
};

/// Half-edge triangle mesh (OpenMesh) with double-precision points. Vertex i
/// and face f keep the indices they had in the PolygonMesh they came from.
using HalfedgeMesh = OpenMesh::TriMesh_ArrayKernelT<HalfedgeMeshTraits>;

/// Builds the half-edge mesh of a validated triangle mesh (see validateMesh).
/// Throws std::invalid_argument when a face cannot be added (the mesh was not
/// validated, or is not a manifold triangle mesh).
HalfedgeMesh toHalfedgeMesh(const PolygonMesh& mesh);

/// The faces of a half-edge mesh as vertex-index triples, in face order
/// (deleted faces skipped; after garbage collection entry f is face f).
std::vector<std::array<int, 3>> faceTriangles(const HalfedgeMesh& mesh);

/// For every entry of faceTriangles(mesh), the entries of the faces across
/// its three edges: entry k is across the edge opposite corner k, -1 where
/// that edge is on a boundary. Read off the half-edges, where a search over
/// the triangles alone (triangleNeighbours) sorts all directed edges.
std::vector<std::array<int, 3>> faceNeighbours(const HalfedgeMesh& mesh);

/// Points and triangles of a half-edge mesh (no texture coordinates).
PolygonMesh toPolygonMesh(const HalfedgeMesh& mesh);

} // namespace surfacemaps
