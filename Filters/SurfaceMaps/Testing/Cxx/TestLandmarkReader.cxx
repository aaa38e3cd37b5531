#include "base/Error.h"
#include "io/LandmarkReader.h"

#include <gtest/gtest.h>

using namespace surfacemaps;

TEST(LandmarkReader, AllFormats)
{
  EXPECT_EQ(parseLandmarks("4\n7\n\n# comment\n1\n", "a.txt"), (std::vector<int>{ 4, 7, 1 }));
  EXPECT_EQ(parseLandmarks("lk 4816\nlk 4152\n", "a.pinned"), (std::vector<int>{ 4816, 4152 }));
  EXPECT_EQ(parseLandmarks("12 0.5 -1 2e-3\n3 1 1 1\n", "a.vts"), (std::vector<int>{ 12, 3 }));
}

TEST(LandmarkReader, Errors)
{
  EXPECT_THROW(parseLandmarks("lk x\n", "a"), InputError);
  EXPECT_THROW(parseLandmarks("-3\n", "a"), InputError);
  EXPECT_THROW(parseLandmarks("3 foo\n", "a"), InputError);
  try
  {
    parseLandmarks("1\n2\nbanana\n", "a.txt");
    FAIL();
  }
  catch (const InputError& e)
  {
    EXPECT_NE(std::string(e.what()).find("a.txt:3:"), std::string::npos) << e.what();
  }
}

TEST(LandmarkReader, IdsFromIndices)
{
  const std::vector<int> ids = landmarkIdsFromIndices({ 3, 0 }, 5, "l");
  EXPECT_EQ(ids, (std::vector<int>{ 1, -1, -1, 0, -1 }));
  try
  {
    landmarkIdsFromIndices({ 3, 9 }, 5, "l.pinned");
    FAIL();
  }
  catch (const InputError& e)
  {
    EXPECT_NE(std::string(e.what()).find("landmark 1 is vertex 9, out of range for a mesh with 5"),
      std::string::npos)
      << e.what();
  }
  EXPECT_THROW(landmarkIdsFromIndices({ 2, 2 }, 5, "l"), InputError);
}

namespace
{
// The message of the InputError `parse` throws, empty if none.
template <typename Parse>
std::string errorOf(Parse parse)
{
  try
  {
    parse();
  }
  catch (const InputError& e)
  {
    return e.what();
  }
  return "";
}

bool contains(const std::string& text, const std::string& part)
{
  return text.find(part) != std::string::npos;
}
} // namespace

TEST(LandmarkReader, VtsPointsWithoutIndex)
{
  const std::vector<LandmarkRecord> records =
    parseLandmarkRecords("# x y z\n0.5 -1 2e-3\n12 1 2 3\n-1 4 5 6\n7\n", "a.vts");
  ASSERT_EQ(records.size(), 4u);
  EXPECT_EQ(records[0].Vertex, -1);
  EXPECT_EQ(records[0].Point, (std::array<double, 3>{ { 0.5, -1.0, 2e-3 } }));
  EXPECT_EQ(records[0].Line, 2);
  EXPECT_EQ(records[1].Vertex, 12); // a given index wins over its coordinates
  EXPECT_EQ(records[2].Vertex, -1);
  EXPECT_EQ(records[2].Point, (std::array<double, 3>{ { 4.0, 5.0, 6.0 } }));
  EXPECT_EQ(records[3].Vertex, 7);
  for (int k = 0; k < 4; ++k)
  {
    EXPECT_EQ(records[k].Id, k); // file order
  }
  // An index-only reader refuses points, naming the line.
  EXPECT_TRUE(contains(errorOf([] { parseLandmarks("3\n1 2 3\n", "b.vts"); }), "b.vts:2:"));
}

TEST(LandmarkReader, Fcsv)
{
  const std::string slicer4 = "# Markups fiducial file version = 4.11\n"
                              "# CoordinateSystem = LPS\n"
                              "# columns = id,x,y,z,ow,ox,oy,oz,vis,sel,lock,label,desc,"
                              "associatedNodeID\n"
                              "vtkMRMLMarkupsFiducialNode_0,1.5,-2,3,0,0,0,1,1,1,0,F-1,,\n"
                              "vtkMRMLMarkupsFiducialNode_1,4,5,6,0,0,0,1,1,1,0,\"tip, left\",,\n";
  std::vector<LandmarkRecord> records = parseLandmarkRecords(slicer4, "p.fcsv");
  ASSERT_EQ(records.size(), 2u);
  EXPECT_EQ(records[0].Point, (std::array<double, 3>{ { 1.5, -2.0, 3.0 } }));
  EXPECT_EQ(records[0].Label, "F-1");
  EXPECT_EQ(records[1].Label, "tip, left");
  EXPECT_EQ(records[0].Id, 0); // node names are not ids: file order
  EXPECT_EQ(records[1].Id, 1);
  EXPECT_EQ(records[1].Line, 5);

  // Integer ids are used; columns in another order follow the columns line.
  records = parseLandmarkRecords("# columns = label,z,y,x,id\nA,3,2,1,7\nB,6,5,4,2\n", "q.FCSV");
  ASSERT_EQ(records.size(), 2u);
  EXPECT_EQ(records[0].Point, (std::array<double, 3>{ { 1.0, 2.0, 3.0 } }));
  EXPECT_EQ(records[0].Id, 7);
  EXPECT_EQ(records[1].Id, 2);
}

TEST(LandmarkReader, Csv)
{
  std::vector<LandmarkRecord> records = parseLandmarkRecords("1,2,3\n\n4, 5 ,6\r\n", "a.csv");
  ASSERT_EQ(records.size(), 2u);
  EXPECT_EQ(records[1].Point, (std::array<double, 3>{ { 4.0, 5.0, 6.0 } }));
  EXPECT_EQ(records[1].Id, 1);
  EXPECT_EQ(records[1].Line, 3);

  records = parseLandmarkRecords("1,2,3,5\n4,5,6,0\n", "a.csv");
  EXPECT_EQ(records[0].Id, 5);
  EXPECT_EQ(records[1].Id, 0);

  records = parseLandmarkRecords("id,label,x,y,z\n3,nose,1,2,3\n", "a.csv");
  ASSERT_EQ(records.size(), 1u);
  EXPECT_EQ(records[0].Id, 3);
  EXPECT_EQ(records[0].Label, "nose");
  EXPECT_EQ(records[0].Point, (std::array<double, 3>{ { 1.0, 2.0, 3.0 } }));
}

TEST(LandmarkReader, MalformedPointFilesNameTheLine)
{
  struct Case
  {
    const char* Name;
    const char* Text;
    const char* Message;
  };
  for (const Case& c : {
         Case{ "a.csv", "1,2,3\n1,2\n", "a.csv:2: expected x,y,z or x,y,z,id, got 2 values" },
         Case{ "a.csv", "1,2,3\n1,x,3\n", "a.csv:2: expected a coordinate, got 'x'" },
         Case{ "a.csv", "1,2,3\n1,2,nan\n", "a.csv:2: the coordinate 'nan' is not finite" },
         Case{ "a.csv", "1,2,3,0\n1,2,3\n", "a.csv:2: this line gives no id, but others do" },
         Case{ "a.csv", "1,2,3,0\n4,5,6,0\n", "a.csv:2: landmark id 0 is given twice (also on line 1)" },
         Case{ "a.csv", "1,2,3,-4\n", "a.csv:1: expected a landmark id (an integer >= 0), got '-4'" },
         Case{ "a.csv", "name,value\n", "a.csv:1: the header names no x, y and z columns" },
         Case{ "a.fcsv", "# columns = id,x,y,z\nn0,1,2\n", "a.fcsv:2: expected at least 4 comma-separated values, got 3" },
         Case{ "a.fcsv", "n0,1,2,\"3\n", "a.fcsv:1: a quoted field is not closed" },
         // Slicer ids: one unusable id refuses the file instead of renumbering every point.
         Case{ "a.fcsv", "# columns = id,x,y,z\n3,0,0,0\n2,1,0,0\n1,0,1,0\nF-4,0,0,1\n", "a.fcsv:5: the id 'F-4' is no landmark id (an integer >= 0), but line 2 gives one (3): give an integer id to every point or to none" },
         Case{ "a.fcsv", "# columns = id,x,y,z\n3,0,0,0\n,1,0,0\n", "a.fcsv:3: this point gives no landmark id, but line 2 gives one (3)" },
         Case{ "a.fcsv", "3,0,0,0\n99999999999,1,0,0\n", "a.fcsv:2: this point has the id '99999999999', which is no landmark id (an integer from 0 to 2147483647)" },
         Case{ "a.fcsv", "-2,0,0,0\n", "a.fcsv:1: this point has the id '-2', which is no landmark id" },
         Case{ "a.fcsv", "1.5,0,0,0\n", "a.fcsv:1: this point has the id '1.5', which is no landmark id" },
         Case{ "a.vts", "1 2\n", "a.vts:1: expected 'index', 'index x y z' or 'x y z', got 2 values" },
         Case{ "a.vts", "0 0 0\n1 inf 0\n", "a.vts:2: the coordinate 'inf' is not finite" },
       })
  {
    const std::string error = errorOf([&] { parseLandmarkRecords(c.Text, c.Name); });
    EXPECT_TRUE(contains(error, c.Message)) << c.Name << " '" << c.Text << "': " << error;
  }
}

TEST(LandmarkReader, IdsFromRecords)
{
  std::vector<LandmarkRecord> records(2);
  records[0].Id = 4;
  records[0].Vertex = 2;
  records[0].Line = 1;
  records[1].Id = 1;
  records[1].Vertex = 0;
  records[1].Line = 3;
  EXPECT_EQ(landmarkIdsFromRecords(records, 3, "l"), (std::vector<int>{ 1, -1, 4 }));
  records[1].Vertex = 2; // two points snapped to one vertex
  EXPECT_TRUE(contains(errorOf([&] { landmarkIdsFromRecords(records, 3, "l.csv"); }),
    "l.csv:3: landmark 1 falls on vertex 2, which already carries landmark 4 (line 1)"));
  records[1].Vertex = 3;
  EXPECT_TRUE(contains(errorOf([&] { landmarkIdsFromRecords(records, 3, "l.csv"); }),
    "l.csv:3: landmark 1 is vertex 3, out of range for a mesh with 3 vertices"));
}
