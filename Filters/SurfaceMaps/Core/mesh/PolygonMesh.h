// SurfaceMaps engine: an indexed polygon mesh as read from a file.
#pragma once

#include <Eigen/Core>

#include <array>
#include <cstddef>
#include <initializer_list>
#include <string>
#include <vector>

namespace surfacemaps
{

/// A per-vertex array read from a file (e.g. PLY colours, normals, texture
/// coordinates and other scalar properties), with the value type the file
/// gives it so integer data stays integer (labels are carried categorically).
struct PolygonMeshPointArray
{
  enum class Type
  {
    UInt8,
    Int32,
    Int64,
    Float32,
    Float64
  };
  std::string name;
  int components = 1;
  Type type = Type::Float64;
  /// Point p's component c at values[p * components + c].
  std::vector<double> values;
};

/// Indexed polygon mesh with optional per-corner texture coordinates and normals. This is
/// what readers produce and what validation inspects; it may hold anything a
/// file can contain (non-triangles, bad indices, non-manifold configurations).
/// Once validated it is turned into a HalfedgeMesh for the algorithms.
struct PolygonMesh
{
  std::vector<Eigen::Vector3d> points;
  /// Face f uses faceVertices[faceOffsets[f] .. faceOffsets[f+1]).
  std::vector<int> faceOffsets{ 0 };
  std::vector<int> faceVertices;
  /// Empty, or one entry per entry of faceVertices (NaN where a corner has none).
  std::vector<Eigen::Vector2d> cornerTexCoords;
  /// Empty, or one entry per entry of faceVertices (NaN where a corner has
  /// none): the file's per-corner normals (OBJ `vn`), as given (not normalised).
  std::vector<Eigen::Vector3d> cornerNormals;
  /// Per-vertex arrays of the file, one tuple per entry of points.
  std::vector<PolygonMeshPointArray> pointArrays;
  /// Cells of the source that are not polygons (lines, vertices, strips).
  std::size_t nonPolygonCells = 0;
  /// Face corners of the source whose vertex index does not fit an int (64-bit
  /// ids): stored as -1 in faceVertices, the first one's face and index kept
  /// here so validation can name it instead of a wrapped value.
  std::size_t wideIndices = 0;
  long long firstWideIndexFace = -1;
  long long firstWideIndex = 0;

  std::size_t numberOfFaces() const { return this->faceOffsets.size() - 1; }
  int faceSize(std::size_t f) const { return this->faceOffsets[f + 1] - this->faceOffsets[f]; }
  const int* face(std::size_t f) const { return this->faceVertices.data() + this->faceOffsets[f]; }

  /// The faces as vertex triples; every face must be a triangle.
  std::vector<std::array<int, 3>> triangles() const
  {
    std::vector<std::array<int, 3>> result(this->numberOfFaces());
    for (std::size_t f = 0; f < result.size(); ++f)
    {
      const int* t = this->face(f);
      result[f] = { t[0], t[1], t[2] };
    }
    return result;
  }

  void addFace(std::initializer_list<int> vertices)
  {
    this->faceVertices.insert(this->faceVertices.end(), vertices.begin(), vertices.end());
    this->faceOffsets.push_back(static_cast<int>(this->faceVertices.size()));
  }
  template<typename It>
  void addFace(It begin, It end)
  {
    this->faceVertices.insert(this->faceVertices.end(), begin, end);
    this->faceOffsets.push_back(static_cast<int>(this->faceVertices.size()));
  }
};

} // namespace surfacemaps
