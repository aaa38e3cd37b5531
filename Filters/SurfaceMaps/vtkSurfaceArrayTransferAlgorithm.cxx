#include "vtkSurfaceArrayTransferAlgorithm.h"

#include "vtkSurfaceMapsErrorGuard.h"
#include "vtkSurfaceMapsExecutive.h"

#include "vtkAbstractArray.h"
#include "vtkDataArray.h"

#include <iterator>
#include <map>
#include <string>

struct vtkSurfaceArrayTransferAlgorithm::vtkArrayModes
{
  std::map<std::string, int> Modes; // only choices other than ARRAY_TRANSFER_BY_TYPE
};

vtkSurfaceArrayTransferAlgorithm::vtkSurfaceArrayTransferAlgorithm()
  : ArrayModes(new vtkArrayModes)
{
}

vtkSurfaceArrayTransferAlgorithm::~vtkSurfaceArrayTransferAlgorithm() = default;

void vtkSurfaceArrayTransferAlgorithm::SetArrayTransferMode(const char* name, int mode)
{
  if (!name || !*name)
  {
    vtkErrorMacro(<< "SetArrayTransferMode needs an array name");
    return;
  }
  if (mode < ARRAY_TRANSFER_BY_TYPE || mode > ARRAY_TRANSFER_CATEGORICAL)
  {
    vtkErrorMacro(<< "array transfer mode " << mode << " for '" << name
                  << "' is none of ARRAY_TRANSFER_BY_TYPE (0), ARRAY_TRANSFER_CONTINUOUS (1), "
                     "ARRAY_TRANSFER_CATEGORICAL (2)");
    return;
  }
  std::map<std::string, int>& modes = this->ArrayModes->Modes;
  auto found = modes.find(name);
  if (mode == ARRAY_TRANSFER_BY_TYPE)
  {
    if (found != modes.end())
    {
      modes.erase(found);
      this->Modified();
    }
    return;
  }
  if (found == modes.end() || found->second != mode)
  {
    modes[name] = mode;
    this->Modified();
  }
}

int vtkSurfaceArrayTransferAlgorithm::GetArrayTransferMode(const char* name)
{
  if (!name)
  {
    return ARRAY_TRANSFER_BY_TYPE;
  }
  auto found = this->ArrayModes->Modes.find(name);
  return found == this->ArrayModes->Modes.end() ? ARRAY_TRANSFER_BY_TYPE : found->second;
}

void vtkSurfaceArrayTransferAlgorithm::ClearArrayTransferModes()
{
  if (!this->ArrayModes->Modes.empty())
  {
    this->ArrayModes->Modes.clear();
    this->Modified();
  }
}

int vtkSurfaceArrayTransferAlgorithm::GetNumberOfArrayTransferModes()
{
  return static_cast<int>(this->ArrayModes->Modes.size());
}

const char* vtkSurfaceArrayTransferAlgorithm::GetArrayTransferModeArrayName(int i)
{
  if (i < 0 || i >= this->GetNumberOfArrayTransferModes())
  {
    return nullptr;
  }
  return std::next(this->ArrayModes->Modes.begin(), i)->first.c_str();
}

int vtkSurfaceArrayTransferAlgorithm::ResolveArrayTransferMode(vtkAbstractArray* array)
{
  auto* data = vtkDataArray::SafeDownCast(array);
  if (!data)
  {
    return ARRAY_TRANSFER_CATEGORICAL; // strings and variants cannot be blended
  }
  const int chosen = this->GetArrayTransferMode(array->GetName());
  if (chosen != ARRAY_TRANSFER_BY_TYPE)
  {
    return chosen;
  }
  const int type = data->GetDataType();
  return type == VTK_FLOAT || type == VTK_DOUBLE ? ARRAY_TRANSFER_CONTINUOUS
                                                 : ARRAY_TRANSFER_CATEGORICAL;
}

const char* vtkSurfaceArrayTransferAlgorithm::GetArrayTransferModeAsString(int mode)
{
  switch (mode)
  {
    case ARRAY_TRANSFER_BY_TYPE:
      return "by type";
    case ARRAY_TRANSFER_CONTINUOUS:
      return "continuous";
    case ARRAY_TRANSFER_CATEGORICAL:
      return "categorical";
    default:
      return nullptr;
  }
}

const char* vtkSurfaceArrayTransferAlgorithm::GetLastErrorMessage() const
{
  return vtkSurfaceMapsErrorGuard::LastErrorMessage(this);
}

vtkExecutive* vtkSurfaceArrayTransferAlgorithm::CreateDefaultExecutive()
{
  return vtkSurfaceMapsExecutive::New();
}

void vtkSurfaceArrayTransferAlgorithm::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ArrayTransferModes:";
  if (this->ArrayModes->Modes.empty())
  {
    os << " (by type: integer arrays categorical, floating-point arrays continuous)";
  }
  for (const auto& mode : this->ArrayModes->Modes)
  {
    os << " " << mode.first << ": " << GetArrayTransferModeAsString(mode.second) << ";";
  }
  os << "\n";
}
