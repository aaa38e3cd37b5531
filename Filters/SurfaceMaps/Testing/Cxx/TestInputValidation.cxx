// The module's one input validation seen through its filters: 64-bit vertex
// ids, the Landmarks array's shape and values, and what evaluation accepts.
#include "FilterTestData.h"
#include "vtkSphereEmbeddingFilter.h"
#include "vtkSurfaceAverage.h"
#include "vtkSurfaceMapEvaluation.h"
#include "vtkSurfaceMeshValidator.h"

#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkIdTypeArray.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkTable.h"
#include "vtkVariant.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace
{
using filtertest::read;

vtkSmartPointer<vtkPolyData> copyOf(vtkPolyData* mesh)
{
  auto copy = vtkSmartPointer<vtkPolyData>::New();
  copy->DeepCopy(mesh);
  return copy;
}

// The validator's defects for one input ("" when valid).
std::string defectsOf(vtkPolyData* mesh)
{
  vtkNew<vtkSurfaceMeshValidator> validator;
  validator->AddInputDataObject(mesh);
  validator->Update();
  return validator->GetOutput()->GetValueByName(0, "Defects").ToString();
}

// The evaluation's first error message ("" when it succeeded).
std::string evaluationError(vtkPolyData* source,
  vtkPolyData* target,
  vtkPolyData* sourceOriginal = nullptr,
  vtkPolyData* targetOriginal = nullptr)
{
  vtkNew<vtkSurfaceMapEvaluation> evaluation;
  filtertest::Events events;
  filtertest::watch(evaluation, events);
  evaluation->SetInputDataObject(0, source);
  evaluation->SetInputDataObject(1, target);
  if (sourceOriginal)
  {
    evaluation->SetInputDataObject(2, sourceOriginal);
  }
  if (targetOriginal)
  {
    evaluation->SetInputDataObject(3, targetOriginal);
  }
  evaluation->Update();
  return events.Errors.empty() ? std::string() : events.Errors.front();
}

// A copy of `mesh` whose polygon connectivity (64-bit ids) holds `value` at `position`.
vtkSmartPointer<vtkPolyData> withIndex(vtkPolyData* mesh, vtkIdType position, vtkIdType value)
{
  vtkSmartPointer<vtkPolyData> copy = copyOf(mesh);
  vtkNew<vtkIdTypeArray> offsets;
  offsets->DeepCopy(mesh->GetPolys()->GetOffsetsArray());
  vtkNew<vtkIdTypeArray> connectivity;
  connectivity->DeepCopy(mesh->GetPolys()->GetConnectivityArray());
  connectivity->SetValue(position, value);
  vtkNew<vtkCellArray> polys;
  polys->SetData(offsets, connectivity);
  copy->SetPolys(polys);
  return copy;
}

void setLandmarks(vtkPolyData* mesh, vtkDataArray* array)
{
  array->SetName("Landmarks");
  mesh->GetPointData()->AddArray(array);
}

bool contains(const std::string& text, const std::string& part)
{
  return text.find(part) != std::string::npos;
}
} // namespace

TEST(InputValidation, SixtyFourBitIndexIsRejectedNotWrapped)
{
  // 2^32 + 3 would wrap to vertex 3, a valid index, if cast to int.
  vtkSmartPointer<vtkPolyData> mesh = withIndex(read("ellipsoid.obj"), 4, 4294967299LL);
  const std::string defects = defectsOf(mesh);
  EXPECT_TRUE(contains(defects, "face 1 uses vertex index 4294967299")) << defects;

  const std::string error = evaluationError(mesh, mesh);
  EXPECT_TRUE(contains(error, "4294967299")) << error;
}

TEST(InputValidation, LandmarksWithTwoComponentsAreRejected)
{
  vtkSmartPointer<vtkPolyData> mesh = copyOf(read("ellipsoid.obj"));
  vtkNew<vtkIntArray> landmarks;
  landmarks->SetNumberOfComponents(2);
  landmarks->SetNumberOfTuples(mesh->GetNumberOfPoints());
  landmarks->Fill(-1);
  landmarks->SetComponent(5, 0, 0);
  setLandmarks(mesh, landmarks);
  EXPECT_TRUE(contains(defectsOf(mesh), "Landmarks array with 2 components")) << defectsOf(mesh);

  vtkNew<vtkSphereEmbeddingFilter> embedding;
  filtertest::Events events;
  filtertest::watch(embedding, events);
  embedding->SetInputData(mesh);
  embedding->Update();
  ASSERT_FALSE(events.Errors.empty());
  EXPECT_TRUE(contains(events.Errors.front(), "2 components")) << events.Errors.front();
  EXPECT_EQ(embedding->GetOutput()->GetNumberOfPoints(), 0);
}

TEST(InputValidation, NonIntegerLandmarkIdsAreRejected)
{
  vtkSmartPointer<vtkPolyData> mesh = copyOf(read("ellipsoid.obj"));
  vtkNew<vtkDoubleArray> landmarks;
  landmarks->SetNumberOfTuples(mesh->GetNumberOfPoints());
  landmarks->Fill(-1.0);
  landmarks->SetValue(3, 0.0);
  landmarks->SetValue(9, 1.0);
  setLandmarks(mesh, landmarks);
  EXPECT_EQ(defectsOf(mesh), ""); // integer-valued floats are ids

  landmarks->SetValue(9, 1.5);
  EXPECT_TRUE(contains(defectsOf(mesh), "not an integer (1.5 at vertex 9)")) << defectsOf(mesh);
  landmarks->SetValue(9, NAN);
  EXPECT_TRUE(contains(defectsOf(mesh), "not an integer")) << defectsOf(mesh);
}

TEST(InputValidation, EvaluationRejectsWhatItCannotMeasure)
{
  vtkNew<vtkPolyData> empty;
  EXPECT_TRUE(contains(evaluationError(empty, empty), "contains no vertices"));

  vtkSmartPointer<vtkPolyData> mesh = read("ellipsoid.obj");
  vtkNew<vtkPolyData> pointsOnly;
  pointsOnly->SetPoints(mesh->GetPoints());
  EXPECT_TRUE(contains(evaluationError(pointsOnly, pointsOnly), "contains no triangles"));

  vtkSmartPointer<vtkPolyData> outOfRange = withIndex(mesh, 0, 100000);
  std::string error = evaluationError(outOfRange, outOfRange);
  EXPECT_TRUE(contains(error, "uses vertex index 100000")) << error;
  outOfRange = withIndex(mesh, 0, -5);
  error = evaluationError(outOfRange, outOfRange);
  EXPECT_TRUE(contains(error, "uses vertex index -5")) << error;
  outOfRange = withIndex(mesh, 0, 1000000000000LL);
  error = evaluationError(outOfRange, outOfRange);
  EXPECT_TRUE(contains(error, "uses vertex index 1000000000000")) << error;

  vtkSmartPointer<vtkPolyData> nanOriginal = copyOf(mesh);
  nanOriginal->GetPoints()->SetPoint(17, NAN, 0.0, 0.0);
  error = evaluationError(mesh, mesh, nanOriginal, mesh);
  EXPECT_TRUE(contains(error, "non-finite coordinates (first: vertex 17")) << error;

  EXPECT_EQ(evaluationError(mesh, mesh, mesh, mesh), "");
}

TEST(InputValidation, AverageRejectsIndicesOutsideThePoints)
{
  vtkSmartPointer<vtkPolyData> mesh = read("ellipsoid.obj");
  for (const vtkIdType bad : { vtkIdType(-2), vtkIdType(642), vtkIdType(4294967299LL) })
  {
    vtkSmartPointer<vtkPolyData> broken = withIndex(mesh, 7, bad);
    vtkNew<vtkSurfaceAverage> average;
    filtertest::Events events;
    filtertest::watch(average, events);
    average->AddInputData(broken);
    average->AddInputData(broken);
    average->Update();
    ASSERT_FALSE(events.Errors.empty()) << bad;
    EXPECT_TRUE(contains(events.Errors.front(), "cell 2 uses vertex index " + std::to_string(bad)))
      << events.Errors.front();
    EXPECT_EQ(average->GetOutput()->GetNumberOfPoints(), 0);
  }
}
