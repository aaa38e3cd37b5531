// The `surfacemap` command line: where `surfacemap map` writes a map, so that
// a map directory has one writer at a time and holds one complete map or
// none at every instant.
#pragma once

#include "MapDirectory.h"

#include <memory>
#include <string>
#include <vector>

namespace surfacemap
{

class DirectoryLock;
class InterruptCleanup;

/// Where `surfacemap map` writes its files, and their publication as a whole.
///
/// Made before computing. The map is written into a private staging
/// directory beside DIR (DIR.tmp.<pid>: same file system, locked by this run
/// while it lives), and commit() publishes it under a lock on DIR's parent
/// with SIGINT and SIGTERM held back:
/// - no DIR: the staging directory becomes DIR (renameat2 RENAME_NOREPLACE);
/// - DIR without a map (empty or with other files): the map's files are
///   moved into it, report.json last, so DIR stays the same directory;
/// - DIR with a map, and `overwrite`: DIR and the staging directory are
///   exchanged in one step (RENAME_EXCHANGE; two renames where the file
///   system has no exchange), DIR's other files carried over and the
///   earlier map removed;
/// - DIR with a map (or an interrupted run's files) without `overwrite`,
///   published by another run while this one computed: refused, DIR
///   untouched.
/// A second run for DIR while a first one's staging directory is locked is
/// refused before it computes. Staging directories that killed runs left
/// (DIR.tmp.<pid>, or DIR.old.<pid> of earlier versions; unlocked, holding
/// map files) are cleaned up first: map files removed, other files carried
/// back into DIR, a DIR.old.<pid> renamed back when DIR is gone (each with a
/// "note:" on stderr).
///
/// Where DIR cannot be replaced by renames (it is or holds the working
/// directory, a mount point, or its parent is not writable), the files go
/// into DIR itself under a lock on DIR, and an earlier map is removed once
/// the new one is computed (report.json first; a note says so): never a
/// mix of two maps, but no earlier map either should writing the new one
/// fail.
class MapDestination
{
public:
  /// Prepares DIR's parents (created if missing) and the staging
  /// directory, checked for writing. Throws std::runtime_error naming DIR
  /// when it holds a map or an interrupted run's files and !overwrite, when
  /// another run is writing it, or when it cannot be prepared.
  MapDestination(const std::string& directory, bool overwrite);
  /// Removes the staging directory, and the parents it created, unless committed.
  ~MapDestination();
  MapDestination(const MapDestination&) = delete;
  MapDestination& operator=(const MapDestination&) = delete;

  /// Where to write the map's files.
  const std::string& path() const { return this->Path; }
  /// Called once the map is computed, before its files are written: where
  /// the map is written in place, removes the earlier map (with a note on
  /// stderr).
  void beginWriting();

  /// Puts the map written into path(), `names` with report.json, in place.
  /// Throws std::runtime_error (DIR as it was) if a file does not match
  /// report.json, DIR holds a map now and !overwrite, or a rename fails.
  void commit(const std::vector<std::string>& names);

private:
  void prepare();
  /// What the destructor does: removes the staging directory and the
  /// parents created, unless committed.
  void discard();
  void prepareInPlace(const std::string& why);
  void prepareStaged();
  /// Refuses when a live run's staging directory is beside DIR; with
  /// `clean`, cleans up those of killed runs.
  void refuseOtherWriters(bool clean);
  [[noreturn]] void refuseEarlierMap(MapState state, bool meanwhile) const;
  void publishInto(const std::vector<std::string>& names);
  void publishOver();
  void published();

  std::string Given;
  std::string Directory;
  std::string Path;
  /// Why the map is written in place; empty when staged.
  std::string InPlaceReason;
  bool Overwrite = false;
  bool Staged = false;
  bool Committed = false;
  std::vector<std::string> CreatedParents;
  std::unique_ptr<DirectoryLock> Lock;
  std::unique_ptr<InterruptCleanup> Cleanup;
};

} // namespace surfacemap
