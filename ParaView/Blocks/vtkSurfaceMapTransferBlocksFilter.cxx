#include "vtkSurfaceMapTransferBlocksFilter.h"

#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPolyData.h"
#include "vtkSurfaceMapsBlockList.h"

vtkStandardNewMacro(vtkSurfaceMapTransferBlocksFilter);

vtkSurfaceMapTransferBlocksFilter::vtkSurfaceMapTransferBlocksFilter()
{
  this->SetNumberOfInputPorts(2);
}

vtkSurfaceMapTransferBlocksFilter::~vtkSurfaceMapTransferBlocksFilter() = default;

int vtkSurfaceMapTransferBlocksFilter::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkCompositeDataSet");
  info->Set(vtkAlgorithm::INPUT_IS_REPEATABLE(), 1);
  return 1;
}

int vtkSurfaceMapTransferBlocksFilter::RequestData(vtkInformation* request,
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector)
{
  vtkPolyData::GetData(outputVector, 0)->Initialize();
  vtkNew<vtkInformationVector> embeddings, commons;
  std::vector<std::string> names;
  if (!vtkSurfaceMapsBlockList::Flatten(this, inputVector[0], embeddings, names) ||
    !vtkSurfaceMapsBlockList::Flatten(this, inputVector[1], commons, names))
  {
    return 0;
  }
  // vtkSurfaceMapTransfer's ports: target mesh, source mesh, T on each.
  vtkNew<vtkInformationVector> target, source, targetCommon, sourceCommon;
  using List = vtkSurfaceMapsBlockList;
  if (!List::Pick(this, embeddings, this->TargetIndex, "target embedding", target) ||
    !List::Pick(this, embeddings, this->SourceIndex, "source embedding", source) ||
    !List::Pick(this, commons, this->TargetIndex, "target common triangulation", targetCommon) ||
    !List::Pick(this, commons, this->SourceIndex, "source common triangulation", sourceCommon))
  {
    return 0;
  }
  vtkInformationVector* ports[4] = { target, source, targetCommon, sourceCommon };
  return this->Superclass::RequestData(request, ports, outputVector);
}

void vtkSurfaceMapTransferBlocksFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "SourceIndex: " << this->SourceIndex << "\n";
  os << indent << "TargetIndex: " << this->TargetIndex << "\n";
}
