#include "vtkSphereEmbeddingFilter.h"

#include "vtkSurfaceMapsConversion.h"

#include "MeshValidation.h"
#include "SphereEmbedding.h"

#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkLogger.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <string>

vtkStandardNewMacro(vtkSphereEmbeddingFilter);

namespace
{
template<typename ArrayT, typename T>
void addFieldValue(vtkPolyData* output, const char* name, T value)
{
  auto array = vtkSmartPointer<ArrayT>::New();
  array->SetName(name);
  array->InsertNextValue(value);
  output->GetFieldData()->AddArray(array);
}
} // namespace

vtkSphereEmbeddingFilter::vtkSphereEmbeddingFilter() = default;

int vtkSphereEmbeddingFilter::RequestData(vtkInformation*,
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0], 0);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  output->Initialize();
  const std::string name = vtkSurfaceMapsConversion::InputName(input, 0);

  try
  {
    this->SetProgressText("Validating the input");
    const surfacemaps::PolygonMesh mesh = vtkSurfaceMapsConversion::ToPolygonMesh(input);
    const surfacemaps::MeshValidationResult validation = surfacemaps::validateMesh(mesh);
    if (!validation.valid())
    {
      std::string message;
      for (const std::string& defect : validation.defects)
      {
        message += (message.empty() ? "" : "; ") + name + " " + defect;
      }
      vtkErrorMacro(<< message);
      return 0;
    }

    this->SetProgressText("Sphere embedding");
    this->UpdateProgress(0.0);
    surfacemaps::SphereEmbeddingOptions options;
    options.barrierWeight = this->BarrierWeight;
    options.levelIterations = this->LevelIterations;
    options.levelIterationsLarge = this->LargeLevelIterations;
    options.finalIterations = this->FinalIterations;
    options.finalTolerance = this->FinalTolerance;
    options.progress = [this](double fraction)
    {
      this->UpdateProgress(fraction);
      return !this->GetAbortExecute();
    };
    options.log.sink = [](surfacemaps::Logger::Level level, const std::string& message)
    {
      if (level == surfacemaps::Logger::Warning)
      {
        vtkLog(WARNING, << message);
      }
      else
      {
        vtkLog(TRACE, << message);
      }
    };

    const surfacemaps::SphereEmbeddingResult result = surfacemaps::embedOnSphere(mesh, options);

    output->ShallowCopy(input);
    auto sphere = vtkSmartPointer<vtkDoubleArray>::New();
    sphere->SetName("SpherePosition");
    sphere->SetNumberOfComponents(3);
    sphere->SetNumberOfTuples(static_cast<vtkIdType>(result.positions.size()));
    for (std::size_t i = 0; i < result.positions.size(); ++i)
    {
      sphere->SetTuple(static_cast<vtkIdType>(i), result.positions[i].data());
    }
    // ShallowCopy gave the output its own attribute and field data objects
    // (sharing the arrays), so adding arrays leaves the input untouched.
    output->GetPointData()->AddArray(sphere);

    if (this->OutputPointsOnSphere)
    {
      auto original = vtkSmartPointer<vtkDoubleArray>::New();
      original->DeepCopy(input->GetPoints()->GetData());
      original->SetName("InputPosition");
      output->GetPointData()->AddArray(original);
      auto points = vtkSmartPointer<vtkPoints>::New();
      points->SetDataTypeToDouble();
      points->SetData(sphere);
      output->SetPoints(points);
    }

    addFieldValue<vtkDoubleArray>(output, "EmbeddingDistortion", result.distortion);
    addFieldValue<vtkDoubleArray>(output, "EmbeddingEnergy", result.energy);
    addFieldValue<vtkIntArray>(output, "EmbeddingNewtonIterations", result.newtonIterations);
    addFieldValue<vtkIntArray>(output, "EmbeddingLevels", result.levels);
    addFieldValue<vtkIntArray>(output, "EmbeddingAttempt", result.attempt);
    addFieldValue<vtkDoubleArray>(output, "EmbeddingSeconds", result.seconds);
    this->UpdateProgress(1.0);
  }
  catch (const surfacemaps::EmbeddingAborted&)
  {
    output->Initialize();
    return 1;
  }
  catch (const std::exception& e)
  {
    output->Initialize();
    vtkErrorMacro(<< name << ": " << e.what());
    return 0;
  }
  return 1;
}

void vtkSphereEmbeddingFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "OutputPointsOnSphere: " << this->OutputPointsOnSphere << "\n";
  os << indent << "BarrierWeight: " << this->BarrierWeight << "\n";
  os << indent << "LevelIterations: " << this->LevelIterations << "\n";
  os << indent << "LargeLevelIterations: " << this->LargeLevelIterations << "\n";
  os << indent << "FinalIterations: " << this->FinalIterations << "\n";
  os << indent << "FinalTolerance: " << this->FinalTolerance << "\n";
}
