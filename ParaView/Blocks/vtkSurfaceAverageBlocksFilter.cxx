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
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkCompositeDataSet");
  info->Set(vtkAlgorithm::INPUT_IS_REPEATABLE(), 1);
  return 1;
}

int vtkSurfaceAverageBlocksFilter::RequestData(vtkInformation* request,
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

void vtkSurfaceAverageBlocksFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
