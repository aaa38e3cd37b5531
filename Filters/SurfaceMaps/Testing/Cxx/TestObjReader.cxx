#include "base/Error.h"
#include "io/ObjReader.h"

#include "ExpectInputError.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace surfacemaps;
using namespace surfacemaps::testing;

namespace
{
// Expects parseObj to throw an InputError whose message contains `part`.
void expectObjError(const std::string& text, const std::string& part)
{
  expectInputError([&] { parseObj(text, "mesh.obj"); }, part);
}
} // namespace

TEST(ObjReader, VerticesFollowVLinesAndCornersKeepTexCoords)
{
  // Two triangles sharing an edge whose corners have different texture
  // coordinates: still 4 vertices, not one per v/vt combination.
  const std::string text = "# comment\n"
                           "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\n"
                           "vt 0 0\nvt 1 0\nvt 0 1\nvt 0.5 0.5\nvn 0 0 1\n"
                           "g part\ns 1\nusemtl m\n"
                           "f 1/1/1 2/2/1 3/3/1\n"
                           "f 2/4/1 4/2/1 3/1/1\n";
  const PolygonMesh mesh = parseObj(text, "mesh.obj");
  ASSERT_EQ(mesh.points.size(), 4u);
  ASSERT_EQ(mesh.numberOfFaces(), 2u);
  EXPECT_EQ(mesh.face(1)[0], 1);
  EXPECT_EQ(mesh.face(1)[1], 3);
  EXPECT_EQ(mesh.face(1)[2], 2);
  ASSERT_EQ(mesh.cornerTexCoords.size(), 6u);
  EXPECT_DOUBLE_EQ(mesh.cornerTexCoords[3].x(), 0.5); // face 1, corner 0 uses vt 4
  EXPECT_DOUBLE_EQ(mesh.cornerTexCoords[5].y(), 0.0); // face 1, corner 2 uses vt 1
}

TEST(ObjReader, CornersKeepTheirNormals)
{
  // Vertex 2 (index 1) has a different normal in each face: kept per corner.
  const std::string text = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nvt 0 0\n"
                           "vn 0 0 1\nvn 0 0.6 0.8\nvn 1 0 0\n"
                           "f 1/1/1 2/1/2 3/1/1\n"
                           "f 2//3 4//-2 3//-1\n";
  const PolygonMesh mesh = parseObj(text, "mesh.obj");
  ASSERT_EQ(mesh.cornerNormals.size(), 6u);
  EXPECT_EQ(mesh.cornerNormals[0], Eigen::Vector3d(0, 0, 1));
  EXPECT_EQ(mesh.cornerNormals[1], Eigen::Vector3d(0, 0.6, 0.8)); // as given, not normalised
  EXPECT_EQ(mesh.cornerNormals[3], Eigen::Vector3d(1, 0, 0));     // vertex 2 again, vn 3
  EXPECT_EQ(mesh.cornerNormals[4], Eigen::Vector3d(0, 0.6, 0.8)); // relative index -2
  EXPECT_EQ(mesh.cornerNormals[5], Eigen::Vector3d(1, 0, 0));
  // `f a//c` has no texture coordinates: NaN at those corners, the others kept.
  ASSERT_EQ(mesh.cornerTexCoords.size(), 6u);
  EXPECT_EQ(mesh.cornerTexCoords[2], Eigen::Vector2d(0, 0));
  EXPECT_TRUE(std::isnan(mesh.cornerTexCoords[3].x()));
}

TEST(ObjReader, CornersWithoutNormalsAreNaN)
{
  const PolygonMesh mesh =
    parseObj("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nvn 0 0 1\nf 1 2 3\nf 2//1 4 3//1\n", "m");
  ASSERT_EQ(mesh.cornerNormals.size(), 6u);
  for (int c : { 0, 1, 2, 4 })
  {
    EXPECT_TRUE(mesh.cornerNormals[c].array().isNaN().all()) << "corner " << c;
  }
  EXPECT_EQ(mesh.cornerNormals[3], Eigen::Vector3d(0, 0, 1));
  EXPECT_EQ(mesh.cornerNormals[5], Eigen::Vector3d(0, 0, 1));
}

TEST(ObjReader, NormalsThatNoFaceUsesGiveNone)
{
  const PolygonMesh mesh = parseObj("v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1 2 3\n", "m");
  EXPECT_TRUE(mesh.cornerNormals.empty());
  EXPECT_TRUE(mesh.cornerTexCoords.empty());
}

TEST(ObjReader, NegativeIndicesAndPolygons)
{
  const PolygonMesh mesh = parseObj("v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf -4 -3 -2 -1\n", "m");
  ASSERT_EQ(mesh.numberOfFaces(), 1u);
  EXPECT_EQ(mesh.faceSize(0), 4);
  EXPECT_EQ(mesh.face(0)[0], 0);
  EXPECT_EQ(mesh.face(0)[3], 3);
  EXPECT_TRUE(mesh.cornerTexCoords.empty());
}

TEST(ObjReader, NonFiniteCoordinatesAreReadNotRejected)
{
  // Validation reports them with the vertex index; the reader keeps them.
  const PolygonMesh mesh = parseObj("v nan 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "m");
  EXPECT_TRUE(std::isnan(mesh.points[0].x()));
}

TEST(ObjReader, ByteOrderMarkIsSkipped)
{
  const PolygonMesh mesh = parseObj("\xEF\xBB\xBFv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "bom.obj");
  EXPECT_EQ(mesh.points.size(), 3u);
  EXPECT_EQ(mesh.numberOfFaces(), 1u);
  expectObjError("\xEF\xBB\xBFv 0 0 0\nv 1 0 0\nf 1 2 9\n", "mesh.obj:3:");
}

TEST(ObjReader, LinesAreCountedAsNonPolygonCells)
{
  const PolygonMesh mesh = parseObj("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nl 1 2\n", "m");
  EXPECT_EQ(mesh.nonPolygonCells, 1u);
}

TEST(ObjReader, Errors)
{
  expectObjError("v 0 0 0\nv 1 x 0\n", "mesh.obj:2: bad vertex coordinate 'x'");
  expectObjError("v 0 0\n", "mesh.obj:1: vertex has 2 coordinates");
  expectObjError("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n", "mesh.obj:4: face refers to vertex 4");
  expectObjError("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 0\n", "face refers to vertex 0");
  expectObjError("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2/7 3\n", "bad texture index");
  expectObjError("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2\n", "face has 2 vertices");
  expectObjError("v 0 0 0\nvn 0 x 1\n", "mesh.obj:2: bad normal coordinate 'x'");
  expectObjError("v 0 0 0\nvn 0 1\n", "mesh.obj:2: normal has 2 coordinates (3 expected)");
  expectObjError("v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//2 3//1\n",
    "mesh.obj:5: bad normal index in face corner '2//2' (1 defined before it)");
  expectObjError("v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//0 3//1\n",
    "mesh.obj:5: bad normal index in face corner '2//0'");
  expectObjError("v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//a 3//1\n",
    "mesh.obj:5: bad normal index in face corner '2//a'");
  // A normal defined after the face does not count (OBJ refers backwards only).
  expectObjError("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1//1 2//1 3//1\nvn 0 0 1\n",
    "mesh.obj:4: bad normal index in face corner '1//1' (0 defined before it)");
}

TEST(ObjReader, TruncatedFileIsNamedAsSuch)
{
  expectObjError("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 3", "looks truncated");
  expectObjError("v 0 0 0\nv 1 0 0\nv 0 1", "looks truncated");
  expectObjError("v 0 0 0\nv 1 0 0\nv 0 1 0", "looks truncated");
}

TEST(ObjReader, MissingFile)
{
  try
  {
    readObj("/nonexistent/dir/mesh.obj");
    FAIL();
  }
  catch (const InputError& e)
  {
    EXPECT_NE(
      std::string(e.what()).find("cannot open '/nonexistent/dir/mesh.obj'"), std::string::npos);
  }
}
