// surfacemap transfer: point data of one input of a map carried onto another.
#include "AlgorithmMessages.h"
#include "Arguments.h"
#include "ArrayTransferFlags.h"
#include "AtomicFiles.h"
#include "Commands.h"
#include "MapDirectory.h"
#include "MeshFiles.h"
#include "Pictures.h"
#include "Terminal.h"
#include "TransferPictures.h"

#include "vtkSurfaceMapTransfer.h"
#include "vtkSurfaceTextureSeamSplitter.h"

#include "vtkAbstractArray.h"
#include "vtkCellData.h"

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

namespace
{
const char* const TransferHelpIntro =
  "usage: surfacemap transfer MAPDIR --from I --to J [--arrays NAME ...]\n"
  "                           [--source-data MESH] [--categorical NAME]\n"
  "                           [--continuous NAME] [--split-seams] [--pictures]\n"
  "                           -o OUT.vtp|OUT.obj\n"
  "\n"
  "Carries the point data of input I of a map onto the vertices of input J\n"
  "through the exact map that 'surfacemap map' computed (no optimisation runs):\n"
  "every vertex of J is sent onto input I by the map, and I's point arrays are\n"
  "read where it lands: continuous arrays (floating-point ones by default)\n"
  "interpolated in the triangle of I it lands in, categorical ones (integer\n"
  "arrays by default: labels) taken from that triangle's nearest corner, so J\n"
  "never receives a label I does not have. Reads from MAPDIR (an output\n"
  "directory of 'surfacemap map'): embedding_I.vtp and embedding_J.vtp (the\n"
  "inputs with their sphere embeddings), common_I.vtp and common_J.vtp (the\n"
  "common triangulation lifted onto them), each checked against report.json\n"
  "and each embedding against its common file (a missing, stale, swapped,\n"
  "changed or rotated file is refused by name). Writes OUT.vtp, atomically:\n"
  "input J's mesh with the point arrays\n"
  "  <I's arrays>       continuous or categorical (all but SpherePosition,\n"
  "                     Landmarks, SourceCellId and SourceBarycentric, or those\n"
  "                     of --arrays)\n"
  "  SourceCellId       the triangle of input I each vertex lands in\n"
  "  SourceBarycentric  its barycentric coordinates there\n"
  "  TCoords            I's per-corner texture coordinates (OBJ 'vt')\n"
  "                     evaluated there, or I's point texture coordinates\n"
  "and, when input I has per-corner texture coordinates, the cell array\n"
  "  CornerTCoords      per triangle corner, so that no triangle spans a\n"
  "                     texture seam (one value per vertex cannot hold a seam)\n"
  "\n"
  "  --from I           the input whose data is carried (0-based, in the order\n"
  "                     given to 'surfacemap map': 0 to N - 1 for N inputs)\n"
  "  --to J             the input that receives it (0 to N - 1)\n"
  "  --arrays NAME ...  only these point arrays of input I\n"
  "  --source-data MESH carry the point arrays (and per-corner texture\n"
  "                     coordinates) of MESH instead of those input I had when\n"
  "                     the map was computed: MESH must have input I's\n"
  "                     connectivity (the same vertex count and the same\n"
  "                     triangles in the same order, as a copy of input I with\n"
  "                     new arrays has), else exit code 2 naming the mismatch\n"
  "  --split-seams      give every distinct corner texture coordinate its own\n"
  "                     point (copies of J's vertices along the seams, with\n"
  "                     the point array OriginalPointId), so that TCoords\n"
  "                     renders the texture without seam artifacts\n"
  "  -o, --output FILE  the output (checked for writing before computing):\n"
  "                     .vtp with every array above; .obj with the points,\n"
  "                     the triangles and, with CornerTCoords, 'vt' per corner\n"
  "                     (OBJ holds no other data)\n"
  "  --pictures         also write, beside FILE, one PNG per carried numeric\n"
  "                     array NAME: FILE without its extension + _NAME.png\n"
  "                     (e.g. out_Labels.png), input I with its array and\n"
  "                     input J with the received one side by side in the\n"
  "                     same colours: continuous arrays on a colour map with a\n"
  "                     legend, categorical ones one flat colour per label\n"
  "                     (each triangle in its corners' majority label),\n"
  "                     unsigned char RGB(A) arrays as colours; with texture\n"
  "                     coordinates, FILE + _texture.png: both inputs with the\n"
  "                     package's checkerboard texture, J split at the seams.\n"
  "                     Rendered with VTK through OpenGL on the display, or\n"
  "                     without one on a virtual display (Xvfb, Debian package\n"
  "                     xvfb) started for the command and stopped at its end;\n"
  "                     with neither the command stops with exit code 2\n"
  "                     before computing\n";

const char* const TransferExitCodes =
  "\n"
  "Exit code 0 on success, 2 for bad usage or input (missing map files, an\n"
  "unknown array name, an output that cannot be written, no display nor\n"
  "Xvfb for --pictures), 1 for an internal error.\n";

const std::string TransferHelpText =
  std::string(TransferHelpIntro) + ArrayTransferFlagsHelp + TransferExitCodes;
} // namespace

const char* const TransferHelp = TransferHelpText.c_str();

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
  std::string directory, output, sourceData;
  int from = -1, to = -1;
  bool splitSeams = false;
  std::vector<std::string> arrays;
  bool pictures = false;
};

TransferArguments parseArguments(const std::vector<std::string>& args,
  vtkSurfaceMapTransfer* transfer)
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
    else if (a == "--split-seams")
    {
      parsed.splitSeams = true;
    }
    else if (a == "--source-data")
    {
      parsed.sourceData = optionValue(args, i, "a mesh file");
    }
    else if (a == "--arrays")
    {
      inArrays = sawArrays = true;
    }
    else if (a == "--pictures")
    {
      parsed.pictures = true;
    }
    else if (parseArrayTransferFlag(transfer, args, i))
    {
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

// Input I's embedding (`embedding`, embedding_I.vtp) with the point arrays and
// cell data of `data` (--source-data) instead of its own, keeping its
// SpherePosition. Throws std::runtime_error naming the first mismatch of
// vertex count or triangles.
vtkSmartPointer<vtkPolyData> withSourceData(vtkPolyData* embedding,
  vtkPolyData* data,
  const std::string& dataPath,
  const std::string& embeddingName,
  int from)
{
  const std::string input = "input " + std::to_string(from) + " (" + embeddingName + ")";
  const std::string difference =
    vtkSurfaceMapTransfer::DescribeConnectivityDifference(data, embedding, input.c_str());
  if (!difference.empty())
  {
    throw std::runtime_error("--source-data " + dataPath + " " + difference +
      ": not the connectivity of input " + std::to_string(from));
  }
  auto source = vtkSmartPointer<vtkPolyData>::New();
  source->ShallowCopy(embedding);
  vtkAbstractArray* sphere = embedding->GetPointData()->GetAbstractArray("SpherePosition");
  source->GetPointData()->ShallowCopy(data->GetPointData());
  source->GetPointData()->RemoveArray("SpherePosition");
  source->GetPointData()->AddArray(sphere);
  source->GetCellData()->ShallowCopy(data->GetCellData());
  return source;
}

// Reads the map's files into the transfer's ports; false after printing why.
// Throws UsageError for --categorical or --continuous arrays input I lacks.
bool readMapFiles(vtkSurfaceMapTransfer* transfer,
  const TransferArguments& arguments,
  const std::vector<std::string>& files)
{
  for (int port = 0; port < static_cast<int>(files.size()); ++port)
  {
    vtkSmartPointer<vtkPolyData> data = readMesh(arguments.directory + "/" + files[port]);
    if (!data)
    {
      return false;
    }
    if (port == 1 && !arguments.sourceData.empty())
    {
      vtkSmartPointer<vtkPolyData> given = readMesh(arguments.sourceData);
      if (!given ||
        !succeeds(
          [&] {
            data = withSourceData(data, given, arguments.sourceData, files[port], arguments.from);
          }))
      {
        return false;
      }
    }
    transfer->SetInputDataObject(port, data);
  }
  const std::string missing = missingArrayTransferNames(
    transfer, { vtkPolyData::SafeDownCast(transfer->GetInputDataObject(1, 0)) });
  if (!missing.empty())
  {
    throw UsageError{ "input " + std::to_string(arguments.from) + " (" +
      (arguments.sourceData.empty() ? files[1] : arguments.sourceData) + ") has no point array " +
      missing + " (named by --categorical or --continuous)" };
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

// Prints which arrays input J received, and how those of input I were carried.
void reportTransfer(const TransferArguments& arguments, vtkSurfaceMapTransfer* transfer)
{
  vtkPolyData* result = transfer->GetOutput();
  auto* source = vtkPolyData::SafeDownCast(transfer->GetInputDataObject(1, 0));
  std::string names;
  vtkPointData* pd = result->GetPointData();
  for (int a = 0; a < pd->GetNumberOfArrays(); ++a)
  {
    const char* name = pd->GetArrayName(a);
    names += (names.empty() ? "" : ", ") + std::string(name ? name : "(unnamed)");
    vtkAbstractArray* carried =
      name && source ? source->GetPointData()->GetAbstractArray(name) : nullptr;
    if (carried)
    {
      names += std::string(" (") +
        vtkSurfaceMapTransfer::GetArrayTransferModeAsString(
          transfer->ResolveArrayTransferMode(carried)) +
        ")";
    }
  }
  std::printf("input %d -> input %d: %lld vertices of input %d received %s\n",
    arguments.from,
    arguments.to,
    static_cast<long long>(result->GetNumberOfPoints()),
    arguments.to,
    names.c_str());
  std::printf("  written to %s\n", arguments.output.c_str());
}

// Throws UsageError if `output` is report.json or a map file of `directory`.
void refuseMapFileAsOutput(const std::string& output, const std::string& directory)
{
  std::error_code error;
  const auto file = std::filesystem::weakly_canonical(output, error);
  const auto folder = std::filesystem::weakly_canonical(directory, error);
  const std::string name = file.filename().string();
  if (!error && file.parent_path() == folder && (name == "report.json" || isMapFileName(name)))
  {
    throw UsageError{ "-o " + output + " would overwrite a file of the map in " + directory };
  }
}

} // namespace

int runTransfer(const std::vector<std::string>& args)
{
  vtkNew<vtkSurfaceMapTransfer> transfer;
  const TransferArguments arguments = parseArguments(args, transfer);
  refuseMapFileAsOutput(arguments.output, arguments.directory);
  const std::vector<std::string> files = mapFiles(arguments);
  if ((arguments.pictures && !checkDisplayForPictures()) ||
    !findMapFiles(arguments.directory, files) || !canWrite(arguments.output) ||
    !succeeds([&] { verifyMapFiles(arguments.directory, files); }))
  {
    return ExitBadInput;
  }
  if (!readMapFiles(transfer, arguments, files))
  {
    return ExitBadInput;
  }
  const int computed = computeTransfer(transfer, arguments.arrays);
  if (computed != ExitOk)
  {
    return computed;
  }
  vtkSmartPointer<vtkPolyData> result = transfer->GetOutput();
  if (arguments.splitSeams)
  {
    vtkNew<vtkSurfaceTextureSeamSplitter> splitter;
    splitter->SetInputData(result);
    splitter->Update();
    result = splitter->GetOutput();
  }
  if (!succeeds([&] { writeMeshAtomically(result, arguments.output); }))
  {
    return ExitBadInput;
  }
  reportTransfer(arguments, transfer);
  const auto pictures = [&] {
    printPictures(writeTransferPictures(transfer, arguments.from, arguments.to, arguments.output));
  };
  if (arguments.pictures && !succeeds(pictures))
  {
    return ExitBadInput;
  }
  return ExitOk;
}

} // namespace surfacemap
