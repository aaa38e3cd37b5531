#include "vtkSurfaceMapFilter.h"

#include "vtkSurfaceMapInputs.h"
#include "vtkSurfaceMapOutputs.h"
#include "vtkSurfaceMapsConversion.h"
#include "vtkSurfaceMapsErrorGuard.h"
#include "vtkSurfaceMapsSettingAccess.h"
#include "vtkSurfaceMapsSettings.h"

#include "base/ThreadCount.h"
#include "map/AddToMap.h"
#include "map/MapPresets.h"
#include "map/MapSettings.h"
#include "map/SurfaceMap.h"

#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPolyData.h"
#include "vtkWeakPointer.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <mutex>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkSurfaceMapFilter);

static_assert(
  vtkSurfaceMapFilter::InvalidInputError == vtkSurfaceMapsErrorGuard::InvalidInputError &&
    vtkSurfaceMapFilter::NotCertifiedError == vtkSurfaceMapsErrorGuard::NotCertifiedError,
  "the module's error codes");

namespace
{
using surfacemaps::MapSetting;
using Settings = vtkSurfaceMapsSettings;

// The list's map entries between the filter's members and the engine's
// options (see vtkSurfaceMapsSettingAccess).
struct Access
{
  static const std::vector<MapSetting>& Table() { return surfacemaps::mapSettings(); }

  static surfacemaps::SurfaceMapOptions OptionsOf(vtkSurfaceMapFilter* filter)
  {
    surfacemaps::SurfaceMapOptions options;
#define SURFACEMAPS_MAP_SETTING(Name, field, Type, ...)                                            \
  options.field = surfacemaps::settingValue<Type>(filter->Get##Name());
#include "settings/SettingList.def"
    return options;
  }

  static void SetAll(vtkSurfaceMapFilter* filter, const surfacemaps::SurfaceMapOptions& options)
  {
#define SURFACEMAPS_MAP_SETTING(Name, field, ...)                                                  \
  filter->Set##Name(                                                                               \
    static_cast<decltype(filter->Get##Name())>(surfacemaps::settingNumber(options.field)));
#include "settings/SettingList.def"
  }
};

void clear(const std::vector<vtkPolyData*>& outputs)
{
  for (vtkPolyData* output : outputs)
  {
    output->Initialize();
  }
}

/// The preset with this index; nullptr out of range.
const surfacemaps::MapPreset* presetAt(int i)
{
  static const std::vector<surfacemaps::MapPreset> all = surfacemaps::presets();
  return i >= 0 && i < static_cast<int>(all.size()) ? &all[i] : nullptr;
}
} // namespace

// The map computed last, kept with what it was computed from, so that
// switching OutputMode or MappedInput does not recompute it.
struct vtkSurfaceMapFilter::vtkInternals
{
  explicit vtkInternals(vtkSurfaceMapFilter* filter)
    : Filter(filter)
  {
  }

  vtkSurfaceMapFilter* Filter;

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

  void ClearMap() { *this = vtkInternals(this->Filter); }

  // Every setting that changes the map (the table's and SizingMode), in
  // full precision: whether the kept map can be reused.
  static std::string SettingsKey(const surfacemaps::SurfaceMapOptions& options, int sizingMode)
  {
    std::ostringstream key;
    key.precision(17);
    for (const MapSetting& setting : Access::Table())
    {
      key << setting.get(options) << " ";
    }
    key << sizingMode;
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

  // Progress never goes back within an update; false once aborted.
  bool Report(double fraction, const std::string& text)
  {
    this->Progress = std::max(this->Progress, std::min(1.0, fraction));
    this->Filter->SetProgressText(text.c_str());
    this->Filter->UpdateProgress(this->Progress);
    return !this->Filter->GetAbortExecute();
  }

  // Validated inputs, sphere embeddings, the map (`existing`: port 1, a map
  // of the first inputs to add the others to).
  void ComputeMap(const std::vector<vtkPolyData*>& inputs,
    const std::vector<vtkPolyData*>& existing,
    surfacemaps::SurfaceMapOptions options,
    bool useSizing)
  {
    vtkInternals& internals = *this;
    internals.ClearMap();
    this->Report(0.0, "Validating the inputs");
    std::vector<std::string> warnings;
    std::vector<surfacemaps::MapInput> mapInputs =
      vtkSurfaceMapInputs::Read(inputs, useSizing, warnings);
    for (const std::string& warning : warnings)
    {
      vtkWarningWithObjectMacro(this->Filter, << warning);
    }

    // Sphere embeddings: the first 40 % of the progress when any is computed.
    const double embeddingShare = 0.4;
    std::vector<double> embeddingSeconds = vtkSurfaceMapInputs::Embed(inputs,
      mapInputs,
      [this, embeddingShare](double fraction, const std::string& text)
      { return this->Report(embeddingShare * fraction, text); });
    const bool computed =
      std::any_of(embeddingSeconds.begin(), embeddingSeconds.end(), [](double s) { return s > 0; });
    const double start = computed ? embeddingShare : 0.0;

    // The engine's warnings (landmarks set aside, an uncertain rotation) are
    // the filter's: vtkWarningMacro reaches every front end (the command
    // line shows no vtkLogger output without -v). The rest goes to vtkLogger.
    std::vector<std::string> engineWarnings;
    std::mutex warningsMutex;
    const surfacemaps::Logger engineLog = vtkSurfaceMapsConversion::EngineLog();
    options.log.sink = [&](surfacemaps::Logger::Level level, const std::string& message)
    {
      if (level != surfacemaps::Logger::Warning)
      {
        engineLog(level, message);
        return;
      }
      const std::lock_guard<std::mutex> lock(warningsMutex);
      engineWarnings.push_back(message);
    };
    options.progress = [this, start](const surfacemaps::SurfaceMapProgress& p)
    {
      std::ostringstream text;
      text << "Surface map: " << p.phase << " phase, iteration " << p.iteration << ", "
           << p.vertices << " vertices";
      return this->Report(start + (0.98 - start) * p.fraction, text.str());
    };
    if (!this->Report(start, "Surface map"))
    {
      throw surfacemaps::Aborted();
    }
    internals.Map = existing.empty()
      ? surfacemaps::computeSurfaceMap(mapInputs, options)
      : surfacemaps::addToSurfaceMap(vtkSurfaceMapInputs::Existing(existing), mapInputs, options);
    for (const std::string& warning : engineWarnings)
    {
      vtkWarningWithObjectMacro(this->Filter, << warning);
    }
    const std::string far = surfacemaps::landmarkPhaseWarning(internals.Map);
    if (!far.empty())
    {
      vtkWarningWithObjectMacro(this->Filter, << far);
    }
    internals.MapInputs = std::move(mapInputs);
    internals.EmbeddingSeconds = std::move(embeddingSeconds);
  }

  // The outputs of `mode` from the kept map.
  void WriteOutputs(int mode,
    int mappedInput,
    const std::vector<vtkPolyData*>& inputs,
    const std::vector<vtkPolyData*>& outputs) const
  {
    if (outputs.size() != inputs.size())
    {
      throw std::logic_error(std::to_string(inputs.size()) + " inputs but " +
        std::to_string(outputs.size()) + " output ports");
    }
    const vtkInternals& internals = *this;
    const vtkSurfaceMapOutputs writer(
      internals.Map, inputs, internals.MapInputs, internals.EmbeddingSeconds, this->Filter);
    switch (mode)
    {
      case vtkSurfaceMapFilter::INPUT_EMBEDDINGS:
        writer.InputEmbeddings(outputs);
        break;
      case vtkSurfaceMapFilter::MAPPED_INPUT:
        writer.MappedInput(outputs, mappedInput);
        break;
      default:
        writer.CommonTriangulation(outputs);
        break;
    }
  }

  void Keep(const std::vector<vtkPolyData*>& inputs, const std::string& settings)
  {
    this->Settings = settings;
    for (vtkPolyData* input : inputs)
    {
      this->Inputs.emplace_back(input);
      this->InputTimes.push_back(input->GetMTime());
    }
    this->HasMap = true;
  }
};

int vtkSurfaceMapFilter::GetNumberOfSettings()
{
  return Settings::GetNumberOfSettings(Settings::MAP_SETTINGS);
}

// The table for tools is vtkSurfaceMapsSettings' MAP_SETTINGS.
const char* vtkSurfaceMapFilter::GetSettingName(int i)
{
  return Settings::GetName(Settings::MAP_SETTINGS, i);
}

const char* vtkSurfaceMapFilter::GetSettingFlag(int i)
{
  return Settings::GetFlag(Settings::MAP_SETTINGS, i);
}

const char* vtkSurfaceMapFilter::GetSettingOffFlag(int i)
{
  return Settings::GetOffFlag(Settings::MAP_SETTINGS, i);
}

const char* vtkSurfaceMapFilter::GetSettingChoices(int i)
{
  return Settings::GetChoices(Settings::MAP_SETTINGS, i);
}

const char* vtkSurfaceMapFilter::GetSettingDocumentation(int i)
{
  return Settings::GetDocumentation(Settings::MAP_SETTINGS, i);
}

const char* vtkSurfaceMapFilter::GetSettingTopic(int i)
{
  return Settings::GetTopic(Settings::MAP_SETTINGS, i);
}

int vtkSurfaceMapFilter::GetSettingType(int i)
{
  return Settings::GetType(Settings::MAP_SETTINGS, i);
}

double vtkSurfaceMapFilter::GetSettingMinimum(int i)
{
  return Settings::GetMinimum(Settings::MAP_SETTINGS, i);
}

double vtkSurfaceMapFilter::GetSettingMaximum(int i)
{
  return Settings::GetMaximum(Settings::MAP_SETTINGS, i);
}

double vtkSurfaceMapFilter::GetSettingDefault(int i)
{
  return Settings::GetDefault(Settings::MAP_SETTINGS, i);
}

bool vtkSurfaceMapFilter::ParseSettingValue(int i, const char* text, double* value)
{
  const double parsed = Settings::Parse(Settings::MAP_SETTINGS, i, text);
  if (std::isnan(parsed) || !value)
  {
    return false;
  }
  *value = parsed;
  return true;
}

double vtkSurfaceMapFilter::GetSetting(int i)
{
  return vtkSurfaceMapsSettingAccess::Get<Access>(this, i);
}

void vtkSurfaceMapFilter::SetSetting(int i, double value)
{
  vtkSurfaceMapsSettingAccess::Set<Access>(this, i, value);
}

void vtkSurfaceMapFilter::ApplyPreset(int preset)
{
  if (!presetAt(preset))
  {
    vtkErrorMacro(<< "no preset " << preset << " (0 to " << GetNumberOfPresets() - 1 << ")");
    return;
  }
  surfacemaps::SurfaceMapOptions options = Access::OptionsOf(this);
  surfacemaps::applyPreset(options, *presetAt(preset));
  Access::SetAll(this, options);
}

int vtkSurfaceMapFilter::GetNumberOfPresets()
{
  return static_cast<int>(surfacemaps::presets().size());
}

const char* vtkSurfaceMapFilter::GetPresetName(int preset)
{
  return presetAt(preset) ? surfacemaps::presetName(*presetAt(preset)) : nullptr;
}

const char* vtkSurfaceMapFilter::GetPresetDocumentation(int preset)
{
  static const std::vector<std::string> docs = []
  {
    std::vector<std::string> all;
    for (surfacemaps::MapPreset p : surfacemaps::presets())
    {
      all.push_back(surfacemaps::presetDescription(p));
    }
    return all;
  }();
  return presetAt(preset) ? docs[preset].c_str() : nullptr;
}

vtkSurfaceMapFilter::vtkSurfaceMapFilter()
  : Internals(new vtkInternals(this))
{
  this->SetNumberOfInputPorts(2);
  this->SetNumberOfOutputPorts(1);
}

vtkSurfaceMapFilter::~vtkSurfaceMapFilter() = default;

int vtkSurfaceMapFilter::FillInputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  info->Set(vtkAlgorithm::INPUT_IS_REPEATABLE(), 1);
  if (port == 1)
  {
    info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  }
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
  const std::vector<vtkPolyData*> inputs = vtkSurfaceMapsConversion::PolyDataOf(inputVector[0]);
  const std::vector<vtkPolyData*> existing = vtkSurfaceMapsConversion::PolyDataOf(inputVector[1]);
  // What the kept map was computed from: both ports.
  std::vector<vtkPolyData*> sources = inputs;
  sources.insert(sources.end(), existing.begin(), existing.end());
  const std::vector<vtkPolyData*> outputs = vtkSurfaceMapsConversion::PolyDataOf(outputVector);
  clear(outputs);
  this->Internals->Progress = 0.0;
  const int n = static_cast<int>(inputs.size());
  // A bad MappedInput is a setting error: the kept map stays.
  if (this->OutputMode == MAPPED_INPUT && this->MappedInput > 0 && this->MappedInput >= n)
  {
    return vtkSurfaceMapsErrorGuard::Fail(this,
      InvalidInputError,
      "MappedInput is " + std::to_string(this->MappedInput) + " but there " +
        (n == 1 ? "is 1 input" : "are " + std::to_string(n) + " inputs"));
  }
  const surfacemaps::ScopedThreadCount threads(this->NumberOfThreads);
  vtkSurfaceMapsErrorGuard::Policy policy;
  policy.NoResultError.Prefix = "no certified map: ";
  policy.OtherError.Prefix = "internal error: ";
  policy.AbortedOutputs = outputVector;
  return vtkSurfaceMapsErrorGuard::Run(
    this,
    policy,
    [&]()
    {
      const surfacemaps::SurfaceMapOptions options = Access::OptionsOf(this);
      vtkSurfaceMapsSettingAccess::CheckRanges<Access>(options);
      const std::string settings = vtkInternals::SettingsKey(options, this->SizingMode);
      if (!this->Internals->Matches(sources, settings))
      {
        this->Internals->ComputeMap(
          inputs, existing, options, this->SizingMode == SIZING_ARRAY_OR_CURVATURE);
        this->Internals->Keep(sources, settings);
      }
      this->Internals->Report(0.98, "Writing the outputs");
      this->Internals->WriteOutputs(this->OutputMode, this->MappedInput, inputs, outputs);
      this->Internals->Report(1.0, "Done");
      return 1;
    },
    [&]()
    {
      this->Internals->ClearMap();
      clear(outputs);
    });
}

void vtkSurfaceMapFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  vtkSurfaceMapsSettingAccess::Print<Access>(this, os, indent);
  os << indent << "SizingMode: " << this->SizingMode << "\n";
  os << indent << "OutputMode: " << this->OutputMode << "\n";
  os << indent << "MappedInput: " << this->MappedInput << "\n";
  os << indent << "NumberOfThreads: " << this->NumberOfThreads << "\n";
}
