#include "FilterTestData.h"
#include "vtkSurfaceAverage.h"
#include "vtkSurfaceMapsConversion.h"
#include "vtkSurfaceShapeStatistics.h"

#include "mesh/Primitives.h"
#include "statistics/Procrustes.h"

#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

namespace
{

using Field = std::vector<Eigen::Vector3d>;

double dot(const Field& a, const Field& b, const std::vector<double>& w)
{
  double sum = 0.0;
  for (std::size_t v = 0; v < a.size(); ++v)
  {
    sum += w[v] * a[v].dot(b[v]);
  }
  return sum;
}

Field pointsOf(vtkPolyData* mesh)
{
  return vtkSurfaceMapsConversion::ToPolygonMesh(mesh).points;
}

Field arrayOf(vtkPolyData* mesh, const char* name)
{
  vtkDataArray* array = mesh->GetPointData()->GetArray(name);
  Field field(array ? array->GetNumberOfTuples() : 0);
  for (std::size_t v = 0; v < field.size(); ++v)
  {
    array->GetTuple(static_cast<vtkIdType>(v), field[v].data());
  }
  return field;
}

// A population of N ellipsoids deformed by two planted, area-orthonormal
// displacement fields with random coefficients of variances exactly 0.1^2
// and 0.05^2 (and uncorrelated), plus small noise, each in a random pose.
struct Population
{
  surfacemaps::PolygonMesh base;
  std::vector<double> areas; // the base's normalised vertex areas
  Field modes[2];
  std::vector<double> coefficients[2];
  std::vector<vtkSmartPointer<vtkPolyData>> meshes;
};

Population makePopulation(int n)
{
  Population p;
  p.base = surfacemaps::makeIcosphere(3);
  Field normals;
  for (Eigen::Vector3d& x : p.base.points)
  {
    normals.push_back(x.normalized());
    x = Eigen::Vector3d(1.0 * x.x(), 0.75 * x.y(), 0.5 * x.z());
  }
  p.areas = surfacemaps::vertexAreaWeights(p.base.points, p.base.triangles());
  for (std::size_t v = 0; v < normals.size(); ++v)
  {
    const Eigen::Vector3d& d = normals[v];
    p.modes[0].push_back(d * (3.0 * d.z() * d.z() - 1.0)); // elongation along z
    p.modes[1].push_back(d * (d.x() * d.x() - d.y() * d.y())); // flattening
    // Both are mirror-symmetric in every axis, like the ellipsoid, so no
    // rigid motion takes up any of them.
  }
  // Area-orthonormal: the second against the first, both of unit norm.
  const auto scale = [](Field& f, double s)
  {
    for (Eigen::Vector3d& u : f)
    {
      u *= s;
    }
  };
  scale(p.modes[0], 1.0 / std::sqrt(dot(p.modes[0], p.modes[0], p.areas)));
  const double along = dot(p.modes[1], p.modes[0], p.areas);
  for (std::size_t v = 0; v < normals.size(); ++v)
  {
    p.modes[1][v] -= along * p.modes[0][v];
  }
  scale(p.modes[1], 1.0 / std::sqrt(dot(p.modes[1], p.modes[1], p.areas)));

  std::mt19937 random(18);
  std::normal_distribution<double> normal(0.0, 1.0), noise(0.0, 0.001);
  std::uniform_real_distribution<double> angle(-0.5, 0.5);
  Eigen::VectorXd c[2];
  for (Eigen::VectorXd& column : c)
  {
    column.resize(n);
    for (int i = 0; i < n; ++i)
    {
      column(i) = normal(random);
    }
    column.array() -= column.mean();
  }
  c[1] -= c[1].dot(c[0]) / c[0].squaredNorm() * c[0];
  c[0] *= 0.1 * std::sqrt(n) / c[0].norm();
  c[1] *= 0.05 * std::sqrt(n) / c[1].norm();
  for (int m = 0; m < 2; ++m)
  {
    p.coefficients[m].assign(c[m].data(), c[m].data() + n);
  }
  for (int i = 0; i < n; ++i)
  {
    const Eigen::Matrix3d R = (Eigen::AngleAxisd(angle(random), Eigen::Vector3d::UnitX()) *
      Eigen::AngleAxisd(angle(random), Eigen::Vector3d::UnitY()))
                                .toRotationMatrix();
    const Eigen::Vector3d t(angle(random), angle(random), angle(random));
    surfacemaps::PolygonMesh specimen = p.base;
    for (std::size_t v = 0; v < normals.size(); ++v)
    {
      Eigen::Vector3d x = p.base.points[v] + c[0](i) * p.modes[0][v] + c[1](i) * p.modes[1][v] +
        Eigen::Vector3d(noise(random), noise(random), noise(random));
      specimen.points[v] = R * x + t;
    }
    p.meshes.push_back(vtkSurfaceMapsConversion::ToPolyData(specimen));
  }
  return p;
}

double sampleVariance(const std::vector<double>& x)
{
  double mean = 0.0, sum = 0.0;
  for (double v : x)
  {
    mean += v / x.size();
  }
  for (double v : x)
  {
    sum += (v - mean) * (v - mean) / x.size();
  }
  return sum;
}

double correlation(const std::vector<double>& a, const std::vector<double>& b)
{
  Eigen::Map<const Eigen::VectorXd> x(a.data(), a.size()), y(b.data(), b.size());
  const Eigen::VectorXd dx = x.array() - x.mean(), dy = y.array() - y.mean();
  return dx.dot(dy) / (dx.norm() * dy.norm());
}

void addInputs(vtkSurfaceShapeStatistics* statistics, const Population& p)
{
  for (vtkPolyData* mesh : p.meshes)
  {
    statistics->AddInputData(mesh);
  }
}

bool contains(const std::string& text, const std::string& part)
{
  return text.find(part) != std::string::npos;
}

} // namespace

TEST(SurfaceShapeStatistics, RecoversTwoPlantedModes)
{
  const Population p = makePopulation(40);
  vtkNew<vtkSurfaceShapeStatistics> statistics;
  EXPECT_EQ(statistics->GetNumberOfModes(), 3);
  EXPECT_EQ(statistics->GetAlignMode(), vtkSurfaceShapeStatistics::ALIGN_RIGID);
  addInputs(statistics, p);
  statistics->Update();
  vtkPolyData* mean = statistics->GetOutput();
  ASSERT_EQ(mean->GetNumberOfPoints(), static_cast<vtkIdType>(p.base.points.size()));
  vtkFieldData* fields = mean->GetFieldData();
  vtkDataArray* variance = fields->GetArray("Variance");
  vtkDataArray* fraction = fields->GetArray("ExplainedVarianceFraction");
  vtkDataArray* scores = fields->GetArray("Scores");
  ASSERT_NE(variance, nullptr);
  ASSERT_NE(fraction, nullptr);
  ASSERT_NE(scores, nullptr);
  ASSERT_EQ(variance->GetNumberOfTuples(), 3);
  ASSERT_EQ(scores->GetNumberOfTuples(), 40);
  ASSERT_EQ(scores->GetNumberOfComponents(), 3);
  ASSERT_NE(fields->GetArray("AlignmentRMS"), nullptr);

  // The filter's vertex weights: the specimens' own areas, averaged.
  std::vector<double> areas(p.base.points.size(), 0.0);
  for (vtkPolyData* mesh : p.meshes)
  {
    const std::vector<double> own = surfacemaps::vertexAreaWeights(pointsOf(mesh), p.base.triangles());
    for (std::size_t v = 0; v < areas.size(); ++v)
    {
      areas[v] += own[v] / p.meshes.size();
    }
  }

  // The planted variances and their shares of the total (noise: 3 * 0.001^2).
  const double planted[2] = { sampleVariance(p.coefficients[0]),
    sampleVariance(p.coefficients[1]) };
  const double total = planted[0] + planted[1] + 3e-6;
  const double totalVariance = fields->GetArray("TotalVariance")->GetTuple1(0);
  EXPECT_NEAR(totalVariance, total, 0.05 * total);
  for (int m = 0; m < 2; ++m)
  {
    EXPECT_NEAR(variance->GetTuple1(m), planted[m], 0.05 * planted[m]) << m;
    EXPECT_NEAR(fraction->GetTuple1(m), planted[m] / total, 0.05 * planted[m] / total) << m;
    // The mode's shape: correlation with the planted field (either sign).
    const Field mode = arrayOf(mean, ("Mode_" + std::to_string(m + 1)).c_str());
    ASSERT_EQ(mode.size(), p.base.points.size());
    EXPECT_NEAR(dot(mode, mode, areas), 1.0, 1e-9) << m; // unit norm
    EXPECT_GT(std::abs(dot(mode, p.modes[m], p.areas)) / std::sqrt(dot(mode, mode, p.areas)), 0.99)
      << m;
    // The scores are the planted coefficients (up to the sign).
    std::vector<double> column;
    double squares = 0.0;
    for (int i = 0; i < 40; ++i)
    {
      column.push_back(scores->GetComponent(i, m));
      squares += column.back() * column.back() / 40.0;
    }
    EXPECT_GT(std::abs(correlation(column, p.coefficients[m])), 0.99) << m;
    EXPECT_NEAR(squares, variance->GetTuple1(m), 1e-12 * squares) << m;
  }
  EXPECT_LT(variance->GetTuple1(2), 0.01 * planted[1]); // the third is noise

  // StandardDeviation: sum_v A_v SD_v^2 is the total variance.
  vtkDataArray* spread = mean->GetPointData()->GetArray("StandardDeviation");
  ASSERT_NE(spread, nullptr);
  double sum = 0.0;
  for (vtkIdType v = 0; v < spread->GetNumberOfTuples(); ++v)
  {
    sum += areas[v] * spread->GetTuple1(v) * spread->GetTuple1(v);
  }
  EXPECT_NEAR(sum, totalVariance, 1e-12 * totalVariance);

  // The mean is vtkSurfaceAverage's mean of the same inputs.
  vtkNew<vtkSurfaceAverage> average;
  for (vtkPolyData* mesh : p.meshes)
  {
    average->AddInputData(mesh);
  }
  average->Update();
  const Field a = pointsOf(average->GetOutput()), b = pointsOf(mean);
  for (std::size_t v = 0; v < a.size(); ++v)
  {
    ASSERT_LT((a[v] - b[v]).norm(), 1e-12) << v;
  }
}

TEST(SurfaceShapeStatistics, ShapesAlongAModeFollowTheFormula)
{
  const Population p = makePopulation(12);
  vtkNew<vtkSurfaceShapeStatistics> statistics;
  addInputs(statistics, p);
  statistics->Update();
  vtkNew<vtkPolyData> mean;
  mean->DeepCopy(statistics->GetOutput());
  const Field m = pointsOf(mean);
  for (int mode : { 1, 2 })
  {
    const Field u = arrayOf(mean, ("Mode_" + std::to_string(mode)).c_str());
    const double sd = std::sqrt(mean->GetFieldData()->GetArray("Variance")->GetTuple1(mode - 1));
    for (double c : { -2.0, 1.5 })
    {
      statistics->SetMode(mode);
      statistics->SetCoefficient(c);
      statistics->Update();
      vtkPolyData* output = statistics->GetOutput();
      ASSERT_EQ(output->GetNumberOfPoints(), mean->GetNumberOfPoints());
      const Field x = pointsOf(output);
      double largest = 0.0;
      for (std::size_t v = 0; v < x.size(); ++v)
      {
        largest = std::max(largest, (x[v] - (m[v] + c * sd * u[v])).norm());
      }
      EXPECT_LT(largest, 1e-12) << mode << " " << c;
      // The arrays stay those of the population.
      EXPECT_EQ(arrayOf(output, "Mode_1"), arrayOf(mean, "Mode_1"));
    }
  }
  // Coefficient 0: the mean again.
  statistics->SetCoefficient(0.0);
  statistics->Update();
  EXPECT_EQ(pointsOf(statistics->GetOutput()), m);
}

TEST(SurfaceShapeStatistics, ErrorsLeaveAnEmptyOutput)
{
  const Population p = makePopulation(3);
  vtkNew<vtkSurfaceShapeStatistics> statistics;
  filtertest::Events errors;
  filtertest::watch(statistics, errors);
  // Mismatched connectivity: named like vtkSurfaceAverage does.
  addInputs(statistics, p);
  statistics->AddInputData(vtkSurfaceMapsConversion::ToPolyData(surfacemaps::makeIcosphere(1)));
  statistics->Update();
  ASSERT_EQ(errors.Errors.size(), 1u);
  EXPECT_TRUE(contains(errors.Errors[0], "input 3 does not have the connectivity of input 0"))
    << errors.Errors[0];
  EXPECT_TRUE(contains(errors.Errors[0], "42 points instead of 642")) << errors.Errors[0];
  EXPECT_EQ(statistics->GetOutput()->GetNumberOfPoints(), 0);

  // Three inputs have two modes: mode 3 is an error.
  statistics->RemoveAllInputConnections(0);
  addInputs(statistics, p);
  statistics->SetMode(3);
  statistics->Update();
  ASSERT_EQ(errors.Errors.size(), 2u);
  EXPECT_TRUE(contains(errors.Errors[1], "Mode 3 is not computed: there are 2 modes"))
    << errors.Errors[1];
  EXPECT_EQ(statistics->GetOutput()->GetNumberOfPoints(), 0);
  statistics->SetMode(2);
  statistics->Update();
  EXPECT_EQ(errors.Errors.size(), 2u);
  EXPECT_EQ(statistics->GetOutput()->GetFieldData()->GetArray("Variance")->GetNumberOfTuples(), 2);

  // One input is no population.
  statistics->RemoveAllInputConnections(0);
  statistics->AddInputData(p.meshes[0]);
  statistics->Update();
  ASSERT_EQ(errors.Errors.size(), 3u);
  EXPECT_TRUE(contains(errors.Errors[2], "at least 2 inputs")) << errors.Errors[2];
  EXPECT_EQ(statistics->GetOutput()->GetNumberOfPoints(), 0);
}
