#include "vtkSurfaceMeshValidator.h"

#include "vtkSurfaceMapsConversion.h"

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

} // namespace

int vtkSurfaceMeshValidator::RequestData(vtkInformation*,
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector)
{
  vtkTable* output = vtkTable::GetData(outputVector, 0);
  const int n = inputVector[0]->GetNumberOfInformationObjects();

  auto* name = addColumn<vtkStringArray>(output, "Input", n);
  auto* valid = addColumn<vtkIntArray>(output, "Valid", n);
  auto* points = addColumn<vtkLongLongArray>(output, "Points", n);
  auto* triangles = addColumn<vtkLongLongArray>(output, "Triangles", n);
  auto* edges = addColumn<vtkLongLongArray>(output, "Edges", n);
  auto* genus = addColumn<vtkIntArray>(output, "Genus", n);
  auto* components = addColumn<vtkLongLongArray>(output, "Components", n);
  auto* boundary = addColumn<vtkLongLongArray>(output, "BoundaryEdges", n);
  auto* nmEdges = addColumn<vtkLongLongArray>(output, "NonManifoldEdges", n);
  auto* nmVertices = addColumn<vtkLongLongArray>(output, "NonManifoldVertices", n);
  auto* area = addColumn<vtkDoubleArray>(output, "Area", n);
  auto* diagonal = addColumn<vtkDoubleArray>(output, "BoundingBoxDiagonal", n);
  auto* minAngle = addColumn<vtkDoubleArray>(output, "MinAngle", n);
  auto* meanMinAngle = addColumn<vtkDoubleArray>(output, "MeanMinAngle", n);
  auto* orientation = addColumn<vtkIntArray>(output, "Orientation", n);
  auto* landmarks = addColumn<vtkIntArray>(output, "Landmarks", n);
  auto* defectsColumn = addColumn<vtkStringArray>(output, "Defects", n);

  surfacemaps::MeshValidationOptions options;
  options.zeroAreaFraction = this->ZeroAreaFraction;

  std::vector<std::vector<std::string>> defects(n);
  std::vector<std::vector<int>> landmarkIds(n);
  std::vector<std::string> names(n);
  bool anyLandmarks = false;
  for (int i = 0; i < n; ++i)
  {
    vtkPolyData* input = vtkPolyData::GetData(inputVector[0], i);
    names[i] = vtkSurfaceMapsConversion::InputName(input, i);
    const surfacemaps::MeshValidationResult result =
      surfacemaps::validateMesh(vtkSurfaceMapsConversion::ToPolygonMesh(input), options);
    const surfacemaps::MeshStatistics& s = result.statistics;
    defects[i] = result.defects;

    landmarkIds[i] = vtkSurfaceMapsConversion::LandmarkIds(input);
    if (!landmarkIds[i].empty() &&
      landmarkIds[i].size() != static_cast<std::size_t>(input->GetNumberOfPoints()))
    {
      defects[i].push_back("has a Landmarks array of the wrong length");
      landmarkIds[i].clear();
    }
    const int count = static_cast<int>(
      std::count_if(landmarkIds[i].begin(), landmarkIds[i].end(), [](int id) { return id >= 0; }));
    anyLandmarks = anyLandmarks || count > 0;

    name->SetValue(i, names[i]);
    points->SetValue(i, s.vertices);
    triangles->SetValue(i, s.faces);
    edges->SetValue(i, s.edges);
    genus->SetValue(i, s.genus);
    components->SetValue(i, s.components);
    boundary->SetValue(i, s.boundaryEdges);
    nmEdges->SetValue(i, s.nonManifoldEdges);
    nmVertices->SetValue(i, s.nonManifoldVertices);
    area->SetValue(i, s.area);
    diagonal->SetValue(i, s.boundingBoxDiagonal);
    minAngle->SetValue(i, s.minAngle);
    meanMinAngle->SetValue(i, s.meanMinAngle);
    orientation->SetValue(i, s.orientation);
    landmarks->SetValue(i, count);
  }

  // Landmark ids: unique per input always; the same on all inputs on request.
  std::vector<std::vector<std::string>> correspondence(n);
  if (this->CheckLandmarkCorrespondence && anyLandmarks && n > 1)
  {
    correspondence = surfacemaps::checkLandmarkCorrespondence(landmarkIds, names);
  }
  for (int i = 0; i < n; ++i)
  {
    for (const std::string& d : surfacemaps::checkLandmarkIds(landmarkIds[i]))
    {
      defects[i].push_back(d);
    }
    defects[i].insert(defects[i].end(), correspondence[i].begin(), correspondence[i].end());
  }

  this->AllValid = n > 0;
  for (int i = 0; i < n; ++i)
  {
    std::string text;
    for (const std::string& d : defects[i])
    {
      text += (text.empty() ? "" : "\n") + d;
    }
    defectsColumn->SetValue(i, text);
    valid->SetValue(i, defects[i].empty() ? 1 : 0);
    this->AllValid = this->AllValid && defects[i].empty();
  }
  return 1;
}

void vtkSurfaceMeshValidator::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ZeroAreaFraction: " << this->ZeroAreaFraction << "\n";
  os << indent << "CheckLandmarkCorrespondence: " << this->CheckLandmarkCorrespondence << "\n";
  os << indent << "AllValid: " << this->AllValid << "\n";
}
