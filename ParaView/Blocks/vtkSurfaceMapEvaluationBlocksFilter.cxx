#include "vtkSurfaceMapEvaluationBlocksFilter.h"

#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPolyData.h"
#include "vtkSurfaceMapsBlockList.h"

vtkStandardNewMacro(vtkSurfaceMapEvaluationBlocksFilter);

vtkSurfaceMapEvaluationBlocksFilter::vtkSurfaceMapEvaluationBlocksFilter()
{
  this->SetNumberOfInputPorts(2);
}

vtkSurfaceMapEvaluationBlocksFilter::~vtkSurfaceMapEvaluationBlocksFilter() = default;

int vtkSurfaceMapEvaluationBlocksFilter::FillInputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkCompositeDataSet");
  info->Set(vtkAlgorithm::INPUT_IS_REPEATABLE(), 1);
  if (port == 1)
  {
    info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  }
  return 1;
}

int vtkSurfaceMapEvaluationBlocksFilter::RequestData(vtkInformation* request,
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector)
{
  vtkPolyData::GetData(outputVector, 0)->Initialize();
  vtkNew<vtkInformationVector> surfaces, originals;
  std::vector<std::string> names;
  if (!vtkSurfaceMapsBlockList::Flatten(this, inputVector[0], surfaces, names) ||
    !vtkSurfaceMapsBlockList::Flatten(this, inputVector[1], originals, names))
  {
    return 0;
  }
  // vtkSurfaceMapEvaluation's ports: P, Q, and optionally their originals.
  vtkNew<vtkInformationVector> source, target, sourceOriginal, targetOriginal;
  if (!vtkSurfaceMapsBlockList::Pick(this, surfaces, this->SourceIndex, "source", source) ||
    !vtkSurfaceMapsBlockList::Pick(this, surfaces, this->TargetIndex, "target", target))
  {
    return 0;
  }
  if (originals->GetNumberOfInformationObjects() > 0 &&
    (!vtkSurfaceMapsBlockList::Pick(this, originals, this->SourceIndex, "source original", sourceOriginal) ||
      !vtkSurfaceMapsBlockList::Pick(this, originals, this->TargetIndex, "target original", targetOriginal)))
  {
    return 0;
  }
  vtkInformationVector* ports[4] = { source, target, sourceOriginal, targetOriginal };
  return this->Superclass::RequestData(request, ports, outputVector);
}

void vtkSurfaceMapEvaluationBlocksFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "SourceIndex: " << this->SourceIndex << "\n";
  os << indent << "TargetIndex: " << this->TargetIndex << "\n";
}
