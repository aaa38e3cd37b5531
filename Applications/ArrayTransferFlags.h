// The `surfacemap` command line: --categorical NAME and --continuous NAME,
// how point arrays are carried onto other surfaces (the array transfer modes
// of vtkSurfaceArrayTransferAlgorithm), shared by the commands that carry
// data (map, transfer).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

class vtkPolyData;
class vtkSurfaceArrayTransferAlgorithm;

namespace surfacemap
{

/// The flags' lines for a command's --help.
extern const char* const ArrayTransferFlagsHelp;

/// If args[i] is --categorical or --continuous, sets that mode on `filter`
/// for the array named by the next argument (i then at the name) and returns
/// true. Throws UsageError when the name is missing or the same array is
/// given both ways. False for any other argument.
bool parseArrayTransferFlag(vtkSurfaceArrayTransferAlgorithm* filter,
  const std::vector<std::string>& args,
  std::size_t& i);

/// The arrays given a mode on `filter` that no mesh of `meshes` has as a
/// point array, quoted and separated by commas ("'A', 'B'"); empty if none.
std::string missingArrayTransferNames(vtkSurfaceArrayTransferAlgorithm* filter,
  const std::vector<vtkPolyData*>& meshes);

} // namespace surfacemap
