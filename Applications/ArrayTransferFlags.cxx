#include "ArrayTransferFlags.h"

#include "Arguments.h"
#include "Commands.h"

#include "vtkSurfaceArrayTransferAlgorithm.h"

#include "vtkPointData.h"
#include "vtkPolyData.h"

namespace surfacemap
{

const char* const ArrayTransferFlagsHelp =
  "  --categorical NAME   carry point array NAME as labels: every vertex takes\n"
  "                       the value of the nearest corner of the source\n"
  "                       triangle it lands in, never a value the source does\n"
  "                       not have (the default for integer arrays); repeatable\n"
  "  --continuous NAME    interpolate point array NAME in the source triangle\n"
  "                       (the default for floating-point arrays; integers are\n"
  "                       rounded); repeatable\n";

bool parseArrayTransferFlag(vtkSurfaceArrayTransferAlgorithm* filter,
  const std::vector<std::string>& args,
  std::size_t& i)
{
  const std::string& flag = args[i];
  int mode = vtkSurfaceArrayTransferAlgorithm::ARRAY_TRANSFER_BY_TYPE;
  if (flag == "--categorical")
  {
    mode = vtkSurfaceArrayTransferAlgorithm::ARRAY_TRANSFER_CATEGORICAL;
  }
  else if (flag == "--continuous")
  {
    mode = vtkSurfaceArrayTransferAlgorithm::ARRAY_TRANSFER_CONTINUOUS;
  }
  else
  {
    return false;
  }
  const std::string& name = optionValue(args, i, "a point array name");
  if (name.empty() || isOption(name))
  {
    throw UsageError{ flag + " needs a point array name, not '" + name + "'" };
  }
  const int before = filter->GetArrayTransferMode(name.c_str());
  if (before != vtkSurfaceArrayTransferAlgorithm::ARRAY_TRANSFER_BY_TYPE && before != mode)
  {
    throw UsageError{ "'" + name + "' is given both as --categorical and as --continuous" };
  }
  filter->SetArrayTransferMode(name.c_str(), mode);
  return true;
}

std::string missingArrayTransferNames(vtkSurfaceArrayTransferAlgorithm* filter,
  const std::vector<vtkPolyData*>& meshes)
{
  std::string missing;
  for (int k = 0; k < filter->GetNumberOfArrayTransferModes(); ++k)
  {
    const char* name = filter->GetArrayTransferModeArrayName(k);
    bool found = false;
    for (vtkPolyData* mesh : meshes)
    {
      found = found || (mesh && mesh->GetPointData()->GetAbstractArray(name));
    }
    if (!found)
    {
      missing += (missing.empty() ? "'" : ", '") + std::string(name) + "'";
    }
  }
  return missing;
}

} // namespace surfacemap
