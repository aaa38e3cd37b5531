// surfacemap map: bijective map between N surfaces via a common triangulation.
#include "AlgorithmMessages.h"
#include "Arguments.h"
#include "ArrayTransferFlags.h"
#include "AtomicFiles.h"
#include "Commands.h"
#include "EvaluationSummary.h"
#include "ExistingMapFiles.h"
#include "Json.h"
#include "MapDestination.h"
#include "MapDirectory.h"
#include "MeshFiles.h"
#include "SettingFlags.h"
#include "SpecimenFit.h"
#include "Terminal.h"

#include "vtkSurfaceMapEvaluation.h"
#include "vtkSurfaceMapFilter.h"
#include "vtkSurfaceMapsSettings.h"

#include "base/ThreadCount.h"

#include "vtkAbstractArray.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkStringArray.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <system_error>

namespace surfacemap
{

namespace
{
const char* const MapHelpIntro =
  "usage: surfacemap map A B [C ...] --output-dir DIR [--landmarks FA FB ...]\n"
  "                      [--sizing SA SB ...] [--categorical NAME]\n"
  "                      [--continuous NAME] [--add-to MAPDIR] [SETTING ...]\n"
  "\n"
  "Computes a bijective map between the meshes A, B, ... (closed, manifold,\n"
  "genus 0) through one adaptive common triangulation T (Schmidt, Pieper,\n"
  "Kobbelt 2023): sphere embeddings, then a landmark phase (with landmarks),\n"
  "a coarse and a fine phase of edge splits, collapses, flips and Newton\n"
  "steps, and refinement where the exact map is distorted. The result is\n"
  "certified bijective with exact predicates. One mesh alone gives a\n"
  "bijective remeshing. Writes, each file atomically and report.json last:\n"
  "  DIR/common_<i>.vtp  T lifted onto input i (same triangles for every i),\n"
  "                      with SpherePosition, SourceCellId, SourceBarycentric,\n"
  "                      Landmarks and the input's point arrays (integer\n"
  "                      arrays categorical, floating-point ones interpolated,\n"
  "                      unless --categorical / --continuous say otherwise)\n"
  "  DIR/mapped_<i>.vtp  input 0's mesh mapped onto input i by the exact map\n"
  "  DIR/embedding_<i>.vtp\n"
  "                      input i with its sphere embedding in the map's frame\n"
  "                      (SpherePosition): with common_<i>.vtp, what\n"
  "                      'surfacemap transfer' reads to carry data between inputs\n"
  "  DIR/correspondences.npz\n"
  "                      the same for numpy (numpy.load): points (N x V x 3, T's\n"
  "                      vertices on every input), triangles (F x 3), names\n"
  "                      (the inputs' file stems)\n"
  "  DIR/fit.csv         per input: H of its vertices to T and the two-sided\n"
  "                      distance (% of its bounding-box diagonal), the\n"
  "                      approximating and exact SD and the exact map's max\n"
  "                      distortion and area below 1.5 (maps 0 -> i), the\n"
  "                      landmark error (% of the diagonal); also in report.json\n"
  "  DIR/report.json     every setting of the run (and the sphere embedding's,\n"
  "                      which the map computes embeddings with), sizes,\n"
  "                      energies, per-phase iterations and times (and the\n"
  "                      thread count they were measured with), the\n"
  "                      certificate, the landmark error and the metrics of\n"
  "                      the approximating map\n"
  "                      (common_0 -> common_i) and of the exact map (input 0 ->\n"
  "                      mapped_i): symmetric Dirichlet, area below distortion\n"
  "                      1.5 and 2, max distortion, Hausdorff distance per input\n"
  "                      (% of the bounding-box diagonal; input 0's with the\n"
  "                      first pair only), min and mean minimum angles; the\n"
  "                      map's id and every file's size and MD5 checksum,\n"
  "                      which 'evaluate' and 'transfer' verify\n"
  "\n"
  "  -o, --output-dir DIR where to write (created if missing). The map is\n"
  "                       written into DIR.tmp.<pid> beside DIR (checked for\n"
  "                       writing before computing) and put in place as a\n"
  "                       whole when complete; other files in DIR stay. One\n"
  "                       run at a time: a second run for DIR is refused\n"
  "                       while one computes, and a DIR that received a map\n"
  "                       meanwhile is not replaced without --overwrite\n"
  "  --overwrite          replace an earlier map in DIR as a whole: the new map\n"
  "                       is checked, then exchanged with DIR in one step;\n"
  "                       on failure the earlier map stays; without it a DIR\n"
  "                       holding a map (or an interrupted run's files) is\n"
  "                       refused before computing\n"
  "  --landmarks FA FB ...\n"
  "                       one landmark file per mesh, in the same order (give\n"
  "                       the meshes first); same id = corresponding points\n"
  "                       (formats below; points snap to the closest vertex)\n"
  "  --sizing SA SB ...   the target edge lengths of T, one source per mesh, in\n"
  "                       the same order: a file with one length per vertex\n"
  "                       per line (in the mesh's units; finite, positive, one\n"
  "                       per vertex), or the name of a point array of that\n"
  "                       mesh (a VTP input's); a name that is an existing\n"
  "                       file is read as the file. Used instead of the\n"
  "                       curvature sizing; where the inputs disagree, T\n"
  "                       follows the smallest\n";

const char* const MapHelpSettings =
  "\n"
  "Settings (unit-area units: each input centred and scaled to unit area; a\n"
  "phase stopping at its iteration cap is normal and reported):\n";

const char* const MapExitCodes =
  "\n"
  "Exit code 0 with a certified map, 2 for bad usage or input (also an output\n"
  "directory that cannot be written), 3 if no certified map was found, 1 for\n"
  "an internal error.\n";

const std::string MapHelpText = std::string(MapHelpIntro) + AddToHelp + ArrayTransferFlagsHelp +
  MapHelpSettings + vtkSurfaceMapsSettings::GetPresetHelp() +
  settingsHelp(vtkSurfaceMapsSettings::MAP_SETTINGS) + LandmarkFormatsHelp + MapExitCodes;
} // namespace

const char* const MapHelp = MapHelpText.c_str();

namespace
{

// A field-data value of a map output (tuple k), NaN if absent.
double field(vtkPolyData* data, const char* name, vtkIdType k = 0)
{
  vtkDataArray* a = data->GetFieldData()->GetArray(name);
  return a && k < a->GetNumberOfTuples() ? a->GetTuple1(k) : std::nan("");
}

// Measures source -> target (same connectivity); originals may be null.
// Returns the report's figures; prints one line.
Json::Value evaluate(const char* what,
  int target,
  vtkPolyData* source,
  vtkPolyData* targetMesh,
  vtkPolyData* sourceOriginal,
  vtkPolyData* targetOriginal)
{
  vtkSmartPointer<vtkPolyData> evaluated;
  try
  {
    evaluated = measureMap(source, targetMesh, sourceOriginal, targetOriginal);
  }
  catch (const std::invalid_argument& e)
  {
    throw std::logic_error(
      "evaluating the " + std::string(what) + " 0 -> " + std::to_string(target) + ": " + e.what());
  }
  auto figure = [&evaluated](const char* name) { return summaryValue(evaluated, name); };
  Json::Value figures(Json::objectValue);
  figures["source"] = 0;
  figures["target"] = target;
  for (const char* name : evaluationSummaryNames())
  {
    // The certificate has its own section of the report (T's embeddings).
    const bool certificate =
      std::strcmp(name, "Bijective") == 0 || std::strcmp(name, "NonPositiveTriangles") == 0;
    const double value = figure(name);
    if (!certificate && !std::isnan(value))
    {
      figures[name] = jsonNumber(value);
    }
  }
  std::printf("  %s 0 -> %d: SD %.4f, a1.5 %.3f, a2 %.3f, max %.3g",
    what,
    target,
    figure("SymmetricDirichlet"),
    figure("AreaBelow1.5"),
    figure("AreaBelow2"),
    figure("MaxDistortion"));
  if (sourceOriginal)
  {
    std::printf(", H %.3f%% / %.3f%%", figure("HausdorffSource"), figure("HausdorffTarget"));
  }
  else if (targetOriginal)
  {
    std::printf(", H %.3f%% on input %d", figure("HausdorffTarget"), target);
  }
  std::printf(", min angle %.1f\n", figure("MinAngleTarget"));
  return figures;
}

struct MapArguments
{
  std::vector<std::string> meshes, landmarks, sizing;
  std::string outputDir;
  /// --preset's name, "" without one.
  std::string preset;
  bool overwrite = false;
  /// --add-to's map directory, "" without one.
  std::string addTo;
};

MapArguments parseArguments(const std::vector<std::string>& args, vtkSurfaceMapFilter* map)
{
  MapArguments parsed;
  parsed.preset = applyPresetFlag(map, args);
  // Where a file name goes: the meshes, or the list of the last --landmarks
  // or --sizing.
  std::vector<std::string>* list = &parsed.meshes;
  for (std::size_t i = 0; i < args.size(); ++i)
  {
    const std::string& a = args[i];
    if (isOption(a))
    {
      list = &parsed.meshes;
    }
    if (a == "--landmarks")
    {
      list = &parsed.landmarks;
    }
    else if (a == "--sizing")
    {
      list = &parsed.sizing;
    }
    else if (isOutputDirOption(a))
    {
      parsed.outputDir = optionValue(args, i, "a directory");
    }
    else if (a == "--overwrite")
    {
      parsed.overwrite = true;
    }
    else if (a == "--add-to")
    {
      parsed.addTo = optionValue(args, i, "a map directory");
    }
    else if (parseSettingFlag(map, args, i) || parseArrayTransferFlag(map, args, i))
    {
    }
    else if (isOption(a))
    {
      unknownOption(a);
    }
    else
    {
      list->push_back(a);
    }
  }
  if (parsed.meshes.empty())
  {
    throw UsageError{ parsed.landmarks.empty() && parsed.sizing.empty()
        ? "no meshes given"
        : "no meshes given (the meshes come before --landmarks and --sizing: map A B "
          "--landmarks FA FB)" };
  }
  if (parsed.outputDir.empty())
  {
    throw UsageError{ "no output directory given (-o DIR or --output-dir DIR)" };
  }
  if (!parsed.landmarks.empty() && parsed.landmarks.size() != parsed.meshes.size())
  {
    throw UsageError{ "--landmarks needs one file per mesh (" +
      std::to_string(parsed.meshes.size()) + " meshes, " + std::to_string(parsed.landmarks.size()) +
      " landmark files)" };
  }
  if (!parsed.sizing.empty() && parsed.sizing.size() != parsed.meshes.size())
  {
    throw UsageError{ "--sizing needs one file or array name per mesh (" +
      std::to_string(parsed.meshes.size()) + " meshes, " + std::to_string(parsed.sizing.size()) +
      " sizing sources)" };
  }
  return parsed;
}

// --sizing NAME where NAME is not a file: the point array NAME of `mesh`
// becomes its "Sizing" array, once checked (one component, finite, positive).
// Throws std::runtime_error naming the mesh, the array and the vertex.
void sizingFromArray(vtkPolyData* mesh, const std::string& name, const std::string& meshPath)
{
  vtkDataArray* array = mesh->GetPointData()->GetArray(name.c_str());
  if (!array)
  {
    throw std::runtime_error("--sizing " + name + ": no such file, and " + meshPath +
      " has no numeric point array of that name");
  }
  if (array->GetNumberOfComponents() != 1)
  {
    throw std::runtime_error("--sizing " + name + ": the point array of " + meshPath + " has " +
      std::to_string(array->GetNumberOfComponents()) + " components, not one length per vertex");
  }
  vtkNew<vtkDoubleArray> sizing;
  sizing->SetName("Sizing");
  sizing->SetNumberOfValues(array->GetNumberOfTuples());
  for (vtkIdType v = 0; v < array->GetNumberOfTuples(); ++v)
  {
    const double value = array->GetTuple1(v);
    if (!std::isfinite(value) || value <= 0.0)
    {
      std::ostringstream message;
      message << "--sizing " << name << ": the point array of " << meshPath << " has " << value
              << " at vertex " << v << ", not a finite positive length";
      throw std::runtime_error(message.str());
    }
    sizing->SetValue(v, value);
  }
  mesh->GetPointData()->AddArray(sizing);
}

// Every mesh read (with its landmark file and sizing); null after printing why. The map
// filter validates them (once, with every defect of every input named).
std::vector<vtkSmartPointer<vtkPolyData>> readInputs(const MapArguments& arguments)
{
  std::vector<vtkSmartPointer<vtkPolyData>> inputs;
  for (std::size_t i = 0; i < arguments.meshes.size(); ++i)
  {
    const std::string sizing = arguments.sizing.empty() ? "" : arguments.sizing[i];
    const bool sizingFile = !sizing.empty() && isFile(sizing);
    inputs.push_back(readMesh(arguments.meshes[i],
      arguments.landmarks.empty() ? "" : arguments.landmarks[i],
      sizingFile ? sizing : ""));
    if (!inputs.back() ||
      (!sizing.empty() && !sizingFile &&
        !succeeds([&] { sizingFromArray(inputs.back(), sizing, arguments.meshes[i]); })))
    {
      return {};
    }
  }
  return inputs;
}

// Runs the filter; prints its errors and returns the exit code on failure.
int computeMap(vtkSurfaceMapFilter* map,
  const std::vector<vtkSmartPointer<vtkPolyData>>& inputs,
  ErrorCapture& errors)
{
  for (const auto& input : inputs)
  {
    map->AddInputData(input);
  }
  {
    WarningPrinter warnings(map);
    ProgressBar bar(map);
    map->Update();
  }
  if (errors.messages().empty() && map->GetOutput(0)->GetNumberOfPoints() > 0)
  {
    return ExitOk;
  }
  printErrors(errors.messages());
  return map->GetErrorCode() == vtkSurfaceMapFilter::InvalidInputError ? ExitBadInput
    : map->GetErrorCode() == vtkSurfaceMapFilter::NotCertifiedError    ? ExitNoCertifiedResult
                                                                       : ExitInternalError;
}

// Absolute paths, so `surfacemap evaluate DIR` finds the inputs from anywhere.
std::string absolute(const std::string& path)
{
  std::error_code ec;
  const std::filesystem::path p = std::filesystem::absolute(path, ec);
  return ec ? path : p.lexically_normal().string();
}

// The report's inputs: files, snapped landmarks, sizing, sizes, embedding times.
Json::Value reportInputs(vtkPolyData* first,
  const MapArguments& arguments,
  const std::vector<vtkSmartPointer<vtkPolyData>>& inputs)
{
  Json::Value list(Json::arrayValue);
  for (std::size_t i = 0; i < inputs.size(); ++i)
  {
    Json::Value input(Json::objectValue);
    input["file"] = absolute(arguments.meshes[i]);
    input["landmarks"] =
      arguments.landmarks.empty() ? Json::Value() : Json::Value(absolute(arguments.landmarks[i]));
    input["landmark_snap"] = landmarkSnapJson(inputs[i]);
    input["sizing"] = arguments.sizing.empty() ? Json::Value()
      : isFile(arguments.sizing[i])            ? Json::Value(absolute(arguments.sizing[i]))
                                               : Json::Value("point array " + arguments.sizing[i]);
    input["vertices"] = static_cast<Json::Int64>(inputs[i]->GetNumberOfPoints());
    input["triangles"] = static_cast<Json::Int64>(inputs[i]->GetNumberOfPolys());
    input["embedding_seconds"] =
      jsonNumber(field(first, "EmbeddingSeconds", static_cast<vtkIdType>(i)));
    list.append(input);
  }
  return list;
}

// The report's inputs, sizes, certificate, energies, times and settings;
// prints the summary line.
Json::Value reportMap(vtkSurfaceMapFilter* map,
  const MapArguments& arguments,
  const std::vector<vtkSmartPointer<vtkPolyData>>& inputs,
  double seconds)
{
  const int n = static_cast<int>(inputs.size());
  vtkPolyData* first = map->GetOutput(0);
  const bool certified = field(first, "Bijective") == 1.0;
  std::printf("map of %d surface%s: %s, T has %lld vertices (%lld triangles), %.2f s\n",
    n,
    n == 1 ? "" : "s",
    certified ? "certified bijective" : "NOT certified",
    static_cast<long long>(field(first, "CommonVertices")),
    static_cast<long long>(field(first, "CommonTriangles")),
    seconds);
  Json::Value report(Json::objectValue);
  report["inputs"] = reportInputs(first, arguments, inputs);
  report["common_triangulation"]["vertices"] = jsonNumber(field(first, "CommonVertices"));
  report["common_triangulation"]["triangles"] = jsonNumber(field(first, "CommonTriangles"));
  report["certificate"]["bijective"] = certified;
  report["certificate"]["spherical_degrees"] = Json::Value(Json::arrayValue);
  for (int i = 0; i < n; ++i)
  {
    report["certificate"]["spherical_degrees"].append(
      jsonNumber(field(map->GetOutput(i), "SphericalDegree")));
  }
  report["landmark_error"] = jsonNumber(field(first, "LandmarkError"));
  report["set_aside_landmarks"] = Json::Value(Json::arrayValue);
  if (vtkDataArray* setAside = first->GetFieldData()->GetArray("SetAsideLandmarks"))
  {
    for (vtkIdType k = 0; k < setAside->GetNumberOfTuples(); ++k)
    {
      report["set_aside_landmarks"].append(static_cast<int>(setAside->GetTuple1(k)));
    }
  }
  const std::pair<const char*, const char*> energies[] = { { "total", "Energy" },
    { "barrier", "BarrierEnergy" },
    { "mesh", "MeshEnergy" },
    { "approximation", "ApproximationEnergy" },
    { "map", "MapEnergy" } };
  for (const auto& [key, name] : energies)
  {
    report["energy"][key] = jsonNumber(field(first, name));
  }
  report["seconds"]["total"] = jsonNumber(seconds);
  report["seconds"]["map"] = jsonNumber(field(first, "MapSeconds"));
  // The times depend on it (--threads, else OpenMP's default).
  report["threads"] = surfacemaps::ScopedThreadCount::current();
  report["preset"] = arguments.preset.empty() ? Json::Value() : Json::Value(arguments.preset);
  report["settings"] = settingsJson(map);
  // The map computes the embeddings it is not given with the defaults.
  report["embedding_settings"] = settingsJson(vtkSurfaceMapsSettings::SPHERE_EMBEDDING_SETTINGS,
    [](int k)
    {
      return vtkSurfaceMapsSettings::GetDefault(
        vtkSurfaceMapsSettings::SPHERE_EMBEDDING_SETTINGS, k);
    });
  report["array_transfer_modes"] = Json::Value(Json::objectValue);
  for (int k = 0; k < map->GetNumberOfArrayTransferModes(); ++k)
  {
    const char* name = map->GetArrayTransferModeArrayName(k);
    report["array_transfer_modes"][name] =
      vtkSurfaceMapFilter::GetArrayTransferModeAsString(map->GetArrayTransferMode(name));
  }
  return report;
}

// The report's phases, printed one line each.
Json::Value reportPhases(vtkPolyData* first)
{
  Json::Value phases(Json::arrayValue);
  auto* phaseNames =
    vtkStringArray::SafeDownCast(first->GetFieldData()->GetAbstractArray("PhaseName"));
  for (vtkIdType k = 0; phaseNames && k < phaseNames->GetNumberOfValues(); ++k)
  {
    const bool converged = field(first, "PhaseConverged", k) == 1.0;
    Json::Value phase(Json::objectValue);
    phase["name"] = phaseNames->GetValue(k);
    const std::pair<const char*, const char*> columns[] = { { "iterations", "PhaseIterations" },
      { "stalled_iterations", "PhaseStalledIterations" },
      { "seconds", "PhaseSeconds" },
      { "vertices", "PhaseVertices" },
      { "energy", "PhaseEnergy" },
      { "splits", "PhaseSplits" },
      { "collapses", "PhaseCollapses" },
      { "flips", "PhaseFlips" },
      { "landmark_error", "PhaseLandmarkError" },
      { "remesh_seconds", "PhaseRemeshSeconds" },
      { "derivative_seconds", "PhaseDerivativeSeconds" },
      { "solve_seconds", "PhaseSolveSeconds" },
      { "line_search_seconds", "PhaseLineSearchSeconds" } };
    for (const auto& [key, name] : columns)
    {
      phase[key] = jsonNumber(field(first, name, k));
    }
    phase["converged"] = converged;
    phases.append(phase);
    std::printf("  %-10s %4d iterations%s, %d stalled, %.2f s, %d vertices, %d splits, "
                "%d collapses, %d flips\n",
      (phaseNames->GetValue(k) + ":").c_str(),
      static_cast<int>(field(first, "PhaseIterations", k)),
      converged ? " (converged)" : " (iteration cap)",
      static_cast<int>(field(first, "PhaseStalledIterations", k)),
      field(first, "PhaseSeconds", k),
      static_cast<int>(field(first, "PhaseVertices", k)),
      static_cast<int>(field(first, "PhaseSplits", k)),
      static_cast<int>(field(first, "PhaseCollapses", k)),
      static_cast<int>(field(first, "PhaseFlips", k)));
  }
  if (phaseNames && phaseNames->GetNumberOfValues() > 0 && phaseNames->GetValue(0) == "landmarks")
  {
    std::printf("  landmark error %.3g (input units)\n", field(first, "LandmarkError"));
  }
  return phases;
}

// The error bound, certified on every input vertex (input units), into
// `report` when the map has one.
void reportErrorBound(Json::Value& report, vtkSurfaceMapFilter* map, int n)
{
  if (map->GetMaxError() <= 0.0)
  {
    return;
  }
  Json::Value& bounds = report["error_bound"];
  bounds = Json::Value(Json::arrayValue);
  for (int i = 0; i < n; ++i)
  {
    const double distance = field(map->GetOutput(i), "BaseDistance");
    const double bound = field(map->GetOutput(i), "ErrorBound");
    Json::Value input(Json::objectValue);
    input["input"] = i;
    input["base_distance"] = jsonNumber(distance);
    input["bound"] = jsonNumber(bound);
    bounds.append(input);
    std::printf("  error bound on input %d: every vertex within %.4g of its base point on T "
                "(bound %.4g = %g x bbox diagonal)\n",
      i,
      distance,
      bound,
      map->GetMaxError());
  }
}

// Writes one output mode's outputs as DIR/<prefix>_<i>.vtp (the filter reuses
// the computed map); returns the report's metrics of maps 0 -> i, or null
// with a null `what`.
Json::Value writeOutputs(vtkSurfaceMapFilter* map,
  ErrorCapture& errors,
  MapWriter& files,
  const char* prefix,
  const char* what,
  const std::vector<vtkSmartPointer<vtkPolyData>>& inputs,
  bool withSourceOriginal)
{
  map->Update();
  if (!errors.messages().empty() || map->GetOutput(0)->GetNumberOfPoints() == 0)
  {
    throw std::logic_error(std::string("the ") + prefix + " outputs failed: " +
      (errors.messages().empty() ? std::string("empty") : errors.messages().front()));
  }
  const int n = static_cast<int>(inputs.size());
  for (int i = 0; i < n; ++i)
  {
    files.write(map->GetOutput(i), mapFileName(prefix, i));
  }
  if (!what)
  {
    return Json::Value();
  }
  Json::Value maps(Json::arrayValue);
  for (int i = n > 1 ? 1 : 0; i < n; ++i)
  {
    maps.append(evaluate(what,
      i,
      map->GetOutput(0),
      map->GetOutput(i),
      // Input 0's distance to T_0 is the same for every pair: measured once.
      withSourceOriginal && i <= 1 ? inputs[0].Get() : nullptr,
      inputs[i]));
  }
  return maps;
}

// With --add-to: the existing map's inputs (with the embeddings it used) go
// first, its T to the filter's port 1, its input files into the arguments
// (their report entries are the existing map's: mergeExistingReport).
void addExisting(MapArguments& arguments,
  std::vector<vtkSmartPointer<vtkPolyData>>& inputs,
  const ExistingMapFiles& existing,
  vtkSurfaceMapFilter* map)
{
  inputs.insert(inputs.begin(), existing.embeddings.begin(), existing.embeddings.end());
  for (const auto& common : existing.common)
  {
    map->AddInputData(1, common);
  }
  const std::vector<std::string> files = existingInputFiles(existing);
  arguments.meshes.insert(arguments.meshes.begin(), files.begin(), files.end());
  for (std::vector<std::string>* list : { &arguments.landmarks, &arguments.sizing })
  {
    if (!list->empty())
    {
      list->insert(list->begin(), files.size(), "");
    }
  }
}

} // namespace

int runMap(const std::vector<std::string>& args)
{
  vtkNew<vtkSurfaceMapFilter> map;
  // The existing map's settings first, so that the flags override them.
  ExistingMapFiles existing;
  const std::string addTo = addToDirectory(args);
  if (!addTo.empty() && !succeeds([&] { existing = readExistingMap(addTo, map); }))
  {
    return ExitBadInput;
  }
  MapArguments arguments = parseArguments(args, map);
  std::vector<vtkSmartPointer<vtkPolyData>> inputs = readInputs(arguments);
  if (inputs.empty())
  {
    return ExitBadInput;
  }
  if (!addTo.empty())
  {
    addExisting(arguments, inputs, existing, map);
  }
  const std::string missing =
    missingArrayTransferNames(map, std::vector<vtkPolyData*>(inputs.begin(), inputs.end()));
  if (!missing.empty())
  {
    throw UsageError{ "no input has a point array " + missing +
      " (named by --categorical or --continuous)" };
  }
  // Before computing: the directory's parents, this run's staging
  // directory, and the refusals (an earlier map, another run writing it).
  std::unique_ptr<MapDestination> destination;
  if (!succeeds(
        [&] {
          destination = std::make_unique<MapDestination>(arguments.outputDir, arguments.overwrite);
        }))
  {
    return ExitBadInput;
  }
  const auto start = std::chrono::steady_clock::now();
  ErrorCapture errors(map);
  const int computed = computeMap(map, inputs, errors);
  if (computed != ExitOk)
  {
    return computed; // the destination removes its staging directory
  }
  const double seconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const bool certified = field(map->GetOutput(0), "Bijective") == 1.0;
  Json::Value report = reportMap(map, arguments, inputs, seconds);
  if (!addTo.empty())
  {
    mergeExistingReport(report, existing);
  }
  report["phases"] = reportPhases(map->GetOutput(0));
  reportErrorBound(report, map, static_cast<int>(inputs.size()));
  try
  {
    // The earlier map, if any, stays untouched until the new one is
    // complete and checked beside it (MapDestination).
    destination->beginWriting();
    MapWriter files(destination->path());
    report["approximating_map"] =
      writeOutputs(map, errors, files, "common", "approximating map", inputs, true);
    // From T on every input, before the output mode changes the outputs.
    const std::vector<std::string> names = specimenNames(arguments.meshes);
    std::vector<vtkPolyData*> common;
    for (std::size_t i = 0; i < inputs.size(); ++i)
    {
      common.push_back(map->GetOutput(static_cast<int>(i)));
    }
    files.writeBytes(correspondencesArchive(names, common), "correspondences.npz");
    const std::vector<double> landmarkDistances = landmarkErrors(inputs, common);
    map->SetOutputModeToMappedFirstInput();
    report["exact_map"] = writeOutputs(map, errors, files, "mapped", "exact map", inputs, false);
    map->SetOutputModeToInputEmbeddings();
    writeOutputs(map, errors, files, "embedding", nullptr, inputs, false);
    report["specimens"] = specimenFit(report, names, landmarkDistances);
    files.writeBytes(specimenFitCsv(report["specimens"]), "fit.csv");
    files.addToReport(report);
    writeFileAtomically(destination->path() + "/report.json", jsonText(report));
    destination->commit(files.names());
  }
  catch (const std::runtime_error& e)
  {
    printError(e.what());
    return ExitBadInput;
  }
  std::printf("  written to %s: common_<i>.vtp, mapped_<i>.vtp, embedding_<i>.vtp (i < %d), "
              "correspondences.npz, fit.csv, report.json\n",
    arguments.outputDir.c_str(),
    static_cast<int>(inputs.size()));
  return certified ? ExitOk : ExitNoCertifiedResult;
}

} // namespace surfacemap
