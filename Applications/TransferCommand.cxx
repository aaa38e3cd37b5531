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

struct TransferArguments
{
  std::string directory, output;
  int from = -1, to = -1;
  std::vector<std::string> arrays;
};

TransferArguments parseArguments(const std::vector<std::string>& args)
{
  TransferArguments parsed;
  bool inArrays = false, sawArrays = false;
  for (std::size_t i = 0; i < args.size(); ++i)
  {
    const std::string& a = args[i];
    if (isOption(a))
    {
      inArrays = false;
    }
    if (a == "--from")
    {
      parsed.from = parseIndex(a, optionValue(args, i));
    }
    else if (a == "--to")
    {
      parsed.to = parseIndex(a, optionValue(args, i));
    }
    else if (a == "-o" || a == "--output")
    {
      parsed.output = optionValue(args, i);
    }
    else if (a == "--arrays")
    {
      inArrays = sawArrays = true;
    }
    else if (isOption(a))
    {
      unknownOption(a);
    }
    else if (inArrays)
    {
      parsed.arrays.push_back(a);
    }
    else if (parsed.directory.empty())
    {
      parsed.directory = a;
    }
    else
    {
      throw UsageError{ "one map directory only ('" + parsed.directory + "', then '" + a + "')" };
    }
  }
  if (parsed.directory.empty())
  {
    throw UsageError{ "no map directory given" };
  }
  if (parsed.from < 0 || parsed.to < 0)
  {
    throw UsageError{ "give the inputs with --from I --to J" };
  }
  if (parsed.output.empty())
  {
    throw UsageError{ "no output file given (-o OUT.vtp)" };
  }
  if (sawArrays && parsed.arrays.empty())
  {
    throw UsageError{ "--arrays needs at least one array name" };
  }
  return parsed;
}

// The map's files vtkSurfaceMapTransfer reads, by port: J's and I's
// embeddings, then T lifted onto J and onto I.
std::vector<std::string> mapFiles(const TransferArguments& arguments)
{
  return { mapFileName("embedding", arguments.to),
    mapFileName("embedding", arguments.from),
    mapFileName("common", arguments.to),
    mapFileName("common", arguments.from) };
}

// True if `directory` holds every file; otherwise prints every one missing.
bool findMapFiles(const std::string& directory, const std::vector<std::string>& files)
{
  std::error_code ec;
  if (!std::filesystem::is_directory(directory, ec))
  {
    printError(
      "'" + directory + "' is not a directory (give an output directory of 'surfacemap map')");
    return false;
  }
  std::string missing;
  for (const std::string& file : files)
  {
    if (!isFile(directory + "/" + file) && missing.find(file) == std::string::npos)
    {
      missing += (missing.empty() ? "" : ", ") + file;
    }
  }
  if (!missing.empty())
  {
    printError(directory + " has no " + missing +
      " (written by 'surfacemap map' for each input; is the input index right?)");
    return false;
  }
  return true;
}

// Reads the map's files into the transfer's ports; false after printing why.
bool readMapFiles(vtkSurfaceMapTransfer* transfer,
  const std::string& directory,
  const std::vector<std::string>& files)
{
  for (int port = 0; port < static_cast<int>(files.size()); ++port)
  {
    vtkSmartPointer<vtkPolyData> data = readMesh(directory + "/" + files[port]);
    if (!data)
    {
      return false;
    }
    transfer->SetInputDataObject(port, data);
  }
  return true;
}

// Runs the transfer; prints its errors and returns the exit code on failure.
int computeTransfer(vtkSurfaceMapTransfer* transfer, const std::vector<std::string>& arrays)
{
  for (const std::string& name : arrays)
  {
    transfer->AddArrayName(name.c_str());
  }
  ErrorCapture errors(transfer);
  {
    ProgressBar bar(transfer);
    transfer->Update();
  }
  if (errors.messages().empty() && transfer->GetOutput()->GetNumberOfPoints() > 0)
  {
    return ExitOk;
  }
  printErrors(errors.messages());
  return transfer->GetErrorCode() == vtkSurfaceMapTransfer::InvalidInputError ? ExitBadInput
                                                                              : ExitInternalError;
}

// Prints which arrays input J received.
void reportTransfer(const TransferArguments& arguments, vtkPolyData* result)
{
  std::string names;
  vtkPointData* pd = result->GetPointData();
  for (int a = 0; a < pd->GetNumberOfArrays(); ++a)
  {
    const char* name = pd->GetArrayName(a);
    names += (names.empty() ? "" : ", ") + std::string(name ? name : "(unnamed)");
  }
  std::printf("input %d -> input %d: %lld vertices of input %d received %s\n",
    arguments.from,
    arguments.to,
    static_cast<long long>(result->GetNumberOfPoints()),
    arguments.to,
    names.c_str());
  std::printf("  written to %s\n", arguments.output.c_str());
}

} // namespace

int runTransfer(const std::vector<std::string>& args)
{
  const TransferArguments arguments = parseArguments(args);
  const std::vector<std::string> files = mapFiles(arguments);
  if (!findMapFiles(arguments.directory, files) || !canWrite(arguments.output))
  {
    return ExitBadInput;
  }
  vtkNew<vtkSurfaceMapTransfer> transfer;
  if (!readMapFiles(transfer, arguments.directory, files))
  {
    return ExitBadInput;
  }
  const int computed = computeTransfer(transfer, arguments.arrays);
  if (computed != ExitOk)
  {
    return computed;
  }
  vtkPolyData* result = transfer->GetOutput();
  if (!succeeds([&] { writePolyDataAtomically(result, arguments.output); }))
  {
    return ExitBadInput;
  }
  reportTransfer(arguments, result);
  return ExitOk;
}

} // namespace surfacemap
