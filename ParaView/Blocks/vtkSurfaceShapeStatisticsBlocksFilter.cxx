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
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkCompositeDataSet");
  info->Set(vtkAlgorithm::INPUT_IS_REPEATABLE(), 1);
  return 1;
}

int vtkSurfaceShapeStatisticsBlocksFilter::RequestData(vtkInformation* request,
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector)
{
  vtkNew<vtkInformationVector> inputs;
  std::vector<std::string> names;
  if (!vtkSurfaceMapsBlockList::Flatten(this, inputVector[0], inputs, names))
  {
    vtkPolyData::GetData(outputVector, 0)->Initialize();
    return 0;
  }
  vtkInformationVector* flatInputs[1] = { inputs };
  return this->Superclass::RequestData(request, flatInputs, outputVector);
}

void vtkSurfaceShapeStatisticsBlocksFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
