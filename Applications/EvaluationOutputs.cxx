#include "EvaluationOutputs.h"

#include "AtomicFiles.h"
#include "EvaluationSummary.h"

#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"

#include <algorithm>
#include <iomanip>
#include <sstream>

namespace surfacemap
{

namespace
{

// The evaluation's per-triangle arrays and their CSV columns.
const char* const TriangleArrays[] = { "SingularValueMax",
  "SingularValueMin",
  "MaxStretch",
  "AreaSource",
  "AreaTarget" };
const char* const TriangleColumns = "triangle,s1,s2,distortion,area_source,area_target\n";

std::string trianglesCsv(vtkPolyData* result)
{
  std::ostringstream csv;
  csv << TriangleColumns;
  vtkCellData* cd = result->GetCellData();
  for (vtkIdType t = 0; t < result->GetNumberOfCells(); ++t)
  {
    csv << t;
    for (const char* name : TriangleArrays)
    {
      csv << "," << std::setprecision(10) << cd->GetArray(name)->GetTuple1(t);
    }
    csv << "\n";
  }
  return csv.str();
}

std::string curveCsv(vtkPolyData* result)
{
  std::ostringstream curve;
  curve << "distortion,area_fraction_below\n";
  vtkDataArray* samples = result->GetFieldData()->GetArray("DistortionCurve");
  for (vtkIdType k = 0; samples && k < samples->GetNumberOfTuples(); ++k)
  {
    curve << std::setprecision(10) << samples->GetComponent(k, 0) << ","
          << samples->GetComponent(k, 1) << "\n";
  }
  return curve.str();
}

} // namespace

void writeEvaluationTables(vtkPolyData* result, const std::string& prefix)
{
  writeFileAtomically(prefix + "triangles.csv", trianglesCsv(result));
  writeFileAtomically(prefix + "distortion_curve.csv", curveCsv(result));
}

vtkSmartPointer<vtkDoubleArray> sourcePositions(vtkPolyData* source)
{
  double bounds[6];
  source->GetBounds(bounds);
  const double longest =
    std::max({ bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4] });
  const double scale = longest > 0.0 ? 2.0 / longest : 1.0;
  auto positions = vtkSmartPointer<vtkDoubleArray>::New();
  positions->SetName("SourcePosition");
  positions->SetNumberOfComponents(3);
  positions->SetNumberOfTuples(source->GetNumberOfPoints());
  for (vtkIdType v = 0; v < source->GetNumberOfPoints(); ++v)
  {
    double p[3];
    source->GetPoint(v, p);
    for (int k = 0; k < 3; ++k)
    {
      p[k] = (p[k] - 0.5 * (bounds[2 * k] + bounds[2 * k + 1])) * scale;
    }
    positions->SetTuple(v, p);
  }
  return positions;
}

vtkSmartPointer<vtkPolyData> targetWithFigures(vtkPolyData* target,
  vtkPolyData* source,
  vtkPolyData* result)
{
  auto view = vtkSmartPointer<vtkPolyData>::New();
  view->ShallowCopy(target);
  for (const char* name : TriangleArrays)
  {
    view->GetCellData()->AddArray(result->GetCellData()->GetArray(name));
  }
  for (const char* name : evaluationSummaryNames())
  {
    if (vtkDataArray* a = result->GetFieldData()->GetArray(name))
    {
      view->GetFieldData()->AddArray(a);
    }
  }
  view->GetFieldData()->AddArray(result->GetFieldData()->GetArray("DistortionCurve"));
  view->GetPointData()->AddArray(sourcePositions(source));
  return view;
}

} // namespace surfacemap
