#include "base/Error.h"
#include "io/PlyReader.h"

#include "ExpectInputError.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>

using namespace surfacemaps;
using namespace surfacemaps::testing;

namespace
{
void expectPlyError(const std::string& bytes, const std::string& part)
{
  expectInputError([&] { parsePly(bytes, "mesh.ply"); }, part);
}

template<typename T>
void put(std::string& bytes, T value, bool bigEndian)
{
  char raw[sizeof(T)];
  std::memcpy(raw, &value, sizeof(T));
  if (bigEndian)
  {
    std::reverse(raw, raw + sizeof(T));
  }
  bytes.append(raw, sizeof(T));
}

// A tetrahedron in binary PLY with an extra per-vertex property and an extra element.
std::string binaryTetrahedron(bool bigEndian)
{
  std::string bytes = std::string("ply\nformat ") +
    (bigEndian ? "binary_big_endian" : "binary_little_endian") +
    " 1.0\ncomment test\nelement vertex 4\nproperty float x\nproperty float y\n"
    "property float z\nproperty uchar red\nelement face 4\n"
    "property list uchar int vertex_indices\nelement edge 1\nproperty int vertex1\n"
    "property int vertex2\nend_header\n";
  const float p[4][3] = { { 1, 1, 1 }, { 1, -1, -1 }, { -1, 1, -1 }, { -1, -1, 1 } };
  for (const auto& v : p)
  {
    for (float c : v)
    {
      put(bytes, c, bigEndian);
    }
    put<std::uint8_t>(bytes, 200, bigEndian);
  }
  const int f[4][3] = { { 0, 1, 2 }, { 0, 3, 1 }, { 0, 2, 3 }, { 1, 3, 2 } };
  for (const auto& t : f)
  {
    put<std::uint8_t>(bytes, 3, bigEndian);
    for (int i : t)
    {
      put<std::int32_t>(bytes, i, bigEndian);
    }
  }
  put<std::int32_t>(bytes, 0, bigEndian);
  put<std::int32_t>(bytes, 1, bigEndian);
  return bytes;
}
} // namespace

TEST(PlyReader, Ascii)
{
  const std::string text = "ply\nformat ascii 1.0\nelement vertex 3\nproperty double x\n"
                           "property double y\nproperty double z\nelement face 1\n"
                           "property list uchar int vertex_index\n"
                           "property list uchar float texcoord\nend_header\n"
                           "0 0 0\n1 0 0\n0 1 0\n3 0 1 2 6 0 0 1 0 0 1\n";
  const PolygonMesh mesh = parsePly(text, "m");
  ASSERT_EQ(mesh.points.size(), 3u);
  ASSERT_EQ(mesh.numberOfFaces(), 1u);
  ASSERT_EQ(mesh.cornerTexCoords.size(), 3u);
  EXPECT_DOUBLE_EQ(mesh.cornerTexCoords[2].y(), 1.0);
}

TEST(PlyReader, BinaryBothEndians)
{
  for (bool big : { false, true })
  {
    const PolygonMesh mesh = parsePly(binaryTetrahedron(big), "m");
    ASSERT_EQ(mesh.points.size(), 4u);
    ASSERT_EQ(mesh.numberOfFaces(), 4u);
    EXPECT_FLOAT_EQ(mesh.points[1].y(), -1.0f);
    EXPECT_EQ(mesh.face(3)[1], 3);
  }
}

TEST(PlyReader, VertexPropertiesBecomePointArrays)
{
  // A lone "red" is no colour group: it keeps its own name and type.
  const PolygonMesh tetra = parsePly(binaryTetrahedron(true), "m");
  ASSERT_EQ(tetra.pointArrays.size(), 1u);
  EXPECT_EQ(tetra.pointArrays[0].name, "red");
  EXPECT_EQ(tetra.pointArrays[0].type, PolygonMeshPointArray::Type::UInt8);
  EXPECT_EQ(tetra.pointArrays[0].values, std::vector<double>(4, 200.0));

  const std::string text = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"
                           "property float y\nproperty float z\nproperty uchar red\n"
                           "property uchar green\nproperty uchar blue\nproperty float nx\n"
                           "property float ny\nproperty float nz\nproperty float s\n"
                           "property float t\nproperty int label\nproperty uint big\n"
                           "property double quality\nelement face 1\n"
                           "property list uchar int vertex_indices\nend_header\n"
                           "0 0 0 1 2 3 0 0 1 0.5 0.25 7 4000000000 0.125\n"
                           "1 0 0 4 5 6 0 0 1 1 0 -2 1 1.5\n"
                           "0 1 0 7 8 9 0 0 1 0 1 3 2 2.5\n3 0 1 2\n";
  const PolygonMesh mesh = parsePly(text, "m");
  std::vector<std::string> names;
  for (const auto& a : mesh.pointArrays)
  {
    names.push_back(a.name + "/" + std::to_string(a.components));
  }
  EXPECT_EQ(names,
    (std::vector<std::string>{ "RGB/3", "Normals/3", "TCoords/2", "label/1", "big/1", "quality/1" }));
  using Type = PolygonMeshPointArray::Type;
  EXPECT_EQ(mesh.pointArrays[0].type, Type::UInt8);
  EXPECT_EQ(mesh.pointArrays[3].type, Type::Int32);
  EXPECT_EQ(mesh.pointArrays[4].type, Type::Int64);
  EXPECT_EQ(mesh.pointArrays[5].type, Type::Float64);
  EXPECT_EQ(mesh.pointArrays[0].values, (std::vector<double>{ 1, 2, 3, 4, 5, 6, 7, 8, 9 }));
  EXPECT_EQ(mesh.pointArrays[2].values, (std::vector<double>{ 0.5, 0.25, 1, 0, 0, 1 }));
  EXPECT_EQ(mesh.pointArrays[3].values, (std::vector<double>{ 7, -2, 3 }));
  EXPECT_EQ(mesh.pointArrays[4].values[0], 4000000000.0);
}

TEST(PlyReader, Errors)
{
  expectPlyError("this is not ply\n", "not a PLY file");
  expectPlyError("ply\nformat ascii 1.0\nelement vertex 3\n", "no end_header");
  const std::string tet = binaryTetrahedron(false);
  expectPlyError(tet.substr(0, tet.size() - 30), "the data ends in element");
  expectPlyError("ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                 "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
                 "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 5\n",
    "face 0 refers to vertex 5");
  expectPlyError("ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
                 "end_header\n0 0\n",
    "lacks an x, y or z property");
}

TEST(PlyReader, ElementCountsTheFileDoesNotHold)
{
  const std::string header = "ply\nformat ascii 1.0\nelement vertex 3\nproperty double x\n"
                             "property double y\nproperty double z\nelement face ";
  const std::string tail = "\nproperty list uchar int vertex_indices\nend_header\n"
                           "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  // Fewer faces declared than the file holds: refused, not read with holes.
  expectPlyError(header + "1" + tail + "3 0 2 1\n",
    "mesh.ply: the data goes on after the elements the header declares (3 vertex, 1 face): "
    "the header's counts do not match the file");
  // More declared than it holds.
  expectPlyError(header + "2" + tail, "the header declares 2 face elements, but the data ends");
  EXPECT_EQ(parsePly(header + "1" + tail + "\n\n", "m").numberOfFaces(), 1u);
  // Binary: a byte left over is refused, a final line end is not.
  EXPECT_EQ(parsePly(binaryTetrahedron(false) + "\n", "m").numberOfFaces(), 4u);
  expectPlyError(binaryTetrahedron(false) + std::string(1, '\3'), "the data goes on after");
}
