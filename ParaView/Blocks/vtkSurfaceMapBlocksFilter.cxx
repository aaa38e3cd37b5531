#include "vtkSurfaceMapBlocksFilter.h"

#include "vtkCompositeDataPipeline.h"
#include "vtkDataObject.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPolyData.h"
#include "vtkSurfaceMapsBlockList.h"

vtkStandardNewMacro(vtkSurfaceMapBlocksFilter);

vtkSurfaceMapBlocksFilter::vtkSurfaceMapBlocksFilter()
{
  this->SetNumberOfOutputPorts(1);
}

vtkSurfaceMapBlocksFilter::~vtkSurfaceMapBlocksFilter() = default;

void vtkSurfaceMapBlocksFilter::UpdateNumberOfOutputPorts()
{
  // One composite port whatever the connections.
}

int vtkSurfaceMapBlocksFilter::FillInputPortInformation(int, vtkInformation* info)
{
  // Taking composites whole keeps the composite pipeline from running the map
  // once per block.
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkCompositeDataSet");
  info->Set(vtkAlgorithm::INPUT_IS_REPEATABLE(), 1);
  return 1;
}

int vtkSurfaceMapBlocksFilter::FillOutputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkDataObject::DATA_TYPE_NAME(), "vtkMultiBlockDataSet");
  return 1;
}

int vtkSurfaceMapBlocksFilter::RequestInformation(vtkInformation*,
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector)
{
  int n = 0;
  for (int c = 0; c < inputVector[0]->GetNumberOfInformationObjects(); ++c)
  {
    n += vtkSurfaceMapsBlockList::CountSurfaces(inputVector[0]->GetInformationObject(c));
  }
  vtkNew<vtkMultiBlockDataSet> announced;
  announced->SetNumberOfBlocks(static_cast<unsigned int>(n));
  outputVector->GetInformationObject(0)->Set(
    vtkCompositeDataPipeline::COMPOSITE_DATA_META_DATA(), announced);
  return 1;
}

int vtkSurfaceMapBlocksFilter::RequestData(vtkInformation* request,
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector)
{
  vtkMultiBlockDataSet* output = vtkMultiBlockDataSet::GetData(outputVector, 0);
  output->Initialize();
  vtkNew<vtkInformationVector> inputs;
  std::vector<std::string> names;
  if (!vtkSurfaceMapsBlockList::Flatten(this, inputVector[0], inputs, names))
  {
    return 0;
  }
  // vtkSurfaceMapFilter writes output i into the i-th information object of
  // the vector it is given, whatever its own port count.
  vtkNew<vtkInformationVector> outputs;
  const auto surfaces =
    vtkSurfaceMapsBlockList::NewSurfaces(inputs->GetNumberOfInformationObjects(), outputs);
  vtkInformationVector* flatInputs[1] = { inputs };
  const int ok = this->Superclass::RequestData(request, flatInputs, outputs);
  vtkSurfaceMapsBlockList::Gather(surfaces, names, output);
  return ok;
}

void vtkSurfaceMapBlocksFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
