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

#include "Json.h"

#include "vtkSmartPointer.h"

#include <memory>
#include <string>
#include <vector>

class vtkPolyData;

namespace surfacemap
{

class InterruptCleanup;

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

/// Where `surfacemap map` writes a map, so that an output directory holding
/// an earlier map is replaced as a whole or stays as it was.
///
/// Without an earlier map the files go straight into the directory (a
/// directory without report.json is no map). With one, they go into a
/// staging directory beside it (DIR.tmp.<pid>, same file system), and
/// commit() checks every file against the new report.json, renames DIR to
/// DIR.old.<pid>, the staging directory to DIR, carries over what DIR held
/// besides the earlier map's files, and removes DIR.old.<pid>. Until then
/// the earlier map is untouched: on any failure, or SIGINT/SIGTERM, the
/// staging directory is removed (the signal handler also undoes a swap
/// caught between its two renames). Where no sibling can be made or a
/// rename cannot work (DIR is the working directory or holds it, a mount
/// point, or its parent is not writable), the earlier map is removed first
/// (report.json before its files) and `note` says so: never a mix of two
/// maps, but no old map left either should the new one fail.
class MapDestination
{
public:
  /// `directory` exists and is writable (prepareOutputDirectory);
  /// `replacing`: it holds an earlier map to replace (removed here when it
  /// cannot be staged). Throws std::runtime_error naming a directory or
  /// file that cannot be prepared or removed.
  MapDestination(const std::string& directory, bool replacing);
  /// Removes the staging directory unless committed.
  ~MapDestination();
  MapDestination(const MapDestination&) = delete;
  MapDestination& operator=(const MapDestination&) = delete;

  /// Where to write the map's files.
  const std::string& path() const { return this->Path; }
  /// Why the earlier map is replaced in place (empty when staged or new).
  const std::string& note() const { return this->Note; }

  /// Puts the map written into path(), `names` with report.json, in place.
  /// Throws std::runtime_error (the earlier map intact) if a file does not
  /// match report.json or the swap fails.
  void commit(const std::vector<std::string>& names);

private:
  std::string Directory;
  std::string Path;
  std::string Note;
  bool Staged = false;
  bool Committed = false;
  std::unique_ptr<InterruptCleanup> Cleanup;
};

/// The name of an output file of 'surfacemap map' for input i:
/// <stem>_<i>.vtp (stem common, mapped or embedding).
std::string mapFileName(const char* stem, int i);

/// True for a name like a map file's: common_<i>.vtp, mapped_<i>.vtp,
/// embedding_<i>.vtp.
bool isMapFileName(const std::string& name);

/// The input files a map directory's report.json (`report`) names, in
/// order. Throws std::runtime_error naming the file and what is wrong with it
/// (missing, not JSON, no inputs).
std::vector<std::string> mapReportInputs(const std::string& report);

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
