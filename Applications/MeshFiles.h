// The `surfacemap` command line: mesh files read (with landmark and sizing
// files, validated on request) and written (VTK XML or OBJ, atomically).
#pragma once

#include "vtkSmartPointer.h"

#include <string>

class vtkPolyData;
namespace Json
{
class Value;
}

namespace surfacemap
{

/// The landmark file formats, for the help of every command with --landmarks
/// (indented by 2, lines of at most 78 characters).
extern const char* const LandmarkFormatsHelp;

/// Reads a mesh with vtkSurfaceMeshReader; on failure prints the reason and
/// returns null. Landmarks given as points: the reader's warnings (a point
/// far from every vertex) go to stderr and landmarkSnapSummary to stdout.
/// `sizing` names a sizing file (vtkSurfaceMeshReader::SetSizingFileName).
vtkSmartPointer<vtkPolyData> readMesh(const std::string& path,
  const std::string& landmarks = "",
  const std::string& sizing = "");

/// Reads a mesh (and optional landmark file) with vtkSurfaceMeshReader and
/// validates it; on failure prints the reasons and returns null.
vtkSmartPointer<vtkPolyData> readValidMesh(const std::string& path, const std::string& landmarks);

/// One line on the landmarks of `mesh` (read by vtkSurfaceMeshReader from
/// `landmarks`) that were given as points and snapped to vertices: how many,
/// the largest snap distance, absolute and in % of the bounding-box diagonal;
/// empty when none was a point.
std::string landmarkSnapSummary(vtkPolyData* mesh, const std::string& landmarks);

/// The snapped landmarks of `mesh` as a JSON list of { id, vertex, distance,
/// percent_of_diagonal }, null when none was a point.
Json::Value landmarkSnapJson(vtkPolyData* mesh);

/// True if `path` is a regular file (false on any error).
bool isFile(const std::string& path);

/// `data` as the bytes of a VTK XML PolyData file (appended raw, zlib), as
/// writePolyDataAtomically writes them. Throws std::runtime_error naming
/// `path` when the XML writer fails.
std::string polyDataFileBytes(vtkPolyData* data, const std::string& path);

/// Writes VTK XML PolyData (also checking the writer's own error code)
/// through writeFileAtomically, so a failed or interrupted write never leaves
/// a half-written file. Throws std::runtime_error naming the file on failure.
void writePolyDataAtomically(vtkPolyData* data, const std::string& path);

/// writeObjAtomically (ObjWriter.h) for a path ending in .obj (any case),
/// else writePolyDataAtomically.
void writeMeshAtomically(vtkPolyData* data, const std::string& path);

} // namespace surfacemap
