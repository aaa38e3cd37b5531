// SurfaceMaps engine: landmark (vertex correspondence) files.
#pragma once

#include <array>
#include <string>
#include <vector>

namespace surfacemaps
{

/// One landmark as a file gives it: a vertex index, or a point for the caller
/// to snap to the closest vertex of its mesh.
struct LandmarkRecord
{
  /// Landmark id: the position in the file, or the id the file gives.
  int Id = -1;
  /// 0-based vertex index; -1 when the landmark is a point.
  int Vertex = -1;
  /// The point (when Vertex is -1), in the mesh's coordinates.
  std::array<double, 3> Point{ { 0.0, 0.0, 0.0 } };
  /// The file's label for it (Slicer markups), empty if none; for messages.
  std::string Label;
  /// 1-based line of the file it comes from, for messages.
  int Line = 0;
};

/// Parses a landmark file by the extension of `name` (case-insensitive):
/// - `.fcsv` (3D Slicer markups CSV): '#' comment lines (a `# columns = ...`
///   line names the columns; default id,x,y,z,...), one point per line;
/// - `.csv`: `x,y,z[,id]` per line, optionally after a header line naming the
///   columns (x, y, z, id, label);
/// - anything else (`.pinned`, `.txt`, `.vts`): whitespace-separated lines,
///   `index` or `lk index` (a vertex), `index x y z` (SHREC `.vts`: the
///   vertex; the coordinates are ignored), or `x y z` / `-1 x y z` (a point:
///   the index is missing). Blank lines and `#` comments are skipped.
/// `.mrk.json` (Slicer markups JSON) is read by the VTK layer, which has a
/// JSON parser; it calls finishLandmarkIds like the parsers here.
/// Ids follow the file order unless the file gives them (see
/// finishLandmarkIds; Slicer ids: markupLandmarkId). Throws InputError "name:line: defect".
std::vector<LandmarkRecord> parseLandmarkRecords(const std::string& text, const std::string& name);

/// Reads and parses a landmark file (parseLandmarkRecords); throws InputError
/// naming the file when it cannot be read or lists no landmarks.
std::vector<LandmarkRecord> readLandmarkRecords(const std::string& path);

/// Sets the ids of records read in file order: `givenIds[k]` is the id the
/// file gives record k (-1 if none). When every record has one, those are the
/// ids; when none has (no id column, or Slicer node names), the k-th record
/// gets id k. A file that gives ids to some records only is refused: it
/// cannot be told which points the others correspond to. `idTexts[k]`, when
/// given, is the file's text of record k's id, for that message. Throws
/// InputError "name:line: ..." for that and for an id given twice.
void finishLandmarkIds(std::vector<LandmarkRecord>& records,
  const std::vector<long long>& givenIds,
  const std::string& name,
  const std::vector<std::string>& idTexts = {});

/// The id a 3D Slicer markups file gives a point, from its text (the `.fcsv`
/// id column, the `.mrk.json` "id"): an integer from 0 to INT_MAX is the id;
/// text that is no number (a node name such as vtkMRMLMarkupsFiducialNode_0,
/// or nothing) gives none (-1). Any other number is refused: InputError
/// "name:line: `what` has the id 'text', ..." (a negative, fractional or
/// too large id is a mistake, not a name).
long long markupLandmarkId(const std::string& text,
  const std::string& what,
  const std::string& name,
  int line);

/// Reads a landmark file of vertex indices only (any whitespace format of
/// parseLandmarkRecords); the k-th index carries landmark id k. Throws
/// InputError "path:line: defect", also for a landmark given as a point.
std::vector<int> readLandmarks(const std::string& path);

/// Same, from text already in memory; `name` is used in messages.
std::vector<int> parseLandmarks(const std::string& text, const std::string& name);

/// Per-vertex landmark ids (-1 none) from a list of vertex indices (id = position
/// in the list). Throws InputError naming `name` when an index is out of range
/// or a vertex is listed twice.
std::vector<int> landmarkIdsFromIndices(const std::vector<int>& indices,
  std::size_t numberOfVertices,
  const std::string& name);

/// Per-vertex landmark ids (-1 none) from records whose Vertex is set (points
/// already snapped). Throws InputError naming `name` and the line when a
/// vertex is out of range or carries two landmarks.
std::vector<int> landmarkIdsFromRecords(const std::vector<LandmarkRecord>& records,
  std::size_t numberOfVertices,
  const std::string& name);

} // namespace surfacemaps
