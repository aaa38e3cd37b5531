#include "FilterTestData.h"
#include "vtkSphereEmbeddingFilter.h"
#include "vtkSurfaceMapEvaluation.h"
#include "vtkSurfaceMapFilter.h"
#include "vtkSurfaceMapsConversion.h"
#include "vtkSurfaceMeshReader.h"

#include "base/ThreadCount.h"
#include "geometry/SphericalTriangulation.h"
#include "mesh/Primitives.h"

#include "vtkAlgorithmOutput.h"
#include "vtkCallbackCommand.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkStringArray.h"
#include "vtkTrivialProducer.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
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

const std::string Data = SURFACEMAPS_DATA_DIR;

// An icosphere scaled to an ellipsoid with semi-axes a, b, c, with a smooth
// radial bump of the given height around +z.
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

// Landmarks 0..3 at the vertices with largest x, smallest x, largest y and
// largest z: corresponding points on similar shapes.
void addExtremeLandmarks(vtkPolyData* mesh)
{
  vtkNew<vtkIntArray> ids;
  ids->SetName("Landmarks");
  ids->SetNumberOfValues(mesh->GetNumberOfPoints());
  ids->Fill(-1);
  const int axes[4] = { 0, 0, 1, 2 };
  const double signs[4] = { 1, -1, 1, 1 };
  for (int k = 0; k < 4; ++k)
  {
    vtkIdType best = 0;
    for (vtkIdType v = 0; v < mesh->GetNumberOfPoints(); ++v)
    {
      if (signs[k] * mesh->GetPoint(v)[axes[k]] > signs[k] * mesh->GetPoint(best)[axes[k]])
      {
        best = v;
      }
    }
    ids->SetValue(best, k);
  }
  mesh->GetPointData()->AddArray(ids);
}

// Short schedules: small meshes, a few iterations per phase.
double fieldValue(vtkPolyData* data, const char* name, vtkIdType k = 0)
{
  vtkDataArray* a = data->GetFieldData()->GetArray(name);
  return a && k < a->GetNumberOfTuples() ? a->GetTuple1(k) : std::nan("");
}

// Every output point equals the barycentric combination its SourceCellId and
// SourceBarycentric name on `source`.
void expectOnSource(vtkPolyData* output, vtkPolyData* source)
{
  vtkDataArray* cells = output->GetPointData()->GetArray("SourceCellId");
  vtkDataArray* weights = output->GetPointData()->GetArray("SourceBarycentric");
  ASSERT_NE(cells, nullptr);
  ASSERT_NE(weights, nullptr);
  ASSERT_EQ(weights->GetNumberOfComponents(), 3);
  const double tolerance = 1e-9 * source->GetLength();
  for (vtkIdType v = 0; v < output->GetNumberOfPoints(); ++v)
  {
    const vtkIdType cell = static_cast<vtkIdType>(cells->GetTuple1(v));
    ASSERT_GE(cell, 0);
    ASSERT_LT(cell, source->GetNumberOfPolys());
    vtkIdType n;
    const vtkIdType* corners;
    source->GetPolys()->GetCellAtId(cell, n, corners);
    ASSERT_EQ(n, 3);
    const double* w = weights->GetTuple3(v);
    EXPECT_NEAR(w[0] + w[1] + w[2], 1.0, 1e-9);
    double expected[3] = { 0, 0, 0 };
    for (int k = 0; k < 3; ++k)
    {
      EXPECT_GE(w[k], -1e-9);
      const double* c = source->GetPoint(corners[k]);
      for (int d = 0; d < 3; ++d)
      {
        expected[d] += w[k] * c[d];
      }
    }
    const double* p = output->GetPoint(v);
    ASSERT_NEAR(p[0], expected[0], tolerance) << "point " << v;
    ASSERT_NEAR(p[1], expected[1], tolerance) << "point " << v;
    ASSERT_NEAR(p[2], expected[2], tolerance) << "point " << v;
  }
}

// The area-weighted mean of "Distortion" is the map's symmetric Dirichlet
// energy as vtkSurfaceMapEvaluation measures it.
void expectDistortionMatchesEvaluation(vtkPolyData* first, vtkPolyData* other)
{
  vtkNew<vtkSurfaceMapEvaluation> evaluation;
  evaluation->SetInputDataObject(0, first);
  evaluation->SetInputDataObject(1, other);
  evaluation->Update();
  vtkDataArray* areaP = evaluation->GetOutput()->GetCellData()->GetArray("AreaSource");
  vtkDataArray* areaQ = evaluation->GetOutput()->GetCellData()->GetArray("AreaTarget");
  vtkDataArray* distortion = other->GetCellData()->GetArray("Distortion");
  ASSERT_NE(distortion, nullptr);
  ASSERT_EQ(distortion->GetNumberOfTuples(), other->GetNumberOfPolys());
  double sum = 0.0;
  for (vtkIdType t = 0; t < distortion->GetNumberOfTuples(); ++t)
  {
    EXPECT_GE(distortion->GetTuple1(t), 1.0 - 1e-9);
    sum += distortion->GetTuple1(t) * 0.5 * (areaP->GetTuple1(t) + areaQ->GetTuple1(t));
  }
  EXPECT_NEAR(sum, evaluation->GetSummaryValue("SymmetricDirichlet"), 1e-9 * sum);
}

} // namespace

TEST(SurfaceMapFilter, OutputPortsFollowTheConnections)
{
  vtkNew<vtkSurfaceMapFilter> filter;
  EXPECT_EQ(filter->GetNumberOfOutputPorts(), 1);
  vtkNew<vtkTrivialProducer> a, b, c;
  a->SetOutput(ellipsoid(1, 1, 1, 1));
  b->SetOutput(ellipsoid(1, 1, 2, 1));
  c->SetOutput(ellipsoid(1, 2, 1, 1));

  filter->AddInputConnection(a->GetOutputPort());
  EXPECT_EQ(filter->GetNumberOfOutputPorts(), 1);
  filter->AddInputConnection(0, b->GetOutputPort());
  EXPECT_EQ(filter->GetNumberOfOutputPorts(), 2);
  EXPECT_NE(filter->GetOutputPort(1), nullptr);
  filter->AddInputData(ellipsoid(1, 1, 1, 2));
  EXPECT_EQ(filter->GetNumberOfOutputPorts(), 3);
  ASSERT_NE(filter->GetOutputPort(2), nullptr);
  EXPECT_EQ(filter->GetOutputPort(2)->GetIndex(), 2);
  filter->AddInputConnection(c->GetOutputPort());
  EXPECT_EQ(filter->GetNumberOfOutputPorts(), 4);

  filter->RemoveInputConnection(0, b->GetOutputPort());
  EXPECT_EQ(filter->GetNumberOfOutputPorts(), 3);
  filter->RemoveInputConnection(0, 0);
  EXPECT_EQ(filter->GetNumberOfOutputPorts(), 2);
  filter->SetInputConnection(c->GetOutputPort());
  EXPECT_EQ(filter->GetNumberOfOutputPorts(), 1);
  filter->RemoveAllInputConnections(0);
  EXPECT_EQ(filter->GetNumberOfOutputPorts(), 1); // never fewer than one
  EXPECT_EQ(filter->GetNumberOfInputConnections(0), 0);
  filter->SetInputData(ellipsoid(1, 1, 1, 1));
  filter->AddInputData(ellipsoid(1, 1, 1, 1));
  EXPECT_EQ(filter->GetNumberOfOutputPorts(), 2);
  filter->RemoveAllInputs();
  EXPECT_EQ(filter->GetNumberOfOutputPorts(), 1);
}

// One map of three inputs through a pipeline, computed once and checked by
// the tests below, one behaviour each.
class ThreeInputPipeline : public ::testing::Test
{
protected:
  static void SetUpTestSuite()
  {
    Inputs[0] = read("ellipsoid_coarse.stl");
    Inputs[1] = ellipsoid(2, 1.2, 1.0, 0.7);
    Inputs[2] = ellipsoid(2, 1.0, 0.9, 0.6, 0.3);
    // A point array that is a linear function of position: interpolated at
    // the lifted points it must equal their coordinate.
    vtkNew<vtkDoubleArray> height;
    height->SetName("Height");
    for (vtkIdType v = 0; v < Inputs[1]->GetNumberOfPoints(); ++v)
    {
      height->InsertNextValue(Inputs[1]->GetPoint(v)[2]);
    }
    Inputs[1]->GetPointData()->AddArray(height);
    for (auto& input : Inputs)
    {
      addExtremeLandmarks(input);
    }
    Filter = vtkSmartPointer<vtkSurfaceMapFilter>::New();
    useShortSchedule(Filter);
    watch(Filter, Log);
    // Downstream consumers connected to every output port before any update.
    for (int i = 0; i < 3; ++i)
    {
      Producers[i] = vtkSmartPointer<vtkTrivialProducer>::New();
      Producers[i]->SetOutput(Inputs[i]);
      Filter->AddInputConnection(0, Producers[i]->GetOutputPort());
    }
    Downstream = vtkSmartPointer<vtkSurfaceMapEvaluation>::New();
    Downstream->SetInputConnection(0, Filter->GetOutputPort(0));
    Downstream->SetInputConnection(1, Filter->GetOutputPort(2));
    Downstream->Update();
  }

  static void TearDownTestSuite()
  {
    Downstream = nullptr;
    Filter = nullptr;
    for (int i = 0; i < 3; ++i)
    {
      Producers[i] = nullptr;
      Inputs[i] = nullptr;
    }
  }

  void SetUp() override { ASSERT_TRUE(Log.Errors.empty()) << Log.Errors.front(); }

  static vtkPolyData* output(int i) { return Filter->GetOutput(i); }

  static vtkSmartPointer<vtkPolyData> Inputs[3];
  static vtkSmartPointer<vtkTrivialProducer> Producers[3];
  static vtkSmartPointer<vtkSurfaceMapFilter> Filter;
  static vtkSmartPointer<vtkSurfaceMapEvaluation> Downstream;
  static Events Log;
};

vtkSmartPointer<vtkPolyData> ThreeInputPipeline::Inputs[3];
vtkSmartPointer<vtkTrivialProducer> ThreeInputPipeline::Producers[3];
vtkSmartPointer<vtkSurfaceMapFilter> ThreeInputPipeline::Filter;
vtkSmartPointer<vtkSurfaceMapEvaluation> ThreeInputPipeline::Downstream;
Events ThreeInputPipeline::Log;

TEST_F(ThreeInputPipeline, DownstreamSeesACertifiedMap)
{
  EXPECT_GE(Downstream->GetSummaryValue("SymmetricDirichlet"), 1.0);
  EXPECT_EQ(Downstream->GetSummaryValue("Bijective"), 1.0);
}

TEST_F(ThreeInputPipeline, OutputsShareTAndTheFieldData)
{
  const vtkIdType nv = output(0)->GetNumberOfPoints();
  ASSERT_GT(nv, 4);
  for (int i = 0; i < 3; ++i)
  {
    SCOPED_TRACE("output " + std::to_string(i));
    vtkPolyData* out = output(i);
    ASSERT_EQ(out->GetNumberOfPoints(), nv);
    EXPECT_EQ(connectivity(out), connectivity(output(0)));
    EXPECT_EQ(fieldValue(out, "InputIndex"), i);
    EXPECT_EQ(fieldValue(out, "Bijective"), 1.0);
    EXPECT_EQ(fieldValue(out, "CommonVertices"), nv);
    EXPECT_EQ(fieldValue(out, "CommonTriangles"), out->GetNumberOfPolys());
    EXPECT_GT(fieldValue(out, "Energy"), 0.0);
    EXPECT_GE(fieldValue(out, "MapEnergy"), 1.0);
    EXPECT_GT(fieldValue(out, "EmbeddingSeconds", 2), 0.0);
    auto* phases = vtkStringArray::SafeDownCast(out->GetFieldData()->GetAbstractArray("PhaseName"));
    ASSERT_NE(phases, nullptr);
    ASSERT_EQ(phases->GetNumberOfValues(), 3);
    EXPECT_EQ(phases->GetValue(0), "landmarks");
    EXPECT_EQ(phases->GetValue(2), "fine");
    EXPECT_LE(fieldValue(out, "PhaseIterations", 1), 3);
    EXPECT_LE(fieldValue(out, "PhaseIterations", 2), 3);
    EXPECT_GT(fieldValue(out, "PhaseSeconds", 2), 0.0);
  }
}

TEST_F(ThreeInputPipeline, EveryEmbeddingIsCertifiedAndLiesOnItsInput)
{
  for (int i = 0; i < 3; ++i)
  {
    SCOPED_TRACE("output " + std::to_string(i));
    vtkPolyData* out = output(i);
    const vtkIdType nv = out->GetNumberOfPoints();
    vtkDataArray* sphere = out->GetPointData()->GetArray("SpherePosition");
    ASSERT_NE(sphere, nullptr);
    std::vector<Eigen::Vector3d> g(nv);
    for (vtkIdType v = 0; v < nv; ++v)
    {
      sphere->GetTuple(v, g[v].data());
      EXPECT_NEAR(g[v].norm(), 1.0, 1e-12);
    }
    EXPECT_TRUE(surfacemaps::certifyBijective(g, triangles(out)).bijective);
    expectOnSource(out, Inputs[i]);
  }
}

TEST_F(ThreeInputPipeline, LandmarksAreKeptExactly)
{
  for (int i = 0; i < 3; ++i)
  {
    SCOPED_TRACE("output " + std::to_string(i));
    vtkPolyData* out = output(i);
    vtkDataArray* landmarks = out->GetPointData()->GetArray("Landmarks");
    ASSERT_NE(landmarks, nullptr);
    vtkDataArray* inputLandmarks = Inputs[i]->GetPointData()->GetArray("Landmarks");
    int found = 0;
    for (vtkIdType v = 0; v < out->GetNumberOfPoints(); ++v)
    {
      const int id = static_cast<int>(landmarks->GetTuple1(v));
      if (id < 0)
      {
        continue;
      }
      ++found;
      for (vtkIdType w = 0; w < Inputs[i]->GetNumberOfPoints(); ++w)
      {
        if (static_cast<int>(inputLandmarks->GetTuple1(w)) == id)
        {
          const double* p = out->GetPoint(v);
          const double* q = Inputs[i]->GetPoint(w);
          EXPECT_NEAR(
            std::hypot(p[0] - q[0], p[1] - q[1], p[2] - q[2]), 0.0, 1e-9 * Inputs[i]->GetLength())
            << "landmark " << id;
        }
      }
    }
    EXPECT_EQ(found, 4);
  }
}

TEST_F(ThreeInputPipeline, InputArraysAreInterpolated)
{
  // The input's own arrays, interpolated; its Landmarks are not (T has its own).
  vtkDataArray* interpolated = output(1)->GetPointData()->GetArray("Height");
  ASSERT_NE(interpolated, nullptr);
  for (vtkIdType v = 0; v < output(1)->GetNumberOfPoints(); ++v)
  {
    ASSERT_NEAR(interpolated->GetTuple1(v), output(1)->GetPoint(v)[2], 1e-12);
  }
  EXPECT_EQ(output(0)->GetPointData()->GetArray("Height"), nullptr);
}

TEST_F(ThreeInputPipeline, DistortionIsTheEvaluations)
{
  vtkDataArray* first = output(0)->GetCellData()->GetArray("Distortion");
  ASSERT_NE(first, nullptr);
  for (vtkIdType t = 0; t < first->GetNumberOfTuples(); ++t)
  {
    ASSERT_EQ(first->GetTuple1(t), 1.0);
  }
  expectDistortionMatchesEvaluation(output(0), output(1));
  expectDistortionMatchesEvaluation(output(0), output(2));
}

TEST_F(ThreeInputPipeline, ProgressIsMonotoneWithATextPerStage)
{
  ASSERT_FALSE(Log.Progress.empty());
  EXPECT_TRUE(std::is_sorted(Log.Progress.begin(), Log.Progress.end()));
  EXPECT_EQ(Log.Progress.back(), 1.0);
  EXPECT_TRUE(computedTheMap(Log));
  // No input carries a SpherePosition: all three embedded at once.
  EXPECT_NE(std::find(Log.Texts.begin(), Log.Texts.end(), "Sphere embeddings of 3 inputs"),
    Log.Texts.end());
}

TEST(SurfaceMapFilter, MappedFirstInputReusesTheMap)
{
  vtkSmartPointer<vtkPolyData> a = ellipsoid(2, 1.0, 0.8, 0.6);
  vtkSmartPointer<vtkPolyData> b = read("ellipsoid_coarse.stl");
  vtkSmartPointer<vtkPolyData> c = ellipsoid(1, 1.0, 1.0, 0.5, 0.2);
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
  const double mapSeconds = fieldValue(filter->GetOutput(0), "MapSeconds");
  const vtkIdType commonVertices = filter->GetOutput(0)->GetNumberOfPoints();

  events.Texts.clear();
  filter->SetOutputModeToMappedFirstInput();
  filter->Update();
  ASSERT_TRUE(events.Errors.empty()) << events.Errors.front();
  EXPECT_FALSE(computedTheMap(events)); // the kept map was reused
  vtkSmartPointer<vtkPolyData> inputs[3] = { a, b, c };
  for (int j = 0; j < 3; ++j)
  {
    SCOPED_TRACE("output " + std::to_string(j));
    vtkPolyData* out = filter->GetOutput(j);
    ASSERT_EQ(out->GetNumberOfPoints(), a->GetNumberOfPoints());
    EXPECT_EQ(connectivity(out), connectivity(a));
    EXPECT_EQ(fieldValue(out, "MapSeconds"), mapSeconds);
    EXPECT_EQ(fieldValue(out, "CommonVertices"), commonVertices);
    expectOnSource(out, inputs[j]);
    if (j > 0)
    {
      expectDistortionMatchesEvaluation(filter->GetOutput(0), out);
    }
  }
  // Input 0 on itself is input 0.
  for (vtkIdType v = 0; v < a->GetNumberOfPoints(); ++v)
  {
    const double* p = filter->GetOutput(0)->GetPoint(v);
    const double* q = a->GetPoint(v);
    ASSERT_NEAR(std::hypot(p[0] - q[0], p[1] - q[1], p[2] - q[2]), 0.0, 1e-12);
  }

  // Back to T: still no recomputation; another setting recomputes.
  events.Texts.clear();
  filter->SetOutputModeToCommonTriangulation();
  filter->Update();
  EXPECT_FALSE(computedTheMap(events));
  EXPECT_EQ(filter->GetOutput(2)->GetNumberOfPoints(), commonVertices);
  filter->SetFineIterations(2);
  filter->Update();
  EXPECT_TRUE(computedTheMap(events));
  EXPECT_TRUE(events.Errors.empty());

  // The thread count changes only the time: reused. A change in the ninth
  // digit of a setting changes the map: recomputed.
  events.Texts.clear();
  filter->SetNumberOfThreads(1);
  filter->Update();
  EXPECT_FALSE(computedTheMap(events));
  filter->SetTargetError(filter->GetTargetError() * (1.0 + 1e-9));
  filter->Update();
  EXPECT_TRUE(computedTheMap(events));
  EXPECT_TRUE(events.Errors.empty());
}

// NumberOfThreads changes how fast, not what: the same map bit for bit with
// one, two and four threads, and the caller's OpenMP thread count is its own
// again after the update.
TEST(SurfaceMapFilter, NumberOfThreadsGivesTheSameMapAndIsRestored)
{
  vtkSmartPointer<vtkPolyData> a = ellipsoid(2, 1.0, 0.8, 0.6);
  vtkSmartPointer<vtkPolyData> b = ellipsoid(2, 1.0, 1.0, 0.5, 0.2);
  const int callers = surfacemaps::ScopedThreadCount::current() + 2;
  const surfacemaps::ScopedThreadCount caller(callers);
  std::vector<std::vector<double>> points;
  for (int threads : { 1, 2, 4 })
  {
    SCOPED_TRACE("threads " + std::to_string(threads));
    vtkNew<vtkSurfaceMapFilter> filter;
    useShortSchedule(filter);
    filter->SetNumberOfThreads(threads);
    Events events;
    watch(filter, events);
    filter->AddInputData(a);
    filter->AddInputData(b);
    filter->Update();
    ASSERT_TRUE(events.Errors.empty()) << events.Errors.front();
    EXPECT_EQ(surfacemaps::ScopedThreadCount::current(), callers);
    std::vector<double> xyz;
    for (int i = 0; i < 2; ++i)
    {
      vtkPolyData* out = filter->GetOutput(i);
      ASSERT_GT(out->GetNumberOfPoints(), 0);
      for (vtkIdType v = 0; v < out->GetNumberOfPoints(); ++v)
      {
        const double* p = out->GetPoint(v);
        xyz.insert(xyz.end(), p, p + 3);
      }
    }
    points.push_back(xyz);
  }
  EXPECT_EQ(points[0], points[1]);
  EXPECT_EQ(points[0], points[2]);
}

TEST(SurfaceMapFilter, RefinementSettingsReachTheEngine)
{
  // Every input triangle is distorted beyond 1 + 1e-9: one refinement round
  // of two iterations runs after the fine phase.
  vtkNew<vtkSurfaceMapFilter> filter;
  useShortSchedule(filter);
  filter->SetRefinementRounds(1);
  filter->SetRefinementIterations(2);
  filter->SetRefinementDistortion(1.0 + 1e-9);
  Events events;
  watch(filter, events);
  filter->AddInputData(ellipsoid(2, 1.0, 0.8, 0.6));
  filter->AddInputData(ellipsoid(2, 1.0, 1.0, 0.5, 0.2));
  filter->Update();
  ASSERT_TRUE(events.Errors.empty()) << events.Errors.front();
  vtkPolyData* out = filter->GetOutput(1);
  auto* phases = vtkStringArray::SafeDownCast(out->GetFieldData()->GetAbstractArray("PhaseName"));
  ASSERT_NE(phases, nullptr);
  ASSERT_GE(phases->GetNumberOfValues(), 3);
  const vtkIdType last = phases->GetNumberOfValues() - 1;
  EXPECT_EQ(phases->GetValue(last), "refine");
  EXPECT_EQ(phases->GetValue(last - 1), "fine");
  EXPECT_LE(fieldValue(out, "PhaseIterations", static_cast<int>(last)), 2);
  EXPECT_EQ(fieldValue(out, "Bijective"), 1.0);
}

TEST(SurfaceMapFilter, GivenSpherePositionIsUsed)
{
  vtkNew<vtkSphereEmbeddingFilter> embedding;
  embedding->SetInputData(ellipsoid(2, 1.0, 0.7, 0.5));
  embedding->Update();
  vtkNew<vtkSurfaceMapFilter> filter;
  useShortSchedule(filter);
  Events events;
  watch(filter, events);
  filter->AddInputConnection(embedding->GetOutputPort());
  filter->AddInputData(ellipsoid(1, 1.0, 1.0, 1.0));
  filter->Update();
  ASSERT_TRUE(events.Errors.empty()) << events.Errors.front();
  EXPECT_EQ(fieldValue(filter->GetOutput(1), "EmbeddingSeconds", 0), 0.0);
  EXPECT_GT(fieldValue(filter->GetOutput(1), "EmbeddingSeconds", 1), 0.0);
  EXPECT_EQ(std::count(events.Texts.begin(), events.Texts.end(), "Sphere embedding of input 0"), 0);
  EXPECT_GT(std::count(events.Texts.begin(), events.Texts.end(), "Sphere embedding of input 1"), 0);
  // The given embedding is not interpolated onto T (T has its own).
  EXPECT_EQ(fieldValue(filter->GetOutput(0), "Bijective"), 1.0);
}

TEST(SurfaceMapFilter, EmbeddingThatIsNotBijectiveIsAnError)
{
  vtkSmartPointer<vtkPolyData> mesh = ellipsoid(1, 1.0, 0.7, 0.5);
  vtkNew<vtkDoubleArray> sphere;
  sphere->SetName("SpherePosition");
  sphere->SetNumberOfComponents(3);
  for (vtkIdType v = 0; v < mesh->GetNumberOfPoints(); ++v)
  {
    const double* p = mesh->GetPoint(v);
    double q[3] = { p[0], p[1], p[2] };
    if (v == 7)
    {
      q[0] = -q[0]; // folds the triangles around vertex 7
      q[1] = -q[1];
      q[2] = -q[2];
    }
    sphere->InsertNextTuple(q);
  }
  mesh->GetPointData()->AddArray(sphere);
  vtkNew<vtkSurfaceMapFilter> filter;
  Events events;
  watch(filter, events);
  filter->AddInputData(ellipsoid(1, 1.0, 1.0, 1.0));
  filter->AddInputData(mesh);
  filter->Update();
  ASSERT_EQ(events.Errors.size(), 1u);
  EXPECT_NE(events.Errors[0].find("input 1 has a SpherePosition array that is not a bijective"),
    std::string::npos)
    << events.Errors[0];
  EXPECT_EQ(
    filter->GetErrorCode(), static_cast<unsigned long>(vtkSurfaceMapFilter::InvalidInputError));
  EXPECT_EQ(filter->GetOutput(0)->GetNumberOfPoints(), 0);
  EXPECT_EQ(filter->GetOutput(1)->GetNumberOfPoints(), 0);
}

TEST(SurfaceMapFilter, BadInputNamesTheInputAndLeavesEmptyOutputs)
{
  vtkNew<vtkSurfaceMapFilter> filter;
  Events events;
  watch(filter, events);
  filter->AddInputData(read("ellipsoid_coarse.stl"));
  filter->AddInputData(read("bad/hemisphere.obj"));
  filter->AddInputData(ellipsoid(1, 1, 1, 1));
  filter->Update();
  ASSERT_EQ(events.Errors.size(), 1u);
  const std::string& message = events.Errors[0];
  EXPECT_NE(
    message.find("input 1 (" + Data + "/bad/hemisphere.obj) is not closed: "), std::string::npos)
    << message;
  EXPECT_NE(message.find("boundary edges (first: edge "), std::string::npos) << message;
  EXPECT_EQ(message.find("input 0"), std::string::npos) << message;
  EXPECT_EQ(
    filter->GetErrorCode(), static_cast<unsigned long>(vtkSurfaceMapFilter::InvalidInputError));
  for (int i = 0; i < 3; ++i)
  {
    EXPECT_EQ(filter->GetOutput(i)->GetNumberOfPoints(), 0);
    EXPECT_EQ(filter->GetOutput(i)->GetNumberOfCells(), 0);
  }
  EXPECT_FALSE(computedTheMap(events));
}

TEST(SurfaceMapFilter, LandmarksMustCorrespond)
{
  vtkSmartPointer<vtkPolyData> a = ellipsoid(1, 1, 1, 1);
  vtkSmartPointer<vtkPolyData> b = ellipsoid(1, 1, 1, 2);
  addExtremeLandmarks(a);
  addExtremeLandmarks(b);
  b->GetPointData()->GetArray("Landmarks")->SetTuple1(0, 9); // a fifth id
  vtkNew<vtkSurfaceMapFilter> filter;
  Events events;
  watch(filter, events);
  filter->AddInputData(a);
  filter->AddInputData(b);
  filter->Update();
  ASSERT_EQ(events.Errors.size(), 1u);
  EXPECT_NE(events.Errors[0].find("landmark counts do not match: input 0 has 4, input 1 has 5"),
    std::string::npos)
    << events.Errors[0];
  EXPECT_EQ(
    filter->GetErrorCode(), static_cast<unsigned long>(vtkSurfaceMapFilter::InvalidInputError));
  EXPECT_EQ(filter->GetOutput(1)->GetNumberOfPoints(), 0);
}

TEST(SurfaceMapFilter, SizingMustBePositiveUnlessIgnored)
{
  vtkSmartPointer<vtkPolyData> mesh = ellipsoid(1, 1, 1, 1);
  vtkNew<vtkDoubleArray> sizing;
  sizing->SetName("Sizing");
  sizing->SetNumberOfValues(mesh->GetNumberOfPoints());
  sizing->Fill(0.1);
  sizing->SetValue(5, -1.0);
  mesh->GetPointData()->AddArray(sizing);
  vtkNew<vtkSurfaceMapFilter> filter;
  useShortSchedule(filter);
  Events events;
  watch(filter, events);
  filter->AddInputData(ellipsoid(1, 1, 1, 2));
  filter->AddInputData(mesh);
  filter->Update();
  ASSERT_EQ(events.Errors.size(), 1u);
  EXPECT_NE(
    events.Errors[0].find("input 1 has a Sizing value that is not a positive length (-1.000000 "
                          "at point 5)"),
    std::string::npos)
    << events.Errors[0];
  EXPECT_EQ(filter->GetOutput(1)->GetNumberOfPoints(), 0);

  // With curvature sizing the array is not read (nor interpolated).
  filter->SetSizingModeToCurvature();
  filter->Update();
  ASSERT_EQ(events.Errors.size(), 1u) << events.Errors.back();
  ASSERT_GT(filter->GetOutput(1)->GetNumberOfPoints(), 0);
  EXPECT_EQ(filter->GetOutput(1)->GetPointData()->GetArray("Sizing"), nullptr);
}

TEST(SurfaceMapFilter, AbortLeavesEmptyOutputs)
{
  vtkNew<vtkSurfaceMapFilter> filter;
  Events events;
  events.AbortAbove = 0.5; // inside the map's phases
  watch(filter, events);
  useShortSchedule(filter);
  filter->AddInputData(ellipsoid(2, 1.0, 0.8, 0.6));
  filter->AddInputData(read("ellipsoid_coarse.stl"));
  filter->Update();
  EXPECT_TRUE(events.Errors.empty());
  EXPECT_EQ(filter->GetErrorCode(), static_cast<unsigned long>(vtkErrorCode::NoError));
  EXPECT_EQ(filter->GetOutput(0)->GetNumberOfPoints(), 0);
  EXPECT_EQ(filter->GetOutput(1)->GetNumberOfPoints(), 0);
  ASSERT_FALSE(events.Progress.empty());
  EXPECT_TRUE(std::is_sorted(events.Progress.begin(), events.Progress.end()));
  EXPECT_LT(events.Progress.back(), 1.0);
  EXPECT_TRUE(computedTheMap(events)); // it stopped inside the map, not before it

  // The next update runs to the end (AbortExecute is reset per update).
  events.AbortAbove = 2.0;
  filter->Update();
  EXPECT_TRUE(events.Errors.empty());
  EXPECT_GT(filter->GetOutput(1)->GetNumberOfPoints(), 0);
  // ... after which the outputs are up to date again.
  events.Texts.clear();
  filter->Update();
  EXPECT_TRUE(events.Texts.empty());
}

TEST(SurfaceMapFilter, SettingsComeFromTheEngineTable)
{
  vtkNew<vtkSurfaceMapFilter> filter;
  const int n = vtkSurfaceMapFilter::GetNumberOfSettings();
  ASSERT_GE(n, 30);
  std::set<std::string> names, flags;
  for (int i = 0; i < n; ++i)
  {
    const std::string name = vtkSurfaceMapFilter::GetSettingName(i);
    EXPECT_TRUE(names.insert(name).second) << name;
    EXPECT_TRUE(flags.insert(vtkSurfaceMapFilter::GetSettingFlag(i)).second) << name;
    EXPECT_GT(std::strlen(vtkSurfaceMapFilter::GetSettingDocumentation(i)), 20u) << name;
    // A new filter starts at the table's default, inside the table's range.
    const double value = filter->GetSetting(i);
    EXPECT_EQ(value, vtkSurfaceMapFilter::GetSettingDefault(i)) << name;
    EXPECT_GE(value, vtkSurfaceMapFilter::GetSettingMinimum(i)) << name;
    EXPECT_LE(value, vtkSurfaceMapFilter::GetSettingMaximum(i)) << name;
    EXPECT_EQ(vtkSurfaceMapFilter::GetSettingOffFlag(i) != nullptr,
      vtkSurfaceMapFilter::GetSettingType(i) == vtkSurfaceMapFilter::SETTING_SWITCH)
      << name;
    // Setting clamps into the range and marks the filter modified.
    const vtkMTimeType before = filter->GetMTime();
    filter->SetSetting(i, vtkSurfaceMapFilter::GetSettingMaximum(i) * 2 + 1);
    EXPECT_EQ(filter->GetSetting(i), vtkSurfaceMapFilter::GetSettingMaximum(i)) << name;
    EXPECT_EQ(filter->GetMTime() > before, value != filter->GetSetting(i)) << name;
    filter->SetSetting(i, vtkSurfaceMapFilter::GetSettingMinimum(i) - 1);
    EXPECT_EQ(filter->GetSetting(i), vtkSurfaceMapFilter::GetSettingMinimum(i)) << name;
  }
  EXPECT_EQ(vtkSurfaceMapFilter::GetSettingName(n), nullptr);
  EXPECT_TRUE(std::isnan(filter->GetSetting(-1)));
  for (const char* name : { "TargetError", "RefinementDistortion", "KeepLandmarks", "PairMode" })
  {
    EXPECT_EQ(names.count(name), 1u) << name;
  }
}

// A preset sets the settings its documentation names and leaves the others;
// the pair preset restores those settings' defaults.
TEST(SurfaceMapFilter, PresetsSetTheirSettingsAndUndoEachOther)
{
  vtkNew<vtkSurfaceMapFilter> filter;
  ASSERT_EQ(vtkSurfaceMapFilter::GetNumberOfPresets(), 2);
  EXPECT_STREQ(vtkSurfaceMapFilter::GetPresetName(vtkSurfaceMapFilter::PRESET_POPULATION),
    "population");
  EXPECT_EQ(vtkSurfaceMapFilter::GetPresetName(2), nullptr);
  const std::string doc =
    vtkSurfaceMapFilter::GetPresetDocumentation(vtkSurfaceMapFilter::PRESET_POPULATION);
  filter->SetMapWeight(3.0);
  const vtkMTimeType before = filter->GetMTime();
  filter->SetScheduleToPopulation();
  EXPECT_GT(filter->GetMTime(), before);
  int changed = 0;
  for (int i = 0; i < vtkSurfaceMapFilter::GetNumberOfSettings(); ++i)
  {
    const std::string name = vtkSurfaceMapFilter::GetSettingName(i);
    const bool named = doc.find(" " + name + " ") != std::string::npos;
    const double expected = name == "MapWeight" ? 3.0 : vtkSurfaceMapFilter::GetSettingDefault(i);
    EXPECT_EQ(filter->GetSetting(i) != expected, named) << name;
    changed += named ? 1 : 0;
  }
  EXPECT_GE(changed, 3);
  EXPECT_EQ(filter->GetTargetError(), 0.01);
  EXPECT_EQ(filter->GetRefinementRounds(), 0);
  filter->SetScheduleToPair();
  for (int i = 0; i < vtkSurfaceMapFilter::GetNumberOfSettings(); ++i)
  {
    const std::string name = vtkSurfaceMapFilter::GetSettingName(i);
    EXPECT_EQ(filter->GetSetting(i),
      name == "MapWeight" ? 3.0 : vtkSurfaceMapFilter::GetSettingDefault(i))
      << name;
  }
}

TEST(SurfaceMapFilter, NamedSettersUseTheTable)
{
  vtkNew<vtkSurfaceMapFilter> filter;
  const auto index = [](const char* name)
  {
    for (int i = 0; i < vtkSurfaceMapFilter::GetNumberOfSettings(); ++i)
    {
      if (std::string(vtkSurfaceMapFilter::GetSettingName(i)) == name)
      {
        return i;
      }
    }
    return -1;
  };
  const int refinement = index("RefinementDistortion");
  ASSERT_GE(refinement, 0);
  EXPECT_EQ(filter->GetRefinementDistortion(), vtkSurfaceMapFilter::GetSettingDefault(refinement));
  EXPECT_EQ(
    filter->GetRefinementDistortionMinValue(), vtkSurfaceMapFilter::GetSettingMinimum(refinement));
  filter->SetRefinementDistortion(0.5);
  EXPECT_EQ(filter->GetRefinementDistortion(), filter->GetRefinementDistortionMinValue());
  filter->SetRefinementDistortion(2.5);
  EXPECT_EQ(filter->GetSetting(refinement), 2.5);
  filter->SetFineIterations(-3);
  EXPECT_EQ(filter->GetFineIterations(), 0);
  filter->SetFineIterations(7);
  EXPECT_EQ(filter->GetSetting(index("FineIterations")), 7.0);
  filter->SetPairModeToCycle();
  EXPECT_EQ(filter->GetPairMode(), vtkSurfaceMapFilter::PAIRS_CYCLE);
  filter->SetPairMode(17);
  EXPECT_EQ(filter->GetPairMode(), vtkSurfaceMapFilter::PAIRS_MEAN);
  filter->KeepLandmarksOff();
  EXPECT_FALSE(filter->GetKeepLandmarks());
  EXPECT_EQ(filter->GetSetting(index("KeepLandmarks")), 0.0);
}

TEST(SurfaceMapFilter, PrintSelfPrintsEverySetting)
{
  vtkNew<vtkSurfaceMapFilter> filter;
  filter->SetPairModeToAll();
  filter->KeepLandmarksOff();
  filter->SetRefinementDistortion(2.5);
  std::ostringstream print;
  filter->Print(print);
  for (int i = 0; i < vtkSurfaceMapFilter::GetNumberOfSettings(); ++i)
  {
    const std::string name = vtkSurfaceMapFilter::GetSettingName(i);
    EXPECT_NE(print.str().find(name + ": "), std::string::npos) << name;
  }
  for (const char* line : { "PairMode: all\n",
         "KeepLandmarks: off\n",
         "RefinementDistortion: 2.5\n",
         "OutputMode: 0",
         "NumberOfThreads: 0",
         "SizingMode: 0" })
  {
    EXPECT_NE(print.str().find(line), std::string::npos) << line;
  }
}
