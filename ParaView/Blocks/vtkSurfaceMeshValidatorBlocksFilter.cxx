#include "vtkSurfaceMeshValidatorBlocksFilter.h"

#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkTable.h"
#include "vtkSurfaceMapsBlockList.h"

vtkStandardNewMacro(vtkSurfaceMeshValidatorBlocksFilter);

vtkSurfaceMeshValidatorBlocksFilter::vtkSurfaceMeshValidatorBlocksFilter() = default;
vtkSurfaceMeshValidatorBlocksFilter::~vtkSurfaceMeshValidatorBlocksFilter() = default;

int vtkSurfaceMeshValidatorBlocksFilter::FillInputPortInformation(int, vtkInformation* info)
{
  return vtkSurfaceMapsBlockList::FillRepeatableBlocksPort(info);
}

int vtkSurfaceMeshValidatorBlocksFilter::RequestData(vtkInformation* request,
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector)
{
  return vtkSurfaceMapsBlockList::RequestFlattened(this, inputVector[0], outputVector,
    [&](vtkInformationVector** flat)
    { return this->Superclass::RequestData(request, flat, outputVector); });
}

void vtkSurfaceMeshValidatorBlocksFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
