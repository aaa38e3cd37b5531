// surfacemap transfer: point data of one input of a map carried onto another.
#include "CommandSupport.h"
#include "Commands.h"

#include "vtkSurfaceMapTransfer.h"

#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <system_error>
#include <vector>

namespace surfacemap
{

const char* const TransferHelp =
  "usage: surfacemap transfer MAPDIR --from I --to J [--arrays NAME ...] -o OUT.vtp\n"
  "\n"
  "Carries the point data of input I of a map onto the vertices of input J\n"
  "through the exact map that 'surfacemap map' computed (no optimisation runs):\n"
  "every vertex of J is sent onto input I by the map, and I's point arrays are\n"
  "interpolated where it lands. Reads from MAPDIR (an output directory of\n"
  "'surfacemap map'): embedding_I.vtp and embedding_J.vtp (the inputs with\n"
  "their sphere embeddings), common_I.vtp and common_J.vtp (the common\n"
  "triangulation lifted onto them). Writes OUT.vtp, atomically: input J's mesh\n"
  "with the point arrays\n"
  "  <I's arrays>       interpolated (all but SpherePosition, Landmarks,\n"
  "                     SourceCellId and SourceBarycentric, or those of --arrays)\n"
  "  SourceCellId       the triangle of input I each vertex lands in\n"
  "  SourceBarycentric  its barycentric coordinates there\n"
  "  TCoords            I's per-corner texture coordinates (OBJ 'vt')\n"
  "                     evaluated there, or I's point texture coordinates\n"
  "\n"
  "  --from I           the input whose data is carried (0-based, in the order\n"
  "                     given to 'surfacemap map')\n"
  "  --to J             the input that receives it\n"
  "  --arrays NAME ...  only these point arrays of input I\n"
  "  -o, --output FILE  the output .vtp (checked for writing before computing)\n"
  "\n"
  "Exit code 0 on success, 2 for bad usage or input (missing map files, an\n"
  "unknown array name, an output that cannot be written), 1 for an internal\n"
  "error.\n";

namespace
{

int parseIndex(const std::string& option, const std::string& text)
{
  std::size_t used = 0;
  long value = -1;
  try
  {
    value = std::stol(text, &used);
  }
  catch (const std::exception&)
  {
    used = 0;
  }
  if (used != text.size() || value < 0 || value > 1000000)
  {
    throw UsageError{ option + " needs an input index (0, 1, ...), not '" + text + "'" };
  }
  return static_cast<int>(value);
}

} // namespace

int runTransfer(const std::vector<std::string>& args)
{
  std::string directory, output;
  int from = -1, to = -1;
  std::vector<std::string> arrays;
  bool inArrays = false, sawArrays = false;
  for (std::size_t i = 0; i < args.size(); ++i)
  {
    const std::string& a = args[i];
    const bool takesValue = a == "--from" || a == "--to" || a == "-o" || a == "--output";
    if (takesValue && i + 1 >= args.size())
    {
      throw UsageError{ a + " needs a value" };
    }
    if (!a.empty() && a[0] == '-')
    {
      inArrays = false;
    }
    if (a == "--from")
    {
      from = parseIndex(a, args[++i]);
    }
    else if (a == "--to")
    {
      to = parseIndex(a, args[++i]);
    }
    else if (a == "-o" || a == "--output")
    {
      output = args[++i];
    }
    else if (a == "--arrays")
    {
      inArrays = sawArrays = true;
    }
    else if (!a.empty() && a[0] == '-')
    {
      throw UsageError{ "unknown option '" + a + "'" };
    }
    else if (inArrays)
    {
      arrays.push_back(a);
    }
    else if (directory.empty())
    {
      directory = a;
    }
    else
    {
      throw UsageError{ "one map directory only ('" + directory + "', then '" + a + "')" };
    }
  }
  if (directory.empty())
  {
    throw UsageError{ "no map directory given" };
  }
  if (from < 0 || to < 0)
  {
    throw UsageError{ "give the inputs with --from I --to J" };
  }
  if (output.empty())
  {
    throw UsageError{ "no output file given (-o OUT.vtp)" };
  }
  if (sawArrays && arrays.empty())
  {
    throw UsageError{ "--arrays needs at least one array name" };
  }

  // The map's files: name every one that is missing.
  std::error_code ec;
  if (!std::filesystem::is_directory(directory, ec))
  {
    printError(
      "'" + directory + "' is not a directory (give an output directory of 'surfacemap map')");
    return ExitBadInput;
  }
  const std::string files[4] = { "embedding_" + std::to_string(to) + ".vtp",
    "embedding_" + std::to_string(from) + ".vtp",
    "common_" + std::to_string(to) + ".vtp",
    "common_" + std::to_string(from) + ".vtp" };
  std::string missing;
  for (const std::string& file : files)
  {
    if (!std::filesystem::is_regular_file(directory + "/" + file, ec) &&
      missing.find(file) == std::string::npos)
    {
      missing += (missing.empty() ? "" : ", ") + file;
    }
  }
  if (!missing.empty())
  {
    printError(directory + " has no " + missing +
      " (written by 'surfacemap map' for each input; is the input index right?)");
    return ExitBadInput;
  }
  if (!canWrite(output))
  {
    return ExitBadInput;
  }

  vtkNew<vtkSurfaceMapTransfer> transfer;
  for (int port = 0; port < 4; ++port)
  {
    vtkSmartPointer<vtkPolyData> data = readMesh(directory + "/" + files[port]);
    if (!data)
    {
      return ExitBadInput;
    }
    transfer->SetInputDataObject(port, data);
  }
  for (const std::string& name : arrays)
  {
    transfer->AddArrayName(name.c_str());
  }
  ErrorCapture errors(transfer);
  {
    ProgressBar bar(transfer);
    transfer->Update();
  }
  vtkPolyData* result = transfer->GetOutput();
  if (!errors.messages().empty() || result->GetNumberOfPoints() == 0)
  {
    for (const std::string& m : errors.messages())
    {
      printError(m);
    }
    return transfer->GetErrorCode() == vtkSurfaceMapTransfer::InvalidInputError ? ExitBadInput
                                                                                : ExitInternalError;
  }
  try
  {
    writePolyDataAtomically(result, output);
  }
  catch (const std::runtime_error& e)
  {
    printError(e.what());
    return ExitBadInput;
  }

  std::string names;
  vtkPointData* pd = result->GetPointData();
  for (int a = 0; a < pd->GetNumberOfArrays(); ++a)
  {
    const char* name = pd->GetArrayName(a);
    names += (names.empty() ? "" : ", ") + std::string(name ? name : "(unnamed)");
  }
  std::printf("input %d -> input %d: %lld vertices of input %d received %s\n",
    from,
    to,
    static_cast<long long>(result->GetNumberOfPoints()),
    to,
    names.c_str());
  std::printf("  written to %s\n", output.c_str());
  return ExitOk;
}

} // namespace surfacemap
