#include "vtkSurfaceAverageBlocksFilter.h"

#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPolyData.h"
#include "vtkSurfaceMapsBlockList.h"

vtkStandardNewMacro(vtkSurfaceAverageBlocksFilter);

vtkSurfaceAverageBlocksFilter::vtkSurfaceAverageBlocksFilter() = default;
vtkSurfaceAverageBlocksFilter::~vtkSurfaceAverageBlocksFilter() = default;

int vtkSurfaceAverageBlocksFilter::FillInputPortInformation(int, vtkInformation* info)
{
  return vtkSurfaceMapsBlockList::FillRepeatableBlocksPort(info);
}

int vtkSurfaceAverageBlocksFilter::RequestData(vtkInformation* request,
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector)
{
  return vtkSurfaceMapsBlockList::RequestFlattened(this, inputVector[0], outputVector,
    [&](vtkInformationVector** flat)
    { return this->Superclass::RequestData(request, flat, outputVector); });
}

void vtkSurfaceAverageBlocksFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
