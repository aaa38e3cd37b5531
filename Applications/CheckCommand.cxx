// surfacemap check: validate meshes as inputs and print their statistics.
#include "CommandSupport.h"
#include "Commands.h"

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
const std::string CheckHelpText = std::string(
  "usage: surfacemap check MESH... [--landmarks FILE...]\n"
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
  "Exit code 0 only if every mesh is valid; 2 otherwise.\n") + LandmarkFormatsHelp;
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

} // namespace

int runCheck(const std::vector<std::string>& args)
{
  std::vector<std::string> meshes, landmarks;
  bool inLandmarks = false;
  for (const std::string& a : args)
  {
    if (a == "--landmarks")
    {
      inLandmarks = true;
    }
    else if (isOption(a))
    {
      unknownOption(a);
    }
    else
    {
      (inLandmarks ? landmarks : meshes).push_back(a);
    }
  }
  if (meshes.empty())
  {
    throw UsageError{ landmarks.empty()
        ? "no mesh given"
        : "no mesh given (the meshes come before --landmarks: check A B --landmarks FA FB)" };
  }
  if (inLandmarks && landmarks.size() != meshes.size())
  {
    throw UsageError{ "--landmarks needs one file per mesh (" + std::to_string(meshes.size()) +
      " meshes, " + std::to_string(landmarks.size()) + " landmark files)" };
  }

  bool ok = true;
  vtkNew<vtkSurfaceMeshValidator> validator;
  validator->SetCheckLandmarkCorrespondence(inLandmarks);
  std::vector<std::string> names, snapped;
  for (std::size_t i = 0; i < meshes.size(); ++i)
  {
    vtkNew<vtkSurfaceMeshReader> reader;
    ignoreErrors(reader);
    ErrorCapture warnings(reader, vtkCommand::WarningEvent);
    reader->SetFileName(meshes[i].c_str());
    if (!landmarks.empty())
    {
      reader->SetLandmarkFileName(landmarks[i].c_str());
    }
    reader->Update();
    if (*reader->GetLastErrorMessage())
    {
      printError(reader->GetLastErrorMessage());
      std::cout << meshes[i] << ": UNREADABLE\n";
      ok = false;
      continue;
    }
    vtkSmartPointer<vtkPolyData> mesh = reader->GetOutput();
    for (const std::string& warning : warnings.messages())
    {
      printWarning(warning);
    }
    validator->AddInputDataObject(mesh);
    names.push_back(meshes[i]);
    snapped.push_back(landmarks.empty() ? "" : landmarkSnapSummary(mesh, landmarks[i]));
  }

  if (!names.empty())
  {
    validator->Update();
    vtkTable* table = validator->GetOutput();
    for (vtkIdType r = 0; r < table->GetNumberOfRows(); ++r)
    {
      auto value = [&](const char* column) { return table->GetValueByName(r, column); };
      const bool valid = value("Valid").ToInt() != 0;
      std::cout << names[r] << ": " << (valid ? "valid" : "INVALID") << "\n";
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
      if (!snapped[r].empty())
      {
        std::cout << "  " << snapped[r] << "\n";
      }
      const std::string defects = value("Defects").ToString();
      std::istringstream lines(defects);
      for (std::string line; std::getline(lines, line);)
      {
        printError(names[r] + " " + line);
      }
      ok = ok && valid;
    }
  }
  return ok ? ExitOk : ExitBadInput;
}

} // namespace surfacemap
