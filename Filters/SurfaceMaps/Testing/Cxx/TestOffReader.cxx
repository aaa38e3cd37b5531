#include "base/Error.h"
#include "io/OffReader.h"

#include "ExpectInputError.h"

#include <gtest/gtest.h>

using namespace surfacemaps;
using namespace surfacemaps::testing;

namespace
{
void expectOffError(const std::string& text, const std::string& part)
{
  expectInputError([&] { parseOff(text, "mesh.off"); }, part);
}
const char* const Tetrahedron = "OFF\n# a comment\n4 4 6\n"
                                "1 1 1\n1 -1 -1\n-1 1 -1\n-1 -1 1\n"
                                "3 0 1 2\n3 0 3 1\n3 0 2 3\n3 1 3 2 255 0 0\n";
} // namespace

TEST(OffReader, Tetrahedron)
{
  const PolygonMesh mesh = parseOff(Tetrahedron, "t.off");
  ASSERT_EQ(mesh.points.size(), 4u);
  ASSERT_EQ(mesh.numberOfFaces(), 4u);
  EXPECT_EQ(mesh.face(3)[2], 2);
  EXPECT_DOUBLE_EQ(mesh.points[3].z(), 1.0);
}

TEST(OffReader, CountsOnHeaderLineAndNoHeader)
{
  EXPECT_EQ(parseOff("OFF 3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", "m").numberOfFaces(), 1u);
  EXPECT_EQ(parseOff("3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", "m").numberOfFaces(), 1u);
  EXPECT_EQ(parseOff("COFF\n3 1\n0 0 0 1 1 1 1\n1 0 0 1 1 1 1\n0 1 0 1 1 1 1\n3 0 1 2\n", "m")
              .points.size(),
    3u);
}

TEST(OffReader, Errors)
{
  expectOffError("", "the file is empty");
  expectOffError("hello\n", "not an OFF file");
  expectOffError("OFF BINARY\n", "binary OFF is not supported");
  expectOffError("OFF\n3 1 0\n0 0 0\n1 0 0\n", "declares 3 vertices, but the file ends after 2");
  expectOffError(
    "OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", "declares 2 faces, but the file ends after 1");
  expectOffError("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n",
    "mesh.off:6: face refers to vertex 3, but the file has 3 vertices");
  expectOffError(
    "OFF\n3 1 0\n0 0 0\n1 a 0\n0 1 0\n3 0 1 2\n", "mesh.off:4: bad vertex coordinate 'a'");
  expectOffError("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1", "face declares 3 vertices but lists 2");
}
