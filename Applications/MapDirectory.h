// The command line: a map directory (the output of `surfacemap map`) as one
// consistent set of files.
//
// report.json is written last and holds the map's id and, per file of the
// map, its size and MD5 checksum; each file also carries the map id and its
// own name in its field data (MapId, MapFile: the text's bytes in unsigned
// char arrays). Readers of a map directory
// (`evaluate`, `transfer`, `statistics`) verify every file they use against report.json,
// so a missing, stale (from another map), swapped or modified file is
// refused by name, and a directory whose writing was interrupted (no
// report.json yet) is no map at all.
#pragma once

#include "Json.h"

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
  /// map id and its name, and records the size and checksum of the bytes it
  /// wrote (never read back: the name may be another writer's file by then).
  /// Throws std::runtime_error naming the file on failure.
  void write(vtkPolyData* data, const std::string& name);

  /// Writes `bytes` as `directory/name` (checked, atomic) and records them as
  /// `write` does: for the map's files that are no meshes (fit.csv,
  /// correspondences.npz), which carry no stamp.
  void writeBytes(const std::string& bytes, const std::string& name);

  /// Sets report.json's members "map_id" and "files" (per file written: name,
  /// bytes, md5) in `report`.
  void addToReport(Json::Value& report) const;

  /// The names written so far, in order.
  const std::vector<std::string>& names() const { return this->Names; }

private:
  std::string Directory;
  std::string Id;
  std::vector<std::string> Names;
  Json::Value Records{ Json::arrayValue };
};

/// The name of an output file of 'surfacemap map' for input i:
/// <stem>_<i>.vtp (stem common, mapped or embedding).
std::string mapFileName(const char* stem, int i);

/// True for a name like a map file's: common_<i>.vtp, mapped_<i>.vtp,
/// embedding_<i>.vtp, fit.csv, correspondences.npz.
bool isMapFileName(const std::string& name);

/// The input files a map directory's report.json (`report`) names, in
/// order. Throws std::runtime_error naming the file and what is wrong with it
/// (missing, not JSON, no inputs).
std::vector<std::string> mapReportInputs(const std::string& report);

/// What a directory holds of a map.
enum class MapState
{
  /// Neither report.json nor a file named like a map's.
  None,
  /// Files named like a map's (common_<i>.vtp, mapped_<i>.vtp,
  /// embedding_<i>.vtp) but no report.json: a run that did not finish.
  Interrupted,
  /// report.json (checked by verifyMapFiles when read).
  Complete
};
MapState mapState(const std::string& directory);

/// "<directory> holds an interrupted run (common_/mapped_/embedding_ files,
/// no report.json): give --overwrite or remove it", for every command that
/// meets one.
std::string interruptedRunMessage(const std::string& directory);

/// The number of inputs the map in `directory` has (report.json's
/// "inputs"). Throws std::runtime_error naming report.json (missing, an
/// interrupted run, not JSON, no inputs).
int mapInputCount(const std::string& directory);

/// Removes an earlier map from `directory`: report.json first, so that no
/// reader takes what remains for a map, then every map file. Throws
/// std::runtime_error naming a file that cannot be removed.
void removeMap(const std::string& directory);

/// Checks the files `names` of the map in `directory` against its
/// report.json: listed there, present, of the recorded size and checksum.
/// Throws std::runtime_error naming the first file that is missing, belongs
/// to another map, is another file of this map (swapped, renamed) or was
/// changed, or the directory when it holds no report.json (an interrupted
/// run: interruptedRunMessage). Each common_<j> among `names` is checked
/// together with its embedding_<j> (listed, present, checksum) and then by
/// checkMapGeometry (MapConsistency.h): one triangulation, and embeddings that
/// agree with it. Every reader of a map directory (evaluate, transfer,
/// statistics) and `map` itself before publishing go through it.
void verifyMapFiles(const std::string& directory, const std::vector<std::string>& names);

} // namespace surfacemap
