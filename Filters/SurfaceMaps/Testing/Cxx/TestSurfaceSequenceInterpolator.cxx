#include "vtkSurfaceMapsConversion.h"
#include "vtkSurfaceSequenceInterpolator.h"

#include "mesh/Primitives.h"

#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkInformation.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkTrivialProducer.h"

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

namespace
{

using Path = std::function<Eigen::Vector3d(const Eigen::Vector3d& x, double t)>;

// The icosphere (level 1) moved by `path` at time t, with a point array
// "Value" = |moved point|^2 (it moves along with the points).
vtkSmartPointer<vtkPolyData> keyframe(const Path& path, double t)
{
  surfacemaps::PolygonMesh mesh = surfacemaps::makeIcosphere(1);
  for (Eigen::Vector3d& p : mesh.points)
  {
    p = path(p, t);
  }
  vtkSmartPointer<vtkPolyData> poly = vtkSurfaceMapsConversion::ToPolyData(mesh);
  vtkNew<vtkDoubleArray> value;
  value->SetName("Value");
  for (const Eigen::Vector3d& p : mesh.points)
  {
    value->InsertNextValue(p.x() + 2.0 * p.y() - p.z());
  }
  poly->GetPointData()->AddArray(value);
  return poly;
}

// A motion that is no polynomial in t: non-trivial tangents everywhere.
Eigen::Vector3d wobble(const Eigen::Vector3d& x, double t)
{
  return Eigen::Vector3d(x.x() * (1.0 + 0.3 * std::sin(t)),
    x.y() + 0.2 * std::cos(2.0 * t) * x.z(),
    x.z() * std::exp(0.1 * t) + 0.05 * t * t);
}

// Every vertex on a parabola in time.
Eigen::Vector3d quadratic(const Eigen::Vector3d& x, double t)
{
  return x + t * Eigen::Vector3d(0.3, -0.1, 0.2) +
    t * t * Eigen::Vector3d(0.05 * x.z(), 0.1, -0.02 * x.x());
}

struct Sequence
{
  vtkNew<vtkSurfaceSequenceInterpolator> Interpolator;
  std::vector<vtkSmartPointer<vtkPolyData>> Keyframes;

  // Poses as given and points blended vertex by vertex unless a test chooses
  // otherwise: the figures below are those of the vertex-wise formulas.
  Sequence(const Path& path, const std::vector<double>& times)
  {
    this->Interpolator->SetKeyframeAlignmentToNone();
    this->Interpolator->SetShapeBlendingToVertices();
    for (std::size_t k = 0; k < times.size(); ++k)
    {
      this->Keyframes.push_back(keyframe(path, times[k]));
      this->Interpolator->AddInputData(this->Keyframes.back());
      this->Interpolator->SetKeyframeTime(static_cast<int>(k), times[k]);
    }
  }

  std::vector<Eigen::Vector3d> At(double t)
  {
    this->Interpolator->UpdateTimeStep(t);
    return points(this->Interpolator->GetOutput());
  }

  static std::vector<Eigen::Vector3d> points(vtkPolyData* mesh)
  {
    std::vector<Eigen::Vector3d> x(mesh->GetNumberOfPoints());
    for (vtkIdType v = 0; v < mesh->GetNumberOfPoints(); ++v)
    {
      mesh->GetPoint(v, x[v].data());
    }
    return x;
  }
};

double largestDifference(const std::vector<Eigen::Vector3d>& a,
  const std::vector<Eigen::Vector3d>& b)
{
  EXPECT_EQ(a.size(), b.size());
  double largest = 0.0;
  for (std::size_t v = 0; v < std::min(a.size(), b.size()); ++v)
  {
    largest = std::max(largest, (a[v] - b[v]).norm());
  }
  return largest;
}

std::vector<double> timeSteps(vtkAlgorithm* algorithm)
{
  algorithm->UpdateInformation();
  vtkInformation* info = algorithm->GetOutputInformation(0);
  if (!info->Has(vtkStreamingDemandDrivenPipeline::TIME_STEPS()))
  {
    return {};
  }
  const double* steps = info->Get(vtkStreamingDemandDrivenPipeline::TIME_STEPS());
  return std::vector<double>(
    steps, steps + info->Length(vtkStreamingDemandDrivenPipeline::TIME_STEPS()));
}

const std::vector<double> Times = { 0.0, 1.0, 2.5, 3.0, 5.0 };

} // namespace

TEST(SurfaceSequenceInterpolator, KeyframesAreReproducedExactly)
{
  // mode % 2: linear, smooth; from 2 on with the rotations blended.
  for (int mode : { 0, 1, 2, 3 })
  {
    Sequence s(wobble, Times);
    s.Interpolator->SetInterpolationMode(mode % 2);
    if (mode >= 2)
    {
      s.Interpolator->SetShapeBlendingToRotations();
    }
    for (std::size_t k = 0; k < Times.size(); ++k)
    {
      EXPECT_EQ(largestDifference(s.At(Times[k]), Sequence::points(s.Keyframes[k])), 0.0)
        << "mode " << mode << " keyframe " << k;
      vtkPolyData* output = s.Interpolator->GetOutput();
      vtkDataArray* value = output->GetPointData()->GetArray("Value");
      ASSERT_NE(value, nullptr);
      for (vtkIdType v = 0; v < output->GetNumberOfPoints(); ++v)
      {
        EXPECT_EQ(
          value->GetTuple1(v), s.Keyframes[k]->GetPointData()->GetArray("Value")->GetTuple1(v));
      }
      EXPECT_EQ(output->GetNumberOfPolys(), s.Keyframes[0]->GetNumberOfPolys());
      EXPECT_EQ(output->GetInformation()->Get(vtkDataObject::DATA_TIME_STEP()), Times[k]);
    }
  }
}

TEST(SurfaceSequenceInterpolator, LinearMidpointIsTheMean)
{
  Sequence s(wobble, Times);
  s.Interpolator->SetInterpolationModeToLinear();
  EXPECT_EQ(
    s.Interpolator->GetInterpolationMode(), vtkSurfaceSequenceInterpolator::INTERPOLATE_LINEAR);
  const auto a = Sequence::points(s.Keyframes[1]);
  const auto b = Sequence::points(s.Keyframes[2]);
  std::vector<Eigen::Vector3d> mean(a.size()), quarter(a.size());
  for (std::size_t v = 0; v < a.size(); ++v)
  {
    mean[v] = 0.5 * (a[v] + b[v]);
    quarter[v] = 0.75 * a[v] + 0.25 * b[v];
  }
  EXPECT_LT(largestDifference(s.At(1.75), mean), 1e-12);
  EXPECT_LT(largestDifference(s.At(1.375), quarter), 1e-12);
  vtkDataArray* value = s.Interpolator->GetOutput()->GetPointData()->GetArray("Value");
  ASSERT_NE(value, nullptr);
  EXPECT_NEAR(value->GetTuple1(7),
    0.75 * s.Keyframes[1]->GetPointData()->GetArray("Value")->GetTuple1(7) +
      0.25 * s.Keyframes[2]->GetPointData()->GetArray("Value")->GetTuple1(7),
    1e-12);
}

TEST(SurfaceSequenceInterpolator, SmoothIsC1AtTheKeyframes)
{
  Sequence s(wobble, Times);
  EXPECT_EQ(
    s.Interpolator->GetInterpolationMode(), vtkSurfaceSequenceInterpolator::INTERPOLATE_SMOOTH);
  const double e = 1e-6;
  // Vertex by vertex (k < K), then with the defaults (aligned, rotations
  // blended) at the same keyframes.
  const std::size_t n = Times.size();
  for (std::size_t i = 1; i + 1 < 2 * n; ++i)
  {
    const std::size_t k = i % n;
    if (k == n - 1 || k == 0)
    {
      s.Interpolator->SetKeyframeAlignmentToRigid();
      s.Interpolator->SetShapeBlendingToRotations();
      continue;
    }
    const auto before = s.At(Times[k] - e);
    const auto at = s.At(Times[k]);
    const auto after = s.At(Times[k] + e);
    double largest = 0.0, speed = 0.0;
    for (std::size_t v = 0; v < at.size(); ++v)
    {
      const Eigen::Vector3d left = (at[v] - before[v]) / e, right = (after[v] - at[v]) / e;
      largest = std::max(largest, (left - right).norm());
      speed = std::max(speed, right.norm());
    }
    EXPECT_GT(speed, 0.01) << "keyframe " << k;
    EXPECT_LT(largest, 1e-4) << "keyframe " << k; // O(e) from the second derivative
  }
  // The linear interpolation has a kink there.
  s.Interpolator->SetKeyframeAlignmentToNone();
  s.Interpolator->SetShapeBlendingToVertices();
  s.Interpolator->SetInterpolationModeToLinear();
  const auto before = s.At(Times[1] - e), at = s.At(Times[1]), after = s.At(Times[1] + e);
  double largest = 0.0;
  for (std::size_t v = 0; v < at.size(); ++v)
  {
    largest = std::max(largest, ((at[v] - before[v]) / e - (after[v] - at[v]) / e).norm());
  }
  EXPECT_GT(largest, 0.01);
}

TEST(SurfaceSequenceInterpolator, SmoothFollowsQuadraticPathsExactly)
{
  Sequence s(quadratic, Times);
  for (double t : { 0.1, 0.5, 1.3, 2.0, 2.9, 4.2, 4.99 })
  {
    EXPECT_LT(largestDifference(s.At(t), Sequence::points(keyframe(quadratic, t))), 1e-12) << t;
  }
  s.Interpolator->SetInterpolationModeToLinear();
  EXPECT_GT(largestDifference(s.At(4.0), Sequence::points(keyframe(quadratic, 4.0))), 0.01);
}

TEST(SurfaceSequenceInterpolator, SmoothEqualsLinearForTwoKeyframes)
{
  Sequence s(wobble, { 1.0, 3.0 });
  for (double t : { 1.2, 2.0, 2.7 })
  {
    s.Interpolator->SetInterpolationModeToSmooth();
    const auto smooth = s.At(t);
    s.Interpolator->SetInterpolationModeToLinear();
    EXPECT_LT(largestDifference(smooth, s.At(t)), 1e-12) << t;
  }
}

TEST(SurfaceSequenceInterpolator, OneKeyframeIsConstant)
{
  Sequence s(wobble, { 2.0 });
  EXPECT_EQ(timeSteps(s.Interpolator), std::vector<double>({ 2.0 }));
  EXPECT_EQ(largestDifference(s.At(7.0), Sequence::points(s.Keyframes[0])), 0.0);
}

TEST(SurfaceSequenceInterpolator, TimeStepsFollowStepsPerInterval)
{
  Sequence s(wobble, { 0.0, 1.0, 3.0 });
  EXPECT_EQ(s.Interpolator->GetStepsPerInterval(), 1);
  EXPECT_EQ(timeSteps(s.Interpolator), std::vector<double>({ 0.0, 1.0, 3.0 }));
  s.Interpolator->SetStepsPerInterval(4);
  const std::vector<double> expected = { 0.0, 0.25, 0.5, 0.75, 1.0, 1.5, 2.0, 2.5, 3.0 };
  const std::vector<double> steps = timeSteps(s.Interpolator);
  ASSERT_EQ(steps.size(), expected.size());
  for (std::size_t k = 0; k < steps.size(); ++k)
  {
    EXPECT_DOUBLE_EQ(steps[k], expected[k]);
  }
  vtkInformation* info = s.Interpolator->GetOutputInformation(0);
  ASSERT_TRUE(info->Has(vtkStreamingDemandDrivenPipeline::TIME_RANGE()));
  EXPECT_EQ(info->Get(vtkStreamingDemandDrivenPipeline::TIME_RANGE())[0], 0.0);
  EXPECT_EQ(info->Get(vtkStreamingDemandDrivenPipeline::TIME_RANGE())[1], 3.0);
  s.Interpolator->SetStepsPerInterval(0);
  EXPECT_EQ(s.Interpolator->GetStepsPerInterval(), 1);
  s.Interpolator->SetStepsPerInterval(1000000);
  EXPECT_EQ(s.Interpolator->GetStepsPerInterval(), 10000);
}

TEST(SurfaceSequenceInterpolator, TimesMustIncreaseStrictly)
{
  Sequence s(wobble, { 0.0, 1.0, 2.0 });
  std::vector<std::string> errors;
  vtkNew<vtkCallbackCommand> onError;
  onError->SetClientData(&errors);
  onError->SetCallback(
    [](vtkObject*, unsigned long, void* client, void* text) {
      static_cast<std::vector<std::string>*>(client)->emplace_back(static_cast<const char*>(text));
    });
  s.Interpolator->AddObserver(vtkCommand::ErrorEvent, onError);
  s.At(0.5);
  ASSERT_TRUE(errors.empty());
  s.Interpolator->SetKeyframeTime(2, 1.0);
  EXPECT_EQ(s.Interpolator->GetKeyframeTime(2), 1.0);
  s.Interpolator->Update();
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_NE(errors[0].find("the time of keyframe 2 (1) is not larger than that of keyframe 1 (1)"),
    std::string::npos)
    << errors[0];
  EXPECT_EQ(s.Interpolator->GetOutput()->GetNumberOfPoints(), 0);
  EXPECT_TRUE(timeSteps(s.Interpolator).empty());

  // Back to the default times t_k = k.
  s.Interpolator->RemoveAllKeyframeTimes();
  EXPECT_EQ(s.Interpolator->GetKeyframeTime(2), 2.0);
  s.Interpolator->Update();
  EXPECT_EQ(errors.size(), 1u);
  EXPECT_EQ(s.Interpolator->GetOutput()->GetNumberOfPoints(), s.Keyframes[0]->GetNumberOfPoints());

  // Different connectivity names the keyframe.
  s.Interpolator->AddInputData(vtkSurfaceMapsConversion::ToPolyData(surfacemaps::makeIcosphere(2)));
  s.Interpolator->Update();
  ASSERT_EQ(errors.size(), 2u);
  EXPECT_NE(errors[1].find(
              "keyframe 3 does not have the connectivity of keyframe 0: 162 points instead of 42"),
    std::string::npos)
    << errors[1];
  EXPECT_EQ(s.Interpolator->GetOutput()->GetNumberOfPoints(), 0);
}

TEST(SurfaceSequenceInterpolator, TimesOutsideTheRangeAreClamped)
{
  Sequence s(wobble, Times);
  EXPECT_EQ(largestDifference(s.At(-10.0), Sequence::points(s.Keyframes.front())), 0.0);
  vtkPolyData* output = s.Interpolator->GetOutput();
  EXPECT_EQ(output->GetFieldData()->GetArray("InterpolationTime")->GetTuple1(0), 0.0);
  EXPECT_EQ(output->GetInformation()->Get(vtkDataObject::DATA_TIME_STEP()), -10.0);
  EXPECT_EQ(largestDifference(s.At(99.0), Sequence::points(s.Keyframes.back())), 0.0);
  EXPECT_EQ(
    s.Interpolator->GetOutput()->GetFieldData()->GetArray("InterpolationTime")->GetTuple1(0), 5.0);
}

TEST(SurfaceSequenceInterpolator, PlainUpdateUsesTimeValue)
{
  std::vector<vtkSmartPointer<vtkTrivialProducer>> producers;
  vtkNew<vtkSurfaceSequenceInterpolator> interpolator;
  interpolator->SetKeyframeAlignmentToNone();
  std::vector<vtkSmartPointer<vtkPolyData>> keyframes;
  for (int k = 0; k < 3; ++k)
  {
    keyframes.push_back(keyframe(wobble, k));
    producers.push_back(vtkSmartPointer<vtkTrivialProducer>::New());
    producers.back()->SetOutput(keyframes.back());
    interpolator->AddInputConnection(producers.back()->GetOutputPort());
  }
  EXPECT_EQ(interpolator->GetTimeValue(), 0.0);
  interpolator->Update();
  EXPECT_EQ(
    largestDifference(Sequence::points(interpolator->GetOutput()), Sequence::points(keyframes[0])),
    0.0);
  interpolator->SetTimeValue(2.0);
  interpolator->Update();
  EXPECT_EQ(
    largestDifference(Sequence::points(interpolator->GetOutput()), Sequence::points(keyframes[2])),
    0.0);
  // A requested time wins and stays requested.
  interpolator->UpdateTimeStep(1.0);
  EXPECT_EQ(
    largestDifference(Sequence::points(interpolator->GetOutput()), Sequence::points(keyframes[1])),
    0.0);
  interpolator->Update();
  EXPECT_EQ(
    interpolator->GetOutput()->GetFieldData()->GetArray("InterpolationTime")->GetTuple1(0), 1.0);
}

// Categorical arrays (integers by default) are the keyframe nearest in time;
// continuous ones are blended, also an integer array chosen continuous.
TEST(SurfaceSequenceInterpolator, CategoricalArraysComeFromTheNearestKeyframe)
{
  Sequence s(wobble, Times); // keyframes at 0, 1, 2.5, 3, 5
  s.Interpolator->SetInterpolationModeToLinear();
  for (std::size_t k = 0; k < s.Keyframes.size(); ++k)
  {
    vtkNew<vtkIntArray> stage;
    stage->SetName("Stage");
    stage->SetNumberOfValues(s.Keyframes[k]->GetNumberOfPoints());
    stage->Fill(static_cast<int>(10 * k));
    s.Keyframes[k]->GetPointData()->AddArray(stage);
    s.Keyframes[k]->Modified();
  }
  auto valueAt = [&s](double t, const char* name)
  {
    s.Interpolator->UpdateTimeStep(t);
    vtkDataArray* array = s.Interpolator->GetOutput()->GetPointData()->GetArray(name);
    EXPECT_NE(array, nullptr) << name;
    EXPECT_EQ(array->GetRange()[0], array->GetRange()[1]) << name << " at " << t;
    return array ? array->GetTuple1(0) : -1.0;
  };
  EXPECT_EQ(valueAt(0.4, "Stage"), 0.0);
  EXPECT_EQ(valueAt(0.5, "Stage"), 0.0); // the midpoint: the earlier keyframe
  EXPECT_EQ(valueAt(1.6, "Stage"), 10.0);
  EXPECT_EQ(valueAt(2.0, "Stage"), 20.0);
  EXPECT_EQ(valueAt(4.2, "Stage"), 40.0);
  EXPECT_EQ(valueAt(5.0, "Stage"), 40.0);

  // Chosen continuous: blended and rounded (0.3 of the way from 0 to 10).
  s.Interpolator->SetArrayTransferModeToContinuous("Stage");
  EXPECT_EQ(valueAt(0.3, "Stage"), 3.0);
  EXPECT_EQ(valueAt(0.74, "Stage"), 7.0);
  EXPECT_EQ(s.Interpolator->GetOutput()->GetPointData()->GetArray("Stage")->GetDataType(), VTK_INT);

  // A floating-point array chosen categorical: exactly the nearest keyframe's.
  s.Interpolator->SetArrayTransferModeToCategorical("Value");
  s.Interpolator->UpdateTimeStep(1.6);
  vtkDataArray* value = s.Interpolator->GetOutput()->GetPointData()->GetArray("Value");
  vtkDataArray* expected = s.Keyframes[1]->GetPointData()->GetArray("Value");
  ASSERT_NE(value, nullptr);
  for (vtkIdType v = 0; v < expected->GetNumberOfTuples(); ++v)
  {
    ASSERT_EQ(value->GetTuple1(v), expected->GetTuple1(v)) << v;
  }
}

TEST(SurfaceSequenceInterpolator, PrintSelfShowsEverySetting)
{
  vtkNew<vtkSurfaceSequenceInterpolator> interpolator;
  interpolator->SetKeyframeTime(1, 0.5);
  interpolator->SetStepsPerInterval(3);
  interpolator->SetInterpolationMode(7);
  EXPECT_EQ(
    interpolator->GetInterpolationMode(), vtkSurfaceSequenceInterpolator::INTERPOLATE_SMOOTH);
  EXPECT_EQ(interpolator->GetKeyframeAlignment(), vtkSurfaceSequenceInterpolator::ALIGN_RIGID);
  EXPECT_EQ(interpolator->GetShapeBlending(), vtkSurfaceSequenceInterpolator::BLEND_ROTATIONS);
  interpolator->SetKeyframeAlignment(9);
  interpolator->SetShapeBlendingToVertices();
  std::ostringstream print;
  interpolator->Print(print);
  for (const char* part : { "InterpolationMode: 1",
         "KeyframeAlignment: 2",
         "ShapeBlending: 0",
         "StepsPerInterval: 3",
         "TimeValue: 0",
         "KeyframeTimes: 1: 0.5" })
  {
    EXPECT_NE(print.str().find(part), std::string::npos) << part << "\n" << print.str();
  }
}

namespace
{

// An ellipsoid (icosphere level 2, semi-axes 1, 0.6, 0.3) centred on the
// origin, scaled by `scale`, turned by `angle` about `axis` and moved by
// `shift`.
vtkSmartPointer<vtkPolyData> posedEllipsoid(double angle,
  const Eigen::Vector3d& axis,
  const Eigen::Vector3d& shift = Eigen::Vector3d::Zero(),
  double scale = 1.0)
{
  surfacemaps::PolygonMesh mesh = surfacemaps::makeIcosphere(2);
  const Eigen::Matrix3d R = Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix();
  for (Eigen::Vector3d& p : mesh.points)
  {
    p = scale * (R * Eigen::Vector3d(p.x(), 0.6 * p.y(), 0.3 * p.z())) + shift;
  }
  return vtkSurfaceMapsConversion::ToPolyData(mesh);
}

} // namespace

// Keyframes that differ only by pose (and size, with ALIGN_SIMILARITY) are
// one shape: aligned, the series does not move; as given, it rolls.
TEST(SurfaceSequenceInterpolator, PoseChangesAreNotMotion)
{
  const double pi = std::acos(-1.0);
  for (int alignment : { vtkSurfaceSequenceInterpolator::ALIGN_RIGID,
         vtkSurfaceSequenceInterpolator::ALIGN_SIMILARITY })
  {
    const bool similarity = alignment == vtkSurfaceSequenceInterpolator::ALIGN_SIMILARITY;
    vtkNew<vtkSurfaceSequenceInterpolator> interpolator;
    interpolator->SetKeyframeAlignment(alignment);
    interpolator->AddInputData(posedEllipsoid(0.0, Eigen::Vector3d::UnitX()));
    interpolator->AddInputData(posedEllipsoid(
      0.6 * pi, Eigen::Vector3d(1, 1, 0), Eigen::Vector3d(2, 0, 1), similarity ? 1.5 : 1.0));
    interpolator->AddInputData(
      posedEllipsoid(1.2 * pi, Eigen::Vector3d(0, 1, 1), Eigen::Vector3d(-1, 3, 0)));
    interpolator->UpdateTimeStep(0.0);
    const auto first = Sequence::points(interpolator->GetOutput());
    for (double t : { 0.25, 0.5, 1.0, 1.5, 2.0 })
    {
      interpolator->UpdateTimeStep(t);
      EXPECT_LT(largestDifference(Sequence::points(interpolator->GetOutput()), first), 1e-9)
        << "alignment " << alignment << " at t = " << t;
    }
    vtkFieldData* fields = interpolator->GetOutput()->GetFieldData();
    ASSERT_NE(fields->GetArray("AlignmentTransform"), nullptr);
    EXPECT_EQ(fields->GetArray("AlignmentTransform")->GetNumberOfTuples(), 3);
    EXPECT_EQ(fields->GetArray("AlignmentScale") != nullptr, similarity);
    EXPECT_LT(fields->GetArray("AlignmentRMS")->GetRange()[1], 1e-9);

    interpolator->SetKeyframeAlignmentToNone();
    interpolator->UpdateTimeStep(0.5);
    EXPECT_GT(largestDifference(Sequence::points(interpolator->GetOutput()), first), 0.5);
    EXPECT_EQ(interpolator->GetOutput()->GetFieldData()->GetArray("AlignmentTransform"), nullptr);
  }
}

// With BLEND_ROTATIONS a rigid turn between keyframes is interpolated as the
// turn by the interpolated angle; vertex by vertex the shape thins.
TEST(SurfaceSequenceInterpolator, RotationsBlendATurnByItsAngle)
{
  const double pi = std::acos(-1.0);
  const Eigen::Vector3d axis(1, 2, 0.5);
  const double angle = 0.85 * pi;
  vtkNew<vtkSurfaceSequenceInterpolator> interpolator;
  interpolator->SetKeyframeAlignmentToNone();
  interpolator->SetInterpolationModeToLinear();
  interpolator->AddInputData(posedEllipsoid(0.0, axis));
  interpolator->AddInputData(posedEllipsoid(angle, axis));
  for (double u : { 0.3, 0.5, 0.8 })
  {
    interpolator->SetShapeBlendingToRotations();
    interpolator->UpdateTimeStep(u);
    const auto expected = Sequence::points(posedEllipsoid(u * angle, axis));
    EXPECT_LT(largestDifference(Sequence::points(interpolator->GetOutput()), expected), 1e-9) << u;
    interpolator->SetShapeBlendingToVertices();
    interpolator->UpdateTimeStep(u);
    EXPECT_GT(largestDifference(Sequence::points(interpolator->GetOutput()), expected), 0.1) << u;
  }
}
