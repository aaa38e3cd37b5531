// The `surfacemap` command line: reading meshes with their landmark and
// sizing files, reporting snapped landmarks, writing meshes atomically.
#include "MeshFiles.h"

#include "AlgorithmMessages.h"
#include "AtomicFiles.h"
#include "Commands.h"
#include "Json.h"
#include "ObjWriter.h"
#include "Terminal.h"

#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkSurfaceMeshReader.h"
#include "vtkSurfaceMeshValidator.h"
#include "vtkTable.h"
#include "vtkVariant.h"
#include "vtkXMLPolyDataWriter.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <iomanip>
#include <sstream>
#include <system_error>

namespace surfacemap
{

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
  "                     id,x,y,z,...)\n"
  "  .mrk.json          3D Slicer markups JSON: markups[0].controlPoints, each\n"
  "                     with a position (and optional id and label)\n"
  "                     Slicer ids: integers (0 to 2147483647) on every point\n"
  "                     are the ids; node names (vtkMRMLMarkups...) on every\n"
  "                     point mean the file order; a mix, or another number,\n"
  "                     is refused\n"
  "A point becomes the closest vertex of its mesh; the snap distance is\n"
  "printed (and recorded in report.json by 'map'), with a warning when it\n"
  "exceeds 1 % of the mesh's bounding-box diagonal. Points are read in the\n"
  "mesh's own coordinates, as written (no RAS/LPS conversion). A malformed file\n"
  "is rejected naming the file and line (exit code 2).\n";

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
  line << "landmarks of " << landmarks << ": " << distances->GetNumberOfTuples() << " point"
       << (distances->GetNumberOfTuples() == 1 ? "" : "s")
       << " snapped to the closest vertex, largest snap distance " << std::setprecision(4)
       << largest << " (" << (diagonal > 0.0 ? 100.0 * largest / diagonal : 0.0)
       << " % of the bounding-box diagonal)";
  return line.str();
}

Json::Value landmarkSnapJson(vtkPolyData* mesh)
{
  vtkFieldData* fd = mesh->GetFieldData();
  vtkDataArray* ids = fd->GetArray("LandmarkSnapId");
  vtkDataArray* vertices = fd->GetArray("LandmarkSnapVertex");
  vtkDataArray* distances = fd->GetArray("LandmarkSnapDistance");
  if (!ids || !vertices || !distances || distances->GetNumberOfTuples() == 0)
  {
    return Json::Value(Json::nullValue);
  }
  const double diagonal = mesh->GetLength();
  Json::Value snapped(Json::arrayValue);
  for (vtkIdType k = 0; k < distances->GetNumberOfTuples(); ++k)
  {
    const double d = distances->GetTuple1(k);
    Json::Value landmark(Json::objectValue);
    landmark["id"] = static_cast<Json::Int64>(ids->GetTuple1(k));
    landmark["vertex"] = static_cast<Json::Int64>(vertices->GetTuple1(k));
    landmark["distance"] = jsonNumber(d);
    landmark["percent_of_diagonal"] = jsonNumber(diagonal > 0.0 ? 100.0 * d / diagonal : 0.0);
    snapped.append(landmark);
  }
  return snapped;
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

bool isFile(const std::string& path)
{
  std::error_code ec;
  return std::filesystem::is_regular_file(path, ec);
}

std::string polyDataFileBytes(vtkPolyData* data, const std::string& path)
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
  return writer->GetOutputString();
}

void writePolyDataAtomically(vtkPolyData* data, const std::string& path)
{
  writeFileAtomically(path, polyDataFileBytes(data, path));
}

void writeMeshAtomically(vtkPolyData* data, const std::string& path)
{
  std::string extension = std::filesystem::path(path).extension().string();
  std::transform(extension.begin(),
    extension.end(),
    extension.begin(),
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

} // namespace surfacemap
