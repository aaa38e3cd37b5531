#include "vtkSurfaceMeshReader.h"

#include "vtkCallbackCommand.h"
#include "vtkCellData.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkStringArray.h"

#include <gtest/gtest.h>

#include <cstdio>
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

ReadResult read(const std::string& file, const std::string& landmarks = "")
{
  vtkNew<vtkSurfaceMeshReader> reader;
  ReadResult result;
  vtkNew<vtkCallbackCommand> counter;
  counter->SetClientData(&result.ErrorEvents);
  counter->SetCallback(
    [](vtkObject*, unsigned long, void* count, void*) { ++*static_cast<int*>(count); });
  reader->AddObserver(vtkCommand::ErrorEvent, counter);
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
