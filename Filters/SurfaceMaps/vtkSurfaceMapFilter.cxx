#include "vtkSurfaceMapFilter.h"

#include "vtkSurfaceMapsConversion.h"

#include "base/InputError.h"
#include "geometry/MapMetrics.h"
#include "map/MapTransfer.h"
#include "mesh/MeshValidation.h"
#include "embedding/SphereEmbedding.h"
#include "geometry/SphericalTriangulation.h"
#include "map/SurfaceMap.h"
#include "base/ThreadCount.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDemandDrivenPipeline.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIdList.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkLogger.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkStringArray.h"
#include "vtkWeakPointer.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkSurfaceMapFilter);

// The last computed map, kept so that switching OutputMode does not recompute
// it, and what it was computed from.
struct vtkSurfaceMapFilter::vtkInternals
{
  bool HasMap = false;
  std::vector<vtkWeakPointer<vtkPolyData>> Inputs;
  std::vector<vtkMTimeType> InputTimes;
  std::string Settings;
  /// The inputs as the engine saw them (meshes, embeddings f_i, landmarks).
  std::vector<surfacemaps::MapInput> MapInputs;
  std::vector<double> EmbeddingSeconds;
  surfacemaps::SurfaceMapResult Map;
  /// Largest progress reported in the current update.
  double Progress = 0.0;

  void Clear() { *this = vtkInternals(); }

  // Every setting that changes the map (all but OutputMode, MappedInput and
  // NumberOfThreads, which change only what is shown or how fast), in full
  // precision: the key that decides whether the kept map can be reused. One
  // list with PrintSelf, so a new setting cannot be printed but forgotten here.
  static std::string SettingsKey(vtkSurfaceMapFilter* filter)
  {
    std::ostringstream key;
    key.precision(17);
    filter->PrintSettings(key, vtkIndent(), false);
    return key.str();
  }

  bool Matches(const std::vector<vtkPolyData*>& inputs, const std::string& settings) const
  {
    if (!this->HasMap || inputs.size() != this->Inputs.size() || settings != this->Settings)
    {
      return false;
    }
    for (std::size_t i = 0; i < inputs.size(); ++i)
    {
      if (this->Inputs[i].GetPointer() != inputs[i] || this->InputTimes[i] != inputs[i]->GetMTime())
      {
        return false;
      }
    }
    return true;
  }
};

namespace
{
const char* const LandmarksName = "Landmarks";
const char* const SizingName = "Sizing";
const char* const SpherePositionName = "SpherePosition";
const char* const SourceCellIdName = "SourceCellId";
const char* const SourceBarycentricName = "SourceBarycentric";

// "input 1" or "input 1 (a.obj)" when the input carries a file name.
std::string inputName(vtkPolyData* input, int index)
{
  const std::string plain = "input " + std::to_string(index);
  const std::string name = vtkSurfaceMapsConversion::InputName(input, index);
  return name == plain ? plain : plain + " (" + name + ")";
}

surfacemaps::SurfaceMapOptions mapOptions(vtkSurfaceMapFilter* f)
{
  surfacemaps::SurfaceMapOptions options;
  const surfacemaps::PairMode modes[] = { surfacemaps::PairMode::Star,
    surfacemaps::PairMode::Sequence,
    surfacemaps::PairMode::Cycle,
    surfacemaps::PairMode::All };
  options.pairs = modes[f->GetPairMode()];
  options.landmarkIterations = f->GetLandmarkIterations();
  options.landmarkWeight = f->GetLandmarkWeight();
  options.landmarkBarrierWeight = f->GetLandmarkBarrierWeight();
  options.landmarkTolerance = f->GetLandmarkTolerance();
  options.relaxLandmarkPhase = f->GetRelaxLandmarkPhase();
  options.keepLandmarks = f->GetKeepLandmarks();
  options.coarse.enabled = f->GetCoarseIterations() > 0;
  options.coarse.maxIterations = f->GetCoarseIterations();
  options.coarse.targetError = f->GetCoarseError();
  options.coarse.barrierWeight = f->GetCoarseBarrierWeight();
  options.fine.enabled = f->GetFineIterations() > 0;
  options.fine.maxIterations = f->GetFineIterations();
  options.fine.targetError = f->GetTargetError();
  options.fine.barrierWeight = f->GetFineBarrierWeight();
  options.meshWeight = f->GetMeshWeight();
  options.mapWeight = f->GetMapWeight();
  options.approximationWeight = f->GetApproximationWeight();
  options.maxError = f->GetMaxError();
  options.boundIterations = f->GetBoundIterations();
  options.refinementRounds = f->GetRefinementRounds();
  options.refinementIterations = f->GetRefinementIterations();
  options.refinementDistortion = f->GetRefinementDistortion();
  options.refinementGrowth = f->GetRefinementGrowth();
  options.squeezeDistortion = f->GetSqueezeDistortion();
  options.kinkRetries = f->GetKinkRetries();
  options.approximationSamples = f->GetApproximationSamples();
  options.minEdgeLength = f->GetMinEdgeLength();
  options.maxEdgeLength = f->GetMaxEdgeLength();
  options.decrementTolerance = f->GetDecrementTolerance();
  return options;
}

surfacemaps::Logger vtkLogSink()
{
  surfacemaps::Logger log;
  log.sink = [](surfacemaps::Logger::Level level, const std::string& message)
  {
    if (level == surfacemaps::Logger::Warning)
    {
      vtkLog(WARNING, << message);
    }
    else
    {
      vtkLog(TRACE, << message);
    }
  };
  return log;
}

std::string joined(const std::vector<std::string>& messages)
{
  std::string text;
  for (const std::string& m : messages)
  {
    text += (text.empty() ? "" : "; ") + m;
  }
  return text;
}

// The "Sizing" array of an input (empty if absent); defects are reported.
std::vector<double> readSizing(vtkPolyData* input,
  const std::string& name,
  std::vector<std::string>& defects)
{
  std::vector<double> sizing;
  vtkDataArray* array = input->GetPointData()->GetArray(SizingName);
  if (!array)
  {
    return sizing;
  }
  if (array->GetNumberOfComponents() != 1 ||
    array->GetNumberOfTuples() != input->GetNumberOfPoints())
  {
    defects.push_back(name + " has a Sizing array of the wrong shape (" +
      std::to_string(array->GetNumberOfTuples()) + " x " +
      std::to_string(array->GetNumberOfComponents()) + " values for " +
      std::to_string(input->GetNumberOfPoints()) + " points)");
    return sizing;
  }
  sizing.resize(static_cast<std::size_t>(array->GetNumberOfTuples()));
  for (vtkIdType v = 0; v < array->GetNumberOfTuples(); ++v)
  {
    sizing[v] = array->GetComponent(v, 0);
    if (!std::isfinite(sizing[v]) || sizing[v] <= 0.0)
    {
      defects.push_back(name + " has a Sizing value that is not a positive length (" +
        std::to_string(sizing[v]) + " at point " + std::to_string(v) + ")");
      sizing.clear();
      break;
    }
  }
  return sizing;
}

// Step 1: the inputs as engine inputs (mesh, landmarks, sizing), validated.
// Throws InputError naming every defect of every input.
std::vector<surfacemaps::MapInput> readInputs(const std::vector<vtkPolyData*>& inputs,
  bool useSizing)
{
  const int n = static_cast<int>(inputs.size());
  std::vector<surfacemaps::MapInput> result(n);
  std::vector<std::string> defects, names(n);
  std::vector<std::vector<int>> landmarks(n);
  bool anyLandmarks = false;
  for (int i = 0; i < n; ++i)
  {
    names[i] = inputName(inputs[i], i);
    result[i].mesh = vtkSurfaceMapsConversion::ToPolygonMesh(inputs[i]);
    for (const std::string& d : surfacemaps::validateMesh(result[i].mesh).defects)
    {
      defects.push_back(names[i] + " " + d);
    }

    landmarks[i] = vtkSurfaceMapsConversion::LandmarkIds(inputs[i]);
    if (!landmarks[i].empty() && landmarks[i].size() != result[i].mesh.points.size())
    {
      defects.push_back(names[i] + " has a Landmarks array of the wrong length (" +
        std::to_string(landmarks[i].size()) + " values for " +
        std::to_string(result[i].mesh.points.size()) + " points)");
      landmarks[i].clear();
    }
    for (const std::string& d : surfacemaps::checkLandmarkIds(landmarks[i]))
    {
      defects.push_back(names[i] + " " + d);
    }
    anyLandmarks = anyLandmarks ||
      std::any_of(landmarks[i].begin(), landmarks[i].end(), [](int id) { return id >= 0; });

    if (useSizing)
    {
      result[i].sizing = readSizing(inputs[i], names[i], defects);
    }
  }
  if (anyLandmarks && n > 1)
  {
    for (const auto& perInput : surfacemaps::checkLandmarkCorrespondence(landmarks, names))
    {
      defects.insert(defects.end(), perInput.begin(), perInput.end());
    }
  }
  if (!defects.empty())
  {
    throw surfacemaps::InputError(joined(defects));
  }
  for (int i = 0; i < n && anyLandmarks; ++i)
  {
    result[i].landmarks = landmarks[i].empty() ? std::vector<int>(result[i].mesh.points.size(), -1)
                                               : std::move(landmarks[i]);
  }
  return result;
}

// A present "SpherePosition" array, normalised and certified; empty if absent.
std::vector<Eigen::Vector3d> givenEmbedding(vtkPolyData* input,
  const surfacemaps::MapInput& mapInput,
  const std::string& name)
{
  vtkDataArray* array = input->GetPointData()->GetArray(SpherePositionName);
  if (!array)
  {
    return {};
  }
  std::vector<Eigen::Vector3d> positions = vtkSurfaceMapsConversion::SpherePositions(input);
  if (positions.empty())
  {
    throw surfacemaps::InputError(name + " has a SpherePosition array of the wrong shape (" +
      std::to_string(array->GetNumberOfTuples()) + " x " +
      std::to_string(array->GetNumberOfComponents()) + " values for " +
      std::to_string(input->GetNumberOfPoints()) + " points)");
  }
  for (std::size_t v = 0; v < positions.size(); ++v)
  {
    const double length = positions[v].norm();
    if (!std::isfinite(length) || length == 0.0)
    {
      throw surfacemaps::InputError(
        name + " has a SpherePosition that is not a direction at point " + std::to_string(v));
    }
    positions[v] /= length;
  }
  const surfacemaps::BijectivityCertificate certificate =
    surfacemaps::certifyBijective(positions, mapInput.mesh.triangles());
  if (!certificate.bijective)
  {
    throw surfacemaps::InputError(name +
      " has a SpherePosition array that is not a bijective embedding: " + certificate.reason);
  }
  return positions;
}

template<typename ArrayT, typename T>
void addField(vtkFieldData* fields, const char* name, const std::vector<T>& values)
{
  auto array = vtkSmartPointer<ArrayT>::New();
  array->SetName(name);
  array->SetNumberOfValues(static_cast<vtkIdType>(values.size()));
  for (std::size_t k = 0; k < values.size(); ++k)
  {
    array->SetValue(static_cast<vtkIdType>(k), values[k]);
  }
  fields->AddArray(array);
}

template<typename ArrayT, typename T>
void addField(vtkFieldData* fields, const char* name, T value)
{
  addField<ArrayT>(fields, name, std::vector<T>{ value });
}

vtkSmartPointer<vtkDoubleArray> vectorArray(const char* name,
  const std::vector<Eigen::Vector3d>& values)
{
  auto array = vtkSmartPointer<vtkDoubleArray>::New();
  array->SetName(name);
  array->SetNumberOfComponents(3);
  array->SetNumberOfTuples(static_cast<vtkIdType>(values.size()));
  for (std::size_t v = 0; v < values.size(); ++v)
  {
    array->SetTypedTuple(static_cast<vtkIdType>(v), values[v].data());
  }
  return array;
}

// Per-triangle symmetric Dirichlet density of the map P -> Q (see the class
// documentation): 1 for an isometric triangle.
std::vector<double> distortionPerTriangle(const std::vector<Eigen::Vector3d>& P,
  const std::vector<Eigen::Vector3d>& Q,
  const std::vector<std::array<int, 3>>& triangles)
{
  const surfacemaps::MapMetrics metrics = surfacemaps::measureMap(P, Q, triangles);
  std::vector<double> result(triangles.size(), std::numeric_limits<double>::infinity());
  for (std::size_t t = 0; t < triangles.size(); ++t)
  {
    const double s1 = metrics.s1[t], s2 = metrics.s2[t];
    const double a0 = metrics.areaP[t], a1 = metrics.areaQ[t];
    if (std::isfinite(metrics.distortion[t]) && s2 > 0.0 && a0 + a1 > 0.0)
    {
      result[t] =
        (a1 * (s1 * s1 + s2 * s2) + a0 * (1.0 / (s1 * s1) + 1.0 / (s2 * s2))) / (2.0 * (a0 + a1));
    }
  }
  return result;
}

// Points and triangles of an output.
void setGeometry(vtkPolyData* output,
  const std::vector<Eigen::Vector3d>& points,
  const std::vector<std::array<int, 3>>& triangles)
{
  surfacemaps::PolygonMesh mesh;
  mesh.points = points;
  for (const auto& t : triangles)
  {
    mesh.addFace({ t[0], t[1], t[2] });
  }
  vtkSmartPointer<vtkPolyData> poly = vtkSurfaceMapsConversion::ToPolyData(mesh);
  output->SetPoints(poly->GetPoints());
  output->SetPolys(poly->GetPolys());
}

// Where the output's points lie on `input` (SourceCellId, SourceBarycentric),
// and the input's own point arrays interpolated there.
void setSourcePointData(vtkPolyData* output,
  vtkPolyData* input,
  const surfacemaps::PolygonMesh& inputMesh,
  const std::vector<surfacemaps::SurfacePoint>& points)
{
  const vtkIdType n = static_cast<vtkIdType>(points.size());
  vtkPointData* to = output->GetPointData();
  vtkPointData* from = input->GetPointData();
  for (const char* skip :
    { LandmarksName, SizingName, SpherePositionName, SourceCellIdName, SourceBarycentricName })
  {
    to->CopyFieldOff(skip);
  }
  to->InterpolateAllocate(from, n);
  vtkNew<vtkIdList> corners;
  corners->SetNumberOfIds(3);
  for (vtkIdType v = 0; v < n; ++v)
  {
    const surfacemaps::SurfacePoint& p = points[v];
    if (p.triangle < 0 || static_cast<std::size_t>(p.triangle) >= inputMesh.numberOfFaces())
    {
      throw std::logic_error("point " + std::to_string(v) + " lies on no triangle of its input");
    }
    const int* t = inputMesh.face(static_cast<std::size_t>(p.triangle));
    for (int k = 0; k < 3; ++k)
    {
      corners->SetId(k, t[k]);
    }
    double w[3] = { p.barycentric[0], p.barycentric[1], p.barycentric[2] };
    to->InterpolatePoint(from, v, corners, w);
  }
  vtkSurfaceMapsConversion::AddSourcePoints(to, points);
}

// Input i itself with its sphere embedding f_i as "SpherePosition".
void setEmbeddingOutput(vtkPolyData* output,
  vtkPolyData* input,
  const std::vector<Eigen::Vector3d>& embedding)
{
  output->CopyStructure(input);
  output->GetPointData()->PassData(input->GetPointData());
  output->GetCellData()->PassData(input->GetCellData());
  output->GetPointData()->AddArray(vectorArray(SpherePositionName, embedding));
  output->GetFieldData()->PassData(input->GetFieldData());
}

void setLandmarks(vtkPolyData* output, const std::vector<int>& ids)
{
  const vtkIdType n = output->GetNumberOfPoints();
  auto array = vtkSmartPointer<vtkIntArray>::New();
  array->SetName(LandmarksName);
  array->SetNumberOfValues(n);
  for (vtkIdType v = 0; v < n; ++v)
  {
    array->SetValue(v, static_cast<std::size_t>(n) == ids.size() ? ids[v] : -1);
  }
  output->GetPointData()->AddArray(array);
}

// Field data common to every output: certificate, sizes, energies, phases.
void setMapFieldData(vtkFieldData* fields,
  const surfacemaps::SurfaceMapResult& map,
  const std::vector<double>& embeddingSeconds,
  int index)
{
  bool bijective = !map.certificates.empty();
  for (const auto& c : map.certificates)
  {
    bijective = bijective && c.bijective;
  }
  addField<vtkIntArray>(fields, "InputIndex", index);
  addField<vtkIntArray>(fields, "Bijective", bijective ? 1 : 0);
  addField<vtkDoubleArray>(fields,
    "SphericalDegree",
    index < static_cast<int>(map.certificates.size()) ? map.certificates[index].degree : 0.0);
  addField<vtkIdTypeArray>(fields,
    "CommonVertices",
    static_cast<vtkIdType>(map.spherePositions.empty() ? 0 : map.spherePositions[0].size()));
  addField<vtkIdTypeArray>(fields, "CommonTriangles", static_cast<vtkIdType>(map.triangles.size()));
  addField<vtkDoubleArray>(fields, "Energy", map.energy);
  addField<vtkDoubleArray>(fields, "BarrierEnergy", map.barrierEnergy);
  addField<vtkDoubleArray>(fields, "MeshEnergy", map.meshEnergy);
  addField<vtkDoubleArray>(fields, "ApproximationEnergy", map.approximationEnergy);
  addField<vtkDoubleArray>(fields, "MapEnergy", map.mapEnergy);
  addField<vtkDoubleArray>(fields, "LandmarkError", map.landmarkError);
  addField<vtkDoubleArray>(fields, "BaseDistance", map.baseDistance[index]);
  addField<vtkDoubleArray>(fields, "ErrorBound", map.errorBound[index]);
  addField<vtkDoubleArray>(fields, "MapSeconds", map.seconds);
  addField<vtkDoubleArray>(fields, "EmbeddingSeconds", embeddingSeconds);

  auto names = vtkSmartPointer<vtkStringArray>::New();
  names->SetName("PhaseName");
  std::vector<int> iterations, converged, vertices, splits, collapses, flips;
  std::vector<double> energy, landmarkError, seconds, remesh, derivatives, solve, lineSearch;
  for (const surfacemaps::MapPhaseReport& p : map.phases)
  {
    names->InsertNextValue(p.name);
    iterations.push_back(p.iterations);
    converged.push_back(p.converged ? 1 : 0);
    energy.push_back(p.energy);
    vertices.push_back(p.vertices);
    splits.push_back(p.splits);
    collapses.push_back(p.collapses);
    flips.push_back(p.flips);
    landmarkError.push_back(p.landmarkError);
    seconds.push_back(p.seconds);
    remesh.push_back(p.remeshSeconds);
    derivatives.push_back(p.derivativeSeconds);
    solve.push_back(p.solveSeconds);
    lineSearch.push_back(p.lineSearchSeconds);
  }
  fields->AddArray(names);
  addField<vtkIntArray>(fields, "PhaseIterations", iterations);
  addField<vtkIntArray>(fields, "PhaseConverged", converged);
  addField<vtkDoubleArray>(fields, "PhaseEnergy", energy);
  addField<vtkIntArray>(fields, "PhaseVertices", vertices);
  addField<vtkIntArray>(fields, "PhaseSplits", splits);
  addField<vtkIntArray>(fields, "PhaseCollapses", collapses);
  addField<vtkIntArray>(fields, "PhaseFlips", flips);
  addField<vtkDoubleArray>(fields, "PhaseLandmarkError", landmarkError);
  addField<vtkDoubleArray>(fields, "PhaseSeconds", seconds);
  addField<vtkDoubleArray>(fields, "PhaseRemeshSeconds", remesh);
  addField<vtkDoubleArray>(fields, "PhaseDerivativeSeconds", derivatives);
  addField<vtkDoubleArray>(fields, "PhaseSolveSeconds", solve);
  addField<vtkDoubleArray>(fields, "PhaseLineSearchSeconds", lineSearch);
}

void setDistortion(vtkPolyData* output, const std::vector<double>& distortion)
{
  auto array = vtkSmartPointer<vtkDoubleArray>::New();
  array->SetName("Distortion");
  array->SetNumberOfValues(static_cast<vtkIdType>(distortion.size()));
  for (std::size_t t = 0; t < distortion.size(); ++t)
  {
    array->SetValue(static_cast<vtkIdType>(t), distortion[t]);
  }
  output->GetCellData()->AddArray(array);
}

// After an abort: VTK 9.1 would still mark the empty outputs as up to date
// (the ABORTED key only arrives in 9.3), so the next Update would not run.
void markNotGenerated(vtkInformationVector* outputs)
{
  for (int i = 0; i < outputs->GetNumberOfInformationObjects(); ++i)
  {
    outputs->GetInformationObject(i)->Set(vtkDemandDrivenPipeline::DATA_NOT_GENERATED(), 1);
  }
}

} // namespace

vtkSurfaceMapFilter::vtkSurfaceMapFilter()
  : Internals(new vtkInternals)
{
  this->SetNumberOfInputPorts(1);
  this->SetNumberOfOutputPorts(1);
}

vtkSurfaceMapFilter::~vtkSurfaceMapFilter() = default;

int vtkSurfaceMapFilter::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  info->Set(vtkAlgorithm::INPUT_IS_REPEATABLE(), 1);
  return 1;
}

void vtkSurfaceMapFilter::UpdateNumberOfOutputPorts()
{
  const int n = std::max(1, this->GetNumberOfInputConnections(0));
  if (n != this->GetNumberOfOutputPorts())
  {
    this->SetNumberOfOutputPorts(n);
  }
}

void vtkSurfaceMapFilter::SetInputConnection(int port, vtkAlgorithmOutput* input)
{
  this->Superclass::SetInputConnection(port, input);
  this->UpdateNumberOfOutputPorts();
}

void vtkSurfaceMapFilter::SetInputConnection(vtkAlgorithmOutput* input)
{
  this->SetInputConnection(0, input);
}

void vtkSurfaceMapFilter::AddInputConnection(int port, vtkAlgorithmOutput* input)
{
  this->Superclass::AddInputConnection(port, input);
  this->UpdateNumberOfOutputPorts();
}

void vtkSurfaceMapFilter::AddInputConnection(vtkAlgorithmOutput* input)
{
  this->AddInputConnection(0, input);
}

void vtkSurfaceMapFilter::RemoveInputConnection(int port, vtkAlgorithmOutput* input)
{
  this->Superclass::RemoveInputConnection(port, input);
  this->UpdateNumberOfOutputPorts();
}

void vtkSurfaceMapFilter::RemoveInputConnection(int port, int idx)
{
  this->Superclass::RemoveInputConnection(port, idx);
  this->UpdateNumberOfOutputPorts();
}

void vtkSurfaceMapFilter::RemoveAllInputConnections(int port)
{
  this->Superclass::RemoveAllInputConnections(port);
  this->UpdateNumberOfOutputPorts();
}

void vtkSurfaceMapFilter::SetNumberOfInputConnections(int port, int n)
{
  this->Superclass::SetNumberOfInputConnections(port, n);
  this->UpdateNumberOfOutputPorts();
}

int vtkSurfaceMapFilter::RequestData(vtkInformation*,
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector)
{
  const int n = inputVector[0]->GetNumberOfInformationObjects();
  std::vector<vtkPolyData*> inputs(n);
  for (int i = 0; i < n; ++i)
  {
    inputs[i] = vtkPolyData::GetData(inputVector[0], i);
  }
  std::vector<vtkPolyData*> outputs(outputVector->GetNumberOfInformationObjects());
  for (std::size_t i = 0; i < outputs.size(); ++i)
  {
    outputs[i] = vtkPolyData::GetData(outputVector, static_cast<int>(i));
    outputs[i]->Initialize();
  }
  auto clearOutputs = [&outputs]()
  {
    for (vtkPolyData* output : outputs)
    {
      output->Initialize();
    }
  };
  this->SetErrorCode(vtkErrorCode::NoError);

  vtkInternals& internals = *this->Internals;
  internals.Progress = 0.0;
  // Progress never goes back within an update; false once aborted.
  auto report = [this, &internals](double fraction, const std::string& text)
  {
    internals.Progress = std::max(internals.Progress, std::min(1.0, fraction));
    this->SetProgressText(text.c_str());
    this->UpdateProgress(internals.Progress);
    return !this->GetAbortExecute();
  };

  // A bad MappedInput is a setting error: the kept map stays.
  if (this->OutputMode == MAPPED_INPUT && this->MappedInput > 0 && this->MappedInput >= n)
  {
    this->SetErrorCode(InvalidInputError);
    vtkErrorMacro(<< "MappedInput is " << this->MappedInput << " but there "
                  << (n == 1 ? "is 1 input" : "are " + std::to_string(n) + " inputs"));
    return 0;
  }

  const surfacemaps::ScopedThreadCount threads(this->NumberOfThreads);
  try
  {
    if (static_cast<int>(outputs.size()) != n)
    {
      throw std::logic_error(
        std::to_string(n) + " inputs but " + std::to_string(outputs.size()) + " output ports");
    }
    const std::string settings = vtkInternals::SettingsKey(this);
    if (!internals.Matches(inputs, settings))
    {
      internals.Clear();

      // 1. Inputs, validated (mesh, landmarks, sizing).
      report(0.0, "Validating the inputs");
      std::vector<surfacemaps::MapInput> mapInputs =
        readInputs(inputs, this->SizingMode == SIZING_ARRAY_OR_CURVATURE);

      // 2. Sphere embeddings: given ones certified, missing ones computed.
      std::vector<double> embeddingSeconds(n, 0.0);
      std::vector<int> missing;
      for (int i = 0; i < n; ++i)
      {
        mapInputs[i].spherePositions =
          givenEmbedding(inputs[i], mapInputs[i], inputName(inputs[i], i));
        if (mapInputs[i].spherePositions.empty())
        {
          missing.push_back(i);
        }
      }
      const double embeddingShare = std::min(0.4, 0.1 * static_cast<double>(missing.size()));
      if (!missing.empty())
      {
        // All missing embeddings at once, one per thread.
        const std::string text = missing.size() == 1
          ? "Sphere embedding of " + inputName(inputs[missing[0]], missing[0])
          : "Sphere embeddings of " + std::to_string(missing.size()) + " inputs";
        if (!report(0.0, text))
        {
          throw surfacemaps::Aborted();
        }
        std::vector<const surfacemaps::PolygonMesh*> meshes;
        for (int i : missing)
        {
          meshes.push_back(&mapInputs[i].mesh);
        }
        surfacemaps::SphereEmbeddingOptions options;
        options.progress = [&](double fraction) { return report(embeddingShare * fraction, text); };
        options.log = vtkLogSink();
        try
        {
          std::vector<surfacemaps::SphereEmbeddingResult> embeddings =
            surfacemaps::embedAllOnSphere(meshes, options);
          for (std::size_t k = 0; k < missing.size(); ++k)
          {
            mapInputs[missing[k]].spherePositions = std::move(embeddings[k].positions);
            embeddingSeconds[missing[k]] = embeddings[k].seconds;
          }
        }
        catch (const surfacemaps::EmbeddingFailure& e)
        {
          const int i = missing[e.index];
          throw std::runtime_error(inputName(inputs[i], i) + ": " + e.what());
        }
      }

      // 3. The map.
      surfacemaps::SurfaceMapOptions options = mapOptions(this);
      options.log = vtkLogSink();
      options.progress = [&](const surfacemaps::SurfaceMapProgress& p)
      {
        std::ostringstream text;
        if (p.phase == "output")
        {
          text << "Surface map: certifying and lifting";
        }
        else
        {
          text << "Surface map: " << p.phase << " phase, iteration " << p.iteration << ", "
               << p.vertices << " vertices";
        }
        return report(embeddingShare + (0.98 - embeddingShare) * p.fraction, text.str());
      };
      if (!report(embeddingShare, "Surface map"))
      {
        throw surfacemaps::Aborted();
      }
      internals.Map = surfacemaps::computeSurfaceMap(mapInputs, options);
      internals.MapInputs = std::move(mapInputs);
      internals.EmbeddingSeconds = std::move(embeddingSeconds);
      internals.Settings = settings;
      for (vtkPolyData* input : inputs)
      {
        internals.Inputs.emplace_back(input);
        internals.InputTimes.push_back(input->GetMTime());
      }
      internals.HasMap = true;
    }

    // 4. Outputs.
    report(0.98, "Writing the outputs");
    const surfacemaps::SurfaceMapResult& map = internals.Map;
    const std::vector<surfacemaps::MapInput>& mapInputs = internals.MapInputs;
    if (this->OutputMode == INPUT_EMBEDDINGS)
    {
      for (int i = 0; i < n; ++i)
      {
        setEmbeddingOutput(outputs[i], inputs[i], map.inputSpherePositions[i]);
        setMapFieldData(outputs[i]->GetFieldData(), map, internals.EmbeddingSeconds, i);
      }
      report(1.0, "Done");
      return 1;
    }
    const bool common = this->OutputMode == COMMON_TRIANGULATION;
    // Mapped: input k's vertices carried onto every input j.
    const int k = common ? 0 : this->MappedInput;
    std::vector<std::array<int, 3>> mappedTriangles;
    std::vector<std::vector<surfacemaps::SurfacePoint>> mappedSources(common ? 0 : n);
    std::vector<std::vector<Eigen::Vector3d>> mappedPoints(common ? 0 : n);
    if (!common)
    {
      mappedTriangles = mapInputs[k].mesh.triangles();
      for (int j = 0; j < n; ++j)
      {
        mappedSources[j] = surfacemaps::transferVertices(map, mapInputs, k, j);
        const std::vector<std::array<int, 3>> onJ = mapInputs[j].mesh.triangles();
        for (const surfacemaps::SurfacePoint& p : mappedSources[j])
        {
          mappedPoints[j].push_back(
            surfacemaps::evaluateSurfacePoint(mapInputs[j].mesh.points, onJ, p));
        }
      }
    }
    const auto& triangles = common ? map.triangles : mappedTriangles;
    const auto& points = common ? map.lifted : mappedPoints;
    const auto& sources = common ? map.sourcePoints : mappedSources;
    for (int i = 0; i < n; ++i)
    {
      vtkPolyData* output = outputs[i];
      setGeometry(output, points[i], triangles);
      setSourcePointData(output, inputs[i], mapInputs[i].mesh, sources[i]);
      vtkSurfaceMapsConversion::SetCornerTCoords(
        output->GetPointData(), mapInputs[i].mesh.cornerTexCoords, sources[i]);
      if (common)
      {
        output->GetPointData()->AddArray(vectorArray(SpherePositionName, map.spherePositions[i]));
        setLandmarks(output, map.landmarks);
      }
      else
      {
        setLandmarks(output, mapInputs[k].landmarks);
        output->GetCellData()->PassData(inputs[k]->GetCellData());
      }
      setDistortion(output,
        i == k ? std::vector<double>(triangles.size(), 1.0)
               : distortionPerTriangle(points[k], points[i], triangles));
      output->GetFieldData()->PassData(inputs[i]->GetFieldData());
      setMapFieldData(output->GetFieldData(), map, internals.EmbeddingSeconds, i);
    }
    report(1.0, "Done");
  }
  catch (const surfacemaps::Aborted&)
  {
    internals.Clear();
    clearOutputs();
    markNotGenerated(outputVector);
    return 1;
  }
  catch (const surfacemaps::Aborted&)
  {
    internals.Clear();
    clearOutputs();
    markNotGenerated(outputVector);
    return 1;
  }
  catch (const surfacemaps::InputError& e)
  {
    internals.Clear();
    clearOutputs();
    this->SetErrorCode(InvalidInputError);
    vtkErrorMacro(<< e.what());
    return 0;
  }
  catch (const std::invalid_argument& e)
  {
    internals.Clear();
    clearOutputs();
    this->SetErrorCode(InvalidInputError);
    vtkErrorMacro(<< e.what());
    return 0;
  }
  catch (const std::runtime_error& e)
  {
    internals.Clear();
    clearOutputs();
    this->SetErrorCode(NotCertifiedError);
    vtkErrorMacro(<< "no certified map: " << e.what());
    return 0;
  }
  catch (const std::exception& e)
  {
    internals.Clear();
    clearOutputs();
    this->SetErrorCode(vtkErrorCode::UnknownError);
    vtkErrorMacro(<< "internal error: " << e.what());
    return 0;
  }
  return 1;
}

void vtkSurfaceMapFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  this->PrintSettings(os, indent, true);
}

void vtkSurfaceMapFilter::PrintSettings(ostream& os, vtkIndent indent, bool all)
{
  os << indent << "TargetError: " << this->TargetError << "\n";
  os << indent << "CoarseError: " << this->CoarseError << "\n";
  os << indent << "LandmarkIterations: " << this->LandmarkIterations << "\n";
  os << indent << "CoarseIterations: " << this->CoarseIterations << "\n";
  os << indent << "FineIterations: " << this->FineIterations << "\n";
  os << indent << "LandmarkBarrierWeight: " << this->LandmarkBarrierWeight << "\n";
  os << indent << "CoarseBarrierWeight: " << this->CoarseBarrierWeight << "\n";
  os << indent << "FineBarrierWeight: " << this->FineBarrierWeight << "\n";
  os << indent << "MeshWeight: " << this->MeshWeight << "\n";
  os << indent << "MapWeight: " << this->MapWeight << "\n";
  os << indent << "ApproximationWeight: " << this->ApproximationWeight << "\n";
  os << indent << "LandmarkWeight: " << this->LandmarkWeight << "\n";
  os << indent << "LandmarkTolerance: " << this->LandmarkTolerance << "\n";
  os << indent << "RelaxLandmarkPhase: " << (this->RelaxLandmarkPhase ? "on" : "off") << "\n";
  os << indent << "KeepLandmarks: " << this->KeepLandmarks << "\n";
  os << indent << "PairMode: " << this->PairMode << "\n";
  os << indent << "MaxError: " << this->MaxError << "\n";
  os << indent << "BoundIterations: " << this->BoundIterations << "\n";
  os << indent << "RefinementRounds: " << this->RefinementRounds << "\n";
  os << indent << "RefinementIterations: " << this->RefinementIterations << "\n";
  os << indent << "RefinementDistortion: " << this->RefinementDistortion << "\n";
  os << indent << "RefinementGrowth: " << this->RefinementGrowth << "\n";
  os << indent << "SqueezeDistortion: " << this->SqueezeDistortion << "\n";
  os << indent << "KinkRetries: " << this->KinkRetries << "\n";
  os << indent << "ApproximationSamples: " << this->ApproximationSamples << "\n";
  os << indent << "SizingMode: " << this->SizingMode << "\n";
  os << indent << "MinEdgeLength: " << this->MinEdgeLength << "\n";
  os << indent << "MaxEdgeLength: " << this->MaxEdgeLength << "\n";
  os << indent << "DecrementTolerance: " << this->DecrementTolerance << "\n";
  if (all)
  {
    os << indent << "OutputMode: " << this->OutputMode << "\n";
    os << indent << "MappedInput: " << this->MappedInput << "\n";
    os << indent << "NumberOfThreads: " << this->NumberOfThreads << "\n";
  }
}
