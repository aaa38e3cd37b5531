// The `surfacemap` command line: measuring a map and reading its summary
// figures.
#include "EvaluationSummary.h"

#include "AlgorithmMessages.h"
#include "Json.h"

#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkSurfaceMapEvaluation.h"

#include <algorithm>
#include <limits>
#include <stdexcept>

namespace surfacemap
{

std::string zeroAreaTriangles(vtkPolyData* mesh, const std::string& what)
{
  vtkCellArray* polys = mesh->GetPolys();
  vtkIdType count = 0, first = -1;
  for (vtkIdType t = 0; t < polys->GetNumberOfCells(); ++t)
  {
    vtkIdType n = 0;
    const vtkIdType* corners = nullptr;
    polys->GetCellAtId(t, n, corners);
    const vtkIdType points = mesh->GetNumberOfPoints();
    if (n != 3 ||
      !std::all_of(corners, corners + 3, [points](vtkIdType p) { return p >= 0 && p < points; }))
    {
      continue; // not a triangle, or indices out of range: the evaluation names them
    }
    double p[3][3];
    for (int k = 0; k < 3; ++k)
    {
      mesh->GetPoint(corners[k], p[k]);
    }
    double u[3], v[3], normal[3];
    vtkMath::Subtract(p[1], p[0], u);
    vtkMath::Subtract(p[2], p[0], v);
    vtkMath::Cross(u, v, normal);
    if (vtkMath::Norm(normal) == 0.0)
    {
      first = first < 0 ? t : first;
      ++count;
    }
  }
  if (count == 0)
  {
    return {};
  }
  return what + " has " + std::to_string(count) + " zero-area triangle" + (count == 1 ? "" : "s") +
    " (the first is triangle " + std::to_string(first) +
    "): no map's distortion is defined on them; evaluate needs triangles of positive area";
}

vtkSmartPointer<vtkPolyData> measureMap(vtkPolyData* source,
  vtkPolyData* target,
  vtkPolyData* sourceOriginal,
  vtkPolyData* targetOriginal)
{
  vtkNew<vtkSurfaceMapEvaluation> evaluation;
  ErrorCapture errors(evaluation);
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
  if (!errors.messages().empty())
  {
    throw std::invalid_argument(errors.messages().front());
  }
  vtkSmartPointer<vtkPolyData> result = evaluation->GetOutput();
  return result;
}

const std::vector<const char*>& evaluationSummaryNames()
{
  static const std::vector<const char*> names = { "SymmetricDirichlet",
    "AreaBelow1.5",
    "AreaBelow2",
    "MaxDistortion",
    "DegenerateTriangles",
    "MinAngleSource",
    "MeanMinAngleSource",
    "MinAngleTarget",
    "MeanMinAngleTarget",
    "HausdorffSource",
    "HausdorffTarget",
    "TwoSidedDistanceSource",
    "TwoSidedDistanceTarget",
    "Bijective",
    "NonPositiveTriangles" };
  return names;
}

double summaryValue(vtkPolyData* result, const char* name)
{
  vtkDataArray* a = result->GetFieldData()->GetArray(name);
  return a && a->GetNumberOfTuples() > 0 ? a->GetTuple1(0)
                                         : std::numeric_limits<double>::quiet_NaN();
}

Json::Value summaryJson(vtkPolyData* result)
{
  Json::Value figures(Json::objectValue);
  for (const char* name : evaluationSummaryNames())
  {
    if (result->GetFieldData()->GetArray(name))
    {
      figures[name] = jsonNumber(summaryValue(result, name));
    }
  }
  return figures;
}

} // namespace surfacemap
