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
  return vtkSurfaceMapsBlockList::FillRepeatableBlocksPort(info);
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
  return vtkSurfaceMapsBlockList::RequestFlattened(this, inputVector[0], outputVector,
    [&](vtkInformationVector** flat)
    { return this->Superclass::RequestData(request, flat, outputVector); });
}

void vtkSurfaceSequenceInterpolatorBlocksFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
