// The command line: a map directory (the output of `surfacemap map`) as one
// consistent set of files.
//
// report.json is written last and holds the map's id and, per file of the
// map, its size and MD5 checksum; each file also carries the map id and its
// own name in its field data (MapId, MapFile: the text's bytes in unsigned
// char arrays). Readers of a map directory
// (`evaluate`, `transfer`) verify every file they use against report.json,
// so a missing, stale (from another map), swapped or modified file is
// refused by name, and a directory whose writing was interrupted (no
// report.json yet) is no map at all.
#pragma once

#include "vtkSmartPointer.h"

#include <string>
#include <vector>

class vtkPolyData;

namespace surfacemap
{

/// Writes the files of one map into a directory and records them.
class MapWriter
{
public:
  /// A fresh random map id for the files written into `directory`.
  explicit MapWriter(std::string directory);

  /// Writes `data` as `directory/name` (checked, atomic), stamped with the
  /// map id and its name, and records its size and checksum as written.
  /// Throws std::runtime_error naming the file on failure.
  void write(vtkPolyData* data, const std::string& name);

  /// report.json's members "map_id" and "files" (JSON, each line indented,
  /// no trailing comma).
  std::string reportJson() const;

private:
  std::string Directory;
  std::string Id;
  std::vector<std::string> Records;
};

/// True for a name like a map file's: common_<i>.vtp, mapped_<i>.vtp,
/// embedding_<i>.vtp.
bool isMapFileName(const std::string& name);

/// True if `directory` holds report.json or a file named like a map's
/// (common_<i>.vtp, mapped_<i>.vtp, embedding_<i>.vtp).
bool holdsMap(const std::string& directory);

/// Removes an earlier map from `directory`: report.json first, so that no
/// reader takes what remains for a map, then every map file. Throws
/// std::runtime_error naming a file that cannot be removed.
void removeMap(const std::string& directory);

/// Checks the files `names` of the map in `directory` against its
/// report.json: listed there, present, of the recorded size and checksum.
/// Throws std::runtime_error naming the first file that is missing, belongs
/// to another map, is another file of this map (swapped, renamed) or was
/// changed.
void verifyMapFiles(const std::string& directory, const std::vector<std::string>& names);

} // namespace surfacemap
