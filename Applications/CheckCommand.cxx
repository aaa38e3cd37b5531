// surfacemap check: validate meshes as inputs and print their statistics.
#include "AlgorithmMessages.h"
#include "Arguments.h"
#include "Commands.h"
#include "MeshFiles.h"
#include "Terminal.h"

#include "vtkSurfaceMeshReader.h"
#include "vtkSurfaceMeshValidator.h"

#include "vtkAbstractArray.h"
#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkStringArray.h"
#include "vtkTable.h"
#include "vtkVariant.h"

#include <cstdio>
#include <iostream>
#include <sstream>

namespace surfacemap
{

namespace
{
const std::string CheckHelpText =
  std::string("usage: surfacemap check MESH... [--landmarks FILE...]\n"
              "\n"
              "Checks that every MESH is a valid SurfaceMaps input (closed, manifold,\n"
              "genus-0, triangles only, no duplicate, unused or non-finite vertices, no\n"
              "zero-area triangles) and prints its statistics. Formats: .obj .off .ply\n"
              ".stl .vtp .vtk.\n"
              "\n"
              "  --landmarks FILE...  one landmark file per mesh, in the same order (the\n"
              "                       formats are below). The landmark ids must match\n"
              "                       across meshes, as a map\n"
              "                       between them requires. Without --landmarks each\n"
              "                       mesh is checked on its own (landmark arrays in VTP\n"
              "                       files only need unique ids).\n"
              "\n"
              "Exit code 0 only if every mesh is valid; 2 otherwise.\n") +
  LandmarkFormatsHelp;
} // namespace

const char* const CheckHelp = CheckHelpText.c_str();

namespace
{

void ignoreErrors(vtkObject* object)
{
  // The reader keeps its message and we print it ourselves; an observer
  // without callback consumes the event instead of the output window.
  vtkNew<vtkCallbackCommand> sink;
  object->AddObserver(vtkCommand::ErrorEvent, sink);
}

std::string format(double value)
{
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.6g", value);
  return buffer;
}

// The meshes and their landmark files (empty without --landmarks, which
// also asks for corresponding landmark ids).
struct CheckArguments
{
  std::vector<std::string> meshes, landmarks;
  bool correspondence = false;
};

CheckArguments parseArguments(const std::vector<std::string>& args)
{
  CheckArguments parsed;
  for (const std::string& a : args)
  {
    if (a == "--landmarks")
    {
      parsed.correspondence = true;
    }
    else if (isOption(a))
    {
      unknownOption(a);
    }
    else
    {
      (parsed.correspondence ? parsed.landmarks : parsed.meshes).push_back(a);
    }
  }
  if (parsed.meshes.empty())
  {
    throw UsageError{ parsed.landmarks.empty()
        ? "no mesh given"
        : "no mesh given (the meshes come before --landmarks: check A B --landmarks FA FB)" };
  }
  if (parsed.correspondence && parsed.landmarks.size() != parsed.meshes.size())
  {
    throw UsageError{ "--landmarks needs one file per mesh (" +
      std::to_string(parsed.meshes.size()) + " meshes, " + std::to_string(parsed.landmarks.size()) +
      " landmark files)" };
  }
  return parsed;
}

// The meshes read, in order, with the line on their snapped landmarks.
struct ReadMeshes
{
  std::vector<std::string> names, snapped;
};

// Reads every mesh into the validator; an unreadable one is reported as
// such and clears `ok`.
ReadMeshes readMeshes(const CheckArguments& arguments, vtkSurfaceMeshValidator* validator, bool& ok)
{
  ReadMeshes read;
  for (std::size_t i = 0; i < arguments.meshes.size(); ++i)
  {
    vtkNew<vtkSurfaceMeshReader> reader;
    ignoreErrors(reader);
    ErrorCapture warnings(reader, vtkCommand::WarningEvent);
    reader->SetFileName(arguments.meshes[i].c_str());
    if (!arguments.landmarks.empty())
    {
      reader->SetLandmarkFileName(arguments.landmarks[i].c_str());
    }
    reader->Update();
    if (*reader->GetLastErrorMessage())
    {
      printError(reader->GetLastErrorMessage());
      std::cout << arguments.meshes[i] << ": UNREADABLE\n";
      ok = false;
      continue;
    }
    vtkSmartPointer<vtkPolyData> mesh = reader->GetOutput();
    for (const std::string& warning : warnings.messages())
    {
      printWarning(warning);
    }
    validator->AddInputDataObject(mesh);
    read.names.push_back(arguments.meshes[i]);
    read.snapped.push_back(
      arguments.landmarks.empty() ? "" : landmarkSnapSummary(mesh, arguments.landmarks[i]));
  }
  return read;
}

// Prints row r of the validator's table (mesh `name`): its statistics, the
// snapped landmarks and every defect; returns whether the mesh is valid.
bool printMesh(vtkTable* table, vtkIdType r, const std::string& name, const std::string& snapped)
{
  auto value = [&](const char* column) { return table->GetValueByName(r, column); };
  const bool valid = value("Valid").ToInt() != 0;
  std::cout << name << ": " << (valid ? "valid" : "INVALID") << "\n";
  std::cout << "  vertices " << value("Points").ToString() << ", faces "
            << value("Triangles").ToString() << ", edges " << value("Edges").ToString()
            << ", genus " << value("Genus").ToString() << ", components "
            << value("Components").ToString() << ", boundary edges "
            << value("BoundaryEdges").ToString() << "\n";
  std::cout << "  area " << format(value("Area").ToDouble()) << ", bbox diagonal "
            << format(value("BoundingBoxDiagonal").ToDouble()) << ", min angle "
            << format(value("MinAngle").ToDouble()) << " deg (mean of per-triangle minima "
            << format(value("MeanMinAngle").ToDouble()) << "), landmarks "
            << value("Landmarks").ToString() << "\n";
  if (!snapped.empty())
  {
    std::cout << "  " << snapped << "\n";
  }
  std::istringstream lines(value("Defects").ToString());
  for (std::string line; std::getline(lines, line);)
  {
    printError(name + " " + line);
  }
  return valid;
}

} // namespace

int runCheck(const std::vector<std::string>& args)
{
  const CheckArguments arguments = parseArguments(args);
  bool ok = true;
  vtkNew<vtkSurfaceMeshValidator> validator;
  validator->SetCheckLandmarkCorrespondence(arguments.correspondence);
  const ReadMeshes read = readMeshes(arguments, validator, ok);
  if (!read.names.empty())
  {
    validator->Update();
    vtkTable* table = validator->GetOutput();
    for (vtkIdType r = 0; r < table->GetNumberOfRows(); ++r)
    {
      const bool valid = printMesh(table, r, read.names[r], read.snapped[r]);
      ok = ok && valid;
    }
  }
  return ok ? ExitOk : ExitBadInput;
}

} // namespace surfacemap
