#include "vtkSurfaceSequenceInterpolatorBlocksFilter.h"

#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPolyData.h"
#include "vtkSurfaceMapsBlockList.h"

vtkStandardNewMacro(vtkSurfaceSequenceInterpolatorBlocksFilter);

vtkSurfaceSequenceInterpolatorBlocksFilter::vtkSurfaceSequenceInterpolatorBlocksFilter() = default;
vtkSurfaceSequenceInterpolatorBlocksFilter::~vtkSurfaceSequenceInterpolatorBlocksFilter() = default;

int vtkSurfaceSequenceInterpolatorBlocksFilter::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkCompositeDataSet");
  info->Set(vtkAlgorithm::INPUT_IS_REPEATABLE(), 1);
  return 1;
}

int vtkSurfaceSequenceInterpolatorBlocksFilter::RequestInformation(vtkInformation* request,
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector)
{
  // The superclass only counts the keyframes here: one empty information
  // object per announced surface.
  int n = 0;
  for (int c = 0; c < inputVector[0]->GetNumberOfInformationObjects(); ++c)
  {
    n += vtkSurfaceMapsBlockList::CountSurfaces(inputVector[0]->GetInformationObject(c));
  }
  vtkNew<vtkInformationVector> keyframes;
  for (int k = 0; k < n; ++k)
  {
    vtkNew<vtkInformation> info;
    keyframes->Append(info);
  }
  vtkInformationVector* flatInputs[1] = { keyframes };
  return this->Superclass::RequestInformation(request, flatInputs, outputVector);
}

int vtkSurfaceSequenceInterpolatorBlocksFilter::RequestData(vtkInformation* request,
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

void vtkSurfaceSequenceInterpolatorBlocksFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
