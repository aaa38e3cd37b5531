#include "io/LegacyVtkCheck.h"
#include "io/TextFile.h"

#include "ExpectInputError.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <string>

using namespace surfacemaps;
using namespace surfacemaps::testing;

namespace
{
const std::string Header = "# vtk DataFile Version 4.2\ntitle\nASCII\nDATASET POLYDATA\n";
const std::string Points = "POINTS 4 float\n1 1 1 1 -1 -1 -1 1 -1 -1 -1 1\n";
const std::string Polygons = "POLYGONS 4 16\n3 0 1 2\n3 0 3 1\n3 0 2 3\n3 1 3 2\n";

void expectLegacyError(const std::string& text, const std::string& part)
{
  expectInputError([&] { checkLegacyVtkPolyData(text, "m.vtk"); }, part);
}

std::string bigEndian32(std::int32_t value)
{
  std::string bytes(4, '\0');
  for (int k = 0; k < 4; ++k)
  {
    bytes[k] = static_cast<char>((static_cast<std::uint32_t>(value) >> (8 * (3 - k))) & 0xFF);
  }
  return bytes;
}

// A binary legacy 4.2 tetrahedron whose cell 1, corner 2 is `index`.
std::string binaryTetrahedron(std::int32_t index)
{
  std::string text = "# vtk DataFile Version 4.2\nt\nBINARY\nDATASET POLYDATA\nPOINTS 4 int\n";
  for (int v : { 1, 1, 1, 1, -1, -1, -1, 1, -1, -1, -1, 1 })
  {
    text += bigEndian32(v);
  }
  text += "\nPOLYGONS 4 16\n";
  const int cells[4][3] = { { 0, 1, 2 }, { 0, 3, index }, { 0, 2, 3 }, { 1, 3, 2 } };
  for (const auto& cell : cells)
  {
    text += bigEndian32(3);
    for (int v : cell)
    {
      text += bigEndian32(v);
    }
  }
  return text + "\n";
}
} // namespace

TEST(LegacyVtkCheck, AcceptsWellFormedFiles)
{
  checkLegacyVtkPolyData(Header + Points + Polygons, "m.vtk");
  checkLegacyVtkPolyData(Header + Points + Polygons +
      "POINT_DATA 4\nSCALARS Landmarks int 1\nLOOKUP_TABLE default\n0 -1 -1 1\n",
    "m.vtk");
  // File version 5: OFFSETS and CONNECTIVITY.
  checkLegacyVtkPolyData("# vtk DataFile Version 5.1\nt\nASCII\nDATASET POLYDATA\n" + Points +
      "POLYGONS 5 12\nOFFSETS vtktypeint64\n0 3 6 9 12\nCONNECTIVITY vtktypeint64\n"
      "0 1 2 0 3 1 0 2 3 1 3 2\n",
    "m.vtk");
  checkLegacyVtkPolyData(binaryTetrahedron(1), "m.vtk");
  const std::string limbs = readTextFile(std::string(SURFACEMAPS_DATA_DIR) + "/limbs_coarse.vtk");
  checkLegacyVtkPolyData(limbs, "limbs_coarse.vtk");
}

TEST(LegacyVtkCheck, NamesAnIndexBeyond32Bits)
{
  std::string text = Header + Points + "POLYGONS 4 16\n3 0 1 2\n3 0 4294967301 1\n3 0 2 3\n3 1 3 2\n";
  expectLegacyError(text, "m.vtk:9: polygons cell 1 uses point index 4294967301, out of range for 4 points");
  expectLegacyError(binaryTetrahedron(-7), "polygons cell 1 uses point index -7, out of range for 4 points");
  expectLegacyError(binaryTetrahedron(4), "m.vtk: byte ");
}

TEST(LegacyVtkCheck, RefusesCountsTheFileCannotHold)
{
  expectLegacyError(Header + "POINTS 99999999999 float\n1 1 1\n",
    "m.vtk:5: declares a point count of 99999999999, more than the file's");
  expectLegacyError(Header + "POINTS 20 float\n1 1 1 1 -1 -1\n",
    "POINTS declares 60 values, more than the rest of the file can hold");
  expectLegacyError(Header + Points + "POLYGONS 4 17\n3 0 1 2\n3 0 3 1\n3 0 2 3\n3 1 3 2\n",
    "polygons declares a size of 17 values, but its 4 cells use 16");
  expectLegacyError(Header + Points + Polygons + "POINT_DATA 5\n", "point_data declares 5 tuples for 4 points");
  expectLegacyError("# vtk DataFile Version 5.1\nt\nASCII\nDATASET POLYDATA\n" + Points +
      "POLYGONS 2 3\nOFFSETS vtktypeint64\n0 4\nCONNECTIVITY vtktypeint64\n0 1 2\n",
    "polygons offset 1 is 4");
}

TEST(LegacyVtkCheck, RefusesWhatVtkWouldMisread)
{
  expectLegacyError("# vtk DataFile\nt\nASCII\nDATASET POLYDATA\n", "not a legacy VTK file");
  expectLegacyError(Header + Points + Polygons + "POINT_DATA 4\nSCALARS names string 1\n",
    "has data type 'string'");
  expectLegacyError(Header + Points + "POLYGONS 4 16\n3 0 1 2\n3 0 x 1\n3 0 2 3\n3 1 3 2\n",
    "polygons: expected an integer, got 'x'");
}
