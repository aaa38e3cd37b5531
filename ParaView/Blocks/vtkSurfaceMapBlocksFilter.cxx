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

#include <cmath>
#include <vector>

vtkStandardNewMacro(vtkSurfaceMapBlocksFilter);

namespace
{
/// Setting i's value under `preset` for a filter holding `value`: the
/// preset's where `value` is the table default, else `value`.
double effectiveValue(int i, double value, int preset)
{
  if (value != vtkSurfaceMapFilter::GetSettingDefault(i))
  {
    return value;
  }
  vtkNew<vtkSurfaceMapFilter> presetValues;
  presetValues->ApplyPreset(preset);
  return presetValues->GetSetting(i);
}
} // namespace

vtkSurfaceMapBlocksFilter::vtkSurfaceMapBlocksFilter()
{
  // One composite input: adding specimens to an existing map (the map
  // filter's port 1) is not offered here.
  this->SetNumberOfInputPorts(1);
  this->SetNumberOfOutputPorts(1);
}

vtkSurfaceMapBlocksFilter::~vtkSurfaceMapBlocksFilter() = default;

void vtkSurfaceMapBlocksFilter::SetPreset(int preset)
{
  if (preset < 0 || preset >= GetNumberOfPresets())
  {
    vtkErrorMacro(<< "no preset " << preset << " (0 to " << GetNumberOfPresets() - 1 << ")");
    return;
  }
  if (preset != this->Preset)
  {
    this->Preset = preset;
    this->Modified();
  }
}

double vtkSurfaceMapBlocksFilter::GetEffectiveSetting(int i)
{
  const double value = this->GetSetting(i);
  return std::isnan(value) ? value : effectiveValue(i, value, this->Preset);
}

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
  // The map filter reads its two ports (port 1: no existing map here).
  vtkNew<vtkInformationVector> noExistingMap;
  vtkInformationVector* flatInputs[2] = { inputs, noExistingMap };
  // The preset's values for this run only: the settings as set come back
  // afterwards (the time stamps of these changes precede the output's, so
  // they do not make the pipeline run again).
  const int n = GetNumberOfSettings();
  std::vector<double> set(n);
  for (int i = 0; i < n; ++i)
  {
    set[i] = this->GetSetting(i);
  }
  for (int i = 0; i < n; ++i)
  {
    this->SetSetting(i, effectiveValue(i, set[i], this->Preset));
  }
  const int ok = this->Superclass::RequestData(request, flatInputs, outputs);
  for (int i = 0; i < n; ++i)
  {
    this->SetSetting(i, set[i]);
  }
  vtkSurfaceMapsBlockList::Gather(surfaces, names, output);
  return ok;
}

void vtkSurfaceMapBlocksFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Preset: " << GetPresetName(this->Preset) << "\n";
}
