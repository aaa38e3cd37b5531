// The `surfacemap` command line: measuring a map and reading its summary
// figures.
#include "EvaluationSummary.h"

#include "AlgorithmMessages.h"
#include "Json.h"

#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkSurfaceMapEvaluation.h"

#include <limits>
#include <stdexcept>

namespace surfacemap
{

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
