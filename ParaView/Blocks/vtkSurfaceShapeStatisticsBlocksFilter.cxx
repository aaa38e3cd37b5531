#include "vtkSurfaceShapeStatisticsBlocksFilter.h"

#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPolyData.h"
#include "vtkSurfaceMapsBlockList.h"

vtkStandardNewMacro(vtkSurfaceShapeStatisticsBlocksFilter);

vtkSurfaceShapeStatisticsBlocksFilter::vtkSurfaceShapeStatisticsBlocksFilter() = default;
vtkSurfaceShapeStatisticsBlocksFilter::~vtkSurfaceShapeStatisticsBlocksFilter() = default;

int vtkSurfaceShapeStatisticsBlocksFilter::FillInputPortInformation(int, vtkInformation* info)
{
  return vtkSurfaceMapsBlockList::FillRepeatableBlocksPort(info);
}

int vtkSurfaceShapeStatisticsBlocksFilter::RequestData(vtkInformation* request,
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector)
{
  return vtkSurfaceMapsBlockList::RequestFlattened(this, inputVector[0], outputVector,
    [&](vtkInformationVector** flat)
    { return this->Superclass::RequestData(request, flat, outputVector); });
}

void vtkSurfaceShapeStatisticsBlocksFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
