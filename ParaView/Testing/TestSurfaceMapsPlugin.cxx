// The SurfaceMaps plugin in ParaView's server manager, the way the GUI uses
// it: ParaView's engine initialised in-process with a builtin session, the
// plugin loaded by the plugin manager, proxies created from the plugin's XML,
// properties set and pipelines updated, with nothing but ParaView's SDK
// (pvbatch needs ParaView's Python: ParaView.pvbatch, ParaView/pvsurfacemaps).
//
// Usage: TestSurfaceMapsPlugin PLUGIN_FILE DATA_DIR
// Exit code 0 when every check passes; each failed check prints a line.
#include "vtkAlgorithm.h"
#include "vtkCallbackCommand.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkInformation.h"
#include "vtkInitializationHelper.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkProcessModule.h"
#include "vtkSMDocumentation.h"
#include "vtkSMDoubleRangeDomain.h"
#include "vtkSMEnumerationDomain.h"
#include "vtkSMIntRangeDomain.h"
#include "vtkSMParaViewPipelineController.h"
#include "vtkSMPluginManager.h"
#include "vtkSMProperty.h"
#include "vtkSMPropertyGroup.h"
#include "vtkSMPropertyHelper.h"
#include "vtkSMProxyManager.h"
#include "vtkSMReaderFactory.h"
#include "vtkSMSession.h"
#include "vtkSMSessionProxyManager.h"
#include "vtkSMSourceProxy.h"
#include "vtkSmartPointer.h"
#include "vtkStringArray.h"
#include "vtkStringList.h"
#include "vtkSurfaceMapBlocksFilter.h"
#include "vtkSurfaceMapFilter.h"
#include "vtkTable.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <iostream>
#include <string>
#include <vector>

namespace
{
int failures = 0;

void check(bool ok, const std::string& what)
{
  if (!ok)
  {
    std::cerr << "FAILED: " << what << "\n";
    ++failures;
  }
}

struct Pipeline
{
  vtkSMSessionProxyManager* Manager;
  vtkSMParaViewPipelineController* Controller;

  // A new proxy of the plugin, initialised like the GUI's (domains, defaults).
  vtkSmartPointer<vtkSMSourceProxy> New(const char* group, const char* name)
  {
    vtkSmartPointer<vtkSMSourceProxy> proxy;
    proxy.TakeReference(vtkSMSourceProxy::SafeDownCast(this->Manager->NewProxy(group, name)));
    if (proxy)
    {
      this->Controller->PreInitializeProxy(proxy);
    }
    return proxy;
  }

  // Pushes the properties, finishes initialisation and registers it.
  void Apply(vtkSMSourceProxy* proxy, const char* label)
  {
    proxy->UpdateVTKObjects();
    this->Controller->PostInitializeProxy(proxy);
    this->Controller->RegisterPipelineProxy(proxy, label);
  }
};

template<typename T>
T* outputOf(vtkSMSourceProxy* proxy)
{
  auto* algorithm = vtkAlgorithm::SafeDownCast(proxy->GetClientSideObject());
  return algorithm ? T::SafeDownCast(algorithm->GetOutputDataObject(0)) : nullptr;
}

double fieldValue(vtkDataObject* data, const char* name, int tuple = 0)
{
  vtkDataArray* array = data ? data->GetFieldData()->GetArray(name) : nullptr;
  return array && tuple < array->GetNumberOfTuples() ? array->GetComponent(tuple, 0) : NAN;
}

// Every setting of the engine's table is a property of the map proxy with
// the table's default and range (the XML is generated from the table; this
// holds the generator to it) and reaches the filter through its command.
void checkMapSettings(Pipeline& pipeline)
{
  auto map = pipeline.New("filters", "SurfaceMap");
  check(map != nullptr, "the plugin defines filters/SurfaceMap");
  if (!map)
  {
    return;
  }
  map->UpdateVTKObjects();
  auto* filter = vtkSurfaceMapFilter::SafeDownCast(map->GetClientSideObject());
  check(filter != nullptr, "SurfaceMap's VTK object is a vtkSurfaceMapFilter");
  for (int i = 0; i < vtkSurfaceMapFilter::GetNumberOfSettings(); ++i)
  {
    const std::string name = vtkSurfaceMapFilter::GetSettingName(i);
    vtkSMProperty* property = map->GetProperty(name.c_str());
    check(property != nullptr, "SurfaceMap has the property " + name);
    if (!property)
    {
      continue;
    }
    const double table = vtkSurfaceMapFilter::GetSettingDefault(i);
    check(vtkSMPropertyHelper(property).GetAsDouble() == table,
      name + ": property default " + std::to_string(vtkSMPropertyHelper(property).GetAsDouble()) +
        " is the table's " + std::to_string(table));
    check(filter && filter->GetSetting(i) == table, name + ": the filter holds the default");
    int exists = 0;
    switch (vtkSurfaceMapFilter::GetSettingType(i))
    {
      case vtkSurfaceMapFilter::SETTING_REAL:
      {
        auto* range = vtkSMDoubleRangeDomain::SafeDownCast(property->GetDomain("range"));
        check(range && range->GetMinimum(0, exists) == vtkSurfaceMapFilter::GetSettingMinimum(i) &&
            range->GetMaximum(0, exists) == vtkSurfaceMapFilter::GetSettingMaximum(i),
          name + ": the property's range is the table's");
        break;
      }
      case vtkSurfaceMapFilter::SETTING_COUNT:
      {
        auto* range = vtkSMIntRangeDomain::SafeDownCast(property->GetDomain("range"));
        check(range && range->GetMinimum(0, exists) == vtkSurfaceMapFilter::GetSettingMinimum(i) &&
            range->GetMaximum(0, exists) == vtkSurfaceMapFilter::GetSettingMaximum(i),
          name + ": the property's range is the table's");
        break;
      }
      case vtkSurfaceMapFilter::SETTING_CHOICE:
      {
        auto* choices = vtkSMEnumerationDomain::SafeDownCast(property->GetDomain("enum"));
        check(choices &&
            choices->GetNumberOfEntries() ==
              static_cast<unsigned int>(vtkSurfaceMapFilter::GetSettingMaximum(i) + 1),
          name + ": one enumeration entry per choice");
        break;
      }
      default:
        break;
    }
    check(property->GetDocumentation() != nullptr, name + " is documented");
    // In the panel under its topic: exactly one property group holds it.
    int groups = 0;
    std::string label;
    for (std::size_t g = 0; g < map->GetNumberOfPropertyGroups(); ++g)
    {
      vtkSMPropertyGroup* group = map->GetPropertyGroup(g);
      for (unsigned int p = 0; p < group->GetNumberOfProperties(); ++p)
      {
        if (group->GetProperty(p) == property)
        {
          ++groups;
          label = group->GetXMLLabel() ? group->GetXMLLabel() : "";
        }
      }
    }
    const char* topic = vtkSurfaceMapFilter::GetSettingTopic(i);
    check(groups == 1 && topic && label == topic,
      name + " is in one property group, the table's topic " + (topic ? topic : "(none)") +
        " (found in " + std::to_string(groups) + ", '" + label + "')");
  }
}

// The Preset property: one enumeration entry per preset of the engine's
// table, documented, default "Pair".
void checkPresetProperty(Pipeline& pipeline)
{
  auto map = pipeline.New("filters", "SurfaceMap");
  vtkSMProperty* property = map ? map->GetProperty("Preset") : nullptr;
  check(property != nullptr, "SurfaceMap has the property Preset");
  if (!property)
  {
    return;
  }
  auto* entries = vtkSMEnumerationDomain::SafeDownCast(property->GetDomain("enum"));
  const int n = vtkSurfaceMapFilter::GetNumberOfPresets();
  check(entries && entries->GetNumberOfEntries() == static_cast<unsigned int>(n),
    "Preset has one enumeration entry per preset");
  for (int p = 0; entries && p < n && p < static_cast<int>(entries->GetNumberOfEntries()); ++p)
  {
    std::string name = vtkSurfaceMapFilter::GetPresetName(p);
    name[0] = static_cast<char>(std::toupper(name[0]));
    check(entries->GetEntryValue(static_cast<unsigned int>(p)) == p &&
        name == entries->GetEntryText(static_cast<unsigned int>(p)),
      "Preset entry " + std::to_string(p) + " is " + name);
  }
  check(vtkSMPropertyHelper(property).GetAsInt() == vtkSurfaceMapFilter::PRESET_PAIR,
    "Preset defaults to Pair");
  const std::string doc =
    property->GetDocumentation() && property->GetDocumentation()->GetDescription()
    ? property->GetDocumentation()->GetDescription()
    : "";
  check(doc.find("ApproximationWeight") != std::string::npos,
    "Preset's documentation names the settings it sets: " + doc);
}

// File > Open: the Surface Mesh Reader is the one reader offered for OFF
// files, which ParaView does not read itself, and is not offered for the
// formats that ParaView's own readers read (two readers for an extension
// make every Open ask which to use).
std::vector<std::string> readersFor(vtkSMSession* session, const std::string& file)
{
  vtkSMReaderFactory* factory = vtkSMProxyManager::GetProxyManager()->GetReaderFactory();
  vtkStringList* list = factory->GetReaders(file.c_str(), session);
  std::vector<std::string> names; // (group, name, description) triples: the names
  for (int i = 1; list && i < list->GetLength(); i += 3)
  {
    names.emplace_back(list->GetString(i));
  }
  return names;
}

void checkReaderRegistration(vtkSMSession* session, const std::string& data)
{
  check(readersFor(session, data + "blob.off") == std::vector<std::string>{ "SurfaceMeshReader" },
    "File > Open offers the Surface Mesh Reader alone for .off");
  for (const char* file :
    { "spot.obj", "limbs.ply", "ellipsoid_coarse.stl", "blob.vtp", "limbs_coarse.vtk" })
  {
    const auto names = readersFor(session, data + file);
    check(!names.empty() &&
        std::find(names.begin(), names.end(), "SurfaceMeshReader") == names.end(),
      std::string("File > Open offers ParaView's own readers only for ") + file);
  }
}

int settingIndex(const char* name)
{
  for (int i = 0; i < vtkSurfaceMapFilter::GetNumberOfSettings(); ++i)
  {
    if (std::string(vtkSurfaceMapFilter::GetSettingName(i)) == name)
    {
      return i;
    }
  }
  return -1;
}

// The map's phases as run (field data "PhaseName").
std::vector<std::string> phasesOf(vtkDataObject* data)
{
  std::vector<std::string> phases;
  auto* names = data
    ? vtkStringArray::SafeDownCast(data->GetFieldData()->GetAbstractArray("PhaseName"))
    : nullptr;
  for (vtkIdType k = 0; names && k < names->GetNumberOfValues(); ++k)
  {
    phases.push_back(names->GetValue(k));
  }
  return phases;
}

vtkSmartPointer<vtkSMSourceProxy> read(
  Pipeline& pipeline, const std::string& file, const std::string& landmarks)
{
  auto reader = pipeline.New("sources", "SurfaceMeshReader");
  check(reader != nullptr, "the plugin defines sources/SurfaceMeshReader");
  if (!reader)
  {
    return reader;
  }
  vtkSMPropertyHelper(reader, "FileName").Set(file.c_str());
  if (!landmarks.empty())
  {
    vtkSMPropertyHelper(reader, "LandmarkFileName").Set(landmarks.c_str());
  }
  pipeline.Apply(reader, file.c_str());
  reader->UpdatePipeline();
  auto* mesh = outputOf<vtkPolyData>(reader);
  check(mesh && mesh->GetNumberOfPoints() > 0 && mesh->GetNumberOfPolys() > 0,
    "the reader reads " + file);
  return reader;
}
} // namespace

int main(int argc, char* argv[])
{
  if (argc != 3)
  {
    std::cerr << "usage: " << argv[0] << " PLUGIN_FILE DATA_DIR\n";
    return 2;
  }
  const std::string plugin = argv[1];
  const std::string data = std::string(argv[2]) + "/";

  // No user settings.
  vtkInitializationHelper::SetLoadSettingsFilesDuringInitialization(false);
  // ParaView parses its own options: give it the program name only (and the
  // terminating null its logger insists on).
  char* programOnly[2] = { argv[0], nullptr };
  if (!vtkInitializationHelper::Initialize(1, programOnly, vtkProcessModule::PROCESS_CLIENT))
  {
    std::cerr << "cannot initialise ParaView's engine\n";
    return 1;
  }
  {
    vtkNew<vtkSMSession> session; // builtin: client and server in this process
    vtkProcessModule::GetProcessModule()->RegisterSession(session);
    vtkNew<vtkSMParaViewPipelineController> controller;
    controller->InitializeSession(session);
    vtkSMPluginManager* plugins = vtkSMProxyManager::GetProxyManager()->GetPluginManager();
    const bool loaded = plugins->LoadLocalPlugin(plugin.c_str());
    check(loaded, "the plugin manager loads " + plugin);
    if (!loaded)
    {
      vtkInitializationHelper::Finalize();
      return 1;
    }
    Pipeline pipeline{ session->GetSessionProxyManager(), controller };

    checkMapSettings(pipeline);
    checkPresetProperty(pipeline);
    checkReaderRegistration(session, data);

    // The reader, every format.
    for (const char* file : { "ellipsoid_coarse.stl", "blob.vtp", "limbs.ply", "limbs_coarse.vtk",
           "spot.obj" })
    {
      read(pipeline, data + file, "");
    }
    auto ellipsoid = read(pipeline, data + "ellipsoid.obj", data + "ellipsoid.pinned");
    auto blob = read(pipeline, data + "blob.off", data + "blob.vts");
    if (!ellipsoid || !blob)
    {
      vtkInitializationHelper::Finalize();
      return 1;
    }
    auto* landmarked = outputOf<vtkPolyData>(blob);
    check(landmarked && landmarked->GetPointData()->GetArray("Landmarks"),
      "the landmark file becomes the Landmarks point array");

    // The validator: one row per surface, both valid.
    auto validator = pipeline.New("filters", "SurfaceMeshValidator");
    vtkSMPropertyHelper(validator, "Input").Add(ellipsoid, 0);
    vtkSMPropertyHelper(validator, "Input").Add(blob, 0);
    pipeline.Apply(validator, "validator");
    validator->UpdatePipeline();
    auto* table = outputOf<vtkTable>(validator);
    check(table && table->GetNumberOfRows() == 2, "the validator has one row per surface");
    check(table && table->GetValueByName(0, "Valid").ToInt() == 1 &&
        table->GetValueByName(1, "Valid").ToInt() == 1,
      "the validator accepts both surfaces");

    // The sphere embedding of one surface.
    auto embedding = pipeline.New("filters", "SphereEmbedding");
    vtkSMPropertyHelper(embedding, "Input").Set(ellipsoid, 0);
    pipeline.Apply(embedding, "embedding");
    embedding->UpdatePipeline();
    auto* embedded = outputOf<vtkPolyData>(embedding);
    check(embedded && embedded->GetPointData()->GetArray("SpherePosition"),
      "the embedding has SpherePosition");

    // Spot's per-corner texture coordinates split at the seams.
    auto spot = read(pipeline, data + "spot.obj", "");
    auto splitter = pipeline.New("filters", "SurfaceTextureSeamSplitter");
    vtkSMPropertyHelper(splitter, "Input").Set(spot, 0);
    pipeline.Apply(splitter, "split");
    splitter->UpdatePipeline();
    auto* split = outputOf<vtkPolyData>(splitter);
    auto* spotData = outputOf<vtkPolyData>(spot);
    check(split && spotData && split->GetNumberOfPoints() > spotData->GetNumberOfPoints() &&
        split->GetPointData()->GetArray("OriginalPointId") && split->GetPointData()->GetTCoords(),
      "the seam splitter copies spot's seam vertices and sets TCoords");

    // The map of two surfaces, a short schedule: one composite output, one
    // certified block per input.
    auto map = pipeline.New("filters", "SurfaceMap");
    vtkSMPropertyHelper(map, "Input").Add(ellipsoid, 0);
    vtkSMPropertyHelper(map, "Input").Add(blob, 0);
    vtkSMPropertyHelper(map, "PairMode").Set(1); // sequence, for the interpolator
    vtkSMPropertyHelper(map, "LandmarkIterations").Set(20);
    vtkSMPropertyHelper(map, "CoarseIterations").Set(3);
    vtkSMPropertyHelper(map, "FineIterations").Set(3);
    vtkSMPropertyHelper(map, "RefinementRounds").Set(0);
    pipeline.Apply(map, "map");
    map->UpdatePipeline();
    auto* blocks = outputOf<vtkMultiBlockDataSet>(map);
    check(blocks && blocks->GetNumberOfBlocks() == 2, "the map has one block per input");
    vtkIdType commonPoints = -1;
    for (unsigned int b = 0; blocks && b < blocks->GetNumberOfBlocks(); ++b)
    {
      auto* lifted = vtkPolyData::SafeDownCast(blocks->GetBlock(b));
      const std::string block = "map block " + std::to_string(b);
      check(lifted && lifted->GetNumberOfPoints() > 0, block + " is a non-empty surface");
      if (!lifted)
      {
        continue;
      }
      check(fieldValue(lifted, "Bijective") == 1.0, block + " is certified bijective");
      check(lifted->GetPointData()->GetArray("SpherePosition") &&
          lifted->GetPointData()->GetArray("SourceBarycentric") &&
          lifted->GetCellData()->GetArray("Distortion"),
        block + " has SpherePosition, SourceBarycentric and Distortion");
      check(commonPoints < 0 || lifted->GetNumberOfPoints() == commonPoints,
        block + " has T's points");
      commonPoints = lifted->GetNumberOfPoints();
    }
    check(std::string(blocks && blocks->HasMetaData(1u)
                ? blocks->GetMetaData(1u)->Get(vtkCompositeDataSet::NAME())
                : "") == "blob.off",
      "block 1 is named after its input's file");

    // The average of the map's blocks.
    auto average = pipeline.New("filters", "SurfaceAverage");
    vtkSMPropertyHelper(average, "Input").Set(map, 0);
    pipeline.Apply(average, "average");
    average->UpdatePipeline();
    auto* mean = outputOf<vtkPolyData>(average);
    check(mean && mean->GetNumberOfPoints() == commonPoints,
      "the average has the common triangulation's points");
    vtkDataArray* weights = mean ? mean->GetFieldData()->GetArray("AverageWeight") : nullptr;
    check(weights && weights->GetNumberOfTuples() == 2 && weights->GetComponent(0, 0) == 0.5,
      "the average weighs both blocks equally");

    // The shape statistics of the map's blocks: two surfaces, one mode; the
    // mean at Coefficient 0, and at Coefficient 2 the mean moved by two
    // standard deviations along Mode_1.
    auto statistics = pipeline.New("filters", "SurfaceShapeStatistics");
    check(statistics != nullptr, "the plugin defines filters/SurfaceShapeStatistics");
    if (statistics)
    {
      check(vtkSMDoubleRangeDomain::SafeDownCast(
              statistics->GetProperty("Coefficient")->GetDomain("range")) != nullptr,
        "Coefficient has a range (a slider)");
      vtkSMPropertyHelper(statistics, "Input").Set(map, 0);
      pipeline.Apply(statistics, "statistics");
      statistics->UpdatePipeline();
      vtkNew<vtkPolyData> meanShape;
      if (auto* shape = outputOf<vtkPolyData>(statistics))
      {
        meanShape->DeepCopy(shape);
      }
      check(meanShape->GetNumberOfPoints() == commonPoints,
        "the statistics' mean has the common triangulation's points");
      vtkDataArray* spread = meanShape->GetPointData()->GetArray("StandardDeviation");
      vtkDataArray* mode = meanShape->GetPointData()->GetArray("Mode_1");
      check(spread && mode && mode->GetNumberOfComponents() == 3 &&
          !meanShape->GetPointData()->GetArray("Mode_2"),
        "the statistics of two surfaces have StandardDeviation and exactly one mode");
      const double variance = fieldValue(meanShape, "Variance");
      check(variance > 0 && fieldValue(meanShape, "ExplainedVarianceFraction") > 0.999,
        "one mode explains the variance of two different surfaces");
      vtkSMPropertyHelper(statistics, "Coefficient").Set(2.0);
      statistics->UpdateVTKObjects();
      statistics->UpdatePipeline();
      auto* moved = outputOf<vtkPolyData>(statistics);
      double largest = 0.0;
      double mismatch = 0.0;
      for (vtkIdType v = 0; moved && mode && v < commonPoints; ++v)
      {
        double p[3], q[3], u[3];
        meanShape->GetPoint(v, p);
        moved->GetPoint(v, q);
        mode->GetTuple(v, u);
        for (int c = 0; c < 3; ++c)
        {
          const double expected = 2.0 * std::sqrt(variance) * u[c];
          largest = std::max(largest, std::abs(expected));
          mismatch = std::max(mismatch, std::abs(q[c] - p[c] - expected));
        }
      }
      check(moved && moved->GetNumberOfPoints() == commonPoints && largest > 0 &&
          mismatch <= 1e-9 * (1.0 + largest),
        "Coefficient 2 moves the mean by two standard deviations along Mode_1 (mismatch " +
          std::to_string(mismatch) + ")");
      vtkSMPropertyHelper(statistics, "Mode").Set(2);
      statistics->UpdateVTKObjects();
      statistics->UpdatePipeline();
      moved = outputOf<vtkPolyData>(statistics);
      check(moved && moved->GetNumberOfPoints() == 0,
        "Mode 2 of two surfaces (one mode) is an error with an empty output");
    }

    // The population preset: the settings it sets that are left at their
    // defaults take its values, a changed one (FineIterations) wins, and the
    // run is the same as with those values set by hand.
    auto population = pipeline.New("filters", "SurfaceMap");
    auto byHand = pipeline.New("filters", "SurfaceMap");
    for (auto* proxy : { population.GetPointer(), byHand.GetPointer() })
    {
      vtkSMPropertyHelper(proxy, "Input").Add(ellipsoid, 0);
      vtkSMPropertyHelper(proxy, "Input").Add(blob, 0);
      vtkSMPropertyHelper(proxy, "LandmarkIterations").Set(20);
      vtkSMPropertyHelper(proxy, "CoarseIterations").Set(3);
      vtkSMPropertyHelper(proxy, "FineIterations").Set(3);
    }
    vtkSMPropertyHelper(population, "Preset").Set(vtkSurfaceMapFilter::PRESET_POPULATION);
    vtkSMPropertyHelper(byHand, "TargetError").Set(1e-2);
    vtkSMPropertyHelper(byHand, "ApproximationWeight").Set(2.0);
    vtkSMPropertyHelper(byHand, "RefinementRounds").Set(0);
    vtkSMPropertyHelper(byHand, "PairMode").Set(vtkSurfaceMapFilter::PAIRS_MEAN);
    pipeline.Apply(population, "population");
    pipeline.Apply(byHand, "by hand");
    auto* presetFilter = vtkSurfaceMapBlocksFilter::SafeDownCast(population->GetClientSideObject());
    check(presetFilter && presetFilter->GetPreset() == vtkSurfaceMapFilter::PRESET_POPULATION,
      "the Preset property reaches the filter");
    const int targetError = settingIndex("TargetError");
    const int fineIterations = settingIndex("FineIterations");
    const int refinementRounds = settingIndex("RefinementRounds");
    check(presetFilter && presetFilter->GetEffectiveSetting(targetError) == 1e-2 &&
        presetFilter->GetEffectiveSetting(refinementRounds) == 0 &&
        presetFilter->GetEffectiveSetting(fineIterations) == 3,
      "under Population the map runs with TargetError 0.01 and no refinement rounds, and the "
      "FineIterations set wins over the preset's");
    population->UpdatePipeline();
    byHand->UpdatePipeline();
    check(vtkSMPropertyHelper(population, "TargetError").GetAsDouble() ==
          vtkSurfaceMapFilter::GetSettingDefault(targetError) &&
        presetFilter &&
        presetFilter->GetSetting(targetError) ==
          vtkSurfaceMapFilter::GetSettingDefault(targetError),
      "the preset leaves the TargetError property and the filter's setting as set");
    auto* presetBlocks = outputOf<vtkMultiBlockDataSet>(population);
    auto* handBlocks = outputOf<vtkMultiBlockDataSet>(byHand);
    auto* presetT = presetBlocks ? vtkPolyData::SafeDownCast(presetBlocks->GetBlock(0)) : nullptr;
    auto* handT = handBlocks ? vtkPolyData::SafeDownCast(handBlocks->GetBlock(0)) : nullptr;
    check(presetT && handT && fieldValue(presetT, "Bijective") == 1.0 &&
        presetT->GetNumberOfPoints() == handT->GetNumberOfPoints() &&
        fieldValue(presetT, "Energy") == fieldValue(handT, "Energy") &&
        phasesOf(presetT) == phasesOf(handT),
      "the Population map is the map with the preset's values set by hand (" +
        std::to_string(presetT ? presetT->GetNumberOfPoints() : -1) + " and " +
        std::to_string(handT ? handT->GetNumberOfPoints() : -1) + " vertices)");
    const auto phases = phasesOf(presetT);
    check(!phases.empty() && std::find(phases.begin(), phases.end(), "refine") == phases.end(),
      "the Population map runs no refinement phase");
    auto* pairT = blocks ? vtkPolyData::SafeDownCast(blocks->GetBlock(0)) : nullptr;
    check(presetT && pairT && fieldValue(presetT, "Energy") != fieldValue(pairT, "Energy"),
      "the Population map differs from the Pair map of the same caps");

    // The evaluation of block 0 -> block 1.
    auto evaluation = pipeline.New("filters", "SurfaceMapEvaluation");
    vtkSMPropertyHelper(evaluation, "Input").Set(map, 0);
    pipeline.Apply(evaluation, "evaluation");
    evaluation->UpdatePipeline();
    const double sd = fieldValue(outputOf<vtkPolyData>(evaluation), "SymmetricDirichlet");
    check(std::isfinite(sd) && sd >= 1.0, "the evaluation's symmetric Dirichlet is finite, >= 1");

    // The interpolator: time steps announced before its first update, and a
    // surface between the keyframes.
    auto sequence = pipeline.New("filters", "SurfaceSequenceInterpolator");
    vtkSMPropertyHelper(sequence, "Input").Set(map, 0);
    vtkSMPropertyHelper(sequence, "StepsPerInterval").Set(4);
    pipeline.Apply(sequence, "sequence");
    sequence->UpdatePipelineInformation();
    check(vtkSMPropertyHelper(sequence, "TimestepValues").GetNumberOfElements() == 5,
      "the interpolator reports 5 time steps for 2 keyframes and 4 steps per interval");
    sequence->UpdatePipeline(0.5);
    auto* between = outputOf<vtkPolyData>(sequence);
    auto* first = blocks ? vtkPolyData::SafeDownCast(blocks->GetBlock(0)) : nullptr;
    auto* last = blocks ? vtkPolyData::SafeDownCast(blocks->GetBlock(1)) : nullptr;
    if (between && first && last && between->GetNumberOfPoints() == commonPoints)
    {
      double p[3], a[3], b[3];
      between->GetPoint(0, p);
      first->GetPoint(0, a);
      last->GetPoint(0, b);
      check(std::hypot(p[0] - a[0], p[1] - a[1], p[2] - a[2]) > 0 &&
          std::hypot(p[0] - b[0], p[1] - b[1], p[2] - b[2]) > 0,
        "the surface at t = 0.5 lies between the keyframes");
    }
    else
    {
      check(false, "the interpolator's output at t = 0.5 has the common triangulation's points");
    }

    // The transfer of blob's point arrays onto the ellipsoid's vertices,
    // from a second map proxy in "Input embeddings" mode (same inputs and
    // settings): the ellipsoid's vertices, each with where the exact map puts
    // it on the blob ("SourceBarycentric").
    auto embeddings = pipeline.New("filters", "SurfaceMap");
    vtkSMPropertyHelper(embeddings, "Input").Add(ellipsoid, 0);
    vtkSMPropertyHelper(embeddings, "Input").Add(blob, 0);
    for (const char* name : { "PairMode", "LandmarkIterations", "CoarseIterations",
           "FineIterations", "RefinementRounds" })
    {
      vtkSMPropertyHelper(embeddings, name).Set(vtkSMPropertyHelper(map, name).GetAsInt());
    }
    vtkSMPropertyHelper(embeddings, "OutputMode").Set(2);
    pipeline.Apply(embeddings, "embeddings");
    auto transfer = pipeline.New("filters", "SurfaceMapTransfer");
    vtkSMPropertyHelper(transfer, "Embeddings").Set(embeddings, 0);
    vtkSMPropertyHelper(transfer, "Common").Set(map, 0);
    pipeline.Apply(transfer, "transfer");
    transfer->UpdatePipeline();
    auto* carried = outputOf<vtkPolyData>(transfer);
    auto* ellipsoidMesh = outputOf<vtkPolyData>(ellipsoid);
    check(carried && ellipsoidMesh &&
        carried->GetNumberOfPoints() == ellipsoidMesh->GetNumberOfPoints() &&
        carried->GetPointData()->GetArray("SourceBarycentric"),
      "the transfer gives the ellipsoid's vertices their place on the blob");

    // Output mode "Mapped input": input 0's mesh on every input.
    vtkSMPropertyHelper(map, "OutputMode").Set(1);
    map->UpdateVTKObjects();
    map->UpdatePipeline();
    blocks = outputOf<vtkMultiBlockDataSet>(map);
    auto* mapped = blocks ? vtkPolyData::SafeDownCast(blocks->GetBlock(1)) : nullptr;
    auto* source = outputOf<vtkPolyData>(ellipsoid);
    check(mapped && source && mapped->GetNumberOfPoints() == source->GetNumberOfPoints(),
      "in Mapped input mode block 1 has input 0's vertices");

    // Progress and abort as the GUI sees them: ProgressEvents from the
    // proxy's VTK object while the map runs, and AbortExecute set from one
    // (what ParaView's abort does) stops the map with empty blocks and no
    // error; the next update computes the map again.
    auto* filter = vtkAlgorithm::SafeDownCast(map->GetClientSideObject());
    vtkNew<vtkCallbackCommand> abortAt;
    int progressEvents = 0;
    abortAt->SetClientData(&progressEvents);
    abortAt->SetCallback(
      [](vtkObject* caller, unsigned long, void* count, void*)
      {
        if (++*static_cast<int*>(count) == 3)
        {
          static_cast<vtkAlgorithm*>(caller)->SetAbortExecute(1);
        }
      });
    const unsigned long observer = filter->AddObserver(vtkCommand::ProgressEvent, abortAt);
    vtkSMPropertyHelper(map, "OutputMode").Set(0);
    vtkSMPropertyHelper(map, "FineIterations").Set(4); // a new map
    map->UpdateVTKObjects();
    map->UpdatePipeline();
    blocks = outputOf<vtkMultiBlockDataSet>(map);
    auto* aborted = blocks ? vtkPolyData::SafeDownCast(blocks->GetBlock(0)) : nullptr;
    check(progressEvents >= 3, "the map reports progress while it runs");
    check(aborted && aborted->GetNumberOfPoints() == 0, "an aborted map leaves empty blocks");
    filter->RemoveObserver(observer);
    filter->SetAbortExecute(0);
    vtkSMPropertyHelper(map, "FineIterations").Set(3);
    map->UpdateVTKObjects();
    map->UpdatePipeline();
    blocks = outputOf<vtkMultiBlockDataSet>(map);
    auto* again = blocks ? vtkPolyData::SafeDownCast(blocks->GetBlock(0)) : nullptr;
    check(again && again->GetNumberOfPoints() == commonPoints &&
        fieldValue(again, "Bijective") == 1.0,
      "after an abort the next update computes the map again");

    vtkProcessModule::GetProcessModule()->UnRegisterSession(session);
  }
  vtkInitializationHelper::Finalize();
  if (failures > 0)
  {
    std::cerr << failures << " check(s) failed\n";
    return 1;
  }
  std::cout << "all checks passed\n";
  return 0;
}
