#include "MapDirectory.h"

#include "AlgorithmMessages.h"
#include "AtomicFiles.h"
#include "MeshFiles.h"
#include "OutputDirectory.h"

#include "vtkFieldData.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkSurfaceMeshReader.h"
#include "vtkUnsignedCharArray.h"

#include <vtksys/MD5.h>

#include <filesystem>
#include <fstream>
#include <random>
#include <regex>
#include <sstream>
#include <stdexcept>

#include <sys/stat.h>
#include <unistd.h>

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

// The stamp `name` of a map file, empty if unreadable or absent.
std::string stampOf(const std::string& path, const char* name)
{
  vtkNew<vtkSurfaceMeshReader> reader;
  ErrorCapture quiet(reader);
  reader->SetFileName(path.c_str());
  reader->Update();
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
  const Json::Value root = readJsonFile(directory + "/report.json",
    "the directory holds no complete map (was 'surfacemap map' interrupted?)");
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
  writePolyDataAtomically(stamped, path);
  this->Names.push_back(name);
  // As on disk: what readers will compare against.
  const std::string bytes = readBytes(path);
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
  static const std::regex pattern("(common|mapped|embedding)_[0-9]+\\.vtp");
  return std::regex_match(name, pattern);
}

bool holdsMap(const std::string& directory)
{
  std::error_code error;
  for (const auto& entry : std::filesystem::directory_iterator(directory, error))
  {
    const std::string name = entry.path().filename().string();
    if (name == "report.json" || isMapFileName(name))
    {
      return true;
    }
  }
  return false;
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
  for (const std::string& name : names)
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
    const std::string fileId = stampOf(path, MapIdName);
    const std::string fileName = stampOf(path, MapFileName);
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
    throw std::runtime_error(path +
      " was changed after the map was written (its size or "
      "checksum differs from " +
      directory + "/report.json)");
  }
}

namespace
{
// Why DIR cannot be swapped by renames; empty if it can.
std::string whyNotSwappable(const std::filesystem::path& directory)
{
  std::error_code ec;
  const std::filesystem::path cwd = std::filesystem::current_path(ec);
  if (!ec)
  {
    const auto relative = cwd.lexically_relative(directory);
    if (!relative.empty() && *relative.begin() != "..")
    {
      return "it is or holds the working directory";
    }
  }
  struct stat self, parent;
  if (stat(directory.c_str(), &self) != 0 || stat(directory.parent_path().c_str(), &parent) != 0 ||
    self.st_dev != parent.st_dev)
  {
    return "it is a mount point";
  }
  if (access(directory.parent_path().c_str(), W_OK) != 0)
  {
    return "its parent directory is not writable";
  }
  return "";
}

std::string withPid(const std::filesystem::path& directory, const char* kind)
{
  return directory.string() + "." + kind + "." + std::to_string(getpid());
}
} // namespace

MapDestination::MapDestination(const std::string& directory, bool replacing)
  : Directory(directory)
  , Path(directory)
{
  if (!replacing)
  {
    return;
  }
  std::error_code ec;
  // A symbolic link keeps pointing at the directory's path, which then holds the new map.
  const std::filesystem::path real = std::filesystem::canonical(directory, ec);
  const std::string why = ec ? ec.message() : whyNotSwappable(real);
  if (!why.empty())
  {
    this->Note = "the earlier map in " + directory + " is removed before the new one is written (" +
      why + ": it cannot be replaced as a whole)";
    // No reader takes a directory without report.json for a map, and the
    // new report lists only the new files: an interruption from here on
    // leaves no map rather than a mix of two.
    removeMap(directory);
    return;
  }
  this->Directory = real.string();
  this->Path = withPid(real, "tmp");
  std::filesystem::remove_all(this->Path, ec); // a leftover of a killed run with this pid
  this->Cleanup = std::make_unique<InterruptCleanup>(this->Path);
  this->Staged = true;
  createOutputDirectory(this->Path, "report.json");
}

MapDestination::~MapDestination()
{
  if (this->Staged && !this->Committed)
  {
    std::error_code ec;
    std::filesystem::remove_all(this->Path, ec);
  }
}

void MapDestination::commit(const std::vector<std::string>& names)
{
  verifyMapFiles(this->Path, names);
  if (!this->Staged)
  {
    this->Committed = true;
    return;
  }
  namespace fs = std::filesystem;
  const std::string old = withPid(this->Directory, "old");
  std::error_code ec;
  fs::remove_all(old, ec);
  {
    InterruptRestore restore(old, this->Directory);
    fs::rename(this->Directory, old, ec);
    if (ec)
    {
      throw std::runtime_error("cannot move the earlier map in " + this->Directory +
        " aside: " + ec.message() + " (it is unchanged)");
    }
    fs::rename(this->Path, this->Directory, ec);
    if (ec)
    {
      const std::string reason = ec.message();
      fs::rename(old, this->Directory, ec);
      throw std::runtime_error("cannot move the new map into " + this->Directory + ": " + reason +
        (ec ? " (the earlier map is in " + old + ")" : " (the earlier map is unchanged)"));
    }
  }
  this->Committed = true;
  this->Cleanup.reset(); // the staging directory is DIR now
  InterruptCleanup removeOld(old);
  // What the directory held besides the earlier map stays in it.
  bool carried = true;
  for (const auto& entry : fs::directory_iterator(old, ec))
  {
    const std::string name = entry.path().filename().string();
    if (name == "report.json" || isMapFileName(name))
    {
      continue;
    }
    std::error_code moved;
    fs::rename(entry.path(), fs::path(this->Directory) / name, moved);
    carried = carried && !moved;
  }
  if (!carried || ec)
  {
    throw std::runtime_error("the new map is in " + this->Directory +
      ", but not every other file of the earlier directory could be moved into it: they are "
      "in " +
      old);
  }
  fs::remove_all(old, ec);
}

} // namespace surfacemap
