#include "FilterTestData.h"
#include "vtkSurfaceAverage.h"
#include "vtkSurfaceMapsConversion.h"

#include "mesh/Primitives.h"
#include "statistics/Procrustes.h"

#include "vtkCallbackCommand.h"
#include "vtkCellArray.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkIdList.h"
#include "vtkIdTypeArray.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkStringArray.h"
#include "vtkTrivialProducer.h"

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

namespace
{

// An icosphere (level 2) scaled to an ellipsoid with a bump: no symmetry, so
// a wrong alignment shows.
vtkSmartPointer<vtkPolyData> shape(double bump = 0.3)
{
  surfacemaps::PolygonMesh mesh = surfacemaps::makeIcosphere(2);
  for (Eigen::Vector3d& p : mesh.points)
  {
    const double r =
      1.0 + bump * std::exp(-4.0 * (1.0 - p.normalized().dot(Eigen::Vector3d(0.6, 0.0, 0.8))));
    p = Eigen::Vector3d(1.0 * p.x(), 0.75 * p.y(), 0.5 * p.z()) * r;
  }
  return vtkSurfaceMapsConversion::ToPolyData(mesh);
}

Eigen::Matrix3d rotation(double angle, const Eigen::Vector3d& axis)
{
  return Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix();
}

// A deep copy of `mesh` with every point moved by x -> s R x + t and the
// active vectors rotated by R.
vtkSmartPointer<vtkPolyData> moved(vtkPolyData* mesh,
  const Eigen::Matrix3d& R,
  const Eigen::Vector3d& t,
  double s = 1.0)
{
  auto copy = vtkSmartPointer<vtkPolyData>::New();
  copy->DeepCopy(mesh);
  for (vtkIdType v = 0; v < copy->GetNumberOfPoints(); ++v)
  {
    Eigen::Vector3d x;
    copy->GetPoint(v, x.data());
    x = s * (R * x) + t;
    copy->GetPoints()->SetPoint(v, x.data());
  }
  if (vtkDataArray* vectors = copy->GetPointData()->GetVectors())
  {
    for (vtkIdType v = 0; v < vectors->GetNumberOfTuples(); ++v)
    {
      Eigen::Vector3d x;
      vectors->GetTuple(v, x.data());
      x = R * x;
      vectors->SetTuple(v, x.data());
    }
  }
  return copy;
}

double largestDistance(vtkPolyData* a, vtkPolyData* b)
{
  double largest = 0.0;
  for (vtkIdType v = 0; v < a->GetNumberOfPoints(); ++v)
  {
    Eigen::Vector3d p, q;
    a->GetPoint(v, p.data());
    b->GetPoint(v, q.data());
    largest = std::max(largest, (p - q).norm());
  }
  return largest;
}

template<typename Array>
vtkSmartPointer<Array> pointArray(vtkPolyData* mesh,
  const char* name,
  int components,
  double (*value)(vtkIdType v, int c))
{
  auto array = vtkSmartPointer<Array>::New();
  array->SetName(name);
  array->SetNumberOfComponents(components);
  array->SetNumberOfTuples(mesh->GetNumberOfPoints());
  for (vtkIdType v = 0; v < mesh->GetNumberOfPoints(); ++v)
  {
    for (int c = 0; c < components; ++c)
    {
      array->SetComponent(v, c, value(v, c));
    }
  }
  mesh->GetPointData()->AddArray(array);
  return array;
}

// The largest distance between `b` and `a` moved onto it by the best
// similarity (rigid unless `withScale`); `scale` receives its scale.
double distanceUpToMotion(vtkPolyData* a, vtkPolyData* b, bool withScale, double* scale = nullptr)
{
  const surfacemaps::ShapePoints x = vtkSurfaceMapsConversion::ToPolygonMesh(a).points;
  const surfacemaps::ShapePoints y = vtkSurfaceMapsConversion::ToPolygonMesh(b).points;
  const std::vector<double> w(x.size(), 1.0 / x.size());
  const surfacemaps::Similarity T = surfacemaps::fitSimilarity(x, y, w, withScale);
  if (scale)
  {
    *scale = T.Scale;
  }
  double largest = 0.0;
  for (std::size_t v = 0; v < x.size(); ++v)
  {
    largest = std::max(largest, (T.apply(x[v]) - y[v]).norm());
  }
  return largest;
}

// Input i's "AlignmentTransform" from the output's field data.
surfacemaps::Similarity alignmentOf(vtkPolyData* output, int i)
{
  double m[12];
  output->GetFieldData()->GetArray("AlignmentTransform")->GetTuple(i, m);
  surfacemaps::Similarity T;
  for (int r = 0; r < 3; ++r)
  {
    for (int c = 0; c < 3; ++c)
    {
      T.Rotation(r, c) = m[4 * r + c];
    }
    T.Translation(r) = m[4 * r + 3];
  }
  return T;
}

// The largest distance between input i moved by its AlignmentTransform and the output.
double alignedDistance(vtkPolyData* input, vtkPolyData* output, int i)
{
  const surfacemaps::Similarity T = alignmentOf(output, i);
  double largest = 0.0;
  for (vtkIdType v = 0; v < input->GetNumberOfPoints(); ++v)
  {
    Eigen::Vector3d x, y;
    input->GetPoint(v, x.data());
    output->GetPoint(v, y.data());
    largest = std::max(largest, (T.apply(x) - y).norm());
  }
  return largest;
}

double diagonal(vtkPolyData* mesh)
{
  double bounds[6];
  mesh->GetBounds(bounds);
  return Eigen::Vector3d(bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4])
    .norm();
}

bool contains(const std::string& text, const std::string& part)
{
  return text.find(part) != std::string::npos;
}

} // namespace

TEST(SurfaceAverage, RigidCopiesGiveTheMeshBack)
{
  vtkSmartPointer<vtkPolyData> mesh = shape();
  vtkNew<vtkSurfaceAverage> average;
  EXPECT_EQ(average->GetAlignMode(), vtkSurfaceAverage::ALIGN_RIGID);
  std::vector<vtkSmartPointer<vtkPolyData>> inputs{ mesh };
  const Eigen::Matrix3d R1 = rotation(2.0, Eigen::Vector3d(1, 2, 3));
  const Eigen::Vector3d t1(5.0, -3.0, 0.5);
  inputs.push_back(moved(mesh, R1, t1));
  inputs.push_back(
    moved(mesh, rotation(-1.0, Eigen::Vector3d(0, 1, 0)), Eigen::Vector3d(1, 1, 1)));
  // A half turn: the determinant test must not mistake it for a reflection.
  inputs.push_back(moved(mesh, rotation(M_PI, Eigen::Vector3d(0, 0, 1)), Eigen::Vector3d::Zero()));
  for (vtkPolyData* input : inputs)
  {
    average->AddInputData(input);
  }
  average->Update();
  vtkPolyData* output = average->GetOutput();
  ASSERT_EQ(output->GetNumberOfPoints(), mesh->GetNumberOfPoints());
  EXPECT_EQ(output->GetNumberOfPolys(), mesh->GetNumberOfPolys());
  // The mesh again, up to a rigid motion (the frame is the mean's own).
  EXPECT_LT(distanceUpToMotion(mesh, output, false), 1e-9);

  vtkDataArray* rms = output->GetFieldData()->GetArray("AlignmentRMS");
  ASSERT_NE(rms, nullptr);
  ASSERT_EQ(rms->GetNumberOfTuples(), 4);
  ASSERT_EQ(output->GetFieldData()->GetArray("AlignmentTransform")->GetNumberOfComponents(), 12);
  for (int i = 0; i < 4; ++i)
  {
    EXPECT_LT(rms->GetTuple1(i), 1e-9);
    // Each transform takes its input onto the mean.
    EXPECT_LT(alignedDistance(inputs[i], output, i), 1e-9) << i;
  }
  EXPECT_EQ(output->GetFieldData()->GetArray("AlignmentScale"), nullptr);
  // Input 1's transform undoes R1, t1 relative to input 0's.
  const surfacemaps::Similarity T0 = alignmentOf(output, 0), T1 = alignmentOf(output, 1);
  EXPECT_LT((T1.Rotation * R1 - T0.Rotation).norm(), 1e-12);
  EXPECT_LT((T1.Rotation * t1 + T1.Translation - T0.Translation).norm(), 1e-12);

  // Placed where the inputs are: its area-weighted centroid is the mean of theirs.
  const surfacemaps::PolygonMesh base = vtkSurfaceMapsConversion::ToPolygonMesh(mesh);
  const std::vector<double> areas = surfacemaps::vertexAreaWeights(base.points, base.triangles());
  Eigen::Vector3d centroids = Eigen::Vector3d::Zero(), centroid = Eigen::Vector3d::Zero();
  for (vtkIdType v = 0; v < mesh->GetNumberOfPoints(); ++v)
  {
    Eigen::Vector3d x;
    for (vtkPolyData* input : inputs)
    {
      input->GetPoint(v, x.data());
      centroids += areas[v] * x;
    }
    output->GetPoint(v, x.data());
    centroid += areas[v] * x;
  }
  EXPECT_LT((centroids / 4.0 - centroid).norm(), 1e-9);

  // Without alignment the copies do not average to the mesh.
  average->SetAlignModeToNone();
  average->Update();
  EXPECT_GT(distanceUpToMotion(mesh, average->GetOutput(), false), 0.1);
}

TEST(SurfaceAverage, SimilarityAlsoUndoesTheScale)
{
  vtkSmartPointer<vtkPolyData> mesh = shape();
  vtkNew<vtkSurfaceAverage> average;
  average->AddInputData(mesh);
  average->AddInputData(
    moved(mesh, rotation(0.7, Eigen::Vector3d(1, -1, 0)), Eigen::Vector3d(2, 0, 0), 0.5));
  average->AddInputData(
    moved(mesh, rotation(2.5, Eigen::Vector3d(0, 1, 1)), Eigen::Vector3d(0, 0, -4), 3.0));
  average->SetAlignModeToSimilarity();
  EXPECT_EQ(average->GetAlignMode(), vtkSurfaceAverage::ALIGN_SIMILARITY);
  average->Update();
  // The mesh at the mean size of the inputs, (1 + 0.5 + 3) / 3.
  double scale = 0.0;
  EXPECT_LT(distanceUpToMotion(mesh, average->GetOutput(), true, &scale), 1e-9);
  EXPECT_NEAR(scale, 1.5, 1e-12);
  vtkDataArray* scales = average->GetOutput()->GetFieldData()->GetArray("AlignmentScale");
  ASSERT_NE(scales, nullptr);
  EXPECT_NEAR(scales->GetTuple1(0), 1.5, 1e-12);
  EXPECT_NEAR(scales->GetTuple1(1), 3.0, 1e-12);
  EXPECT_NEAR(scales->GetTuple1(2), 0.5, 1e-12);

  // Rigid alignment keeps the sizes: the inputs do not fit the mean.
  average->SetAlignModeToRigid();
  average->Update();
  EXPECT_GT(average->GetOutput()->GetFieldData()->GetArray("AlignmentRMS")->GetTuple1(1), 0.01);
}

// Five different shapes in different poses, with weights: the mean must not
// depend on their order (the alignment onto input 0 it replaces gave means
// several % of the diagonal apart).
TEST(SurfaceAverage, PermutingTheInputsKeepsTheMean)
{
  std::vector<vtkSmartPointer<vtkPolyData>> inputs;
  const double weights[5] = { 1.0, 2.0, 0.5, 1.5, 1.0 };
  for (int i = 0; i < 5; ++i)
  {
    vtkSmartPointer<vtkPolyData> s = shape(0.1 + 0.15 * i);
    for (vtkIdType v = 0; v < s->GetNumberOfPoints(); ++v)
    {
      Eigen::Vector3d x;
      s->GetPoint(v, x.data());
      x.y() *= 1.0 + 0.1 * (i - 2) * x.x(); // a different taper on each
      s->GetPoints()->SetPoint(v, x.data());
    }
    inputs.push_back(moved(s,
      rotation(0.3 + 0.25 * i, Eigen::Vector3d(1.0, i - 2.0, 0.5 * i)),
      Eigen::Vector3d(0.2 * i, -0.1 * i, 0.3),
      1.0 + 0.1 * i));
  }
  const int order[5] = { 3, 0, 4, 1, 2 };
  for (int mode : { vtkSurfaceAverage::ALIGN_RIGID, vtkSurfaceAverage::ALIGN_SIMILARITY })
  {
    vtkNew<vtkSurfaceAverage> forward, permuted;
    forward->SetAlignMode(mode);
    permuted->SetAlignMode(mode);
    for (int k = 0; k < 5; ++k)
    {
      forward->AddInputData(inputs[k]);
      forward->SetInputWeight(k, weights[k]);
      permuted->AddInputData(inputs[order[k]]);
      permuted->SetInputWeight(k, weights[order[k]]);
    }
    forward->Update();
    permuted->Update();
    vtkPolyData* a = forward->GetOutput();
    vtkPolyData* b = permuted->GetOutput();
    ASSERT_EQ(a->GetNumberOfPoints(), inputs[0]->GetNumberOfPoints());
    EXPECT_LT(largestDistance(a, b), 1e-9 * diagonal(a)) << mode;
    vtkDataArray* rmsA = a->GetFieldData()->GetArray("AlignmentRMS");
    vtkDataArray* rmsB = b->GetFieldData()->GetArray("AlignmentRMS");
    for (int k = 0; k < 5; ++k)
    {
      EXPECT_GT(rmsA->GetTuple1(order[k]), 1e-3); // the shapes differ
      EXPECT_NEAR(rmsA->GetTuple1(order[k]), rmsB->GetTuple1(k), 1e-9 * diagonal(a));
      EXPECT_LT(alignedDistance(inputs[order[k]], b, k), 0.5 * diagonal(a));
    }
  }
}

TEST(SurfaceAverage, WeightsAreNormalisedAndZeroIgnoresAnInput)
{
  vtkSmartPointer<vtkPolyData> a = shape(0.0);
  vtkSmartPointer<vtkPolyData> b = shape(0.5);
  vtkNew<vtkSurfaceAverage> average;
  average->AddInputData(a);
  average->AddInputData(b);
  average->SetAlignModeToNone();
  average->SetInputWeight(0, 1.0);
  average->SetInputWeight(1, 3.0);
  EXPECT_EQ(average->GetInputWeight(1), 3.0);
  EXPECT_EQ(average->GetInputWeight(7), 1.0);
  average->Update();
  vtkPolyData* output = average->GetOutput();
  ASSERT_EQ(output->GetNumberOfPoints(), a->GetNumberOfPoints());
  double largest = 0.0;
  for (vtkIdType v = 0; v < a->GetNumberOfPoints(); ++v)
  {
    Eigen::Vector3d x, y, m;
    a->GetPoint(v, x.data());
    b->GetPoint(v, y.data());
    output->GetPoint(v, m.data());
    largest = std::max(largest, (m - (0.25 * x + 0.75 * y)).norm());
  }
  EXPECT_LT(largest, 1e-12);
  vtkDataArray* weights = output->GetFieldData()->GetArray("AverageWeight");
  ASSERT_NE(weights, nullptr);
  EXPECT_DOUBLE_EQ(weights->GetTuple1(0), 0.25);
  EXPECT_DOUBLE_EQ(weights->GetTuple1(1), 0.75);

  // Weight 0: input 1 is left out (also with alignment).
  average->SetInputWeight(1, 0.0);
  average->SetAlignModeToRigid();
  average->Update();
  EXPECT_EQ(largestDistance(average->GetOutput(), a), 0.0);

  average->RemoveAllInputWeights();
  EXPECT_EQ(average->GetInputWeight(1), 1.0);
}

TEST(SurfaceAverage, BadWeightsAreErrors)
{
  vtkSmartPointer<vtkPolyData> mesh = shape();
  vtkNew<vtkSurfaceAverage> average;
  filtertest::Events errors;
  filtertest::watch(average, errors);
  average->AddInputData(mesh);
  average->AddInputData(mesh);
  average->SetInputWeight(1, -2.0);
  average->Update();
  ASSERT_EQ(errors.Errors.size(), 1u);
  EXPECT_TRUE(contains(errors.Errors[0], "weight of input 1 is -2")) << errors.Errors[0];
  EXPECT_EQ(average->GetOutput()->GetNumberOfPoints(), 0);

  average->SetInputWeight(0, 0.0);
  average->SetInputWeight(1, 0.0);
  average->Update();
  ASSERT_EQ(errors.Errors.size(), 2u);
  EXPECT_TRUE(contains(errors.Errors[1], "sum to 0")) << errors.Errors[1];
  EXPECT_EQ(average->GetOutput()->GetNumberOfPoints(), 0);

  average->SetInputWeight(-1, 1.0); // ignored, with an error
  EXPECT_EQ(errors.Errors.size(), 3u);
}

TEST(SurfaceAverage, DifferentConnectivityNamesTheInput)
{
  vtkSmartPointer<vtkPolyData> mesh = shape();
  filtertest::Events errors;
  vtkNew<vtkSurfaceAverage> average;
  filtertest::watch(average, errors);
  average->AddInputData(mesh);
  average->AddInputData(mesh);
  average->AddInputData(vtkSurfaceMapsConversion::ToPolyData(surfacemaps::makeIcosphere(1)));
  average->Update();
  ASSERT_EQ(errors.Errors.size(), 1u);
  EXPECT_TRUE(contains(errors.Errors[0], "input 2 does not have the connectivity of input 0"))
    << errors.Errors[0];
  EXPECT_TRUE(contains(errors.Errors[0], "42 points instead of 162")) << errors.Errors[0];
  EXPECT_EQ(average->GetOutput()->GetNumberOfPoints(), 0);
  EXPECT_EQ(average->GetOutput()->GetNumberOfCells(), 0);

  // Same points, one triangle with its corners rotated: named by cell id and file name.
  auto twisted = vtkSmartPointer<vtkPolyData>::New();
  twisted->DeepCopy(mesh);
  vtkNew<vtkIdList> ids;
  twisted->GetPolys()->GetCellAtId(5, ids);
  const vtkIdType turned[3] = { ids->GetId(1), ids->GetId(2), ids->GetId(0) };
  twisted->GetPolys()->ReplaceCellAtId(5, 3, turned);
  vtkNew<vtkStringArray> name;
  name->SetName("FileName");
  name->InsertNextValue("twisted.obj");
  twisted->GetFieldData()->AddArray(name);
  average->RemoveAllInputConnections(0);
  average->AddInputData(mesh);
  average->AddInputData(twisted);
  average->Update();
  ASSERT_EQ(errors.Errors.size(), 2u);
  std::ostringstream expected;
  expected
    << "input 1 (twisted.obj) does not have the connectivity of input 0: cell 5 has the points ("
    << turned[0] << " " << turned[1] << " " << turned[2] << ") instead of (" << ids->GetId(0) << " "
    << ids->GetId(1) << " " << ids->GetId(2) << ")";
  EXPECT_TRUE(contains(errors.Errors[1], expected.str())) << errors.Errors[1];
  EXPECT_EQ(average->GetOutput()->GetNumberOfPoints(), 0);

  // Back to good inputs: a result again.
  average->RemoveAllInputConnections(0);
  average->AddInputData(mesh);
  average->AddInputData(mesh);
  average->Update();
  EXPECT_EQ(errors.Errors.size(), 2u);
  EXPECT_EQ(average->GetOutput()->GetNumberOfPoints(), mesh->GetNumberOfPoints());
}

TEST(SurfaceAverage, PointArraysFollowTheRules)
{
  vtkSmartPointer<vtkPolyData> a = shape();
  auto b = vtkSmartPointer<vtkPolyData>::New();
  b->DeepCopy(a);
  // Averaged: "Thickness" (double) and "Color" (float, 3 components).
  pointArray<vtkDoubleArray>(a, "Thickness", 1, [](vtkIdType v, int) { return 1.0 * v; });
  pointArray<vtkDoubleArray>(b, "Thickness", 1, [](vtkIdType v, int) { return 3.0 * v; });
  pointArray<vtkFloatArray>(a, "Color", 3, [](vtkIdType, int c) { return 0.25 * c; });
  pointArray<vtkFloatArray>(b, "Color", 3, [](vtkIdType, int c) { return 0.75 * c; });
  // Landmarks: input 0's even where input 1 differs.
  pointArray<vtkIntArray>(a, "Landmarks", 1, [](vtkIdType v, int) { return v == 3 ? 0.0 : -1.0; });
  pointArray<vtkIntArray>(b, "Landmarks", 1, [](vtkIdType v, int) { return v == 4 ? 0.0 : -1.0; });
  // Integer labels are categorical: input 0's values, identical or not.
  pointArray<vtkIntArray>(a, "Region", 1, [](vtkIdType v, int) { return v % 3 * 1.0; });
  pointArray<vtkIntArray>(b, "Region", 1, [](vtkIdType v, int) { return v % 3 * 1.0; });
  pointArray<vtkIntArray>(a, "Label", 1, [](vtkIdType v, int) { return v % 2 * 1.0; });
  pointArray<vtkIntArray>(b, "Label", 1, [](vtkIdType v, int) { return v % 5 * 1.0; });
  // Dropped: per-input correspondence data, a type mismatch, a missing array.
  for (vtkPolyData* m : { a.Get(), b.Get() })
  {
    pointArray<vtkIdTypeArray>(m, "SourceCellId", 1, [](vtkIdType v, int) { return 1.0 * v; });
    pointArray<vtkDoubleArray>(m, "SourceBarycentric", 3, [](vtkIdType, int) { return 1.0 / 3; });
    pointArray<vtkDoubleArray>(
      m, "SpherePosition", 3, [](vtkIdType, int c) { return c == 0 ? 1.0 : 0.0; });
  }
  pointArray<vtkDoubleArray>(a, "Pressure", 1, [](vtkIdType, int) { return 1.0; });
  pointArray<vtkFloatArray>(b, "Pressure", 1, [](vtkIdType, int) { return 2.0; });
  pointArray<vtkDoubleArray>(a, "OnlyHere", 1, [](vtkIdType, int) { return 1.0; });
  // Active vectors are rotated with their input; active normals are dropped.
  auto velocity = pointArray<vtkDoubleArray>(
    a, "Velocity", 3, [](vtkIdType v, int c) { return c == 0 ? 1.0 * v : 0.5; });
  a->GetPointData()->SetActiveVectors("Velocity");
  auto normals = pointArray<vtkDoubleArray>(
    a, "Normals", 3, [](vtkIdType, int c) { return c == 2 ? 1.0 : 0.0; });
  a->GetPointData()->SetNormals(normals);
  b->GetPointData()->AddArray(normals);
  auto bVelocity = vtkSmartPointer<vtkDoubleArray>::New();
  bVelocity->DeepCopy(velocity);
  b->GetPointData()->AddArray(bVelocity);
  b->GetPointData()->SetActiveVectors("Velocity");
  const Eigen::Matrix3d R = rotation(1.2, Eigen::Vector3d(1, 1, 0));
  vtkSmartPointer<vtkPolyData> c = moved(b, R, Eigen::Vector3d(0, 2, 0));

  vtkNew<vtkSurfaceAverage> average;
  average->AddInputData(a);
  average->AddInputData(c);
  average->Update();
  vtkPointData* pd = average->GetOutput()->GetPointData();
  // Both inputs' vectors turned into the mean's frame agree: input 0's turned.
  const Eigen::Matrix3d toMean = alignmentOf(average->GetOutput(), 0).Rotation;
  ASSERT_NE(pd->GetArray("Thickness"), nullptr);
  ASSERT_NE(pd->GetArray("Color"), nullptr);
  EXPECT_EQ(pd->GetArray("Color")->GetDataType(), VTK_FLOAT);
  for (vtkIdType v = 0; v < a->GetNumberOfPoints(); ++v)
  {
    EXPECT_NEAR(pd->GetArray("Thickness")->GetTuple1(v), 2.0 * v, 1e-12);
    EXPECT_NEAR(pd->GetArray("Color")->GetComponent(v, 2), 1.0, 1e-7);
    Eigen::Vector3d expected;
    velocity->GetTuple(v, expected.data());
    expected = toMean * expected;
    for (int k = 0; k < 3; ++k)
    {
      EXPECT_NEAR(pd->GetArray("Velocity")->GetComponent(v, k), expected(k), 1e-12);
    }
  }
  ASSERT_NE(pd->GetVectors(), nullptr);
  EXPECT_STREQ(pd->GetVectors()->GetName(), "Velocity");
  ASSERT_NE(pd->GetArray("Landmarks"), nullptr);
  EXPECT_EQ(pd->GetArray("Landmarks")->GetTuple1(3), 0.0);
  EXPECT_EQ(pd->GetArray("Landmarks")->GetTuple1(4), -1.0);
  ASSERT_NE(pd->GetArray("Region"), nullptr);
  EXPECT_EQ(pd->GetArray("Region")->GetTuple1(5), 2.0);
  ASSERT_NE(pd->GetArray("Label"), nullptr);
  EXPECT_EQ(pd->GetArray("Label")->GetDataType(), VTK_INT);
  for (vtkIdType v = 0; v < a->GetNumberOfPoints(); ++v)
  {
    ASSERT_EQ(pd->GetArray("Label")->GetTuple1(v), v % 2 * 1.0) << v; // not a mean of labels
  }
  for (const char* name :
    { "SourceCellId", "SourceBarycentric", "SpherePosition", "Pressure", "OnlyHere", "Normals" })
  {
    EXPECT_EQ(pd->GetAbstractArray(name), nullptr) << name;
  }
}

// The per-array choice both ways: a double array taken from input 0 as a
// label, an int array averaged (and rounded); input 0's weight does not
// matter for categorical arrays.
TEST(SurfaceAverage, ArrayTransferModesOverrideTheType)
{
  vtkSmartPointer<vtkPolyData> a = shape();
  auto b = vtkSmartPointer<vtkPolyData>::New();
  b->DeepCopy(a);
  pointArray<vtkDoubleArray>(a, "Thickness", 1, [](vtkIdType v, int) { return 1.0 * v; });
  pointArray<vtkDoubleArray>(b, "Thickness", 1, [](vtkIdType v, int) { return 3.0 * v; });
  pointArray<vtkIntArray>(a, "Count", 1, [](vtkIdType v, int) { return 10.0 * v; });
  pointArray<vtkIntArray>(b, "Count", 1, [](vtkIdType v, int) { return 10.0 * v + 5.0; });

  vtkNew<vtkSurfaceAverage> average;
  average->AddInputData(a);
  average->AddInputData(b);
  average->SetInputWeight(0, 0.0);
  average->SetArrayTransferModeToCategorical("Thickness");
  average->SetArrayTransferMode("Count", vtkSurfaceAverage::ARRAY_TRANSFER_CONTINUOUS);
  EXPECT_EQ(
    average->GetArrayTransferMode("Thickness"), vtkSurfaceAverage::ARRAY_TRANSFER_CATEGORICAL);
  EXPECT_EQ(average->GetNumberOfArrayTransferModes(), 2);
  average->Update();
  vtkPointData* pd = average->GetOutput()->GetPointData();
  ASSERT_NE(pd->GetArray("Thickness"), nullptr);
  ASSERT_NE(pd->GetArray("Count"), nullptr);
  EXPECT_EQ(pd->GetArray("Count")->GetDataType(), VTK_INT);
  for (vtkIdType v = 0; v < a->GetNumberOfPoints(); ++v)
  {
    ASSERT_EQ(pd->GetArray("Thickness")->GetTuple1(v), 1.0 * v);    // input 0's, weight 0
    ASSERT_EQ(pd->GetArray("Count")->GetTuple1(v), 10.0 * v + 5.0); // input 1's alone
  }

  // Equal weights: the mean 10 v + 2.5 rounds (half away from zero).
  average->SetInputWeight(0, 1.0);
  average->ClearArrayTransferModes();
  average->SetArrayTransferModeToContinuous("Count");
  average->Update();
  pd = average->GetOutput()->GetPointData();
  for (vtkIdType v = 0; v < a->GetNumberOfPoints(); ++v)
  {
    ASSERT_EQ(pd->GetArray("Count")->GetTuple1(v), 10.0 * v + 3.0);
    ASSERT_NEAR(pd->GetArray("Thickness")->GetTuple1(v), 2.0 * v, 1e-12); // by type again
  }
}

TEST(SurfaceAverage, AbortLeavesAnEmptyOutputWithoutError)
{
  vtkSmartPointer<vtkPolyData> mesh = shape();
  vtkNew<vtkSurfaceAverage> average;
  filtertest::Events errors;
  filtertest::watch(average, errors);
  std::vector<double> progress;
  vtkNew<vtkCallbackCommand> onProgress;
  onProgress->SetClientData(&progress);
  onProgress->SetCallback(
    [](vtkObject* object, unsigned long, void* client, void*)
    {
      auto* a = static_cast<vtkSurfaceAverage*>(object);
      static_cast<std::vector<double>*>(client)->push_back(a->GetProgress());
      if (a->GetProgress() > 0.3)
      {
        a->AbortExecuteOn();
      }
    });
  average->AddObserver(vtkCommand::ProgressEvent, onProgress);
  for (int i = 0; i < 4; ++i)
  {
    average->AddInputData(mesh);
  }
  average->Update();
  EXPECT_TRUE(errors.Errors.empty());
  EXPECT_EQ(average->GetOutput()->GetNumberOfPoints(), 0);
  ASSERT_FALSE(progress.empty());
  EXPECT_LT(progress.back(), 1.0);

  // The next update runs again.
  average->AbortExecuteOff();
  average->RemoveObserver(onProgress);
  average->Update();
  EXPECT_EQ(average->GetOutput()->GetNumberOfPoints(), mesh->GetNumberOfPoints());
}

TEST(SurfaceAverage, PipelineAndPrintSelf)
{
  vtkSmartPointer<vtkPolyData> mesh = shape();
  vtkNew<vtkTrivialProducer> first, second;
  first->SetOutput(mesh);
  second->SetOutput(moved(mesh, rotation(0.3, Eigen::Vector3d(0, 0, 1)), Eigen::Vector3d(0, 0, 1)));
  vtkNew<vtkSurfaceAverage> average;
  average->AddInputConnection(first->GetOutputPort());
  average->AddInputConnection(second->GetOutputPort());
  average->SetInputWeight(1, 2.5);
  average->SetAlignMode(9);
  EXPECT_EQ(average->GetAlignMode(), vtkSurfaceAverage::ALIGN_SIMILARITY);
  average->Update();
  EXPECT_LT(distanceUpToMotion(mesh, average->GetOutput(), false), 1e-9);
  std::ostringstream print;
  average->Print(print);
  EXPECT_TRUE(contains(print.str(), "AlignMode: 2")) << print.str();
  EXPECT_TRUE(contains(print.str(), "InputWeights: 1: 2.5")) << print.str();
  EXPECT_TRUE(contains(print.str(), "ArrayTransferModes: (by type")) << print.str();
  average->SetArrayTransferModeToCategorical("Thickness");
  std::ostringstream chosen;
  average->Print(chosen);
  EXPECT_TRUE(contains(chosen.str(), "ArrayTransferModes: Thickness: categorical;"))
    << chosen.str();
}
