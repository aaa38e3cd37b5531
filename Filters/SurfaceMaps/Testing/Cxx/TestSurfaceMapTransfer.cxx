// Data carried between the inputs of a map: vtkSurfaceMapFilter's
// MAPPED_INPUT and INPUT_EMBEDDINGS outputs, and vtkSurfaceMapTransfer on them.
#include "FilterTestData.h"
#include "vtkSurfaceMapFilter.h"
#include "vtkSurfaceCheckerboardSource.h"
#include "vtkSurfaceMapTransfer.h"
#include "vtkSurfaceMapsConversion.h"
#include "vtkSurfaceMeshReader.h"
#include "vtkSurfaceTextureSeamSplitter.h"

#include "geometry/SphereLocator.h"
#include "geometry/SphericalTriangulation.h"
#include "map/MapTransfer.h"
#include "mesh/Primitives.h"

#include "vtkCallbackCommand.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkIdList.h"
#include "vtkIdTypeArray.h"
#include "vtkImageData.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkShortArray.h"
#include "vtkStringArray.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <map>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace
{
using filtertest::computedTheMap;
using filtertest::connectivity;
using filtertest::Events;
using filtertest::read;
using filtertest::triangles;
using filtertest::useShortSchedule;
using filtertest::watch;

// An icosphere scaled to an ellipsoid, with a smooth bump around +z.
vtkSmartPointer<vtkPolyData> ellipsoid(int level, double a, double b, double c, double bump = 0.0)
{
  surfacemaps::PolygonMesh mesh = surfacemaps::makeIcosphere(level);
  for (Eigen::Vector3d& p : mesh.points)
  {
    const double r = 1.0 + bump * std::exp(-4.0 * (1.0 - p.z()));
    p = Eigen::Vector3d(a * p.x(), b * p.y(), c * p.z()) * r;
  }
  return vtkSurfaceMapsConversion::ToPolyData(mesh);
}

// Point array `name` = the z coordinate: linear, so interpolation in a
// triangle gives exactly the z of the interpolated point.
void addHeight(vtkPolyData* mesh, const char* name = "Height")
{
  vtkNew<vtkDoubleArray> height;
  height->SetName(name);
  height->SetNumberOfValues(mesh->GetNumberOfPoints());
  for (vtkIdType v = 0; v < mesh->GetNumberOfPoints(); ++v)
  {
    height->SetValue(v, mesh->GetPoint(v)[2]);
  }
  mesh->GetPointData()->AddArray(height);
}

vtkSmartPointer<vtkPolyData> copyOf(vtkPolyData* data)
{
  auto copy = vtkSmartPointer<vtkPolyData>::New();
  copy->ShallowCopy(data);
  return copy;
}

std::vector<Eigen::Vector3d> vectors(vtkPolyData* data, const char* name)
{
  std::vector<Eigen::Vector3d> result;
  vtkDataArray* a = data->GetPointData()->GetArray(name);
  for (vtkIdType v = 0; a && v < a->GetNumberOfTuples(); ++v)
  {
    result.emplace_back(a->GetTuple3(v));
  }
  return result;
}

Eigen::Vector3d point(vtkPolyData* data, vtkIdType v)
{
  return Eigen::Vector3d(data->GetPoint(v));
}

// Where an output point lies on `source` by its SourceCellId and
// SourceBarycentric: the source triangle's corners and the weights.
struct Landing
{
  std::array<int, 3> corners;
  Eigen::Vector3d weights;
  vtkIdType cell;
};

Landing landing(vtkPolyData* output, vtkPolyData* source, vtkIdType v)
{
  vtkDataArray* cells = output->GetPointData()->GetArray("SourceCellId");
  vtkDataArray* weights = output->GetPointData()->GetArray("SourceBarycentric");
  Landing l;
  l.cell = static_cast<vtkIdType>(cells->GetTuple1(v));
  l.weights = Eigen::Vector3d(weights->GetTuple3(v));
  const auto tris = triangles(source);
  l.corners = tris.at(static_cast<std::size_t>(l.cell));
  return l;
}

Eigen::Vector3d combine(const std::vector<Eigen::Vector3d>& values, const Landing& l)
{
  return l.weights[0] * values[l.corners[0]] + l.weights[1] * values[l.corners[1]] +
    l.weights[2] * values[l.corners[2]];
}

std::vector<Eigen::Vector3d> points(vtkPolyData* data)
{
  std::vector<Eigen::Vector3d> result;
  for (vtkIdType v = 0; v < data->GetNumberOfPoints(); ++v)
  {
    result.push_back(point(data, v));
  }
  return result;
}

// Every output point is the point its SourceCellId / SourceBarycentric name
// on `source`, inside that triangle.
void expectOnSource(vtkPolyData* output, vtkPolyData* source)
{
  ASSERT_NE(output->GetPointData()->GetArray("SourceCellId"), nullptr);
  ASSERT_NE(output->GetPointData()->GetArray("SourceBarycentric"), nullptr);
  const std::vector<Eigen::Vector3d> corners = points(source);
  const auto tris = triangles(source);
  vtkDataArray* cells = output->GetPointData()->GetArray("SourceCellId");
  vtkDataArray* weights = output->GetPointData()->GetArray("SourceBarycentric");
  const double tolerance = 1e-9 * source->GetLength();
  for (vtkIdType v = 0; v < output->GetNumberOfPoints(); ++v)
  {
    const auto cell = static_cast<std::size_t>(cells->GetTuple1(v));
    ASSERT_LT(cell, tris.size());
    const Eigen::Vector3d w(weights->GetTuple3(v));
    ASSERT_NEAR(w.sum(), 1.0, 1e-9);
    ASSERT_GE(w.minCoeff(), -1e-9);
    const auto& t = tris[cell];
    const Eigen::Vector3d expected =
      w[0] * corners[t[0]] + w[1] * corners[t[1]] + w[2] * corners[t[2]];
    ASSERT_LT((point(output, v) - expected).norm(), tolerance) << "point " << v;
  }
}

// The sphere map psi = g_to o g_from^-1 at p, by brute force over T's
// triangles (no locator): the triangle containing p on g_from (largest
// smallest barycentric coordinate, on p's side of the sphere), the same
// barycentric coordinates on g_to, normalised.
Eigen::Vector3d sphereMap(const Eigen::Vector3d& p,
  const std::vector<std::array<int, 3>>& T,
  const std::vector<Eigen::Vector3d>& gFrom,
  const std::vector<Eigen::Vector3d>& gTo)
{
  double best = -1.0;
  Eigen::Vector3d result = Eigen::Vector3d::Zero();
  for (const auto& t : T)
  {
    if (p.dot(gFrom[t[0]] + gFrom[t[1]] + gFrom[t[2]]) <= 0.0)
    {
      continue;
    }
    const auto w =
      surfacemaps::SphereLocator::barycentric(p, gFrom[t[0]], gFrom[t[1]], gFrom[t[2]]);
    const double smallest = std::min({ w[0], w[1], w[2] });
    if (smallest > best)
    {
      best = smallest;
      result = (w[0] * gTo[t[0]] + w[1] * gTo[t[1]] + w[2] * gTo[t[2]]).normalized();
    }
  }
  EXPECT_GE(best, -1e-12) << "no triangle of T contains the point";
  return result;
}

// The four inputs of vtkSurfaceMapTransfer for `from` -> `to`.
void connect(vtkSurfaceMapTransfer* transfer,
  vtkPolyData* embeddingTo,
  vtkPolyData* embeddingFrom,
  vtkPolyData* commonTo,
  vtkPolyData* commonFrom)
{
  transfer->SetInputDataObject(0, embeddingTo);
  transfer->SetInputDataObject(1, embeddingFrom);
  transfer->SetInputDataObject(2, commonTo);
  transfer->SetInputDataObject(3, commonFrom);
}

// A computed map of two inputs with every kind of output kept.
struct MapOutputs
{
  std::vector<vtkSmartPointer<vtkPolyData>> inputs, common, embeddings, mapped;
};

MapOutputs computeMap(const std::vector<vtkSmartPointer<vtkPolyData>>& inputs)
{
  MapOutputs m;
  m.inputs = inputs;
  vtkNew<vtkSurfaceMapFilter> filter;
  useShortSchedule(filter);
  Events events;
  watch(filter, events);
  for (const auto& input : inputs)
  {
    filter->AddInputData(input);
  }
  const int n = static_cast<int>(inputs.size());
  filter->Update();
  EXPECT_TRUE(events.Errors.empty()) << events.Errors.front();
  for (int i = 0; i < n; ++i)
  {
    m.common.push_back(copyOf(filter->GetOutput(i)));
  }
  filter->SetOutputModeToInputEmbeddings();
  filter->Update();
  for (int i = 0; i < n; ++i)
  {
    m.embeddings.push_back(copyOf(filter->GetOutput(i)));
  }
  filter->SetOutputModeToMappedFirstInput();
  filter->Update();
  for (int i = 0; i < n; ++i)
  {
    m.mapped.push_back(copyOf(filter->GetOutput(i)));
  }
  EXPECT_TRUE(events.Errors.empty()) << events.Errors.front();
  return m;
}

} // namespace

TEST(SurfaceMapTransfer, MappedInputCarriesAnyInputWithoutRecomputing)
{
  vtkSmartPointer<vtkPolyData> a = ellipsoid(2, 1.0, 0.8, 0.6);
  vtkSmartPointer<vtkPolyData> b = ellipsoid(3, 1.2, 1.0, 0.7, 0.3);
  vtkSmartPointer<vtkPolyData> c = ellipsoid(1, 1.0, 1.0, 0.5, 0.2);
  addHeight(a);
  vtkNew<vtkSurfaceMapFilter> filter;
  useShortSchedule(filter);
  Events events;
  watch(filter, events);
  filter->AddInputData(a);
  filter->AddInputData(b);
  filter->AddInputData(c);
  filter->Update();
  ASSERT_TRUE(events.Errors.empty()) << events.Errors.front();
  ASSERT_TRUE(computedTheMap(events));

  events.Texts.clear();
  filter->SetOutputModeToMappedInput();
  filter->SetMappedInput(1);
  filter->Update();
  ASSERT_TRUE(events.Errors.empty()) << events.Errors.front();
  EXPECT_FALSE(computedTheMap(events)); // the kept map was reused
  vtkSmartPointer<vtkPolyData> inputs[3] = { a, b, c };
  for (int j = 0; j < 3; ++j)
  {
    SCOPED_TRACE("output " + std::to_string(j));
    vtkPolyData* out = filter->GetOutput(j);
    ASSERT_EQ(out->GetNumberOfPoints(), b->GetNumberOfPoints());
    EXPECT_EQ(connectivity(out), connectivity(b));
    expectOnSource(out, inputs[j]);
    vtkDataArray* distortion = out->GetCellData()->GetArray("Distortion");
    ASSERT_NE(distortion, nullptr);
    EXPECT_EQ(distortion->GetNumberOfTuples(), b->GetNumberOfPolys());
    if (j == 1)
    {
      EXPECT_EQ(distortion->GetRange()[0], 1.0);
      EXPECT_EQ(distortion->GetRange()[1], 1.0);
    }
  }
  // Input 1 on itself is input 1, exactly.
  for (vtkIdType v = 0; v < b->GetNumberOfPoints(); ++v)
  {
    ASSERT_EQ(point(filter->GetOutput(1), v), point(b, v));
  }
  // Input 0's arrays are interpolated on output 0 (input 1 on input 0).
  vtkDataArray* height = filter->GetOutput(0)->GetPointData()->GetArray("Height");
  ASSERT_NE(height, nullptr);
  for (vtkIdType v = 0; v < b->GetNumberOfPoints(); ++v)
  {
    ASSERT_NEAR(height->GetTuple1(v), filter->GetOutput(0)->GetPoint(v)[2], 1e-12);
  }
  EXPECT_EQ(filter->GetOutput(1)->GetPointData()->GetArray("Height"), nullptr);

  // A MappedInput beyond the inputs is an error that keeps the map.
  filter->SetMappedInput(3);
  filter->Update();
  ASSERT_EQ(events.Errors.size(), 1u);
  EXPECT_NE(events.Errors[0].find("MappedInput is 3 but there are 3 inputs"), std::string::npos)
    << events.Errors[0];
  EXPECT_EQ(filter->GetErrorCode(), vtkSurfaceMapFilter::InvalidInputError);
  EXPECT_EQ(filter->GetOutput(0)->GetNumberOfPoints(), 0);
  events.Texts.clear();
  filter->SetMappedInput(2);
  filter->Update();
  EXPECT_EQ(events.Errors.size(), 1u);
  EXPECT_FALSE(computedTheMap(events));
  EXPECT_EQ(connectivity(filter->GetOutput(0)), connectivity(c));
  // Mapped first input: input 0 in MAPPED_INPUT mode.
  filter->SetOutputModeToMappedFirstInput();
  EXPECT_EQ(filter->GetMappedInput(), 0);
  EXPECT_EQ(filter->GetOutputMode(), vtkSurfaceMapFilter::MAPPED_INPUT);
}

TEST(SurfaceMapTransfer, InputEmbeddingsAreInTheFrameOfTheCommonTriangulation)
{
  // With landmarks input 1's embedding is rotated onto input 0's: the
  // embedding output must be the rotated one, the frame of T's g_i.
  const MapOutputs m =
    computeMap({ read("ellipsoid.obj", "ellipsoid.pinned"), read("blob.off", "blob.vts") });
  for (int i = 0; i < 2; ++i)
  {
    SCOPED_TRACE("input " + std::to_string(i));
    vtkPolyData* embedding = m.embeddings[i];
    vtkPolyData* input = m.inputs[i];
    ASSERT_EQ(embedding->GetNumberOfPoints(), input->GetNumberOfPoints());
    EXPECT_EQ(points(embedding), points(input));
    EXPECT_EQ(connectivity(embedding), connectivity(input));
    EXPECT_NE(embedding->GetPointData()->GetArray("Landmarks"), nullptr);
    EXPECT_EQ(embedding->GetCellData()->GetArray("Distortion"), nullptr);
    EXPECT_NE(embedding->GetFieldData()->GetArray("Bijective"), nullptr);
    const std::vector<Eigen::Vector3d> f = vectors(embedding, "SpherePosition");
    ASSERT_EQ(f.size(), static_cast<std::size_t>(input->GetNumberOfPoints()));
    for (const Eigen::Vector3d& p : f)
    {
      ASSERT_NEAR(p.norm(), 1.0, 1e-12);
    }
    EXPECT_TRUE(surfacemaps::certifyBijective(f, triangles(embedding)).bijective);
    // T's vertices: g_i is where their source points lie on f_i.
    vtkPolyData* common = m.common[i];
    const std::vector<Eigen::Vector3d> g = vectors(common, "SpherePosition");
    for (vtkIdType v = 0; v < common->GetNumberOfPoints(); ++v)
    {
      const Landing l = landing(common, input, v);
      ASSERT_LT((combine(f, l).normalized() - g[v]).norm(), 1e-9) << "T vertex " << v;
    }
  }
}

// The largest extent, in u or v, of one triangle's texture coordinates.
double textureSpan(const double corners[6])
{
  double span = 0.0;
  for (int d = 0; d < 2; ++d)
  {
    const double lo = std::min({ corners[d], corners[2 + d], corners[4 + d] });
    const double hi = std::max({ corners[d], corners[2 + d], corners[4 + d] });
    span = std::max(span, hi - lo);
  }
  return span;
}

double largestTextureSpan(vtkDataArray* cornerTCoords)
{
  double span = 0.0;
  for (vtkIdType c = 0; c < cornerTCoords->GetNumberOfTuples(); ++c)
  {
    double t[6];
    cornerTCoords->GetTuple(c, t);
    span = std::max(span, textureSpan(t));
  }
  return span;
}

// Per corner, no triangle of `mesh` spans a texture seam, where one value per
// point stretches triangles across spot's atlas. (The meshes here are coarser
// than spot, so their triangles may span more than one of spot's; the bound
// of the issue, the largest span of a source triangle, is checked on a finer
// mesh below.)
void expectNoTriangleSpansASeam(vtkPolyData* mesh, const char* what)
{
  vtkDataArray* corners = mesh->GetCellData()->GetArray("CornerTCoords");
  ASSERT_NE(corners, nullptr) << what;
  ASSERT_EQ(corners->GetNumberOfComponents(), 6) << what;
  ASSERT_EQ(corners->GetNumberOfTuples(), mesh->GetNumberOfPolys()) << what;
  vtkDataArray* perPoint = mesh->GetPointData()->GetTCoords();
  ASSERT_NE(perPoint, nullptr) << what;
  const auto tri = triangles(mesh);
  double perCorner = 0.0, stretched = 0.0;
  int straddlers = 0;
  for (std::size_t t = 0; t < tri.size(); ++t)
  {
    double c[6], p[6];
    corners->GetTuple(static_cast<vtkIdType>(t), c);
    bool samePerPoint = true;
    for (int k = 0; k < 3; ++k)
    {
      p[2 * k] = perPoint->GetComponent(tri[t][k], 0);
      p[2 * k + 1] = perPoint->GetComponent(tri[t][k], 1);
      samePerPoint = samePerPoint && p[2 * k] == c[2 * k] && p[2 * k + 1] == c[2 * k + 1];
    }
    perCorner = std::max(perCorner, textureSpan(c));
    stretched = std::max(stretched, textureSpan(p));
    straddlers += !samePerPoint;
  }
  EXPECT_GT(stretched, 0.5) << what; // across the atlas
  EXPECT_LT(perCorner, 0.2 * stretched) << what;
  EXPECT_GT(straddlers, 0) << what; // only triangles at seams differ
  EXPECT_LT(straddlers, static_cast<int>(tri.size()) / 3) << what;
}

// The test: per-corner texture coordinates transferred through the
// map land where the map says, evaluated in the containing source triangle.
TEST(SurfaceMapTransfer, CornerTexCoordsLandWhereTheMapSays)
{
  vtkSmartPointer<vtkPolyData> spot = read("spot.obj");
  vtkDataArray* cornerTCoords = spot->GetCellData()->GetArray("CornerTCoords");
  ASSERT_NE(cornerTCoords, nullptr);
  ASSERT_EQ(cornerTCoords->GetNumberOfComponents(), 6);
  const MapOutputs m = computeMap({ read("ellipsoid.obj"), spot });
  vtkPolyData* onSpot = m.mapped[1]; // the ellipsoid's vertices carried onto spot
  vtkDataArray* tcoords = onSpot->GetPointData()->GetTCoords();
  ASSERT_NE(tcoords, nullptr);
  EXPECT_STREQ(tcoords->GetName(), "TCoords");
  ASSERT_EQ(tcoords->GetNumberOfComponents(), 2);
  ASSERT_EQ(tcoords->GetNumberOfTuples(), m.inputs[0]->GetNumberOfPoints());
  EXPECT_EQ(m.mapped[0]->GetPointData()->GetTCoords(), nullptr); // the ellipsoid has none
  EXPECT_NE(m.common[1]->GetPointData()->GetTCoords(), nullptr); // T on spot has them too

  // What the map says: f_0, then T from g_0 to g_1 (brute force), on sphere 1.
  const std::vector<Eigen::Vector3d> f0 = vectors(m.embeddings[0], "SpherePosition");
  const std::vector<Eigen::Vector3d> f1 = vectors(m.embeddings[1], "SpherePosition");
  const std::vector<Eigen::Vector3d> g0 = vectors(m.common[0], "SpherePosition");
  const std::vector<Eigen::Vector3d> g1 = vectors(m.common[1], "SpherePosition");
  const auto T = triangles(m.common[0]);
  const std::vector<Eigen::Vector3d> spotPoints = points(spot);
  const double tolerance = 1e-9 * spot->GetLength();
  std::set<double> distinctU;
  for (vtkIdType v = 0; v < onSpot->GetNumberOfPoints(); ++v)
  {
    const Landing l = landing(onSpot, spot, v);
    // The texture coordinates: the landing triangle's corners, interpolated.
    double corners[6];
    cornerTCoords->GetTuple(l.cell, corners);
    for (int d = 0; d < 2; ++d)
    {
      const double expected =
        l.weights[0] * corners[d] + l.weights[1] * corners[2 + d] + l.weights[2] * corners[4 + d];
      ASSERT_NEAR(tcoords->GetComponent(v, d), expected, 1e-12) << "vertex " << v;
    }
    distinctU.insert(tcoords->GetComponent(v, 0));
    // That landing point is the output's point, in 3D ...
    ASSERT_LT((combine(spotPoints, l) - point(onSpot, v)).norm(), tolerance) << "vertex " << v;
    // ... and where the map sends the vertex, on the sphere.
    const Eigen::Vector3d says = sphereMap(f0[v], T, g0, g1);
    ASSERT_LT((combine(f1, l).normalized() - says).norm(), 1e-9) << "vertex " << v;
  }
  EXPECT_GT(distinctU.size(), 100u); // real texture coordinates, not a constant

  // vtkSurfaceMapTransfer from the saved outputs (spot -> ellipsoid) gives the
  // same landing points and texture coordinates, bit for bit.
  vtkNew<vtkSurfaceMapTransfer> transfer;
  connect(transfer, m.embeddings[0], m.embeddings[1], m.common[0], m.common[1]);
  transfer->Update();
  vtkPolyData* out = transfer->GetOutput();
  ASSERT_EQ(out->GetNumberOfPoints(), m.inputs[0]->GetNumberOfPoints());
  EXPECT_EQ(points(out), points(m.inputs[0])); // the target's own points
  vtkDataArray* transferred = out->GetPointData()->GetTCoords();
  ASSERT_NE(transferred, nullptr);
  for (vtkIdType v = 0; v < out->GetNumberOfPoints(); ++v)
  {
    const Landing a = landing(out, spot, v), b = landing(onSpot, spot, v);
    ASSERT_EQ(a.cell, b.cell) << "vertex " << v;
    ASSERT_EQ(a.weights, b.weights) << "vertex " << v;
    ASSERT_EQ(transferred->GetComponent(v, 0), tcoords->GetComponent(v, 0));
    ASSERT_EQ(transferred->GetComponent(v, 1), tcoords->GetComponent(v, 1));
  }

  // Per corner, no output triangle spans a seam: T on spot, the ellipsoid's
  // triangles on spot, and the transfer's output.
  expectNoTriangleSpansASeam(m.common[1], "T on spot");
  expectNoTriangleSpansASeam(onSpot, "the ellipsoid on spot");
  expectNoTriangleSpansASeam(out, "the transfer's output");
  EXPECT_EQ(m.mapped[0]->GetCellData()->GetArray("CornerTCoords"), nullptr);
}

// Spot subdivided once (each triangle into four), its vertices given as
// points of spot whose triangle is chosen arbitrarily among those around them
// (as point location does at seams): every new triangle lies inside one
// triangle of spot, so its corner values are that triangle's, interpolated,
// whichever chart its corners were located in.
TEST(SurfaceMapTransfer, CornerValuesOfASubdivisionAreTheirParentTriangles)
{
  vtkSmartPointer<vtkPolyData> spot = read("spot.obj");
  const std::vector<Eigen::Vector3d> spotPoints = points(spot);
  const auto spotTriangles = triangles(spot);
  vtkDataArray* cornerTCoords = spot->GetCellData()->GetArray("CornerTCoords");
  std::vector<Eigen::Vector2d> values(3 * spotTriangles.size());
  for (std::size_t t = 0; t < spotTriangles.size(); ++t)
  {
    for (int k = 0; k < 3; ++k)
    {
      values[3 * t + k] = Eigen::Vector2d(cornerTCoords->GetComponent(static_cast<vtkIdType>(t), 2 * k),
        cornerTCoords->GetComponent(static_cast<vtkIdType>(t), 2 * k + 1));
    }
  }
  // Vertices: spot's, in the last triangle around each; edge midpoints, in
  // the last triangle along each edge.
  std::vector<surfacemaps::SurfacePoint> located(spotPoints.size());
  std::map<std::pair<int, int>, int> midpoint;
  auto corner = [](int k) { Eigen::Vector3d b = Eigen::Vector3d::Zero(); b[k] = 1.0; return b; };
  for (int t = 0; t < static_cast<int>(spotTriangles.size()); ++t)
  {
    for (int k = 0; k < 3; ++k)
    {
      located[spotTriangles[t][k]] = { t, corner(k) };
      const int a = spotTriangles[t][k], b = spotTriangles[t][(k + 1) % 3];
      const auto key = std::minmax(a, b);
      auto [it, added] = midpoint.emplace(key, static_cast<int>(located.size()));
      if (added)
      {
        located.emplace_back();
      }
      located[it->second] = { t, (corner(k) + corner((k + 1) % 3)) / 2.0 };
    }
  }
  std::vector<std::array<int, 3>> fine;
  std::vector<Eigen::Vector2d> expected;
  for (std::size_t t = 0; t < spotTriangles.size(); ++t)
  {
    const auto& v = spotTriangles[t];
    const Eigen::Vector2d* c = &values[3 * t];
    int m[3];
    Eigen::Vector2d mid[3];
    for (int k = 0; k < 3; ++k)
    {
      m[k] = midpoint.at(std::minmax(v[k], v[(k + 1) % 3]));
      mid[k] = (c[k] + c[(k + 1) % 3]) / 2.0;
    }
    fine.push_back({ v[0], m[0], m[2] });
    fine.push_back({ m[0], v[1], m[1] });
    fine.push_back({ m[2], m[1], v[2] });
    fine.push_back({ m[0], m[1], m[2] });
    for (const Eigen::Vector2d& e : { c[0], mid[0], mid[2], mid[0], c[1], mid[1], mid[2], mid[1],
           c[2], mid[0], mid[1], mid[2] })
    {
      expected.push_back(e);
    }
  }
  const std::vector<Eigen::Vector2d> result =
    surfacemaps::transferCornerValues(spotPoints, spotTriangles, values, fine, located);
  ASSERT_EQ(result.size(), expected.size());
  const double limit = largestTextureSpan(cornerTCoords);
  int exact = 0, perPointDiffers = 0;
  for (std::size_t t = 0; t < fine.size(); ++t)
  {
    double c[6], p[6];
    bool same = true;
    for (int k = 0; k < 3; ++k)
    {
      const Eigen::Vector2d own = surfacemaps::evaluateCornerValues(values, located[fine[t][k]]);
      c[2 * k] = result[3 * t + k].x();
      c[2 * k + 1] = result[3 * t + k].y();
      p[2 * k] = own.x();
      p[2 * k + 1] = own.y();
      same = same && (result[3 * t + k] - expected[3 * t + k]).norm() < 1e-9;
      perPointDiffers += (own - expected[3 * t + k]).norm() > 1e-9;
    }
    EXPECT_LE(textureSpan(c), limit) << "triangle " << t;
    exact += same;
  }
  EXPECT_GT(perPointDiffers, 1000); // the located points' own values break at seams
  // Most get their parent's values exactly; the others are expressed in the
  // chart of a neighbour of the parent (where that stretches them least).
  EXPECT_GE(exact, 0.95 * fine.size());
}

// Splitting spot's seams: every triangle corner's point carries the corner's
// own texture coordinates, each point copies an input point.
TEST(SurfaceMapTransfer, SeamSplitterGivesEveryCornerItsOwnPoint)
{
  vtkSmartPointer<vtkPolyData> spot = read("spot.obj");
  vtkNew<vtkSurfaceTextureSeamSplitter> splitter;
  splitter->SetInputData(spot);
  splitter->Update();
  vtkPolyData* out = splitter->GetOutput();
  ASSERT_EQ(out->GetNumberOfPolys(), spot->GetNumberOfPolys());
  EXPECT_GT(out->GetNumberOfPoints(), spot->GetNumberOfPoints()); // spot has seams
  auto* original = vtkIdTypeArray::SafeDownCast(out->GetPointData()->GetArray("OriginalPointId"));
  ASSERT_NE(original, nullptr);
  vtkDataArray* tcoords = out->GetPointData()->GetTCoords();
  ASSERT_NE(tcoords, nullptr);
  vtkDataArray* corners = spot->GetCellData()->GetArray("CornerTCoords");
  const auto before = triangles(spot), after = triangles(out);
  std::set<std::pair<vtkIdType, std::pair<double, double>>> distinct;
  for (std::size_t t = 0; t < before.size(); ++t)
  {
    double c[6];
    corners->GetTuple(static_cast<vtkIdType>(t), c);
    for (int k = 0; k < 3; ++k)
    {
      const int p = after[t][k];
      ASSERT_EQ(original->GetValue(p), before[t][k]) << "triangle " << t;
      ASSERT_EQ(tcoords->GetComponent(p, 0), c[2 * k]) << "triangle " << t;
      ASSERT_EQ(tcoords->GetComponent(p, 1), c[2 * k + 1]) << "triangle " << t;
      ASSERT_EQ(point(out, p), point(spot, before[t][k]));
      distinct.insert({ before[t][k], { c[2 * k], c[2 * k + 1] } });
    }
  }
  // One point per distinct (vertex, corner value): no more copies than needed.
  EXPECT_EQ(static_cast<std::size_t>(out->GetNumberOfPoints()), distinct.size());
  // Without per-corner coordinates the mesh passes through.
  vtkSmartPointer<vtkPolyData> plain = read("ellipsoid.obj");
  splitter->SetInputData(plain);
  splitter->Update();
  EXPECT_EQ(splitter->GetOutput()->GetNumberOfPoints(), plain->GetNumberOfPoints());
  EXPECT_NE(splitter->GetOutput()->GetPointData()->GetArray("OriginalPointId"), nullptr);
}

TEST(SurfaceMapTransfer, CheckerboardSourceColoursSquaresByPosition)
{
  vtkNew<vtkSurfaceCheckerboardSource> source;
  source->SetSquares(4);
  source->SetSize(64);
  source->Update();
  vtkImageData* image = source->GetOutput();
  int dims[3];
  image->GetDimensions(dims);
  ASSERT_EQ(dims[0], 64);
  ASSERT_EQ(dims[1], 64);
  ASSERT_EQ(dims[2], 1);
  vtkDataArray* colours = image->GetPointData()->GetScalars();
  ASSERT_NE(colours, nullptr);
  ASSERT_EQ(colours->GetNumberOfComponents(), 3);
  ASSERT_EQ(colours->GetDataType(), VTK_UNSIGNED_CHAR);
  // Per square (16 x 16 pixels): one colour throughout; off-white where
  // i + j is odd, otherwise a colour no other square has.
  std::set<std::array<int, 3>> coloured;
  for (int j = 0; j < 4; ++j)
  {
    for (int i = 0; i < 4; ++i)
    {
      double first[3];
      colours->GetTuple(16 * j * 64 + 16 * i, first);
      for (int y = 16 * j; y < 16 * j + 16; ++y)
      {
        for (int x = 16 * i; x < 16 * i + 16; ++x)
        {
          for (int c = 0; c < 3; ++c)
          {
            ASSERT_EQ(colours->GetComponent(y * 64 + x, c), first[c]) << x << ", " << y;
          }
        }
      }
      if ((i + j) % 2 == 1)
      {
        EXPECT_EQ(first[0], 245.0);
        EXPECT_EQ(first[1], 245.0);
        EXPECT_EQ(first[2], 240.0);
      }
      else
      {
        coloured.insert({ static_cast<int>(first[0]), static_cast<int>(first[1]),
          static_cast<int>(first[2]) });
      }
    }
  }
  EXPECT_EQ(coloured.size(), 8u);
  // Brighter up the image (v): the top row's squares outshine the bottom's.
  double bottom[3], top[3];
  colours->GetTuple(0, bottom);
  colours->GetTuple(63 * 64 + 16, top);
  EXPECT_GT(std::max({ top[0], top[1], top[2] }), std::max({ bottom[0], bottom[1], bottom[2] }));
}

TEST(SurfaceMapTransfer, ConnectivityDifferenceNamesTheFirstMismatch)
{
  vtkSmartPointer<vtkPolyData> blob = read("blob.off");
  auto copy = [&]()
  {
    auto mesh = vtkSmartPointer<vtkPolyData>::New();
    mesh->DeepCopy(blob);
    return mesh;
  };
  auto differs = [&](vtkPolyData* mesh)
  { return vtkSurfaceMapTransfer::DescribeConnectivityDifference(mesh, blob, "input 1"); };
  EXPECT_EQ(differs(copy()), "");
  vtkNew<vtkIdList> ids;
  blob->GetCellPoints(5, ids);
  const vtkIdType a = ids->GetId(0), b = ids->GetId(1), c = ids->GetId(2);
  // The same triangle starting at another corner is the same connectivity.
  vtkSmartPointer<vtkPolyData> rotated = copy();
  const vtkIdType bca[3] = { b, c, a };
  rotated->ReplaceCell(5, 3, bca);
  EXPECT_EQ(differs(rotated), "");
  vtkSmartPointer<vtkPolyData> turned = copy();
  const vtkIdType acb[3] = { a, c, b };
  turned->ReplaceCell(5, 3, acb);
  const auto text = [](vtkIdType x, vtkIdType y, vtkIdType z)
  {
    return "(" + std::to_string(x) + ", " + std::to_string(y) + ", " + std::to_string(z) + ")";
  };
  EXPECT_EQ(differs(turned),
    "has triangle 5 as " + text(a, c, b) + ", input 1 has " + text(a, b, c));
  vtkSmartPointer<vtkPolyData> moreVertices = copy();
  moreVertices->GetPoints()->InsertNextPoint(0.0, 0.0, 0.0);
  EXPECT_EQ(differs(moreVertices),
    "has " + std::to_string(blob->GetNumberOfPoints() + 1) + " vertices, input 1 has " +
      std::to_string(blob->GetNumberOfPoints()));
  // One triangle fewer, then a quadrilateral in place of triangle 5 (not a
  // triangle mesh at all): named by the cell counts.
  const vtkIdType n = blob->GetNumberOfPolys();
  auto withCells = [&](vtkIdType count, bool quadrilateral)
  {
    vtkSmartPointer<vtkPolyData> mesh = copy();
    vtkNew<vtkCellArray> polys;
    for (vtkIdType t = 0; t < count; ++t)
    {
      blob->GetCellPoints(t, ids);
      if (quadrilateral && t == 5)
      {
        ids->InsertNextId(0);
      }
      polys->InsertNextCell(ids);
    }
    mesh->SetPolys(polys);
    return mesh;
  };
  EXPECT_EQ(differs(withCells(n - 1, false)),
    "has " + std::to_string(n - 1) + " cells, input 1 has " + std::to_string(n) + " triangles");
  EXPECT_EQ(differs(withCells(n, true)),
    "has " + std::to_string(n) + " cells, input 1 has " + std::to_string(n) + " triangles");
}

TEST(SurfaceMapTransfer, ChosenArraysAreInterpolatedWithTheirRoles)
{
  vtkSmartPointer<vtkPolyData> a = ellipsoid(2, 1.0, 0.8, 0.6);
  vtkSmartPointer<vtkPolyData> b = ellipsoid(2, 1.2, 1.0, 0.7, 0.3);
  addHeight(b);
  b->GetPointData()->SetActiveScalars("Height");
  vtkNew<vtkIntArray> label;
  label->SetName("Label");
  label->SetNumberOfValues(b->GetNumberOfPoints());
  label->Fill(7);
  b->GetPointData()->AddArray(label);
  const MapOutputs m = computeMap({ a, b });

  // Input 1's arrays onto input 0's vertices.
  vtkNew<vtkSurfaceMapTransfer> transfer;
  Events events;
  watch(transfer, events);
  connect(transfer, m.embeddings[0], m.embeddings[1], m.common[0], m.common[1]);
  transfer->Update();
  ASSERT_TRUE(events.Errors.empty()) << events.Errors.front();
  vtkPointData* pd = transfer->GetOutput()->GetPointData();
  ASSERT_NE(pd->GetArray("Height"), nullptr);
  EXPECT_EQ(pd->GetScalars(), pd->GetArray("Height"));
  ASSERT_NE(pd->GetArray("Label"), nullptr);
  EXPECT_EQ(pd->GetArray("Label")->GetRange()[0], 7.0);
  EXPECT_EQ(pd->GetArray("Label")->GetRange()[1], 7.0);
  EXPECT_EQ(pd->GetArray("SpherePosition"), nullptr);
  EXPECT_EQ(pd->GetArray("Landmarks"), nullptr);
  EXPECT_EQ(pd->GetTCoords(), nullptr);
  EXPECT_EQ(pd->GetNumberOfArrays(), 4); // Height, Label, SourceCellId, SourceBarycentric
  // Height is linear: its value is the z of the landing point on input 1,
  // which is where the map filter sends the vertex (mapped_1).
  for (vtkIdType v = 0; v < a->GetNumberOfPoints(); ++v)
  {
    ASSERT_NEAR(pd->GetArray("Height")->GetTuple1(v), m.mapped[1]->GetPoint(v)[2], 1e-12);
  }

  transfer->AddArrayName("Height");
  EXPECT_EQ(transfer->GetNumberOfArrayNames(), 1);
  EXPECT_STREQ(transfer->GetArrayName(0), "Height");
  transfer->Update();
  EXPECT_EQ(pd, transfer->GetOutput()->GetPointData());
  EXPECT_NE(pd->GetArray("Height"), nullptr);
  EXPECT_EQ(pd->GetArray("Label"), nullptr);

  transfer->AddArrayName("Nope");
  transfer->Update();
  ASSERT_EQ(events.Errors.size(), 1u);
  EXPECT_NE(events.Errors[0].find("has no point array 'Nope'"), std::string::npos)
    << events.Errors[0];
  EXPECT_NE(events.Errors[0].find("port 1 (source mesh"), std::string::npos) << events.Errors[0];
  EXPECT_NE(events.Errors[0].find("Height, Label"), std::string::npos) << events.Errors[0];
  EXPECT_EQ(transfer->GetErrorCode(), vtkSurfaceMapTransfer::InvalidInputError);
  EXPECT_EQ(transfer->GetOutput()->GetNumberOfPoints(), 0);
  transfer->RemoveAllArrayNames();
  EXPECT_EQ(transfer->GetNumberOfArrayNames(), 0);

  // From an input to itself: the identity, the source's values exactly.
  events.Errors.clear();
  connect(transfer, m.embeddings[1], m.embeddings[1], m.common[1], m.common[1]);
  transfer->Update();
  ASSERT_TRUE(events.Errors.empty()) << events.Errors.front();
  vtkDataArray* same = transfer->GetOutput()->GetPointData()->GetArray("Height");
  ASSERT_NE(same, nullptr);
  for (vtkIdType v = 0; v < b->GetNumberOfPoints(); ++v)
  {
    ASSERT_EQ(same->GetTuple1(v), b->GetPoint(v)[2]);
  }
}

TEST(SurfaceMapTransfer, BadInputsNameThePortAndTheDefect)
{
  const MapOutputs m =
    computeMap({ ellipsoid(2, 1.0, 0.8, 0.6), ellipsoid(1, 1.2, 1.0, 0.7, 0.3) });
  auto named = [](vtkPolyData* data, const char* file)
  {
    vtkSmartPointer<vtkPolyData> copy = copyOf(data);
    vtkNew<vtkFieldData> fields;
    vtkNew<vtkStringArray> name;
    name->SetName("FileName");
    name->InsertNextValue(file);
    fields->AddArray(name);
    copy->SetFieldData(fields);
    return copy;
  };
  auto expectError = [&](vtkPolyData* to,
                       vtkPolyData* from,
                       vtkPolyData* commonTo,
                       vtkPolyData* commonFrom,
                       const std::vector<std::string>& parts)
  {
    vtkNew<vtkSurfaceMapTransfer> transfer;
    Events events;
    watch(transfer, events);
    connect(transfer, to, from, commonTo, commonFrom);
    transfer->Update();
    ASSERT_EQ(events.Errors.size(), 1u);
    for (const std::string& part : parts)
    {
      EXPECT_NE(events.Errors[0].find(part), std::string::npos) << events.Errors[0];
    }
    EXPECT_EQ(transfer->GetErrorCode(), vtkSurfaceMapTransfer::InvalidInputError);
    EXPECT_EQ(transfer->GetOutput()->GetNumberOfPoints(), 0);
  };

  // No embedding on the source.
  vtkSmartPointer<vtkPolyData> bare = named(m.embeddings[1], "embedding_1.vtp");
  bare->GetPointData()->RemoveArray("SpherePosition");
  expectError(m.embeddings[0],
    bare,
    m.common[0],
    m.common[1],
    { "port 1 (source mesh, embedding_1.vtp)", "has no SpherePosition point array" });

  // Not unit vectors on the target.
  vtkSmartPointer<vtkPolyData> scaled = copyOf(m.embeddings[0]);
  vtkNew<vtkDoubleArray> doubled;
  doubled->DeepCopy(m.embeddings[0]->GetPointData()->GetArray("SpherePosition"));
  doubled->SetTuple3(5,
    2.0 * doubled->GetComponent(5, 0),
    2.0 * doubled->GetComponent(5, 1),
    2.0 * doubled->GetComponent(5, 2));
  scaled->GetPointData()->AddArray(doubled);
  expectError(scaled,
    m.embeddings[1],
    m.common[0],
    m.common[1],
    { "port 0 (target mesh)", "not a unit vector at point 5 (length 2" });

  // T's embedding on the source folded: two vertices swapped.
  vtkSmartPointer<vtkPolyData> folded = named(m.common[1], "common_1.vtp");
  vtkNew<vtkDoubleArray> swapped;
  swapped->DeepCopy(m.common[1]->GetPointData()->GetArray("SpherePosition"));
  double p0[3], p1[3];
  swapped->GetTuple(0, p0);
  swapped->GetTuple(1, p1);
  swapped->SetTuple(0, p1);
  swapped->SetTuple(1, p0);
  folded->GetPointData()->AddArray(swapped);
  expectError(m.embeddings[0],
    m.embeddings[1],
    m.common[0],
    folded,
    { "port 3 (common triangulation on the source, common_1.vtp)",
      "is not a bijective embedding",
      "not positively oriented" });

  // Port 3 is not T: the source mesh itself.
  expectError(m.embeddings[0],
    m.embeddings[1],
    m.common[0],
    m.embeddings[1],
    { "port 2 (common triangulation on the target)",
      "port 3",
      "do not hold the same common triangulation" });
}

TEST(SurfaceMapTransfer, PrintSelfListsTheArrayNames)
{
  vtkNew<vtkSurfaceMapTransfer> transfer;
  std::ostringstream all;
  transfer->Print(all);
  EXPECT_NE(all.str().find("ArrayNames: (all)"), std::string::npos);
  transfer->AddArrayName("Height");
  transfer->AddArrayName("Label");
  std::ostringstream some;
  transfer->Print(some);
  EXPECT_NE(some.str().find("ArrayNames: Height Label"), std::string::npos);
  EXPECT_EQ(transfer->GetArrayName(2), nullptr);
}

namespace
{
// Point array `name` of type ArrayT, value(v) per vertex.
template<typename ArrayT, typename F>
void addPointArray(vtkPolyData* mesh, const char* name, F value)
{
  vtkNew<ArrayT> array;
  array->SetName(name);
  array->SetNumberOfValues(mesh->GetNumberOfPoints());
  for (vtkIdType v = 0; v < mesh->GetNumberOfPoints(); ++v)
  {
    array->SetValue(v, value(v));
  }
  mesh->GetPointData()->AddArray(array);
}

std::set<double> valuesOf(vtkDataArray* array)
{
  std::set<double> values;
  for (vtkIdType v = 0; v < array->GetNumberOfTuples(); ++v)
  {
    values.insert(array->GetTuple1(v));
  }
  return values;
}

// Every value of `name` on `output` is the value of `source`'s array at the
// corner of the landing triangle (SourceCellId) with the largest
// barycentric coordinate (SourceBarycentric): in particular a source value.
void expectNearestCornerValues(vtkPolyData* output, vtkPolyData* source, const char* name)
{
  vtkDataArray* got = output->GetPointData()->GetArray(name);
  vtkDataArray* own = source->GetPointData()->GetArray(name);
  ASSERT_NE(got, nullptr) << name;
  ASSERT_NE(own, nullptr) << name;
  EXPECT_EQ(got->GetDataType(), own->GetDataType());
  const std::set<double> present = valuesOf(own);
  for (vtkIdType v = 0; v < output->GetNumberOfPoints(); ++v)
  {
    const Landing l = landing(output, source, v);
    int corner = 0;
    for (int k = 1; k < 3; ++k)
    {
      corner = l.weights[k] > l.weights[corner] ? k : corner;
    }
    ASSERT_TRUE(present.count(got->GetTuple1(v)))
      << name << " at " << v << ": " << got->GetTuple1(v);
    ASSERT_EQ(got->GetTuple1(v), own->GetTuple1(l.corners[corner])) << name << " at " << v;
  }
}

// Number of connected regions of equal value of `array` over the edges of `mesh`.
int regionCount(vtkPolyData* mesh, vtkDataArray* array)
{
  const vtkIdType n = mesh->GetNumberOfPoints();
  std::vector<vtkIdType> parent(n);
  for (vtkIdType v = 0; v < n; ++v)
  {
    parent[v] = v;
  }
  std::function<vtkIdType(vtkIdType)> root = [&](vtkIdType v)
  { return parent[v] == v ? v : parent[v] = root(parent[v]); };
  for (const auto& t : triangles(mesh))
  {
    for (int k = 0; k < 3; ++k)
    {
      const int a = t[k], b = t[(k + 1) % 3];
      if (array->GetTuple1(a) == array->GetTuple1(b))
      {
        parent[root(a)] = root(b);
      }
    }
  }
  int regions = 0;
  for (vtkIdType v = 0; v < n; ++v)
  {
    regions += root(v) == v ? 1 : 0;
  }
  return regions;
}

// Contiguous regions: every vertex takes the label of the nearest of `seeds`
// along the edges (breadth first), so each region is connected.
std::vector<int> seededRegions(vtkPolyData* mesh, const std::vector<vtkIdType>& seeds)
{
  const vtkIdType n = mesh->GetNumberOfPoints();
  std::vector<std::vector<int>> neighbours(n);
  for (const auto& t : triangles(mesh))
  {
    for (int k = 0; k < 3; ++k)
    {
      neighbours[t[k]].push_back(t[(k + 1) % 3]);
      neighbours[t[(k + 1) % 3]].push_back(t[k]);
    }
  }
  std::vector<int> label(n, -1);
  std::vector<vtkIdType> queue;
  for (std::size_t s = 0; s < seeds.size(); ++s)
  {
    label[seeds[s]] = 10 * static_cast<int>(s) + 1;
    queue.push_back(seeds[s]);
  }
  for (std::size_t q = 0; q < queue.size(); ++q)
  {
    for (int w : neighbours[queue[q]])
    {
      if (label[w] < 0)
      {
        label[w] = label[queue[q]];
        queue.push_back(w);
      }
    }
  }
  return label;
}

// The Data pair with landmarks, `arrays` adds point arrays to each input.
template<typename F>
std::vector<vtkSmartPointer<vtkPolyData>> dataPair(F arrays)
{
  std::vector<vtkSmartPointer<vtkPolyData>> inputs = { read("ellipsoid.obj", "ellipsoid.pinned"),
    read("blob.off", "blob.vts") };
  for (std::size_t i = 0; i < inputs.size(); ++i)
  {
    arrays(inputs[i], static_cast<int>(i));
  }
  return inputs;
}
} // namespace

// The test: random integer labels never come out as a value the
// source does not have, through the map filter's outputs (T on each input,
// input 0 mapped onto each input) and through the transfer filter.
TEST(SurfaceMapTransfer, CategoricalLabelsAreNeverInvented)
{
  const int palette[] = { -5, 3, 17, 42, 1000 };
  const MapOutputs m = computeMap(dataPair(
    [&palette](vtkPolyData* mesh, int i)
    {
      std::mt19937 random(19 + i);
      std::uniform_int_distribution<int> pick(0, 4);
      addPointArray<vtkIntArray>(mesh, "Label", [&](vtkIdType) { return palette[pick(random)]; });
      addPointArray<vtkShortArray>(
        mesh, "Small", [&](vtkIdType) { return static_cast<short>(pick(random)); });
    }));
  for (int i = 0; i < 2; ++i)
  {
    SCOPED_TRACE("input " + std::to_string(i));
    for (const char* name : { "Label", "Small" })
    {
      expectNearestCornerValues(m.common[i], m.inputs[i], name);
      expectNearestCornerValues(m.mapped[i], m.inputs[i], name);
    }
  }
  // Not a lucky draw: the vertices of input 0 land inside triangles of input
  // 1, where interpolation would mix labels.
  int inside = 0;
  for (vtkIdType v = 0; v < m.mapped[1]->GetNumberOfPoints(); ++v)
  {
    inside += landing(m.mapped[1], m.inputs[1], v).weights.maxCoeff() < 0.9 ? 1 : 0;
  }
  EXPECT_GT(inside, 100);

  for (int from = 0; from < 2; ++from)
  {
    const int to = 1 - from;
    vtkNew<vtkSurfaceMapTransfer> transfer;
    Events events;
    watch(transfer, events);
    connect(transfer, m.embeddings[to], m.embeddings[from], m.common[to], m.common[from]);
    transfer->Update();
    ASSERT_TRUE(events.Errors.empty()) << events.Errors.front();
    SCOPED_TRACE("transfer " + std::to_string(from) + " -> " + std::to_string(to));
    expectNearestCornerValues(transfer->GetOutput(), m.inputs[from], "Label");
    expectNearestCornerValues(transfer->GetOutput(), m.inputs[from], "Small");
  }
}

// A label field of a few contiguous regions stays that many regions on the
// other surface, through the transfer filter and the mapped outputs.
TEST(SurfaceMapTransfer, ContiguousLabelRegionsKeepTheirCount)
{
  const std::vector<vtkIdType> seeds = { 0, 130, 260, 390, 520 };
  const MapOutputs m = computeMap(dataPair(
    [&seeds](vtkPolyData* mesh, int)
    {
      const std::vector<int> labels = seededRegions(mesh, seeds);
      addPointArray<vtkIntArray>(mesh, "Region", [&labels](vtkIdType v) { return labels[v]; });
    }));
  for (int i = 0; i < 2; ++i)
  {
    vtkDataArray* own = m.inputs[i]->GetPointData()->GetArray("Region");
    ASSERT_EQ(regionCount(m.inputs[i], own), 5); // the premise: five connected regions
    ASSERT_EQ(valuesOf(own).size(), 5u);
  }
  // Input 1's regions on input 0's mesh (mapped_1), and input 0's on input 1's.
  vtkDataArray* onMapped = m.mapped[1]->GetPointData()->GetArray("Region");
  ASSERT_NE(onMapped, nullptr);
  EXPECT_EQ(valuesOf(onMapped), valuesOf(m.inputs[1]->GetPointData()->GetArray("Region")));
  EXPECT_EQ(regionCount(m.mapped[1], onMapped), 5);

  vtkNew<vtkSurfaceMapTransfer> transfer;
  connect(transfer, m.embeddings[1], m.embeddings[0], m.common[1], m.common[0]);
  transfer->Update();
  vtkDataArray* onTarget = transfer->GetOutput()->GetPointData()->GetArray("Region");
  ASSERT_NE(onTarget, nullptr);
  EXPECT_EQ(valuesOf(onTarget), valuesOf(m.inputs[0]->GetPointData()->GetArray("Region")));
  EXPECT_EQ(regionCount(transfer->GetOutput(), onTarget), 5);

  // Interpolated instead, the same field gets values between the regions'.
  transfer->SetArrayTransferModeToContinuous("Region");
  transfer->Update();
  onTarget = transfer->GetOutput()->GetPointData()->GetArray("Region");
  EXPECT_GT(valuesOf(onTarget).size(), 5u);
}

// The per-array choice both ways, on the map filter (without recomputing the
// map) and on the transfer filter: a float array chosen categorical keeps to
// the source's values, an int array chosen continuous is interpolated.
TEST(SurfaceMapTransfer, ArrayTransferModesOverrideTheType)
{
  auto inputs = dataPair(
    [](vtkPolyData* mesh, int i)
    {
      std::mt19937 random(7 + i);
      std::uniform_int_distribution<int> coin(0, 1);
      addPointArray<vtkFloatArray>(mesh, "Mask", [&](vtkIdType) { return coin(random) * 1.0f; });
      addPointArray<vtkIntArray>(mesh, "Percent", [&](vtkIdType) { return 100 * coin(random); });
    });
  vtkNew<vtkSurfaceMapFilter> filter;
  useShortSchedule(filter);
  Events events;
  watch(filter, events);
  filter->AddInputData(inputs[0]);
  filter->AddInputData(inputs[1]);
  filter->SetOutputModeToMappedFirstInput();
  filter->Update();
  ASSERT_TRUE(events.Errors.empty()) << events.Errors.front();
  auto values = [&filter](const char* name)
  {
    vtkDataArray* array = filter->GetOutput(1)->GetPointData()->GetArray(name);
    EXPECT_NE(array, nullptr) << name;
    return array ? valuesOf(array) : std::set<double>();
  };
  const std::set<double> twoValues = { 0.0, 1.0 }, twoPercents = { 0.0, 100.0 };
  // By type: the float mask blends, the int percentages do not.
  EXPECT_GT(values("Mask").size(), 2u);
  EXPECT_EQ(values("Percent"), twoPercents);

  events.Texts.clear();
  filter->SetArrayTransferModeToCategorical("Mask");
  filter->SetArrayTransferMode("Percent", vtkSurfaceMapFilter::ARRAY_TRANSFER_CONTINUOUS);
  filter->Update();
  ASSERT_TRUE(events.Errors.empty()) << events.Errors.front();
  EXPECT_FALSE(computedTheMap(events)); // only the outputs changed
  EXPECT_EQ(values("Mask"), twoValues);
  EXPECT_EQ(filter->GetOutput(1)->GetPointData()->GetArray("Mask")->GetDataType(), VTK_FLOAT);
  const std::set<double> percents = values("Percent");
  EXPECT_GT(percents.size(), 2u);
  for (double p : percents)
  {
    ASSERT_EQ(p, std::round(p)); // integers stay integers
    ASSERT_TRUE(p >= 0.0 && p <= 100.0) << p;
  }

  // Back to the types.
  filter->ClearArrayTransferModes();
  EXPECT_EQ(filter->GetNumberOfArrayTransferModes(), 0);
  filter->Update();
  EXPECT_GT(values("Mask").size(), 2u);
  EXPECT_EQ(values("Percent"), twoPercents);

  // The transfer filter, input 1 onto input 0.
  const MapOutputs m = computeMap(inputs);
  vtkNew<vtkSurfaceMapTransfer> transfer;
  connect(transfer, m.embeddings[0], m.embeddings[1], m.common[0], m.common[1]);
  transfer->SetArrayTransferModeToCategorical("Mask");
  transfer->SetArrayTransferModeToContinuous("Percent");
  transfer->Update();
  vtkPointData* pd = transfer->GetOutput()->GetPointData();
  ASSERT_NE(pd->GetArray("Mask"), nullptr);
  expectNearestCornerValues(transfer->GetOutput(), m.inputs[1], "Mask");
  ASSERT_NE(pd->GetArray("Percent"), nullptr);
  EXPECT_GT(valuesOf(pd->GetArray("Percent")).size(), 2u);
}

TEST(SurfaceMapTransfer, ArrayTransferModeSettings)
{
  vtkNew<vtkSurfaceMapTransfer> transfer;
  Events events;
  watch(transfer, events);
  EXPECT_EQ(transfer->GetArrayTransferMode("Label"), vtkSurfaceMapTransfer::ARRAY_TRANSFER_BY_TYPE);
  const vtkMTimeType before = transfer->GetMTime();
  transfer->SetArrayTransferMode("Label", vtkSurfaceMapTransfer::ARRAY_TRANSFER_BY_TYPE);
  EXPECT_EQ(transfer->GetMTime(), before); // nothing changed
  transfer->SetArrayTransferModeToContinuous("Label");
  transfer->SetArrayTransferModeToCategorical("Height");
  EXPECT_GT(transfer->GetMTime(), before);
  EXPECT_EQ(transfer->GetNumberOfArrayTransferModes(), 2);
  EXPECT_STREQ(transfer->GetArrayTransferModeArrayName(0), "Height"); // name order
  EXPECT_STREQ(transfer->GetArrayTransferModeArrayName(1), "Label");
  EXPECT_EQ(transfer->GetArrayTransferModeArrayName(2), nullptr);
  EXPECT_EQ(
    transfer->GetArrayTransferMode("Label"), vtkSurfaceMapTransfer::ARRAY_TRANSFER_CONTINUOUS);

  // The rule: the choice, else the type; strings are always categorical.
  vtkNew<vtkIntArray> label;
  label->SetName("Label");
  vtkNew<vtkIntArray> other;
  other->SetName("Other");
  vtkNew<vtkDoubleArray> height;
  height->SetName("Height");
  vtkNew<vtkDoubleArray> depth;
  depth->SetName("Depth");
  vtkNew<vtkStringArray> names;
  names->SetName("Names");
  EXPECT_EQ(
    transfer->ResolveArrayTransferMode(label), vtkSurfaceMapTransfer::ARRAY_TRANSFER_CONTINUOUS);
  EXPECT_EQ(
    transfer->ResolveArrayTransferMode(other), vtkSurfaceMapTransfer::ARRAY_TRANSFER_CATEGORICAL);
  EXPECT_EQ(
    transfer->ResolveArrayTransferMode(height), vtkSurfaceMapTransfer::ARRAY_TRANSFER_CATEGORICAL);
  EXPECT_EQ(
    transfer->ResolveArrayTransferMode(depth), vtkSurfaceMapTransfer::ARRAY_TRANSFER_CONTINUOUS);
  transfer->SetArrayTransferModeToContinuous("Names");
  EXPECT_EQ(
    transfer->ResolveArrayTransferMode(names), vtkSurfaceMapTransfer::ARRAY_TRANSFER_CATEGORICAL);

  std::ostringstream print;
  transfer->Print(print);
  EXPECT_NE(print.str().find(
              "ArrayTransferModes: Height: categorical; Label: continuous; Names: continuous;"),
    std::string::npos)
    << print.str();

  // Bad modes and names are errors that change nothing; BY_TYPE removes a choice.
  transfer->SetArrayTransferMode("Label", 3);
  transfer->SetArrayTransferMode(nullptr, 1);
  EXPECT_EQ(events.Errors.size(), 2u);
  EXPECT_EQ(
    transfer->GetArrayTransferMode("Label"), vtkSurfaceMapTransfer::ARRAY_TRANSFER_CONTINUOUS);
  transfer->SetArrayTransferMode("Label", vtkSurfaceMapTransfer::ARRAY_TRANSFER_BY_TYPE);
  EXPECT_EQ(transfer->GetNumberOfArrayTransferModes(), 2);
  transfer->ClearArrayTransferModes();
  EXPECT_EQ(transfer->GetNumberOfArrayTransferModes(), 0);
  EXPECT_EQ(
    transfer->ResolveArrayTransferMode(label), vtkSurfaceMapTransfer::ARRAY_TRANSFER_CATEGORICAL);
}
