// The `surfacemap` command line: staging, locking and publishing a map
// directory.
#include "MapDestination.h"

#include "AtomicFiles.h"
#include "DirectoryLock.h"
#include "MapDirectory.h"

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <system_error>

namespace surfacemap
{

namespace
{
namespace fs = std::filesystem;

std::string withPid(const std::string& directory, const char* kind)
{
  return directory + "." + kind + "." + std::to_string(getpid());
}

std::string cannotCreate(const std::string& directory, const std::string& reason)
{
  return "cannot create the output directory '" + directory + "': " + reason;
}

std::string anotherRun(const std::string& directory, const std::string& pid)
{
  return "another 'surfacemap map'" + (pid.empty() ? std::string() : " (pid " + pid + ")") +
    " is writing a map into " + directory +
    ": wait for it to finish, or choose another --output-dir";
}

// Why DIR cannot be replaced by renames; empty if it can.
std::string whyNotSwappable(const fs::path& directory)
{
  if (directory == directory.parent_path())
  {
    return "it is the root directory";
  }
  std::error_code ec;
  const fs::path cwd = fs::current_path(ec);
  if (!ec)
  {
    const auto relative = cwd.lexically_relative(directory);
    if (!relative.empty() && *relative.begin() != "..")
    {
      return "it is or holds the working directory";
    }
  }
  struct stat self, parent;
  if (stat(directory.c_str(), &self) != 0 || stat(directory.parent_path().c_str(), &parent) != 0 ||
    self.st_dev != parent.st_dev)
  {
    return "it is a mount point";
  }
  if (access(directory.parent_path().c_str(), W_OK) != 0)
  {
    return "its parent directory is not writable";
  }
  return "";
}

// A file of the map: removed with it, never carried over.
bool isMapFile(const std::string& name)
{
  return name == "report.json" || isMapFileName(name);
}

std::vector<std::string> namesIn(const fs::path& directory)
{
  std::vector<std::string> names;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(directory, ec))
  {
    names.push_back(entry.path().filename().string());
  }
  return names;
}

// A staging directory beside DIR: DIR.tmp.<pid>, or DIR.old.<pid> (the
// earlier map moved aside, by runs on file systems without an exchange and
// by earlier versions).
struct Sibling
{
  fs::path Path;
  bool Old = false;
  std::string Pid;
};

std::vector<Sibling> stagingSiblings(const fs::path& directory)
{
  std::vector<Sibling> found;
  const std::string base = directory.filename().string();
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(directory.parent_path(), ec))
  {
    const std::string name = entry.path().filename().string();
    for (const std::string kind : { ".tmp.", ".old." })
    {
      const std::string prefix = base + kind;
      if (name.size() > prefix.size() && name.compare(0, prefix.size(), prefix) == 0 &&
        name.find_first_not_of("0123456789", prefix.size()) == std::string::npos &&
        fs::is_directory(fs::symlink_status(entry.path(), ec)))
      {
        found.push_back({ entry.path(), kind == ".old.", name.substr(prefix.size()) });
      }
    }
  }
  // DIR.old.<pid> first: it may have to become DIR again.
  std::stable_partition(found.begin(), found.end(), [](const Sibling& s) { return s.Old; });
  return found;
}

// Cleans up `sibling`, left by a killed run (its lock is free): a DIR.old
// becomes DIR again when DIR is gone; otherwise the map's files and
// temporary files go and the other files (the earlier DIR's, when the run
// was killed while carrying them over) return into DIR. A directory that
// holds none of a map's files is not touched (not one of ours). Returns a
// note for the user, empty if nothing was done.
std::string salvage(const Sibling& sibling, const fs::path& directory, const std::string& given)
{
  const std::vector<std::string> names = namesIn(sibling.Path);
  const bool ours = names.empty() ||
    std::any_of(names.begin(),
      names.end(),
      [](const std::string& name)
      { return isMapFile(name) || name.find(".tmp.") != std::string::npos; });
  if (!ours)
  {
    return "";
  }
  const std::string what =
    sibling.Path.string() + ", left by an interrupted 'surfacemap map' (pid " + sibling.Pid + ")";
  std::error_code ec;
  if (sibling.Old && !fs::exists(fs::symlink_status(directory, ec)) &&
    renameNoReplace(sibling.Path.string(), directory.string()) == 0)
  {
    return "restored " + given + " from " + what;
  }
  for (const std::string& name : names)
  {
    const fs::path path = sibling.Path / name;
    if (isMapFile(name) || name.find(".tmp.") != std::string::npos)
    {
      fs::remove(path, ec);
    }
    else if (fs::is_directory(directory, ec))
    {
      renameNoReplace(path.string(), (directory / name).string());
    }
  }
  fs::remove(sibling.Path, ec);
  if (fs::exists(fs::symlink_status(sibling.Path, ec)))
  {
    return "kept " + what + ": it holds files that could not be moved back into " + given;
  }
  return "removed " + what;
}

} // namespace

MapDestination::MapDestination(const std::string& directory, bool overwrite)
  : Given(directory)
  , Directory(directory)
  , Path(directory)
  , Overwrite(overwrite)
{
  try
  {
    this->prepare();
  }
  catch (...)
  {
    this->discard(); // no destructor runs for a constructor that throws
    throw;
  }
}

void MapDestination::prepare()
{
  std::error_code ec;
  fs::path target = fs::absolute(this->Given, ec).lexically_normal();
  if (ec)
  {
    throw std::runtime_error(cannotCreate(this->Given, ec.message()));
  }
  if (!target.has_filename())
  {
    target = target.parent_path(); // "out/" names "out"
  }
  if (fs::is_directory(fs::status(target, ec)))
  {
    // A symbolic link keeps naming the directory that then holds the map.
    target = fs::canonical(target, ec);
    this->Directory = target.string();
    const std::string why = whyNotSwappable(target);
    if (!why.empty())
    {
      this->prepareInPlace(why);
      return;
    }
  }
  else if (fs::exists(fs::symlink_status(target, ec)))
  {
    throw std::runtime_error(cannotCreate(this->Given, "it exists and is not a directory"));
  }
  else
  {
    const fs::path parent = target.parent_path();
    for (fs::path p = parent; !p.empty() && !fs::exists(p, ec) && p != p.parent_path();
         p = p.parent_path())
    {
      this->CreatedParents.push_back(p.string());
    }
    fs::create_directories(parent, ec);
    if (ec && !fs::is_directory(parent))
    {
      throw std::runtime_error(cannotCreate(this->Given, ec.message()));
    }
    this->Directory = target.string();
  }
  this->prepareStaged();
}

MapDestination::~MapDestination()
{
  this->discard();
}

void MapDestination::discard()
{
  if (this->Committed)
  {
    return;
  }
  std::error_code ec;
  if (this->Staged)
  {
    fs::remove_all(this->Path, ec);
  }
  for (const std::string& parent : this->CreatedParents)
  {
    fs::remove(parent, ec); // deepest first; only while empty
  }
}

void MapDestination::prepareInPlace(const std::string& why)
{
  this->Lock = std::make_unique<DirectoryLock>(this->Directory, false);
  if (this->Lock->busy())
  {
    throw std::runtime_error(anotherRun(this->Given, ""));
  }
  this->refuseOtherWriters(false);
  const MapState state = mapState(this->Directory);
  if (state != MapState::None && !this->Overwrite)
  {
    this->refuseEarlierMap(state, false);
  }
  this->InPlaceReason = why;
  this->Path = this->Directory;
  checkWritable(this->Directory + "/report.json");
}

void MapDestination::prepareStaged()
{
  const fs::path target(this->Directory);
  {
    // Checking for other writers and creating this run's staging directory
    // is one step for every run of this parent.
    const DirectoryLock parentLock(target.parent_path().string(), true);
    this->refuseOtherWriters(true);
    std::error_code ec;
    if (fs::is_directory(target, ec))
    {
      if (lockedByAnother(this->Directory))
      {
        throw std::runtime_error(anotherRun(this->Given, "")); // one writing in place
      }
      const MapState state = mapState(this->Directory);
      if (state != MapState::None && !this->Overwrite)
      {
        this->refuseEarlierMap(state, false);
      }
    }
    this->Path = withPid(this->Directory, "tmp");
    // Created and registered for removal on SIGINT/SIGTERM in one step.
    const InterruptHold hold;
    if (mkdir(this->Path.c_str(), 0777) != 0)
    {
      const int error = errno;
      throw std::runtime_error(cannotCreate(this->Given,
        error == EEXIST ? this->Path + " exists and holds files not written by surfacemap"
                        : std::strerror(error)));
    }
    this->Staged = true;
    this->Cleanup = std::make_unique<InterruptCleanup>(this->Path, InterruptCleanup::Everything);
    this->Lock = std::make_unique<DirectoryLock>(this->Path, false);
  }
  checkWritable(this->Path + "/report.json");
}

void MapDestination::refuseOtherWriters(bool clean)
{
  const fs::path target(this->Directory);
  for (const Sibling& sibling : stagingSiblings(target))
  {
    if (sibling.Path.filename() == fs::path(this->Path).filename())
    {
      continue; // this run's own
    }
    const DirectoryLock lock(sibling.Path.string(), false);
    if (lock.busy())
    {
      throw std::runtime_error(anotherRun(this->Given, sibling.Pid));
    }
    if (clean && lock.locked())
    {
      const std::string note = salvage(sibling, target, this->Given);
      if (!note.empty())
      {
        std::fprintf(stderr, "note: %s\n", note.c_str());
      }
    }
  }
}

void MapDestination::refuseEarlierMap(MapState state, bool meanwhile) const
{
  if (state == MapState::Interrupted)
  {
    throw std::runtime_error(interruptedRunMessage(this->Given));
  }
  if (meanwhile)
  {
    throw std::runtime_error(this->Given +
      " now holds a map that another run wrote while this one computed: this map is not "
      "written (give --overwrite to replace that one)");
  }
  throw std::runtime_error(this->Given +
    " holds an earlier map (report.json or common_/mapped_/embedding_ files); give --overwrite "
    "to replace it");
}

void MapDestination::beginWriting()
{
  if (this->Staged)
  {
    return;
  }
  if (mapState(this->Directory) != MapState::None)
  {
    std::fprintf(stderr,
      "note: the earlier map in %s is removed before the new one is written (%s: it cannot be "
      "replaced as a whole)\n",
      this->Given.c_str(),
      this->InPlaceReason.c_str());
    // No reader takes a directory without report.json for a map, and the
    // new report lists only the new files: an interruption from here on
    // leaves no map rather than a mix of two.
    removeMap(this->Directory);
  }
  this->Cleanup = std::make_unique<InterruptCleanup>(this->Directory, InterruptCleanup::MapFiles);
}

void MapDestination::commit(const std::vector<std::string>& names)
{
  verifyMapFiles(this->Path, names);
  if (!this->Staged)
  {
    this->Committed = true;
    this->Cleanup.reset();
    return;
  }
  // Publishing is a few renames that happen all or none: the signals wait,
  // and other runs of this parent wait for the lock.
  const InterruptHold hold;
  const DirectoryLock parentLock(fs::path(this->Directory).parent_path().string(), true);
  std::error_code ec;
  if (!fs::exists(fs::symlink_status(this->Directory, ec)))
  {
    const int error = renameNoReplace(this->Path, this->Directory);
    if (error == 0)
    {
      this->published();
      return;
    }
    if (error != EEXIST && error != ENOTEMPTY)
    {
      throw std::runtime_error("cannot move the new map from " + this->Path + " to " +
        this->Directory + ": " + std::strerror(error));
    }
  }
  if (!fs::is_directory(this->Directory, ec))
  {
    throw std::runtime_error(this->Given +
      " appeared while this run computed and is not a directory: this map is not written");
  }
  if (lockedByAnother(this->Directory))
  {
    throw std::runtime_error(anotherRun(this->Given, ""));
  }
  const MapState state = mapState(this->Directory);
  if (state == MapState::None)
  {
    this->publishInto(names);
  }
  else if (!this->Overwrite)
  {
    this->refuseEarlierMap(state, true);
  }
  else
  {
    this->publishOver();
  }
}

void MapDestination::published()
{
  this->Committed = true;
  this->Cleanup.reset();
  this->Lock.reset();
}

void MapDestination::publishInto(const std::vector<std::string>& names)
{
  std::vector<std::string> order = names;
  order.push_back("report.json"); // last: until then DIR holds no map
  std::vector<std::string> moved;
  for (const std::string& name : order)
  {
    const int error = renameNoReplace(this->Path + "/" + name, this->Directory + "/" + name);
    if (error != 0)
    {
      for (auto back = moved.rbegin(); back != moved.rend(); ++back)
      {
        std::rename((this->Directory + "/" + *back).c_str(), (this->Path + "/" + *back).c_str());
      }
      throw std::runtime_error("cannot move " + name + " into " + this->Given + ": " +
        std::strerror(error) + " (" + this->Given + " is unchanged)");
    }
    moved.push_back(name);
  }
  this->published();
  std::error_code ec;
  fs::remove(this->Path, ec);
}

void MapDestination::publishOver()
{
  // The new directory takes the place of DIR: with DIR's permissions.
  struct stat info;
  if (stat(this->Directory.c_str(), &info) == 0)
  {
    chmod(this->Path.c_str(), info.st_mode & 07777);
  }
  std::string old = this->Path;
  int error = exchangePaths(this->Path, this->Directory);
  if (renameUnsupported(error))
  {
    // Two renames, with the signals held and other runs waiting for the lock.
    old = withPid(this->Directory, "old");
    if (std::rename(this->Directory.c_str(), old.c_str()) != 0)
    {
      error = errno;
      throw std::runtime_error("cannot move the earlier map in " + this->Given +
        " aside: " + std::strerror(error) + " (it is unchanged)");
    }
    error = std::rename(this->Path.c_str(), this->Directory.c_str()) == 0 ? 0 : errno;
    if (error != 0)
    {
      std::rename(old.c_str(), this->Directory.c_str());
    }
  }
  if (error != 0)
  {
    throw std::runtime_error("cannot put the new map in place of the earlier one in " +
      this->Given + ": " + std::strerror(error) + " (the earlier map is unchanged)");
  }
  this->published();
  // What DIR held besides the earlier map stays in it.
  bool carried = true;
  std::error_code ec;
  for (const std::string& name : namesIn(old))
  {
    const fs::path path = fs::path(old) / name;
    if (isMapFile(name))
    {
      carried = fs::remove(path, ec) && carried;
    }
    else
    {
      carried = renameNoReplace(path.string(), this->Directory + "/" + name) == 0 && carried;
    }
  }
  if (!carried || !fs::remove(old, ec))
  {
    throw std::runtime_error("the new map is in " + this->Given +
      ", but not every other file of the earlier directory could be moved into it: they are "
      "in " +
      old);
  }
}

} // namespace surfacemap
