#include "vtkSurfaceMeshValidator.h"

#include "vtkSurfaceMapsConversion.h"
#include "vtkSurfaceMapsErrorGuard.h"
#include "vtkSurfaceMapsExecutive.h"

#include "mesh/LandmarkValidation.h"
#include "mesh/MeshValidation.h"

#include "vtkAlgorithm.h"
#include "vtkDoubleArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkLongLongArray.h"
#include "vtkObjectFactory.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkStringArray.h"
#include "vtkTable.h"

#include <algorithm>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkSurfaceMeshValidator);

vtkSurfaceMeshValidator::vtkSurfaceMeshValidator()
{
  this->SetNumberOfInputPorts(1);
  this->SetNumberOfOutputPorts(1);
}

int vtkSurfaceMeshValidator::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  info->Set(vtkAlgorithm::INPUT_IS_REPEATABLE(), 1);
  return 1;
}

namespace
{

template<typename ArrayT>
ArrayT* addColumn(vtkTable* table, const char* name, vtkIdType rows)
{
  auto array = vtkSmartPointer<ArrayT>::New();
  array->SetName(name);
  array->SetNumberOfValues(rows);
  table->AddColumn(array);
  return array;
}

// The table's columns, one row per input.
struct Columns
{
  Columns(vtkTable* output, vtkIdType n)
    : Name(addColumn<vtkStringArray>(output, "Input", n))
    , Valid(addColumn<vtkIntArray>(output, "Valid", n))
    , Points(addColumn<vtkLongLongArray>(output, "Points", n))
    , Triangles(addColumn<vtkLongLongArray>(output, "Triangles", n))
    , Edges(addColumn<vtkLongLongArray>(output, "Edges", n))
    , Genus(addColumn<vtkIntArray>(output, "Genus", n))
    , Components(addColumn<vtkLongLongArray>(output, "Components", n))
    , Boundary(addColumn<vtkLongLongArray>(output, "BoundaryEdges", n))
    , NonManifoldEdges(addColumn<vtkLongLongArray>(output, "NonManifoldEdges", n))
    , NonManifoldVertices(addColumn<vtkLongLongArray>(output, "NonManifoldVertices", n))
    , Area(addColumn<vtkDoubleArray>(output, "Area", n))
    , Diagonal(addColumn<vtkDoubleArray>(output, "BoundingBoxDiagonal", n))
    , MinAngle(addColumn<vtkDoubleArray>(output, "MinAngle", n))
    , MeanMinAngle(addColumn<vtkDoubleArray>(output, "MeanMinAngle", n))
    , Orientation(addColumn<vtkIntArray>(output, "Orientation", n))
    , Landmarks(addColumn<vtkIntArray>(output, "Landmarks", n))
    , Defects(addColumn<vtkStringArray>(output, "Defects", n))
  {
  }

  vtkStringArray* Name;
  vtkIntArray* Valid;
  vtkLongLongArray* Points;
  vtkLongLongArray* Triangles;
  vtkLongLongArray* Edges;
  vtkIntArray* Genus;
  vtkLongLongArray* Components;
  vtkLongLongArray* Boundary;
  vtkLongLongArray* NonManifoldEdges;
  vtkLongLongArray* NonManifoldVertices;
  vtkDoubleArray* Area;
  vtkDoubleArray* Diagonal;
  vtkDoubleArray* MinAngle;
  vtkDoubleArray* MeanMinAngle;
  vtkIntArray* Orientation;
  vtkIntArray* Landmarks;
  vtkStringArray* Defects;
};

// What validation found for one input.
struct InputReport
{
  std::string Name;
  std::vector<std::string> Defects;
  std::vector<int> LandmarkIds; // empty when absent or of the wrong length
};

// Validates input i and fills its row (all but Valid and Defects).
InputReport validateInput(vtkPolyData* input,
  int i,
  const surfacemaps::MeshValidationOptions& options,
  Columns& columns)
{
  InputReport report;
  report.Name = vtkSurfaceMapsConversion::InputName(input, i);
  vtkSurfaceMapsConversion::ValidatedInput validated =
    vtkSurfaceMapsConversion::Validate(input, options);
  const surfacemaps::MeshStatistics& s = validated.validation.statistics;
  report.Defects = validated.validation.defects;
  report.LandmarkIds = std::move(validated.landmarkIds);
  const int count = static_cast<int>(std::count_if(
    report.LandmarkIds.begin(), report.LandmarkIds.end(), [](int id) { return id >= 0; }));

  columns.Name->SetValue(i, report.Name);
  columns.Points->SetValue(i, s.vertices);
  columns.Triangles->SetValue(i, s.faces);
  columns.Edges->SetValue(i, s.edges);
  columns.Genus->SetValue(i, s.genus);
  columns.Components->SetValue(i, s.components);
  columns.Boundary->SetValue(i, s.boundaryEdges);
  columns.NonManifoldEdges->SetValue(i, s.nonManifoldEdges);
  columns.NonManifoldVertices->SetValue(i, s.nonManifoldVertices);
  columns.Area->SetValue(i, s.area);
  columns.Diagonal->SetValue(i, s.boundingBoxDiagonal);
  columns.MinAngle->SetValue(i, s.minAngle);
  columns.MeanMinAngle->SetValue(i, s.meanMinAngle);
  columns.Orientation->SetValue(i, s.orientation);
  columns.Landmarks->SetValue(i, count);
  return report;
}

// Landmark ids (each input's own checked by Validate): the same on all
// inputs on request (when any input has landmarks).
void addLandmarkDefects(std::vector<InputReport>& reports, bool checkCorrespondence)
{
  const std::size_t n = reports.size();
  std::vector<std::vector<int>> landmarkIds(n);
  std::vector<std::string> names(n);
  bool anyLandmarks = false;
  for (std::size_t i = 0; i < n; ++i)
  {
    landmarkIds[i] = reports[i].LandmarkIds;
    names[i] = reports[i].Name;
    anyLandmarks = anyLandmarks ||
      std::any_of(landmarkIds[i].begin(), landmarkIds[i].end(), [](int id) { return id >= 0; });
  }
  std::vector<std::vector<std::string>> correspondence(n);
  if (checkCorrespondence && anyLandmarks && n > 1)
  {
    correspondence = surfacemaps::checkLandmarkCorrespondence(landmarkIds, names);
  }
  for (std::size_t i = 0; i < n; ++i)
  {
    std::vector<std::string>& defects = reports[i].Defects;
    defects.insert(defects.end(), correspondence[i].begin(), correspondence[i].end());
  }
}

// The Valid and Defects columns (one line per defect); true when every input
// is valid and there is at least one.
bool writeDefects(const std::vector<InputReport>& reports, Columns& columns)
{
  bool allValid = !reports.empty();
  for (std::size_t i = 0; i < reports.size(); ++i)
  {
    std::string text;
    for (const std::string& d : reports[i].Defects)
    {
      text += (text.empty() ? "" : "\n") + d;
    }
    const vtkIdType row = static_cast<vtkIdType>(i);
    columns.Defects->SetValue(row, text);
    columns.Valid->SetValue(row, reports[i].Defects.empty() ? 1 : 0);
    allValid = allValid && reports[i].Defects.empty();
  }
  return allValid;
}

} // namespace

int vtkSurfaceMeshValidator::RequestData(vtkInformation*,
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector)
{
  vtkTable* output = vtkTable::GetData(outputVector, 0);
  const int n = inputVector[0]->GetNumberOfInformationObjects();
  surfacemaps::MeshValidationOptions options;
  options.zeroAreaFraction = this->ZeroAreaFraction;

  return vtkSurfaceMapsErrorGuard::Run(
    this,
    vtkSurfaceMapsErrorGuard::Policy(),
    [&]
    {
      Columns columns(output, n);
      std::vector<InputReport> reports;
      for (int i = 0; i < n; ++i)
      {
        reports.push_back(
          validateInput(vtkPolyData::GetData(inputVector[0], i), i, options, columns));
      }
      addLandmarkDefects(reports, this->CheckLandmarkCorrespondence);
      this->AllValid = writeDefects(reports, columns);
      return 1;
    },
    [this, output]
    {
      output->Initialize();
      this->AllValid = false;
    });
}

const char* vtkSurfaceMeshValidator::GetLastErrorMessage() const
{
  return vtkSurfaceMapsErrorGuard::LastErrorMessage(this);
}

vtkExecutive* vtkSurfaceMeshValidator::CreateDefaultExecutive()
{
  return vtkSurfaceMapsExecutive::New();
}

void vtkSurfaceMeshValidator::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ZeroAreaFraction: " << this->ZeroAreaFraction << "\n";
  os << indent << "CheckLandmarkCorrespondence: " << this->CheckLandmarkCorrespondence << "\n";
  os << indent << "AllValid: " << this->AllValid << "\n";
}
