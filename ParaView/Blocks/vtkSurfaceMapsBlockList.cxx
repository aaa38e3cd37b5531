#include "vtkSurfaceMapsBlockList.h"

#include "vtkAlgorithm.h"
#include "vtkCompositeDataIterator.h"
#include "vtkCompositeDataPipeline.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataObject.h"
#include "vtkFieldData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkStringArray.h"

namespace
{
std::string baseName(const std::string& path)
{
  const std::size_t slash = path.find_last_of("/\\");
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

// The surface's own name: the reader's "FileName" field data.
std::string fileNameOf(vtkDataObject* data)
{
  vtkFieldData* field = data->GetFieldData();
  auto* names = field ? vtkStringArray::SafeDownCast(field->GetAbstractArray("FileName")) : nullptr;
  return names && names->GetNumberOfValues() > 0 ? baseName(names->GetValue(0)) : std::string();
}

bool append(vtkAlgorithm* self,
  vtkDataObject* leaf,
  const std::string& blockName,
  vtkInformationVector* flat,
  std::vector<std::string>& names)
{
  const int k = flat->GetNumberOfInformationObjects();
  std::string name = fileNameOf(leaf);
  if (name.empty())
  {
    name = blockName.empty() ? "surface " + std::to_string(k) : blockName;
  }
  if (!vtkPolyData::SafeDownCast(leaf))
  {
    vtkErrorWithObjectMacro(self,
      << "surface " << k << " (" << name << ") is a " << leaf->GetClassName()
      << ", not a vtkPolyData: extract its surface first");
    return false;
  }
  vtkNew<vtkInformation> info;
  info->Set(vtkDataObject::DATA_OBJECT(), leaf);
  flat->Append(info);
  names.push_back(name);
  return true;
}
} // namespace

int vtkSurfaceMapsBlockList::FillRepeatableBlocksPort(vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkCompositeDataSet");
  info->Set(vtkAlgorithm::INPUT_IS_REPEATABLE(), 1);
  return 1;
}

int vtkSurfaceMapsBlockList::RequestFlattened(vtkAlgorithm* self,
  vtkInformationVector* port,
  vtkInformationVector* output,
  const std::function<int(vtkInformationVector**)>& run)
{
  vtkNew<vtkInformationVector> inputs;
  std::vector<std::string> names;
  if (!Flatten(self, port, inputs, names))
  {
    vtkDataObject::GetData(output, 0)->Initialize();
    return 0;
  }
  vtkInformationVector* flatInputs[1] = { inputs };
  return run(flatInputs);
}

bool vtkSurfaceMapsBlockList::Flatten(vtkAlgorithm* self,
  vtkInformationVector* port,
  vtkInformationVector* flat,
  std::vector<std::string>& names)
{
  for (int c = 0; c < port->GetNumberOfInformationObjects(); ++c)
  {
    vtkDataObject* data = port->GetInformationObject(c)->Get(vtkDataObject::DATA_OBJECT());
    auto* composite = vtkCompositeDataSet::SafeDownCast(data);
    if (!composite)
    {
      if (data && !append(self, data, std::string(), flat, names))
      {
        return false;
      }
      continue;
    }
    vtkSmartPointer<vtkCompositeDataIterator> it;
    it.TakeReference(composite->NewIterator());
    it->SkipEmptyNodesOn();
    for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem())
    {
      std::string blockName;
      if (it->HasCurrentMetaData() && it->GetCurrentMetaData()->Has(vtkCompositeDataSet::NAME()))
      {
        blockName = it->GetCurrentMetaData()->Get(vtkCompositeDataSet::NAME());
      }
      if (!append(self, it->GetCurrentDataObject(), blockName, flat, names))
      {
        return false;
      }
    }
  }
  return true;
}

int vtkSurfaceMapsBlockList::CountSurfaces(vtkInformation* info)
{
  auto* announced = vtkMultiBlockDataSet::SafeDownCast(
    info->Get(vtkCompositeDataPipeline::COMPOSITE_DATA_META_DATA()));
  if (announced)
  {
    return static_cast<int>(announced->GetNumberOfBlocks());
  }
  vtkDataObject* data = info->Get(vtkDataObject::DATA_OBJECT());
  auto* composite = vtkCompositeDataSet::SafeDownCast(data);
  if (!composite)
  {
    return data ? 1 : 0;
  }
  int n = 0;
  vtkSmartPointer<vtkCompositeDataIterator> it;
  it.TakeReference(composite->NewIterator());
  it->SkipEmptyNodesOn();
  for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem())
  {
    ++n;
  }
  return n;
}

void vtkSurfaceMapsBlockList::Gather(const std::vector<vtkSmartPointer<vtkPolyData>>& surfaces,
  const std::vector<std::string>& names,
  vtkMultiBlockDataSet* output)
{
  output->Initialize();
  output->SetNumberOfBlocks(static_cast<unsigned int>(surfaces.size()));
  for (std::size_t k = 0; k < surfaces.size(); ++k)
  {
    const auto block = static_cast<unsigned int>(k);
    output->SetBlock(block, surfaces[k]);
    if (k < names.size())
    {
      output->GetMetaData(block)->Set(vtkCompositeDataSet::NAME(), names[k].c_str());
    }
  }
}

std::vector<vtkSmartPointer<vtkPolyData>> vtkSurfaceMapsBlockList::NewSurfaces(
  int n, vtkInformationVector* vector)
{
  std::vector<vtkSmartPointer<vtkPolyData>> surfaces;
  for (int k = 0; k < n; ++k)
  {
    surfaces.push_back(vtkSmartPointer<vtkPolyData>::New());
    vtkNew<vtkInformation> info;
    info->Set(vtkDataObject::DATA_OBJECT(), surfaces.back());
    vector->Append(info);
  }
  return surfaces;
}

bool vtkSurfaceMapsBlockList::Pick(vtkAlgorithm* self,
  vtkInformationVector* list,
  int index,
  const char* what,
  vtkInformationVector* picked)
{
  if (index >= list->GetNumberOfInformationObjects())
  {
    vtkErrorWithObjectMacro(self,
      << what << " index " << index << " but there are only "
      << list->GetNumberOfInformationObjects() << " surfaces");
    return false;
  }
  picked->Append(list->GetInformationObject(index));
  return true;
}
