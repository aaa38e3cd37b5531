#include "CommandSupport.h"

#include "Commands.h"

#include "vtkAlgorithm.h"
#include "vtkCallbackCommand.h"
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

#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <limits>
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

ErrorCapture::ErrorCapture(vtkAlgorithm* algorithm)
  : Algorithm(algorithm)
{
  vtkNew<vtkCallbackCommand> command;
  command->SetCallback(&ErrorCapture::callback);
  command->SetClientData(this);
  this->Tag = algorithm->AddObserver(vtkCommand::ErrorEvent, command);
}

ErrorCapture::~ErrorCapture()
{
  this->Algorithm->RemoveObserver(this->Tag);
}

void ErrorCapture::callback(vtkObject*, unsigned long, void* self, void* text)
{
  std::string message = text ? static_cast<const char*>(text) : "unknown error";
  // vtkErrorMacro text: "ERROR: In file, line N\nClass (0x...): message"
  const std::size_t marker = message.find("): ");
  if (marker != std::string::npos)
  {
    message = message.substr(marker + 3);
  }
  while (!message.empty() && (message.back() == '\n' || message.back() == ' '))
  {
    message.pop_back();
  }
  static_cast<ErrorCapture*>(self)->Messages.push_back(message);
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

vtkSmartPointer<vtkPolyData> readMesh(const std::string& path, const std::string& landmarks)
{
  vtkNew<vtkSurfaceMeshReader> reader;
  ErrorCapture readErrors(reader);
  reader->SetFileName(path.c_str());
  if (!landmarks.empty())
  {
    reader->SetLandmarkFileName(landmarks.c_str());
  }
  reader->Update();
  if (*reader->GetLastErrorMessage())
  {
    printError(reader->GetLastErrorMessage());
    return nullptr;
  }
  vtkSmartPointer<vtkPolyData> mesh = reader->GetOutput();
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
} // namespace

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
  const std::string temporary = temporaryName(path);
  std::FILE* file = std::fopen(temporary.c_str(), "wb");
  if (!file)
  {
    throw std::runtime_error("cannot write '" + path + "': " + std::strerror(errno));
  }
  std::fclose(file);
  std::remove(temporary.c_str());
}

bool canWrite(const std::string& path)
{
  return succeeds([&path] { checkWritable(path); });
}

void writeFileAtomically(const std::string& path, const std::string& content)
{
  const std::string temporary = temporaryName(path);
  {
    std::ofstream out(temporary, std::ios::binary);
    out << content;
    if (!out)
    {
      std::remove(temporary.c_str());
      throw std::runtime_error("cannot write '" + path + "': " + std::strerror(errno));
    }
  }
  if (std::rename(temporary.c_str(), path.c_str()) != 0)
  {
    const std::string reason = std::strerror(errno);
    std::remove(temporary.c_str());
    throw std::runtime_error("cannot write '" + path + "': " + reason);
  }
}

void writePolyDataAtomically(vtkPolyData* data, const std::string& path)
{
  const std::string temporary = temporaryName(path);
  vtkNew<vtkXMLPolyDataWriter> writer;
  ErrorCapture errors(writer);
  writer->SetInputData(data);
  writer->SetFileName(temporary.c_str());
  writer->SetDataModeToAppended();
  writer->EncodeAppendedDataOff();
  writer->SetCompressorTypeToZLib();
  const int ok = writer->Write();
  if (!ok || !errors.messages().empty())
  {
    std::remove(temporary.c_str());
    throw std::runtime_error("cannot write '" + path + "'" +
      (errors.messages().empty() ? std::string() : ": " + errors.messages().front()));
  }
  if (std::rename(temporary.c_str(), path.c_str()) != 0)
  {
    const std::string reason = std::strerror(errno);
    std::remove(temporary.c_str());
    throw std::runtime_error("cannot write '" + path + "': " + reason);
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
