#include "vtkSurfaceMeshReader.h"

#include "vtkCallbackCommand.h"
#include "vtkCellData.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkNew.h"
#include "vtkPLYReader.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkStringArray.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <sstream>
#include <unistd.h>
#include <vector>
#include <fstream>
#include <string>

namespace
{
const std::string Data = SURFACEMAPS_DATA_DIR;

struct ReadResult
{
  vtkSmartPointer<vtkPolyData> Output;
  std::string Error;
  int ErrorEvents = 0;
};

// `warnings`, when given, collects the reader's warning messages.
ReadResult read(const std::string& file,
  const std::string& landmarks = "",
  std::vector<std::string>* warnings = nullptr)
{
  vtkNew<vtkSurfaceMeshReader> reader;
  ReadResult result;
  vtkNew<vtkCallbackCommand> counter;
  counter->SetClientData(&result.ErrorEvents);
  counter->SetCallback(
    [](vtkObject*, unsigned long, void* count, void*) { ++*static_cast<int*>(count); });
  reader->AddObserver(vtkCommand::ErrorEvent, counter);
  vtkNew<vtkCallbackCommand> collector;
  if (warnings)
  {
    collector->SetClientData(warnings);
    collector->SetCallback([](vtkObject*, unsigned long, void* messages, void* text)
      { static_cast<std::vector<std::string>*>(messages)->push_back(static_cast<const char*>(text)); });
    reader->AddObserver(vtkCommand::WarningEvent, collector);
  }
  reader->SetFileName(file.c_str());
  if (!landmarks.empty())
  {
    reader->SetLandmarkFileName(landmarks.c_str());
  }
  reader->Update();
  result.Output = reader->GetOutput();
  result.Error = reader->GetLastErrorMessage();
  return result;
}
} // namespace

TEST(SurfaceMeshReader, EveryFormat)
{
  struct Case
  {
    const char* File;
    vtkIdType Points, Polys;
  };
  for (const Case& c : { Case{ "ellipsoid.obj", 642, 1280 },
         Case{ "blob.off", 642, 1280 },
         Case{ "limbs.ply", 2562, 5120 },
         Case{ "ellipsoid_coarse.stl", 162, 320 },
         Case{ "blob.vtp", 642, 1280 },
         Case{ "limbs_coarse.vtk", 642, 1280 },
         Case{ "spot.obj", 2930, 5856 } })
  {
    const ReadResult r = read(Data + "/" + c.File);
    EXPECT_TRUE(r.Error.empty()) << c.File << ": " << r.Error;
    EXPECT_EQ(r.Output->GetNumberOfPoints(), c.Points) << c.File;
    EXPECT_EQ(r.Output->GetNumberOfPolys(), c.Polys) << c.File;
    auto* name =
      vtkStringArray::SafeDownCast(r.Output->GetFieldData()->GetAbstractArray("FileName"));
    ASSERT_NE(name, nullptr);
    EXPECT_EQ(name->GetValue(0), Data + "/" + c.File);
  }
}

// Per-vertex PLY properties come out as VTK's own PLY reader gives them (names,
// types, components, values, attribute roles), in ASCII and binary, plus the
// scalar properties VTK's reader drops.
TEST(SurfaceMeshReader, PlyPropertiesMatchVTKsReader)
{
  const std::string header = "element vertex 4\nproperty float x\nproperty float y\n"
                             "property float z\nproperty float nx\nproperty float ny\n"
                             "property float nz\nproperty uchar red\nproperty uchar green\n"
                             "property uchar blue\nproperty uchar alpha\nproperty float u\n"
                             "property float v\nproperty float quality\nelement face 4\n"
                             "property list uchar int vertex_indices\nend_header\n";
  const float vertices[4][13] = { { 1, 1, 1, 0.5f, 0.5f, 0.5f, 255, 0, 0, 255, 0, 0, 0.5f },
    { 1, -1, -1, 0.5f, -0.5f, -0.5f, 0, 255, 0, 255, 1, 0, 0.25f },
    { -1, 1, -1, -0.5f, 0.5f, -0.5f, 0, 0, 255, 128, 0, 1, 0.75f },
    { -1, -1, 1, -0.5f, -0.5f, 0.5f, 10, 20, 30, 0, 1, 1, 1.5f } };
  const int faces[4][3] = { { 0, 1, 2 }, { 0, 3, 1 }, { 0, 2, 3 }, { 1, 3, 2 } };
  std::string ascii = "ply\nformat ascii 1.0\n" + header;
  std::string binary = "ply\nformat binary_little_endian 1.0\n" + header;
  for (const auto& v : vertices)
  {
    for (int k = 0; k < 13; ++k)
    {
      ascii += std::to_string(v[k]) + (k == 12 ? "\n" : " ");
      if (k >= 6 && k < 10)
      {
        binary.push_back(static_cast<char>(static_cast<unsigned char>(v[k])));
      }
      else
      {
        binary.append(reinterpret_cast<const char*>(&v[k]), sizeof(float));
      }
    }
  }
  for (const auto& f : faces)
  {
    ascii += "3 " + std::to_string(f[0]) + " " + std::to_string(f[1]) + " " + std::to_string(f[2]) + "\n";
    binary.push_back(3);
    binary.append(reinterpret_cast<const char*>(f), sizeof(f));
  }
  for (const auto& [name, bytes] : { std::make_pair("ascii", ascii), std::make_pair("binary", binary) })
  {
    const std::string path = testing::TempDir() + "/properties_" + name + ".ply";
    {
      std::ofstream file(path, std::ios::binary);
      file << bytes;
    }
    const ReadResult ours = read(path);
    ASSERT_TRUE(ours.Error.empty()) << ours.Error;
    vtkNew<vtkPLYReader> theirs;
    theirs->SetFileName(path.c_str());
    theirs->Update();
    vtkPointData* a = ours.Output->GetPointData();
    vtkPointData* b = theirs->GetOutput()->GetPointData();
    ASSERT_EQ(ours.Output->GetNumberOfPoints(), theirs->GetOutput()->GetNumberOfPoints());
    ASSERT_EQ(b->GetNumberOfArrays(), 3) << name;
    for (int i = 0; i < b->GetNumberOfArrays(); ++i)
    {
      vtkDataArray* expected = b->GetArray(i);
      vtkDataArray* got = a->GetArray(expected->GetName());
      ASSERT_NE(got, nullptr) << name << ": " << expected->GetName();
      EXPECT_EQ(got->GetDataType(), expected->GetDataType()) << expected->GetName();
      ASSERT_EQ(got->GetNumberOfComponents(), expected->GetNumberOfComponents());
      for (vtkIdType t = 0; t < expected->GetNumberOfTuples(); ++t)
      {
        for (int c = 0; c < expected->GetNumberOfComponents(); ++c)
        {
          EXPECT_EQ(got->GetComponent(t, c), expected->GetComponent(t, c))
            << name << ": " << expected->GetName() << " " << t << " " << c;
        }
      }
    }
    EXPECT_STREQ(a->GetNormals()->GetName(), b->GetNormals()->GetName());
    EXPECT_STREQ(a->GetTCoords()->GetName(), b->GetTCoords()->GetName());
    EXPECT_STREQ(a->GetScalars()->GetName(), b->GetScalars()->GetName());
    // What VTK's reader drops is kept.
    vtkDataArray* quality = a->GetArray("quality");
    ASSERT_NE(quality, nullptr);
    EXPECT_EQ(quality->GetComponent(3, 0), 1.5);
    std::remove(path.c_str());
  }
}

TEST(SurfaceMeshReader, SpotKeepsItsTextureSeamsClosed)
{
  // spot.obj has 2 930 `v` lines and 17 568 `vt` lines: one point per
  // v/vt/vn combination would tear it open; here it stays 2 930 points and
  // the texture coordinates go with the corners.
  const ReadResult r = read(Data + "/spot.obj");
  ASSERT_EQ(r.Output->GetNumberOfPoints(), 2930);
  vtkDataArray* tc = r.Output->GetCellData()->GetArray("CornerTCoords");
  ASSERT_NE(tc, nullptr);
  EXPECT_EQ(tc->GetNumberOfTuples(), 5856);
  // Face 1 is "f 4/4/4 3/5/3 2/6/2": its second corner has vt 5.
  double t[6];
  tc->GetTuple(1, t);
  const std::string text = []
  {
    std::ifstream in(Data + "/spot.obj");
    std::string line;
    int vt = 0;
    while (std::getline(in, line))
    {
      if (line.rfind("vt ", 0) == 0 && ++vt == 5)
      {
        return line;
      }
    }
    return std::string();
  }();
  double u, v;
  ASSERT_EQ(std::sscanf(text.c_str(), "vt %lf %lf", &u, &v), 2);
  EXPECT_EQ(t[2], u);
  EXPECT_EQ(t[3], v);
}

TEST(SurfaceMeshReader, LandmarkFilesBecomeTheLandmarksArray)
{
  for (const std::string& pair :
    { std::string("ellipsoid.obj|ellipsoid.pinned"), std::string("blob.off|blob.vts") })
  {
    const std::size_t bar = pair.find('|');
    const ReadResult r = read(Data + "/" + pair.substr(0, bar), Data + "/" + pair.substr(bar + 1));
    ASSERT_TRUE(r.Error.empty()) << r.Error;
    vtkDataArray* ids = r.Output->GetPointData()->GetArray("Landmarks");
    ASSERT_NE(ids, nullptr);
    int count = 0;
    for (vtkIdType i = 0; i < ids->GetNumberOfTuples(); ++i)
    {
      count += ids->GetComponent(i, 0) >= 0 ? 1 : 0;
    }
    EXPECT_EQ(count, 4) << pair;
  }
  // The VTP file carries the same landmarks as blob.vts in its own array.
  const ReadResult vtp = read(Data + "/blob.vtp");
  const ReadResult vts = read(Data + "/blob.off", Data + "/blob.vts");
  vtkDataArray* a = vtp.Output->GetPointData()->GetArray("Landmarks");
  vtkDataArray* b = vts.Output->GetPointData()->GetArray("Landmarks");
  ASSERT_NE(a, nullptr);
  for (vtkIdType i = 0; i < a->GetNumberOfTuples(); ++i)
  {
    EXPECT_EQ(a->GetComponent(i, 0), b->GetComponent(i, 0));
  }
}

TEST(SurfaceMeshReader, ErrorsLeaveAnEmptyOutputAndNameTheFile)
{
  struct Case
  {
    std::string File, Landmarks, Message;
  };
  const std::string bad = Data + "/bad/";
  for (const Case& c : {
         Case{ bad + "empty.obj", "", bad + "empty.obj: the file is empty" },
         Case{ bad + "truncated.obj", "", "looks truncated" },
         Case{ bad + "truncated.off", "", "declares 162 vertices, but the file ends after 81" },
         Case{ bad + "truncated.ply", "", "the file looks truncated" },
         Case{ bad + "truncated.vtk", "", "truncated.vtk:90: POINTS: the file ends after 254 of 486 values; it is truncated" },
         Case{ bad + "garbage.ply", "", "not a PLY file" },
         Case{ Data + "/missing.obj", "", "cannot open '" + Data + "/missing.obj'" },
         Case{ Data + "/generate_data.py", "", "unknown mesh format 'py'" },
         Case{ Data + "/ellipsoid.obj",
           bad + "ellipsoid_out_of_range.pinned",
           "landmark 2 is vertex 5000, out of range for a mesh with 642 vertices" },
       })
  {
    const ReadResult r = read(c.File, c.Landmarks);
    EXPECT_NE(r.Error.find(c.Message), std::string::npos) << c.File << ": '" << r.Error << "'";
    EXPECT_EQ(r.ErrorEvents, 1) << c.File;
    EXPECT_EQ(r.Output->GetNumberOfPoints(), 0) << c.File;
    EXPECT_EQ(r.Output->GetNumberOfCells(), 0) << c.File;
  }
}

TEST(SurfaceMeshReader, CanReadFile)
{
  EXPECT_TRUE(vtkSurfaceMeshReader::CanReadFile("a/b/Mesh.OBJ"));
  EXPECT_TRUE(vtkSurfaceMeshReader::CanReadFile("x.vtp"));
  EXPECT_FALSE(vtkSurfaceMeshReader::CanReadFile("x.vtu"));
  EXPECT_FALSE(vtkSurfaceMeshReader::CanReadFile("dir.obj/noext"));
  EXPECT_FALSE(vtkSurfaceMeshReader::CanReadFile(nullptr));
}

namespace
{
// blob.vts: "index x y z" per line.
struct VtsLine
{
  int Index;
  double X, Y, Z;
};

std::vector<VtsLine> blobLandmarks()
{
  std::ifstream in(Data + "/blob.vts");
  std::vector<VtsLine> lines;
  VtsLine l;
  while (in >> l.Index >> l.X >> l.Y >> l.Z)
  {
    lines.push_back(l);
  }
  return lines;
}

// A file in the working directory (the build tree), removed on destruction.
struct ScratchFile
{
  ScratchFile(const std::string& name, const std::string& content)
    : Path("surfacemeshreader_" + std::to_string(getpid()) + "_" + name)
  {
    std::ofstream(this->Path) << content;
  }
  ~ScratchFile() { std::remove(this->Path.c_str()); }
  std::string Path;
};

} // namespace

TEST(SurfaceMeshReader, ObjNormalsBecomeCornerNormals)
{
  // A tetrahedron: faces `v/t/n`, `v//n`, `v/t` and `v` (no normals: NaN).
  const std::string tetrahedron = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nvt 0.25 0.5\n"
                                  "vn 0 0 -1\nvn 0 -1 0\nvn -1 0 0\nvn 0.6 0.8 0\n";
  const ScratchFile file("normals.obj",
    tetrahedron + "f 1/1/1 3/1/1 2/1/1\nf 1//2 2//2 4//4\nf 1/1 4/1 3/1\nf 2 3 4\n");
  const ReadResult r = read(file.Path);
  ASSERT_EQ(r.Error, "");
  ASSERT_EQ(r.Output->GetNumberOfPoints(), 4);
  vtkDataArray* normals = r.Output->GetCellData()->GetArray("CornerNormals");
  ASSERT_NE(normals, nullptr);
  ASSERT_EQ(normals->GetNumberOfComponents(), 9);
  ASSERT_EQ(normals->GetNumberOfTuples(), 4);
  double n[9];
  normals->GetTuple(0, n);
  EXPECT_EQ(std::vector<double>(n, n + 9), std::vector<double>({ 0, 0, -1, 0, 0, -1, 0, 0, -1 }));
  normals->GetTuple(1, n);
  EXPECT_EQ(std::vector<double>(n, n + 9), std::vector<double>({ 0, -1, 0, 0, -1, 0, 0.6, 0.8, 0 }));
  for (vtkIdType face : { 2, 3 })
  {
    normals->GetTuple(face, n);
    for (double c : n)
    {
      EXPECT_TRUE(std::isnan(c)) << "face " << face;
    }
  }
  EXPECT_NE(r.Output->GetCellData()->GetArray("CornerTCoords"), nullptr);

  // Faces that refer to no normal: no array (declared `vn` lines alone do not make one).
  const ScratchFile plain("plain.obj", tetrahedron + "f 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n");
  const ReadResult p = read(plain.Path);
  ASSERT_EQ(p.Error, "");
  EXPECT_EQ(p.Output->GetCellData()->GetArray("CornerNormals"), nullptr);
}

TEST(SurfaceMeshReader, SpotKeepsItsNormalsPerCorner)
{
  // Face 1 of spot.obj is "f 4/4/4 3/5/3 2/6/2": its first corner has vn 4.
  const ReadResult r = read(Data + "/spot.obj");
  vtkDataArray* normals = r.Output->GetCellData()->GetArray("CornerNormals");
  ASSERT_NE(normals, nullptr);
  EXPECT_EQ(normals->GetNumberOfTuples(), 5856);
  std::ifstream in(Data + "/spot.obj");
  std::string line;
  int vn = 0;
  while (std::getline(in, line) && !(line.rfind("vn ", 0) == 0 && ++vn == 4))
  {
  }
  double x, y, z;
  ASSERT_EQ(std::sscanf(line.c_str(), "vn %lf %lf %lf", &x, &y, &z), 3);
  EXPECT_EQ(normals->GetComponent(1, 0), x);
  EXPECT_EQ(normals->GetComponent(1, 1), y);
  EXPECT_EQ(normals->GetComponent(1, 2), z);
}

TEST(SurfaceMeshReader, BadObjNormalsNameFileAndLine)
{
  const ScratchFile line("bad_normal_line.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0\nf 1 2 3\n");
  EXPECT_NE(read(line.Path).Error.find(line.Path + ":4: normal has 2 coordinates"), std::string::npos)
    << read(line.Path).Error;
  const ScratchFile index(
    "bad_normal_index.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//3 3//1\n");
  const ReadResult r = read(index.Path);
  EXPECT_NE(r.Error.find(index.Path + ":5: bad normal index in face corner '2//3'"), std::string::npos)
    << r.Error;
  EXPECT_EQ(r.Output->GetNumberOfPoints(), 0);
}

TEST(SurfaceMeshReader, LandmarkPointsSnapToTheClosestVertex)
{
  const std::vector<VtsLine> blob = blobLandmarks();
  ASSERT_EQ(blob.size(), 4u);
  // Every point 0.001 off its vertex along x (blob's diagonal is about 3.5).
  const double offset = 1e-3;
  std::ostringstream vts, csv, fcsv, json;
  for (std::ostream* s : { &vts, &csv, &fcsv, &json })
  {
    s->precision(17);
  }
  fcsv << "# Markups fiducial file version = 4.11\n# CoordinateSystem = LPS\n"
          "# columns = id,x,y,z,ow,ox,oy,oz,vis,sel,lock,label,desc,associatedNodeID\n";
  json << "{\"@schema\": \"https://raw.githubusercontent.com/slicer/slicer/master/Modules/"
          "Loadable/Markups/Resources/Schema/markups-schema-v1.0.3.json#\",\n \"markups\": [{\n"
          "  \"type\": \"Fiducial\", \"coordinateSystem\": \"LPS\",\n  \"controlPoints\": [\n";
  for (std::size_t k = 0; k < blob.size(); ++k)
  {
    const double x = blob[k].X + offset;
    vts << x << " " << blob[k].Y << " " << blob[k].Z << "\n";
    csv << x << "," << blob[k].Y << "," << blob[k].Z << "\n";
    fcsv << "vtkMRMLMarkupsFiducialNode_" << k << "," << x << "," << blob[k].Y << ","
         << blob[k].Z << ",0,0,0,1,1,1,0,F-" << k + 1 << ",,\n";
    json << (k ? ",\n" : "") << "   {\"id\": \"" << k + 1 << "\", \"label\": \"F-" << k + 1
         << "\", \"position\": [" << x << ", " << blob[k].Y << ", " << blob[k].Z
         << "], \"positionStatus\": \"defined\"}";
  }
  json << "\n  ]\n }]\n}\n";
  const ScratchFile files[] = { { "points.vts", vts.str() },
    { "points.csv", csv.str() },
    { "points.fcsv", fcsv.str() },
    { "points.mrk.json", json.str() } };
  for (const ScratchFile& file : files)
  {
    std::vector<std::string> warnings;
    const ReadResult r = read(Data + "/blob.off", file.Path, &warnings);
    ASSERT_EQ(r.Error, "") << file.Path;
    EXPECT_TRUE(warnings.empty()) << file.Path;
    vtkDataArray* landmarks = r.Output->GetPointData()->GetArray("Landmarks");
    ASSERT_NE(landmarks, nullptr) << file.Path;
    // The JSON's ids are Slicer's "1".."4"; the other files number in file order.
    const int firstId = file.Path.find(".json") != std::string::npos ? 1 : 0;
    for (std::size_t k = 0; k < blob.size(); ++k)
    {
      EXPECT_EQ(landmarks->GetTuple1(blob[k].Index), firstId + static_cast<int>(k)) << file.Path;
    }
    vtkDataArray* distances = r.Output->GetFieldData()->GetArray("LandmarkSnapDistance");
    vtkDataArray* vertices = r.Output->GetFieldData()->GetArray("LandmarkSnapVertex");
    ASSERT_NE(distances, nullptr) << file.Path;
    ASSERT_NE(vertices, nullptr) << file.Path;
    ASSERT_EQ(distances->GetNumberOfTuples(), 4) << file.Path;
    for (std::size_t k = 0; k < blob.size(); ++k)
    {
      EXPECT_NEAR(distances->GetTuple1(k), offset, 1e-6) << file.Path;
      EXPECT_EQ(vertices->GetTuple1(k), blob[k].Index) << file.Path;
    }
  }

  // A point far from the surface still snaps, with a warning naming the file and line.
  std::ostringstream far;
  far.precision(17);
  far << blob[0].X << " " << blob[0].Y << " " << blob[0].Z << "\n"
      << blob[1].X * 1.5 << " " << blob[1].Y << " " << blob[1].Z << "\n";
  const ScratchFile farFile("far.vts", far.str());
  std::vector<std::string> warnings;
  const ReadResult r = read(Data + "/blob.off", farFile.Path, &warnings);
  ASSERT_EQ(r.Error, "");
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find(farFile.Path + ":2: landmark 1 lies"), std::string::npos)
    << warnings[0];
  EXPECT_NE(warnings[0].find("more than 1 %"), std::string::npos) << warnings[0];
  EXPECT_EQ(r.Output->GetFieldData()->GetArray("LandmarkSnapDistance")->GetTuple1(0), 0.0);
}

TEST(SurfaceMeshReader, MalformedMarkupsJsonNamesTheLine)
{
  struct Case
  {
    const char* Text;
    const char* Message;
  };
  for (const Case& c : {
         Case{ "{\"markups\": [{\"controlPoints\": [\n{\"position\": [1, 2]}]}]}", ":2: control point 0 has no \"position\" of three numbers" },
         Case{ "{\"markups\": [{\"controlPoints\": [\n{\"position\": [0,0,0]},\n{\"position\": [1, \"a\", 2]}]}]}", ":3: control point 1 has a position that is not three finite numbers" },
         Case{ "{\"markups\": [{\"controlPoints\": [\n{\"position\": [1,2,3], \"positionStatus\": \"undefined\"}]}]}", ":2: control point 0 has no position (positionStatus \"undefined\")" },
         Case{ "{\"markups\": []}", ":1: not a Slicer markups file" },
         Case{ "{\"markups\": [{\"controlPoints\": []}]}", ": the landmark file lists no landmarks" },
         Case{ "{\n\"markups\": [\n", ":3: not valid JSON" },
         // Slicer ids: one unusable id refuses the file instead of renumbering every point.
         Case{ "{\"markups\": [{\"controlPoints\": [\n{\"id\": \"3\", \"position\": [0,0,0]},\n{\"id\": \"2\", \"position\": [1,0,0]},\n{\"id\": \"99999999999\", \"position\": [0,1,0]}]}]}", ":4: control point 2 has the id '99999999999', which is no landmark id (an integer from 0 to 2147483647)" },
         Case{ "{\"markups\": [{\"controlPoints\": [\n{\"id\": 3, \"position\": [0,0,0]},\n{\"id\": 99999999999, \"position\": [1,0,0]}]}]}", ":3: control point 1 has the id '99999999999', which is no landmark id" },
         Case{ "{\"markups\": [{\"controlPoints\": [\n{\"id\": \"3\", \"position\": [0,0,0]},\n{\"id\": \"vtkMRMLMarkupsFiducialNode_1\", \"position\": [1,0,0]}]}]}", ":3: the id 'vtkMRMLMarkupsFiducialNode_1' is no landmark id (an integer >= 0), but line 2 gives one (3)" },
         Case{ "{\"markups\": [{\"controlPoints\": [\n{\"id\": \"3\", \"position\": [0,0,0]},\n{\"position\": [1,0,0]}]}]}", ":3: this point gives no landmark id, but line 2 gives one (3)" },
         Case{ "{\"markups\": [{\"controlPoints\": [\n{\"id\": true, \"position\": [0,0,0]}]}]}", ":2: control point 0 has an id that is neither a string nor a number" },
       })
  {
    const ScratchFile file("bad.mrk.json", c.Text);
    const ReadResult r = read(Data + "/blob.off", file.Path);
    EXPECT_NE(r.Error.find(file.Path + c.Message), std::string::npos) << c.Text << ": " << r.Error;
    EXPECT_EQ(r.Output->GetNumberOfPoints(), 0);
  }
}

TEST(SurfaceMeshReader, SizingFileBecomesTheSizingArray)
{
  std::ostringstream lengths;
  for (int v = 0; v < 642; ++v)
  {
    lengths << 0.01 * (v + 1) << "\n";
  }
  const ScratchFile good("sizing.txt", lengths.str());
  vtkNew<vtkSurfaceMeshReader> reader;
  reader->SetFileName((Data + "/blob.off").c_str());
  reader->SetSizingFileName(good.Path.c_str());
  reader->Update();
  ASSERT_STREQ(reader->GetLastErrorMessage(), "");
  vtkDataArray* sizing = reader->GetOutput()->GetPointData()->GetArray("Sizing");
  ASSERT_NE(sizing, nullptr);
  EXPECT_EQ(sizing->GetNumberOfTuples(), 642);
  EXPECT_DOUBLE_EQ(sizing->GetTuple1(641), 6.42);

  const ScratchFile shortFile("short.txt", "0.1\n0.2\n");
  vtkNew<vtkCallbackCommand> sink;
  reader->AddObserver(vtkCommand::ErrorEvent, sink);
  reader->SetSizingFileName(shortFile.Path.c_str());
  reader->Update();
  const std::string error = reader->GetLastErrorMessage();
  EXPECT_NE(error.find(shortFile.Path + ":2: the file ends after 2 values, but the mesh has 642"),
    std::string::npos)
    << error;
  EXPECT_NE(error.find("sizing of " + Data + "/blob.off"), std::string::npos) << error;
  EXPECT_EQ(reader->GetOutput()->GetNumberOfPoints(), 0);
}
