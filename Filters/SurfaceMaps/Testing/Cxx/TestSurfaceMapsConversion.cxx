#include "vtkSurfaceMapsConversion.h"

#include "mesh/Primitives.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using namespace surfacemaps;

TEST(SurfaceMapsConversion, PolyDataToHalfedgeMeshAndBack)
{
  const PolygonMesh ico = makeIcosphere(2);
  vtkSmartPointer<vtkPolyData> poly = vtkSurfaceMapsConversion::ToPolyData(ico);
  ASSERT_EQ(poly->GetNumberOfPoints(), 162);
  ASSERT_EQ(poly->GetNumberOfPolys(), 320);

  const HalfedgeMesh mesh = vtkSurfaceMapsConversion::ToHalfedgeMesh(poly);
  EXPECT_EQ(mesh.n_vertices(), 162u);
  EXPECT_EQ(mesh.n_faces(), 320u);

  vtkSmartPointer<vtkPolyData> back = vtkSurfaceMapsConversion::ToPolyData(mesh);
  ASSERT_EQ(back->GetNumberOfPoints(), poly->GetNumberOfPoints());
  ASSERT_EQ(back->GetNumberOfPolys(), poly->GetNumberOfPolys());
  for (vtkIdType i = 0; i < back->GetNumberOfPoints(); ++i)
  {
    double p[3], q[3];
    poly->GetPoint(i, p);
    back->GetPoint(i, q);
    EXPECT_EQ(p[0], q[0]);
    EXPECT_EQ(p[1], q[1]);
    EXPECT_EQ(p[2], q[2]);
  }
  // Same oriented triangles, possibly starting at another corner.
  for (vtkIdType c = 0; c < poly->GetNumberOfPolys(); ++c)
  {
    vtkIdType n1, n2;
    const vtkIdType *a, *b;
    poly->GetPolys()->GetCellAtId(c, n1, a);
    back->GetPolys()->GetCellAtId(c, n2, b);
    ASSERT_EQ(n1, 3);
    ASSERT_EQ(n2, 3);
    int shift = 0;
    while (shift < 3 && b[shift] != a[0])
    {
      ++shift;
    }
    ASSERT_LT(shift, 3) << "cell " << c;
    EXPECT_EQ(b[(shift + 1) % 3], a[1]);
    EXPECT_EQ(b[(shift + 2) % 3], a[2]);
  }
}

TEST(SurfaceMapsConversion, CornerTexCoordsSurviveTheRoundTrip)
{
  PolygonMesh m = makeTetrahedron();
  for (std::size_t i = 0; i < m.faceVertices.size(); ++i)
  {
    m.cornerTexCoords.emplace_back(0.1 * i, 1.0 - 0.05 * i);
  }
  vtkSmartPointer<vtkPolyData> poly = vtkSurfaceMapsConversion::ToPolyData(m);
  vtkDataArray* tc = poly->GetCellData()->GetArray("CornerTCoords");
  ASSERT_NE(tc, nullptr);
  EXPECT_EQ(tc->GetNumberOfComponents(), 6);
  const PolygonMesh back = vtkSurfaceMapsConversion::ToPolygonMesh(poly);
  ASSERT_EQ(back.cornerTexCoords.size(), m.cornerTexCoords.size());
  for (std::size_t i = 0; i < m.cornerTexCoords.size(); ++i)
  {
    EXPECT_EQ(back.cornerTexCoords[i], m.cornerTexCoords[i]);
  }
}

TEST(SurfaceMapsConversion, CornerNormalsSurviveTheRoundTrip)
{
  PolygonMesh m = makeTetrahedron();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (std::size_t i = 0; i < m.faceVertices.size(); ++i)
  {
    m.cornerNormals.push_back(i == 4 ? Eigen::Vector3d(nan, nan, nan)
                                     : Eigen::Vector3d(0.1 * i, -1.0, 0.5 + i));
  }
  vtkSmartPointer<vtkPolyData> poly = vtkSurfaceMapsConversion::ToPolyData(m);
  vtkDataArray* normals = poly->GetCellData()->GetArray("CornerNormals");
  ASSERT_NE(normals, nullptr);
  ASSERT_EQ(normals->GetNumberOfComponents(), 9);
  EXPECT_EQ(poly->GetCellData()->GetArray("CornerTCoords"), nullptr);
  EXPECT_EQ(normals->GetComponent(1, 0), 0.1 * 3); // face 1, corner 0 is corner 3
  EXPECT_TRUE(std::isnan(normals->GetComponent(1, 3))); // corner 4 has none
  EXPECT_EQ(normals->GetComponent(1, 8), 0.5 + 5);      // face 1, corner 2: z of corner 5
  const PolygonMesh back = vtkSurfaceMapsConversion::ToPolygonMesh(poly);
  ASSERT_EQ(back.cornerNormals.size(), m.cornerNormals.size());
  for (std::size_t i = 0; i < m.cornerNormals.size(); ++i)
  {
    EXPECT_TRUE(i == 4 ? back.cornerNormals[i].array().isNaN().all()
                       : back.cornerNormals[i] == m.cornerNormals[i])
      << "corner " << i;
  }
}

TEST(SurfaceMapsConversion, NonPolygonCellsAreCounted)
{
  vtkSmartPointer<vtkPolyData> poly = vtkSurfaceMapsConversion::ToPolyData(makeTetrahedron());
  vtkNew<vtkCellArray> lines;
  const vtkIdType line[2] = { 0, 1 };
  lines->InsertNextCell(2, line);
  poly->SetLines(lines);
  EXPECT_EQ(vtkSurfaceMapsConversion::ToPolygonMesh(poly).nonPolygonCells, 1u);
}

TEST(SurfaceMapsConversion, LandmarkIdsAndInputName)
{
  vtkSmartPointer<vtkPolyData> poly = vtkSurfaceMapsConversion::ToPolyData(makeTetrahedron());
  std::vector<std::string> defects;
  EXPECT_TRUE(vtkSurfaceMapsConversion::LandmarkIds(poly, defects).empty());
  vtkNew<vtkIntArray> ids;
  ids->SetName("Landmarks");
  for (int v : { -1, 2, -1, 0 })
  {
    ids->InsertNextValue(v);
  }
  poly->GetPointData()->AddArray(ids);
  EXPECT_EQ(
    vtkSurfaceMapsConversion::LandmarkIds(poly, defects), (std::vector<int>{ -1, 2, -1, 0 }));
  EXPECT_TRUE(defects.empty());
  EXPECT_EQ(vtkSurfaceMapsConversion::InputName(poly, 3), "input 3");
}
