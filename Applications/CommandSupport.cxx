#include "CommandSupport.h"

#include "Commands.h"

#include "vtkAlgorithm.h"
#include "vtkCallbackCommand.h"
#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkSurfaceMapEvaluation.h"
#include "vtkSurfaceMeshReader.h"
#include "vtkSurfaceMeshValidator.h"
#include "vtkTable.h"
#include "vtkVariant.h"
#include "vtkXMLPolyDataWriter.h"

#include "vtk_jsoncpp.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <atomic>
#include <csignal>

#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <limits>
#include <map>
#include <sstream>
#include <stdexcept>
#include <system_error>

namespace surfacemap
{

bool isOption(const std::string& argument)
{
  return !argument.empty() && argument[0] == '-';
}

const std::string& optionValue(const std::vector<std::string>& args,
  std::size_t& i,
  const char* what)
{
  if (i + 1 >= args.size())
  {
    throw UsageError{ args[i] + " needs " + what };
  }
  return args[++i];
}

void unknownOption(const std::string& argument)
{
  throw UsageError{ "unknown option '" + argument + "'" };
}

void printErrors(const std::vector<std::string>& messages)
{
  for (const std::string& m : messages)
  {
    printError(m);
  }
}

bool succeeds(const std::function<void()>& step)
{
  try
  {
    step();
    return true;
  }
  catch (const std::runtime_error& e)
  {
    printError(e.what());
    return false;
  }
}

ErrorCapture::ErrorCapture(vtkAlgorithm* algorithm, unsigned long event)
  : Algorithm(algorithm)
{
  vtkNew<vtkCallbackCommand> command;
  command->SetCallback(&ErrorCapture::callback);
  command->SetClientData(this);
  this->Tag = algorithm->AddObserver(event ? event : vtkCommand::ErrorEvent, command);
}

ErrorCapture::~ErrorCapture()
{
  this->Algorithm->RemoveObserver(this->Tag);
}

namespace
{
// vtkErrorMacro/vtkWarningMacro text: "ERROR: In file, line N\nClass (0x...): message"
std::string macroMessage(void* text, const char* none)
{
  std::string message = text ? static_cast<const char*>(text) : none;
  const std::size_t marker = message.find("): ");
  if (marker != std::string::npos)
  {
    message = message.substr(marker + 3);
  }
  while (!message.empty() && (message.back() == '\n' || message.back() == ' '))
  {
    message.pop_back();
  }
  return message;
}
} // namespace

void ErrorCapture::callback(vtkObject*, unsigned long, void* self, void* text)
{
  static_cast<ErrorCapture*>(self)->Messages.push_back(macroMessage(text, "unknown error"));
}

WarningPrinter::WarningPrinter(vtkAlgorithm* algorithm)
  : Algorithm(algorithm)
{
  vtkNew<vtkCallbackCommand> command;
  command->SetCallback(&WarningPrinter::callback);
  this->Tag = algorithm->AddObserver(vtkCommand::WarningEvent, command);
}

WarningPrinter::~WarningPrinter()
{
  this->Algorithm->RemoveObserver(this->Tag);
}

void WarningPrinter::callback(vtkObject*, unsigned long, void*, void* text)
{
  std::fprintf(stderr, "surfacemap: warning: %s\n", macroMessage(text, "unknown warning").c_str());
}

ProgressBar::ProgressBar(vtkAlgorithm* algorithm)
  : Algorithm(algorithm)
{
  if (!isatty(STDERR_FILENO))
  {
    return;
  }
  vtkNew<vtkCallbackCommand> command;
  command->SetCallback(&ProgressBar::callback);
  command->SetClientData(this);
  this->Tag = algorithm->AddObserver(vtkCommand::ProgressEvent, command);
}

ProgressBar::~ProgressBar()
{
  if (this->Tag)
  {
    this->Algorithm->RemoveObserver(this->Tag);
  }
  if (this->Shown)
  {
    std::cerr << "\n";
  }
}

void ProgressBar::callback(vtkObject*, unsigned long, void* self, void*)
{
  auto* bar = static_cast<ProgressBar*>(self);
  const double progress = bar->Algorithm->GetProgress();
  const int width = 30;
  const int filled = static_cast<int>(progress * width + 0.5);
  const char* text = bar->Algorithm->GetProgressText();
  // \033[K clears what a longer earlier text left on the line.
  std::cerr << "\r[" << std::string(filled, '#') << std::string(width - filled, ' ') << "] "
            << static_cast<int>(100 * progress + 0.5) << "% " << (text ? text : "") << "\033[K"
            << std::flush;
  bar->Shown = true;
}

const char* const LandmarkFormatsHelp =
  "\n"
  "Landmark files (by extension; the k-th landmark of a file has id k unless\n"
  "the file gives ids; the same id on two meshes means corresponding points):\n"
  "  .pinned .txt .vts  one per line: a 0-based vertex index ('i' or 'lk i'),\n"
  "                     SHREC 'i x y z' (the index is used), or a point\n"
  "                     'x y z' / '-1 x y z' (the index is missing)\n"
  "  .csv               'x,y,z' or 'x,y,z,id' per line, or columns named by a\n"
  "                     header line (x, y, z, id, label)\n"
  "  .fcsv              3D Slicer markups CSV ('#' comment lines, columns\n"
  "                     id,x,y,z,...; integer ids are used, node names are not)\n"
  "  .mrk.json          3D Slicer markups JSON: markups[0].controlPoints, each\n"
  "                     with a position (and optional integer id and label)\n"
  "A point becomes the closest vertex of its mesh; the snap distance is\n"
  "printed (and recorded in report.json by 'map'), with a warning when it\n"
  "exceeds 1 % of the mesh's bounding-box diagonal. Points are read in the\n"
  "mesh's own coordinates, as written (no RAS/LPS conversion). A malformed file\n"
  "is rejected naming the file and line (exit code 2).\n";

void printWarning(const std::string& message)
{
  std::cerr << "surfacemap: warning: " << message << "\n";
}

std::string landmarkSnapSummary(vtkPolyData* mesh, const std::string& landmarks)
{
  vtkDataArray* distances = mesh->GetFieldData()->GetArray("LandmarkSnapDistance");
  if (!distances || distances->GetNumberOfTuples() == 0)
  {
    return "";
  }
  double largest = 0.0;
  for (vtkIdType k = 0; k < distances->GetNumberOfTuples(); ++k)
  {
    largest = std::max(largest, distances->GetTuple1(k));
  }
  const double diagonal = mesh->GetLength();
  std::ostringstream line;
  line << "landmarks of " << landmarks << ": " << distances->GetNumberOfTuples()
       << " point" << (distances->GetNumberOfTuples() == 1 ? "" : "s")
       << " snapped to the closest vertex, largest snap distance " << std::setprecision(4)
       << largest << " (" << (diagonal > 0.0 ? 100.0 * largest / diagonal : 0.0)
       << " % of the bounding-box diagonal)";
  return line.str();
}

std::string landmarkSnapJson(vtkPolyData* mesh)
{
  vtkFieldData* fd = mesh->GetFieldData();
  vtkDataArray* ids = fd->GetArray("LandmarkSnapId");
  vtkDataArray* vertices = fd->GetArray("LandmarkSnapVertex");
  vtkDataArray* distances = fd->GetArray("LandmarkSnapDistance");
  if (!ids || !vertices || !distances || distances->GetNumberOfTuples() == 0)
  {
    return "null";
  }
  const double diagonal = mesh->GetLength();
  std::ostringstream json;
  json << "[";
  for (vtkIdType k = 0; k < distances->GetNumberOfTuples(); ++k)
  {
    const double d = distances->GetTuple1(k);
    json << (k ? ", " : "") << "{ \"id\": " << static_cast<long long>(ids->GetTuple1(k))
         << ", \"vertex\": " << static_cast<long long>(vertices->GetTuple1(k))
         << ", \"distance\": " << jsonNumber(d)
         << ", \"percent_of_diagonal\": " << jsonNumber(diagonal > 0.0 ? 100.0 * d / diagonal : 0.0)
         << " }";
  }
  json << "]";
  return json.str();
}

vtkSmartPointer<vtkPolyData> readMesh(const std::string& path,
  const std::string& landmarks,
  const std::string& sizing)
{
  vtkNew<vtkSurfaceMeshReader> reader;
  ErrorCapture readErrors(reader);
  ErrorCapture readWarnings(reader, vtkCommand::WarningEvent);
  reader->SetFileName(path.c_str());
  if (!landmarks.empty())
  {
    reader->SetLandmarkFileName(landmarks.c_str());
  }
  if (!sizing.empty())
  {
    reader->SetSizingFileName(sizing.c_str());
  }
  reader->Update();
  if (*reader->GetLastErrorMessage())
  {
    printError(reader->GetLastErrorMessage());
    return nullptr;
  }
  vtkSmartPointer<vtkPolyData> mesh = reader->GetOutput();
  for (const std::string& warning : readWarnings.messages())
  {
    printWarning(warning);
  }
  const std::string snapped = landmarkSnapSummary(mesh, landmarks);
  if (!snapped.empty())
  {
    std::printf("%s\n", snapped.c_str());
  }
  return mesh;
}

vtkSmartPointer<vtkPolyData> readValidMesh(const std::string& path, const std::string& landmarks)
{
  vtkSmartPointer<vtkPolyData> mesh = readMesh(path, landmarks);
  if (!mesh)
  {
    return nullptr;
  }
  vtkNew<vtkSurfaceMeshValidator> validator;
  validator->AddInputDataObject(mesh);
  validator->Update();
  if (!validator->GetAllValid())
  {
    std::istringstream defects(validator->GetOutput()->GetValueByName(0, "Defects").ToString());
    for (std::string line; std::getline(defects, line);)
    {
      printError(path + " " + line);
    }
    return nullptr;
  }
  return mesh;
}

std::vector<std::string> mapReportInputs(const std::string& report)
{
  std::ifstream in(report);
  if (!in)
  {
    throw std::runtime_error(
      report + " is missing: it names the map's inputs (or give them with --inputs A B ...)");
  }
  Json::CharReaderBuilder builder;
  Json::Value root;
  std::string problems;
  if (!Json::parseFromStream(builder, in, &root, &problems))
  {
    while (!problems.empty() && (problems.back() == '\n' || problems.back() == ' '))
    {
      problems.pop_back();
    }
    throw std::runtime_error(report + " is not valid JSON: " + problems);
  }
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

std::string jsonNumber(double value)
{
  if (!std::isfinite(value))
  {
    return "null";
  }
  std::ostringstream s;
  s << std::setprecision(10) << value;
  return s.str();
}

std::string jsonString(const std::string& text)
{
  std::string out = "\"";
  for (const char c : text)
  {
    if (c == '"' || c == '\\')
    {
      out += '\\';
      out += c;
    }
    else if (static_cast<unsigned char>(c) < 0x20)
    {
      char buffer[8];
      std::snprintf(buffer, sizeof buffer, "\\u%04x", c);
      out += buffer;
    }
    else
    {
      out += c;
    }
  }
  return out + "\"";
}

namespace
{
std::string temporaryName(const std::string& path)
{
  return path + ".tmp." + std::to_string(getpid());
}

// Temporary files being written, for the signal handler to remove: fixed
// storage, since a handler may neither allocate nor take locks.
constexpr int TemporarySlots = 16;
constexpr std::size_t TemporaryPathSize = 4096;
char TemporaryPaths[TemporarySlots][TemporaryPathSize];
volatile std::sig_atomic_t TemporaryInUse[TemporarySlots];

// Directories for InterruptCleanup and the one rename of InterruptRestore,
// in the same kind of fixed storage.
constexpr int DirectorySlots = 4;
char DirectoryPaths[DirectorySlots][TemporaryPathSize];
volatile std::sig_atomic_t DirectoryInUse[DirectorySlots];
char RestoreFrom[TemporaryPathSize];
char RestoreTo[TemporaryPathSize];
volatile std::sig_atomic_t RestoreInUse = 0;

bool registerPath(char* slot, const std::string& path)
{
  if (path.size() >= TemporaryPathSize)
  {
    return false;
  }
  std::memcpy(slot, path.c_str(), path.size() + 1);
  std::atomic_signal_fence(std::memory_order_seq_cst);
  return true;
}

bool startsWith(const char* text, const char* prefix)
{
  return std::strncmp(text, prefix, std::strlen(prefix)) == 0;
}

// A name a map writes (isMapFileName's pattern, loosely) or a temporary
// file; async-signal-safe (no allocation, no locale).
bool isMapWrittenName(const char* name)
{
  if (std::strcmp(name, "report.json") == 0 || std::strstr(name, ".tmp.") != nullptr)
  {
    return true;
  }
  const std::size_t length = std::strlen(name);
  return (startsWith(name, "common_") || startsWith(name, "mapped_") ||
           startsWith(name, "embedding_")) &&
    length > 4 && std::strcmp(name + length - 4, ".vtp") == 0;
}

// Removes the map's files from `directory`, then the directory if empty,
// with system calls only (a signal handler may not allocate).
void removeMapFilesOf(const char* directory)
{
  const int fd = open(directory, O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0)
  {
    return;
  }
  struct Entry
  {
    std::uint64_t inode;
    std::int64_t offset;
    unsigned short length;
    unsigned char type;
    char name[1];
  };
  alignas(8) static char buffer[8192];
  // Unlinking while reading the directory may skip entries: read it again
  // until a pass removes nothing.
  for (bool removed = true; removed;)
  {
    removed = false;
    lseek(fd, 0, SEEK_SET);
    for (long n; (n = syscall(SYS_getdents64, fd, buffer, sizeof(buffer))) > 0;)
    {
      for (long at = 0; at < n;)
      {
        const auto* entry = reinterpret_cast<const Entry*>(buffer + at);
        at += entry->length;
        if (isMapWrittenName(entry->name) && unlinkat(fd, entry->name, 0) == 0)
        {
          removed = true;
        }
      }
    }
  }
  close(fd);
  rmdir(directory);
}

extern "C" void removeTemporariesAndExit(int signal)
{
  for (int k = 0; k < TemporarySlots; ++k)
  {
    if (TemporaryInUse[k])
    {
      unlink(TemporaryPaths[k]);
    }
  }
  if (RestoreInUse)
  {
    rename(RestoreFrom, RestoreTo);
  }
  for (int k = 0; k < DirectorySlots; ++k)
  {
    if (DirectoryInUse[k])
    {
      removeMapFilesOf(DirectoryPaths[k]);
    }
  }
  // The default action, so the parent sees death by this signal.
  std::signal(signal, SIG_DFL);
  std::raise(signal);
}

// A temporary file name registered for removal on SIGINT/SIGTERM while this
// object lives; the file itself is removed by remove() or the destructor.
class TemporaryFile
{
public:
  explicit TemporaryFile(const std::string& path)
    : Path(temporaryName(path))
  {
    for (int k = 0; k < TemporarySlots; ++k)
    {
      if (!TemporaryInUse[k] && this->Path.size() < TemporaryPathSize)
      {
        std::memcpy(TemporaryPaths[k], this->Path.c_str(), this->Path.size() + 1);
        std::atomic_signal_fence(std::memory_order_seq_cst);
        TemporaryInUse[k] = 1;
        this->Slot = k;
        break;
      }
    }
  }
  ~TemporaryFile()
  {
    this->remove();
    if (this->Slot >= 0)
    {
      TemporaryInUse[this->Slot] = 0;
    }
  }
  TemporaryFile(const TemporaryFile&) = delete;
  TemporaryFile& operator=(const TemporaryFile&) = delete;

  const std::string& path() const { return this->Path; }
  void remove()
  {
    if (!this->Renamed)
    {
      std::remove(this->Path.c_str());
    }
  }
  /// Renames the file to `target`; throws std::runtime_error naming `target`.
  void renameTo(const std::string& target)
  {
    if (std::rename(this->Path.c_str(), target.c_str()) != 0)
    {
      throw std::runtime_error("cannot write '" + target + "': " + std::strerror(errno));
    }
    this->Renamed = true;
  }

private:
  std::string Path;
  int Slot = -1;
  bool Renamed = false;
};

[[noreturn]] void writeFailed(const std::string& path, const std::string& reason)
{
  throw std::runtime_error("cannot write '" + path + "': " + reason);
}

// Writes `content` to a new file `temporary` with every step checked: each
// write, fsync (data on the disk, where the file system supports it), close,
// and the size that arrived. Throws std::runtime_error naming `path`.
void writeChecked(const std::string& temporary, const std::string& path, const std::string& content)
{
  const int fd = open(temporary.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
  if (fd < 0)
  {
    writeFailed(path, std::strerror(errno));
  }
  std::size_t written = 0;
  while (written < content.size())
  {
    const ssize_t n = write(fd, content.data() + written, content.size() - written);
    if (n < 0 && errno == EINTR)
    {
      continue;
    }
    if (n <= 0)
    {
      const std::string reason = n < 0 ? std::strerror(errno) : "nothing was written";
      close(fd);
      writeFailed(path, reason);
    }
    written += static_cast<std::size_t>(n);
  }
  if (fsync(fd) != 0 && errno != EINVAL && errno != EROFS)
  {
    const std::string reason = std::strerror(errno);
    close(fd);
    writeFailed(path, reason);
  }
  if (close(fd) != 0)
  {
    writeFailed(path, std::strerror(errno));
  }
  struct stat info;
  if (stat(temporary.c_str(), &info) != 0)
  {
    writeFailed(path, std::strerror(errno));
  }
  if (static_cast<unsigned long long>(info.st_size) != content.size())
  {
    writeFailed(path,
      "only " + std::to_string(static_cast<long long>(info.st_size)) + " of " +
        std::to_string(content.size()) + " bytes reached the disk");
  }
}
} // namespace

InterruptCleanup::InterruptCleanup(const std::string& directory)
{
  for (int k = 0; k < DirectorySlots; ++k)
  {
    if (!DirectoryInUse[k] && registerPath(DirectoryPaths[k], directory))
    {
      DirectoryInUse[k] = 1;
      this->Slot = k;
      return;
    }
  }
}

InterruptCleanup::~InterruptCleanup()
{
  if (this->Slot >= 0)
  {
    DirectoryInUse[this->Slot] = 0;
  }
}

InterruptRestore::InterruptRestore(const std::string& moved, const std::string& original)
{
  if (!RestoreInUse && registerPath(RestoreFrom, moved) && registerPath(RestoreTo, original))
  {
    RestoreInUse = 1;
    this->Registered = true;
  }
}

InterruptRestore::~InterruptRestore()
{
  if (this->Registered)
  {
    RestoreInUse = 0;
  }
}

void installSignalHandlers()
{
  struct sigaction action = {};
  action.sa_handler = removeTemporariesAndExit;
  sigemptyset(&action.sa_mask);
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
  // Past a file size limit write() then fails with EFBIG, which is reported,
  // instead of the process dying with the temporary file left behind.
  std::signal(SIGXFSZ, SIG_IGN);
}

bool isFile(const std::string& path)
{
  std::error_code ec;
  return std::filesystem::is_regular_file(path, ec);
}

std::string mapFileName(const char* stem, int i)
{
  return std::string(stem) + "_" + std::to_string(i) + ".vtp";
}

void createOutputDirectory(const std::string& directory, const std::string& probe)
{
  std::error_code ec;
  std::filesystem::create_directories(directory, ec);
  if (ec && !std::filesystem::is_directory(directory))
  {
    throw std::runtime_error(
      "cannot create the output directory '" + directory + "': " + ec.message());
  }
  checkWritable(directory + "/" + probe);
}

bool prepareOutputDirectory(const std::string& directory,
  const std::string& probe,
  std::string& created)
{
  created.clear();
  return succeeds(
    [&]
    {
      std::error_code ec;
      for (std::filesystem::path p = std::filesystem::absolute(directory, ec).lexically_normal();
           !ec && !p.empty() && !std::filesystem::exists(p, ec) && p != p.parent_path();
           p = p.parent_path())
      {
        created = p.string();
      }
      createOutputDirectory(directory, probe);
    });
}

void removeCreatedDirectory(const std::string& created)
{
  if (!created.empty())
  {
    std::error_code ec;
    std::filesystem::remove_all(created, ec);
  }
}

void checkWritable(const std::string& path)
{
  TemporaryFile temporary(path);
  std::FILE* file = std::fopen(temporary.path().c_str(), "wb");
  if (!file)
  {
    throw std::runtime_error("cannot write '" + path + "': " + std::strerror(errno));
  }
  std::fclose(file);
}

bool canWrite(const std::string& path)
{
  return succeeds([&path] { checkWritable(path); });
}

void writeFileAtomically(const std::string& path, const std::string& content)
{
  TemporaryFile temporary(path);
  writeChecked(temporary.path(), path, content);
  temporary.renameTo(path);
}

void writePolyDataAtomically(vtkPolyData* data, const std::string& path)
{
  // Into memory first: the XML writer does not notice every failed write
  // (a full disk), so the bytes go to the file through writeFileAtomically.
  vtkNew<vtkXMLPolyDataWriter> writer;
  ErrorCapture errors(writer);
  writer->SetInputData(data);
  writer->WriteToOutputStringOn();
  writer->SetDataModeToAppended();
  writer->EncodeAppendedDataOff();
  writer->SetCompressorTypeToZLib();
  const int ok = writer->Write();
  const unsigned long code = writer->GetErrorCode();
  if (!ok || code != 0 || !errors.messages().empty())
  {
    writeFailed(path,
      errors.messages().empty()
        ? "the XML writer failed (VTK error code " + std::to_string(code) + ")"
        : errors.messages().front());
  }
  writeFileAtomically(path, writer->GetOutputString());
}

namespace
{

// A per-corner cell array of an OBJ's faces ("CornerTCoords" as vt,
// "CornerNormals" as vn): one line per distinct value, numbered in order of
// appearance; a face whose corners are not all finite goes without it.
class ObjCornerAttribute
{
public:
  ObjCornerAttribute(vtkPolyData* data, const char* name, int components, const char* keyword)
    : Keyword(keyword)
    , Components(components)
  {
    vtkDataArray* array = data->GetCellData()->GetArray(name);
    this->Array = array && array->GetNumberOfComponents() == 3 * components ? array : nullptr;
  }

  /// Writes the new values of `cell`'s corners to `obj`; their indices (0: none).
  std::array<long long, 3> add(vtkIdType cell, std::ostream& obj)
  {
    std::array<long long, 3> index{ 0, 0, 0 };
    if (!this->Array)
    {
      return index;
    }
    std::vector<double> values(3 * this->Components);
    this->Array->GetTuple(cell, values.data());
    if (!std::all_of(values.begin(), values.end(), [](double v) { return std::isfinite(v); }))
    {
      return index;
    }
    for (int k = 0; k < 3; ++k)
    {
      const std::vector<double> value(
        values.begin() + k * this->Components, values.begin() + (k + 1) * this->Components);
      const auto added =
        this->Indices.emplace(value, static_cast<long long>(this->Indices.size()) + 1);
      if (added.second)
      {
        obj << this->Keyword;
        for (double v : value)
        {
          obj << ' ' << v;
        }
        obj << '\n';
      }
      index[k] = added.first->second;
    }
    return index;
  }

private:
  const char* Keyword;
  int Components;
  vtkDataArray* Array = nullptr;
  std::map<std::vector<double>, long long> Indices;
};

} // namespace

void writeObjAtomically(vtkPolyData* data, const std::string& path)
{
  std::ostringstream obj;
  obj.precision(17);
  obj << "# written by surfacemap\n";
  for (vtkIdType p = 0; p < data->GetNumberOfPoints(); ++p)
  {
    const double* x = data->GetPoint(p);
    obj << "v " << x[0] << ' ' << x[1] << ' ' << x[2] << '\n';
  }
  ObjCornerAttribute texture(data, "CornerTCoords", 2, "vt");
  ObjCornerAttribute normals(data, "CornerNormals", 3, "vn");
  // Per face: vertex, texture and normal index (1-based; 0: none) per corner.
  std::vector<std::array<std::array<long long, 3>, 3>> faces;
  auto cells = vtk::TakeSmartPointer(data->GetPolys()->NewIterator());
  vtkIdType cell = data->GetNumberOfVerts() + data->GetNumberOfLines();
  for (cells->GoToFirstCell(); !cells->IsDoneWithTraversal(); cells->GoToNextCell(), ++cell)
  {
    vtkIdType size;
    const vtkIdType* ids;
    cells->GetCurrentCell(size, ids);
    if (size != 3)
    {
      writeFailed(
        path, "polygon " + std::to_string(cells->GetCurrentCellId()) + " is not a triangle");
    }
    faces.push_back({ std::array<long long, 3>{ ids[0] + 1, ids[1] + 1, ids[2] + 1 },
      texture.add(cell, obj), normals.add(cell, obj) });
  }
  for (const auto& face : faces)
  {
    obj << 'f';
    for (int k = 0; k < 3; ++k)
    {
      obj << ' ' << face[0][k];
      if (face[1][k] > 0 || face[2][k] > 0)
      {
        obj << '/' << (face[1][k] > 0 ? std::to_string(face[1][k]) : std::string());
      }
      if (face[2][k] > 0)
      {
        obj << '/' << face[2][k];
      }
    }
    obj << '\n';
  }
  writeFileAtomically(path, obj.str());
}

void writeMeshAtomically(vtkPolyData* data, const std::string& path)
{
  std::string extension = std::filesystem::path(path).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
    [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (extension == ".obj")
  {
    writeObjAtomically(data, path);
  }
  else
  {
    writePolyDataAtomically(data, path);
  }
}

vtkSmartPointer<vtkPolyData> measureMap(vtkPolyData* source,
  vtkPolyData* target,
  vtkPolyData* sourceOriginal,
  vtkPolyData* targetOriginal)
{
  vtkNew<vtkSurfaceMapEvaluation> evaluation;
  ErrorCapture errors(evaluation);
  evaluation->SetInputDataObject(0, source);
  evaluation->SetInputDataObject(1, target);
  if (sourceOriginal)
  {
    evaluation->SetInputDataObject(2, sourceOriginal);
  }
  if (targetOriginal)
  {
    evaluation->SetInputDataObject(3, targetOriginal);
  }
  evaluation->Update();
  if (!errors.messages().empty())
  {
    throw std::invalid_argument(errors.messages().front());
  }
  vtkSmartPointer<vtkPolyData> result = evaluation->GetOutput();
  return result;
}

const std::vector<const char*>& evaluationSummaryNames()
{
  static const std::vector<const char*> names = { "SymmetricDirichlet",
    "AreaBelow1.5",
    "AreaBelow2",
    "MaxDistortion",
    "DegenerateTriangles",
    "MinAngleSource",
    "MeanMinAngleSource",
    "MinAngleTarget",
    "MeanMinAngleTarget",
    "HausdorffSource",
    "HausdorffTarget",
    "TwoSidedDistanceSource",
    "TwoSidedDistanceTarget",
    "Bijective",
    "NonPositiveTriangles" };
  return names;
}

double summaryValue(vtkPolyData* result, const char* name)
{
  vtkDataArray* a = result->GetFieldData()->GetArray(name);
  return a && a->GetNumberOfTuples() > 0 ? a->GetTuple1(0)
                                         : std::numeric_limits<double>::quiet_NaN();
}

} // namespace surfacemap
