#include "MapDirectory.h"

#include "AlgorithmMessages.h"
#include "AtomicFiles.h"
#include "MapConsistency.h"
#include "MeshFiles.h"

#include "vtkFieldData.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkSurfaceMeshReader.h"
#include "vtkUnsignedCharArray.h"

#include <vtksys/MD5.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <random>
#include <regex>
#include <sstream>
#include <stdexcept>

namespace surfacemap
{

namespace
{

const char* const MapIdName = "MapId";
const char* const MapFileName = "MapFile";

std::string readBytes(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  std::ostringstream bytes;
  bytes << in.rdbuf();
  if (!in)
  {
    throw std::runtime_error("cannot read '" + path + "'");
  }
  return bytes.str();
}

std::string md5Hex(const std::string& bytes)
{
  vtksysMD5* md5 = vtksysMD5_New();
  vtksysMD5_Initialize(md5);
  vtksysMD5_Append(
    md5, reinterpret_cast<const unsigned char*>(bytes.data()), static_cast<int>(bytes.size()));
  char hex[33] = {};
  vtksysMD5_FinalizeHex(md5, hex);
  vtksysMD5_Delete(md5);
  return std::string(hex, 32);
}

// Stamps are the text's bytes in an unsigned char array, not a string array:
// vtkSurfaceMeshReader hands no String array to VTK's XML reader (see
// io/XmlPolyDataCheck.h), so only numeric arrays come back from a file.
void addStamp(vtkFieldData* fields, const char* name, const std::string& value)
{
  vtkNew<vtkUnsignedCharArray> array;
  array->SetName(name);
  for (const char c : value)
  {
    array->InsertNextValue(static_cast<unsigned char>(c));
  }
  fields->AddArray(array);
}

// The stamp `name` of a map file, empty if unreadable or absent; `readable`
// (if given) receives whether the file reads as a mesh at all.
std::string stampOf(const std::string& path, const char* name, bool* readable = nullptr)
{
  vtkNew<vtkSurfaceMeshReader> reader;
  ErrorCapture quiet(reader);
  reader->SetFileName(path.c_str());
  reader->Update();
  if (readable)
  {
    *readable = quiet.messages().empty() && reader->GetOutput()->GetNumberOfPoints() > 0;
  }
  auto* array =
    vtkUnsignedCharArray::SafeDownCast(reader->GetOutput()->GetFieldData()->GetAbstractArray(name));
  std::string text;
  for (vtkIdType k = 0; array && k < array->GetNumberOfValues(); ++k)
  {
    text += static_cast<char>(array->GetValue(k));
  }
  return text;
}

Json::Value readReport(const std::string& directory)
{
  if (!isFile(directory + "/report.json") && mapState(directory) == MapState::Interrupted)
  {
    throw std::runtime_error(interruptedRunMessage(directory));
  }
  const Json::Value root = readJsonFile(
    directory + "/report.json", "the directory holds no map (written by 'surfacemap map')");
  if (!root["map_id"].isString() || !root["files"].isArray())
  {
    throw std::runtime_error(directory +
      "/report.json has no map id and file checksums (\"map_id\", \"files\"): written by an "
      "older surfacemap; run 'surfacemap map' again");
  }
  return root;
}

} // namespace

MapWriter::MapWriter(std::string directory)
  : Directory(std::move(directory))
{
  std::random_device device;
  std::ostringstream id;
  id << std::hex;
  for (int k = 0; k < 4; ++k)
  {
    id.width(8);
    id.fill('0');
    id << device();
  }
  this->Id = id.str();
}

void MapWriter::write(vtkPolyData* data, const std::string& name)
{
  // The outputs belong to the filter: stamp a copy with fields of its own.
  vtkNew<vtkPolyData> stamped;
  stamped->ShallowCopy(data);
  vtkNew<vtkFieldData> fields;
  fields->ShallowCopy(data->GetFieldData());
  addStamp(fields, MapIdName, this->Id);
  addStamp(fields, MapFileName, name);
  stamped->SetFieldData(fields);
  const std::string path = this->Directory + "/" + name;
  this->writeBytes(polyDataFileBytes(stamped, path), name);
}

void MapWriter::writeBytes(const std::string& bytes, const std::string& name)
{
  writeFileAtomically(this->Directory + "/" + name, bytes);
  this->Names.push_back(name);
  Json::Value record(Json::objectValue);
  record["name"] = name;
  record["bytes"] = static_cast<Json::UInt64>(bytes.size());
  record["md5"] = md5Hex(bytes);
  this->Records.append(record);
}

void MapWriter::addToReport(Json::Value& report) const
{
  report["map_id"] = this->Id;
  report["files"] = this->Records;
}

std::string mapFileName(const char* stem, int i)
{
  return std::string(stem) + "_" + std::to_string(i) + ".vtp";
}

bool isMapFileName(const std::string& name)
{
  static const std::regex pattern(
    "(common|mapped|embedding)_[0-9]+\\.vtp|fit\\.csv|correspondences\\.npz");
  return std::regex_match(name, pattern);
}

MapState mapState(const std::string& directory)
{
  MapState state = MapState::None;
  std::error_code error;
  for (const auto& entry : std::filesystem::directory_iterator(directory, error))
  {
    const std::string name = entry.path().filename().string();
    if (name == "report.json")
    {
      return MapState::Complete;
    }
    if (isMapFileName(name))
    {
      state = MapState::Interrupted;
    }
  }
  return state;
}

std::string interruptedRunMessage(const std::string& directory)
{
  return directory +
    " holds an interrupted run (common_/mapped_/embedding_ files, no report.json): give "
    "--overwrite or remove it";
}

int mapInputCount(const std::string& directory)
{
  if (!isFile(directory + "/report.json") && mapState(directory) == MapState::Interrupted)
  {
    throw std::runtime_error(interruptedRunMessage(directory));
  }
  return static_cast<int>(mapReportInputs(directory + "/report.json").size());
}

void removeMap(const std::string& directory)
{
  std::vector<std::filesystem::path> files;
  std::error_code error;
  for (const auto& entry : std::filesystem::directory_iterator(directory, error))
  {
    if (isMapFileName(entry.path().filename().string()))
    {
      files.push_back(entry.path());
    }
  }
  files.insert(files.begin(), std::filesystem::path(directory) / "report.json");
  for (const auto& file : files)
  {
    std::filesystem::remove(file, error);
    if (error)
    {
      throw std::runtime_error(
        "cannot remove the earlier map's '" + file.string() + "': " + error.message());
    }
  }
}

std::vector<std::string> mapReportInputs(const std::string& report)
{
  const Json::Value root =
    readJsonFile(report, "it names the map's inputs (or give them with --inputs A B ...)");
  const Json::Value& inputs = root["inputs"];
  std::vector<std::string> files;
  for (Json::ArrayIndex i = 0; inputs.isArray() && i < inputs.size(); ++i)
  {
    if (!inputs[i]["file"].isString())
    {
      throw std::runtime_error(
        report + ": inputs[" + std::to_string(i) + "] has no \"file\" (give --inputs A B ...)");
    }
    files.push_back(inputs[i]["file"].asString());
  }
  if (files.empty())
  {
    throw std::runtime_error(report + " lists no inputs (give --inputs A B ...)");
  }
  return files;
}

void verifyMapFiles(const std::string& directory, const std::vector<std::string>& names)
{
  const Json::Value report = readReport(directory);
  const std::string id = report["map_id"].asString();
  // Each common_<j> is checked with its embedding_<j>: an edited report.json
  // can vouch for any bytes, the geometry between the two it cannot.
  std::vector<std::string> checked = names;
  std::vector<int> commons;
  static const std::regex common("common_([0-9]+)\\.vtp");
  for (const std::string& name : names)
  {
    std::smatch match;
    if (std::regex_match(name, match, common))
    {
      commons.push_back(std::stoi(match[1].str()));
      const std::string embedding = mapFileName("embedding", commons.back());
      if (std::find(checked.begin(), checked.end(), embedding) == checked.end())
      {
        checked.push_back(embedding);
      }
    }
  }
  for (const std::string& name : checked)
  {
    const std::string path = directory + "/" + name;
    const Json::Value* record = nullptr;
    for (const Json::Value& file : report["files"])
    {
      if (file["name"].isString() && file["name"].asString() == name)
      {
        record = &file;
      }
    }
    if (!record)
    {
      throw std::runtime_error(
        path + " is not a file of the map " + directory + "/report.json describes");
    }
    if (!isFile(path))
    {
      throw std::runtime_error(path + " is missing (" + directory + "/report.json lists it)");
    }
    const std::string bytes = readBytes(path);
    if ((*record)["bytes"].asUInt64() == bytes.size() &&
      (*record)["md5"].asString() == md5Hex(bytes))
    {
      continue;
    }
    const std::string changed = path +
      " was changed after the map was written (its size or checksum differs from " + directory +
      "/report.json)";
    if (std::filesystem::path(name).extension() != ".vtp")
    {
      throw std::runtime_error(changed); // no mesh: no stamp to say more
    }
    bool readable = false;
    const std::string fileId = stampOf(path, MapIdName, &readable);
    const std::string fileName = stampOf(path, MapFileName);
    if (!readable)
    {
      throw std::runtime_error(path + " is damaged or truncated: it does not read as a mesh (" +
        std::to_string(bytes.size()) + " bytes, " + directory + "/report.json records " +
        std::to_string((*record)["bytes"].asUInt64()) + ")");
    }
    if (fileId != id)
    {
      throw std::runtime_error(path + " belongs to another map (map id " +
        (fileId.empty() ? std::string("none") : fileId) + ", " + directory + "/report.json has " +
        id + "): a stale or copied file");
    }
    if (fileName != name)
    {
      throw std::runtime_error(
        path + " is " + fileName + " of this map, not " + name + ": swapped or renamed");
    }
    throw std::runtime_error(changed);
  }
  checkMapGeometry(directory, commons);
}

} // namespace surfacemap
