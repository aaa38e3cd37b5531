#include "vtkSurfaceMeshReader.h"

#include "vtkSurfaceMapsConversion.h"
#include "vtkSurfaceMapsErrorGuard.h"
#include "vtkSurfaceMapsExecutive.h"
#include "vtkSurfaceMapsMarkups.h"

#include "base/Error.h"
#include "io/LandmarkReader.h"
#include "io/LegacyVtkCheck.h"
#include "io/ObjReader.h"
#include "io/OffReader.h"
#include "io/PlyReader.h"
#include "io/SizingReader.h"
#include "io/TextFile.h"
#include "io/XmlPolyDataCheck.h"

#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkDoubleArray.h"
#include "vtkExecutive.h"
#include "vtkFieldData.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOutputWindow.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkPolyDataReader.h"
#include "vtkSTLReader.h"
#include "vtkSmartPointer.h"
#include "vtkStaticPointLocator.h"
#include "vtkStringArray.h"
#include "vtkXMLPolyDataReader.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <limits>
#include <memory>
#include <new>
#include <sstream>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkSurfaceMeshReader);

namespace
{

std::string extensionOf(const std::string& path)
{
  const std::size_t dot = path.find_last_of('.');
  const std::size_t slash = path.find_last_of("/\\");
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash))
  {
    return {};
  }
  std::string ext = path.substr(dot + 1);
  std::transform(ext.begin(),
    ext.end(),
    ext.begin(),
    [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

// Collects the error messages a VTK reader emits, without its source-location prefix.
struct ErrorCollector
{
  std::string Message;
  bool PipelineFailed = false;

  static void Callback(vtkObject*, unsigned long, void* clientData, void* callData)
  {
    auto* self = static_cast<ErrorCollector*>(clientData);
    std::string text = callData ? static_cast<const char*>(callData) : "unknown error";
    // vtkErrorMacro text: "ERROR: In file, line N\nClass (0x..): message"
    const std::size_t marker = text.find("): ");
    if (marker != std::string::npos)
    {
      text = text.substr(marker + 3);
    }
    while (!text.empty() && (text.back() == '\n' || text.back() == ' '))
    {
      text.pop_back();
    }
    // The executive's "Algorithm X returned failure" repeats what the reader
    // already said (or says nothing useful); keep the reader's own words.
    if (text.rfind("Algorithm ", 0) == 0)
    {
      self->PipelineFailed = true;
    }
    else if (self->Message.empty())
    {
      self->Message = text;
    }
  }
};

// Some of VTK's readers report a premature end of data only as a generic
// warning (not through the reader object); this output window, installed for
// the duration of one read, catches those.
class CapturingOutputWindow : public vtkOutputWindow
{
public:
  static CapturingOutputWindow* New();
  vtkTypeMacro(CapturingOutputWindow, vtkOutputWindow);
  void DisplayText(const char*) override {}
  void DisplayGenericWarningText(const char* text) override
  {
    if (this->Message.empty() && text)
    {
      // Drop the "Generic Warning: In file, line N" source location.
      this->Message = text;
      const std::size_t newline = this->Message.find('\n');
      if (this->Message.rfind("Generic Warning", 0) == 0 && newline != std::string::npos)
      {
        this->Message = this->Message.substr(newline + 1);
      }
    }
  }
  std::string Message;
};
vtkStandardNewMacro(CapturingOutputWindow);

class ScopedOutputWindow
{
public:
  ScopedOutputWindow()
    : Previous(vtkOutputWindow::GetInstance())
  {
    vtkOutputWindow::SetInstance(this->Window);
  }
  ~ScopedOutputWindow() { vtkOutputWindow::SetInstance(this->Previous); }
  const std::string& Message() const { return this->Window->Message; }

private:
  vtkSmartPointer<vtkOutputWindow> Previous;
  vtkNew<CapturingOutputWindow> Window;
};

// Reads with one of VTK's readers; throws InputError when it reports an error.
vtkSmartPointer<vtkPolyData> readWithVTK(vtkAlgorithm* reader, const std::string& path)
{
  ScopedOutputWindow genericWarnings;
  ErrorCollector errors;
  auto observer = vtkSmartPointer<vtkCallbackCommand>::New();
  observer->SetCallback(&ErrorCollector::Callback);
  observer->SetClientData(&errors);
  reader->AddObserver(vtkCommand::ErrorEvent, observer);
  reader->AddObserver(vtkCommand::WarningEvent, observer);
  reader->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, observer);
  reader->Update();
  if (errors.Message.empty() && !genericWarnings.Message().empty())
  {
    errors.Message = genericWarnings.Message();
    const std::size_t end = errors.Message.find_last_not_of("\n ");
    errors.Message.resize(end == std::string::npos ? 0 : end + 1);
  }
  if (errors.PipelineFailed || !errors.Message.empty())
  {
    throw surfacemaps::InputError(
      path + ": " + (errors.Message.empty() ? "the reader failed" : errors.Message));
  }
  auto output = vtkSmartPointer<vtkPolyData>::New();
  output->ShallowCopy(vtkPolyData::SafeDownCast(reader->GetOutputDataObject(0)));
  return output;
}

// A binary STL (every STL that does not start with "solid") is an 80-byte
// header, a little-endian triangle count and 50 bytes per triangle: a file
// of another size is truncated or corrupt, which VTK's reader would turn into
// a mesh with holes (or read past).
void checkBinaryStlSize(const std::string& bytes, const std::string& path)
{
  if (bytes.compare(0, 5, "solid") == 0)
  {
    return;
  }
  if (bytes.size() < 84)
  {
    throw surfacemaps::InputError(path + ": a binary STL file of " + std::to_string(bytes.size()) +
      " bytes, shorter than its 84-byte header; it is truncated");
  }
  unsigned long long triangles = 0;
  for (int k = 3; k >= 0; --k)
  {
    triangles = (triangles << 8) | static_cast<unsigned char>(bytes[80 + k]);
  }
  if (84 + 50 * triangles != bytes.size())
  {
    throw surfacemaps::InputError(path + ": the binary STL header declares " +
      std::to_string(triangles) + " triangles (" + std::to_string(84 + 50 * triangles) +
      " bytes), but the file has " + std::to_string(bytes.size()) +
      " bytes; it is truncated or corrupt");
  }
}

vtkSmartPointer<vtkPolyData> readMesh(const std::string& path)
{
  // Check the file up front so every format gets the same clear message.
  surfacemaps::requireRegularFile(path);
  {
    std::ifstream probe(path, std::ios::binary);
    if (!probe)
    {
      throw surfacemaps::InputError("cannot open '" + path + "': " + std::strerror(errno));
    }
    if (probe.peek() == std::ifstream::traits_type::eof())
    {
      throw surfacemaps::InputError(path + ": the file is empty");
    }
  }

  const std::string ext = extensionOf(path);
  if (ext == "obj")
  {
    const surfacemaps::PolygonMesh mesh = surfacemaps::readObj(path);
    // Refused as a VTP or VTK file with lines or vertices is (the validation):
    // dropping them would hand on another object than the file holds.
    if (mesh.nonPolygonCells > 0)
    {
      throw surfacemaps::InputError(path + ": " + std::to_string(mesh.nonPolygonCells) +
        " line or point element" + (mesh.nonPolygonCells == 1 ? "" : "s") +
        " ('l', 'p'); only triangles ('f') are accepted: remove those lines");
    }
    return vtkSurfaceMapsConversion::ToPolyData(mesh);
  }
  if (ext == "off")
  {
    return vtkSurfaceMapsConversion::ToPolyData(surfacemaps::readOff(path));
  }
  if (ext == "ply")
  {
    return vtkSurfaceMapsConversion::ToPolyData(surfacemaps::readPly(path));
  }
  if (ext == "stl")
  {
    checkBinaryStlSize(surfacemaps::readTextFile(path), path);
    auto reader = vtkSmartPointer<vtkSTLReader>::New();
    reader->SetFileName(path.c_str());
    reader->MergingOn(); // STL repeats every vertex per triangle
    return readWithVTK(reader, path);
  }
  if (ext == "vtp")
  {
    auto reader = vtkSmartPointer<vtkXMLPolyDataReader>::New();
    if (!reader->CanReadFile(path.c_str()))
    {
      throw surfacemaps::InputError(path + ": not a VTK XML PolyData (.vtp) file");
    }
    // VTK's XML reader allocates by the counts and follows the offsets it
    // finds: it reads only checked bytes, without String arrays.
    const std::string bytes = surfacemaps::readTextFile(path);
    surfacemaps::checkXmlPolyDataCounts(bytes, path);
    reader->ReadFromInputStringOn();
    reader->SetInputString(surfacemaps::withoutStringArrays(bytes));
    return readWithVTK(reader, path);
  }
  if (ext == "vtk")
  {
    // VTK's legacy reader trusts the file's counts and indices (it crashes
    // on an index past 2^32): nothing reaches it unchecked.
    surfacemaps::checkLegacyVtkPolyData(surfacemaps::readTextFile(path), path);
    auto reader = vtkSmartPointer<vtkPolyDataReader>::New();
    reader->SetFileName(path.c_str());
    if (!reader->IsFilePolyData())
    {
      throw surfacemaps::InputError(path + ": not a legacy VTK POLYDATA file");
    }
    return readWithVTK(reader, path);
  }
  throw surfacemaps::InputError(
    path + ": unknown mesh format '" + ext + "' (supported: .obj .off .ply .stl .vtp .vtk)");
}

bool isMarkupsJson(const std::string& path)
{
  const std::string ext = extensionOf(path);
  return ext == "json";
}

// Landmarks given as points become the vertex closest to them; returns, per
// such landmark, its id, vertex and distance (input units) and warns when one
// is farther than 1 % of the bounding-box diagonal.
void snapLandmarkPoints(vtkSurfaceMeshReader* self,
  vtkPolyData* mesh,
  std::vector<surfacemaps::LandmarkRecord>& records,
  const std::string& landmarkPath,
  const std::string& meshPath)
{
  if (std::all_of(records.begin(),
        records.end(),
        [](const surfacemaps::LandmarkRecord& r) { return r.Vertex >= 0; }))
  {
    return;
  }
  vtkNew<vtkStaticPointLocator> locator;
  locator->SetDataSet(mesh);
  locator->BuildLocator();
  const double diagonal = mesh->GetLength();
  auto ids = vtkSmartPointer<vtkIntArray>::New();
  ids->SetName("LandmarkSnapId");
  auto vertices = vtkSmartPointer<vtkIdTypeArray>::New();
  vertices->SetName("LandmarkSnapVertex");
  auto distances = vtkSmartPointer<vtkDoubleArray>::New();
  distances->SetName("LandmarkSnapDistance");
  for (surfacemaps::LandmarkRecord& record : records)
  {
    if (record.Vertex >= 0)
    {
      continue;
    }
    vtkIdType closest = locator->FindClosestPoint(record.Point.data());
    double p[3];
    if (closest < 0)
    {
      // The locator gives up on points far outside its bins (coordinates
      // near the double range): look at every vertex.
      double best = std::numeric_limits<double>::infinity();
      for (vtkIdType v = 0; v < mesh->GetNumberOfPoints(); ++v)
      {
        mesh->GetPoint(v, p);
        const double d2 = vtkMath::Distance2BetweenPoints(p, record.Point.data());
        if (d2 < best)
        {
          best = d2;
          closest = v;
        }
      }
    }
    double distance = std::numeric_limits<double>::infinity();
    if (closest >= 0)
    {
      mesh->GetPoint(closest, p);
      distance = std::sqrt(vtkMath::Distance2BetweenPoints(p, record.Point.data()));
    }
    if (!std::isfinite(distance))
    {
      std::ostringstream point;
      point << "(" << record.Point[0] << ", " << record.Point[1] << ", " << record.Point[2] << ")";
      surfacemaps::failAtLine(landmarkPath,
        record.Line,
        "landmark " + std::to_string(record.Id) + " at " + point.str() +
          " is too far from every vertex of " + meshPath + " to snap to one");
    }
    record.Vertex = static_cast<int>(closest);
    ids->InsertNextValue(record.Id);
    vertices->InsertNextValue(closest);
    distances->InsertNextValue(distance);
    if (distance > 0.01 * diagonal)
    {
      std::ostringstream message;
      message << landmarkPath << ":" << record.Line << ": landmark " << record.Id
              << (record.Label.empty() ? "" : " (" + record.Label + ")") << " lies " << distance
              << " from the closest vertex (" << closest << ") of " << meshPath << ", "
              << 100.0 * distance / diagonal
              << " % of its bounding-box diagonal (more than 1 %): is the point in the mesh's "
                 "coordinates?";
      vtkWarningWithObjectMacro(self, << message.str());
    }
  }
  mesh->GetFieldData()->AddArray(ids);
  mesh->GetFieldData()->AddArray(vertices);
  mesh->GetFieldData()->AddArray(distances);
}

// The "Landmarks" point array (id per vertex, -1 elsewhere) from a landmark
// file: vertex indices, or points snapped to the closest vertex.
void addLandmarks(vtkSurfaceMeshReader* self,
  vtkPolyData* mesh,
  const std::string& landmarkPath,
  const std::string& meshPath)
{
  std::vector<surfacemaps::LandmarkRecord> records;
  if (isMarkupsJson(landmarkPath))
  {
    records = vtkSurfaceMapsMarkups::parse(surfacemaps::readTextFile(landmarkPath), landmarkPath);
    if (records.empty())
    {
      throw surfacemaps::InputError(landmarkPath + ": the landmark file lists no landmarks");
    }
  }
  else
  {
    records = surfacemaps::readLandmarkRecords(landmarkPath);
  }
  snapLandmarkPoints(self, mesh, records, landmarkPath, meshPath);
  std::vector<int> ids;
  try
  {
    ids = surfacemaps::landmarkIdsFromRecords(
      records, static_cast<std::size_t>(mesh->GetNumberOfPoints()), landmarkPath);
  }
  catch (const surfacemaps::InputError& e)
  {
    throw surfacemaps::InputError(std::string(e.what()) + " (landmarks of " + meshPath + ")");
  }
  auto landmarks = vtkSmartPointer<vtkIntArray>::New();
  landmarks->SetName("Landmarks");
  landmarks->SetNumberOfValues(static_cast<vtkIdType>(ids.size()));
  for (std::size_t i = 0; i < ids.size(); ++i)
  {
    landmarks->SetValue(static_cast<vtkIdType>(i), ids[i]);
  }
  mesh->GetPointData()->AddArray(landmarks);
}

// The "Sizing" point array from a sizing file.
void addSizing(vtkPolyData* mesh, const std::string& sizingPath, const std::string& meshPath)
{
  std::vector<double> sizing;
  try
  {
    sizing =
      surfacemaps::readSizing(sizingPath, static_cast<std::size_t>(mesh->GetNumberOfPoints()));
  }
  catch (const surfacemaps::InputError& e)
  {
    throw surfacemaps::InputError(std::string(e.what()) + " (sizing of " + meshPath + ")");
  }
  auto array = vtkSmartPointer<vtkDoubleArray>::New();
  array->SetName("Sizing");
  array->SetNumberOfValues(static_cast<vtkIdType>(sizing.size()));
  for (std::size_t i = 0; i < sizing.size(); ++i)
  {
    array->SetValue(static_cast<vtkIdType>(i), sizing[i]);
  }
  mesh->GetPointData()->AddArray(array);
}

// The "FileName" field-data string that names the mesh in messages.
void addFileName(vtkPolyData* mesh, const std::string& path)
{
  auto name = vtkSmartPointer<vtkStringArray>::New();
  name->SetName("FileName");
  name->InsertNextValue(path);
  mesh->GetFieldData()->AddArray(name);
}

} // namespace

vtkSurfaceMeshReader::vtkSurfaceMeshReader()
{
  this->SetNumberOfInputPorts(0);
}

vtkSurfaceMeshReader::~vtkSurfaceMeshReader()
{
  this->SetFileName(nullptr);
  this->SetLandmarkFileName(nullptr);
  this->SetSizingFileName(nullptr);
}

bool vtkSurfaceMeshReader::CanReadFile(const char* fileName)
{
  if (!fileName)
  {
    return false;
  }
  const std::string ext = extensionOf(fileName);
  return ext == "obj" || ext == "off" || ext == "ply" || ext == "stl" || ext == "vtp" ||
    ext == "vtk";
}

const char* vtkSurfaceMeshReader::GetLastErrorMessage() const
{
  return vtkSurfaceMapsErrorGuard::LastErrorMessage(this);
}

vtkExecutive* vtkSurfaceMeshReader::CreateDefaultExecutive()
{
  return vtkSurfaceMapsExecutive::New();
}

int vtkSurfaceMeshReader::RequestData(vtkInformation*,
  vtkInformationVector**,
  vtkInformationVector* outputVector)
{
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  return vtkSurfaceMapsErrorGuard::Run(
    this,
    vtkSurfaceMapsErrorGuard::Policy(),
    [&]
    {
      if (!this->FileName || !*this->FileName)
      {
        throw surfacemaps::InputError("no file name given");
      }
      const std::string path = this->FileName;
      vtkSmartPointer<vtkPolyData> mesh;
      try
      {
        mesh = readMesh(path);
      }
      catch (const std::bad_alloc&)
      {
        // Counts are checked against the file size before allocating, so
        // this is a file larger than memory, named rather than "bad_alloc".
        throw surfacemaps::InputError(path + ": not enough memory to read it");
      }
      if (this->LandmarkFileName && *this->LandmarkFileName)
      {
        addLandmarks(this, mesh, this->LandmarkFileName, path);
      }
      if (this->SizingFileName && *this->SizingFileName)
      {
        addSizing(mesh, this->SizingFileName, path);
      }
      addFileName(mesh, path);
      output->ShallowCopy(mesh);
      return 1;
    },
    [output] { output->Initialize(); });
}

void vtkSurfaceMeshReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
  os << indent
     << "LandmarkFileName: " << (this->LandmarkFileName ? this->LandmarkFileName : "(none)")
     << "\n";
  os << indent << "SizingFileName: " << (this->SizingFileName ? this->SizingFileName : "(none)")
     << "\n";
}
