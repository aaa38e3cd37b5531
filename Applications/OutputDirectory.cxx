// The `surfacemap` command line: creating, checking and removing a
// command's output directory.
#include "OutputDirectory.h"

#include "AtomicFiles.h"
#include "Terminal.h"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <system_error>

namespace surfacemap
{

void createOutputDirectory(const std::string& directory, const std::string& probe)
{
  std::error_code ec;
  std::filesystem::create_directories(directory, ec);
  if (ec && !std::filesystem::is_directory(directory))
  {
    throw std::runtime_error(
      "cannot create the output directory '" + directory + "': " + ec.message());
  }
  checkWritable(directory + "/" + probe);
}

bool prepareOutputDirectory(const std::string& directory,
  const std::string& probe,
  std::string& created)
{
  created.clear();
  return succeeds(
    [&]
    {
      std::error_code ec;
      for (std::filesystem::path p = std::filesystem::absolute(directory, ec).lexically_normal();
           !ec && !p.empty() && !std::filesystem::exists(p, ec) && p != p.parent_path();
           p = p.parent_path())
      {
        created = p.string();
      }
      createOutputDirectory(directory, probe);
    });
}

void removeCreatedDirectory(const std::string& created)
{
  if (!created.empty())
  {
    std::error_code ec;
    std::filesystem::remove_all(created, ec);
  }
}

StagingDirectory::StagingDirectory(const std::string& directory, const std::string& name)
  : Directory(directory)
  , Path(directory + "/" + name + ".tmp." + std::to_string(getpid()))
{
  std::error_code ec;
  std::filesystem::remove_all(this->Path, ec); // a killed run's with this pid
  this->Cleanup = std::make_unique<InterruptCleanup>(this->Path, InterruptCleanup::Everything);
  if (!std::filesystem::create_directory(this->Path, ec))
  {
    writeFailed(this->Path, ec ? ec.message() : "it exists");
  }
}

StagingDirectory::~StagingDirectory()
{
  std::error_code ec;
  std::filesystem::remove_all(this->Path, ec);
}

void StagingDirectory::publish(const std::vector<std::string>& names)
{
  namespace fs = std::filesystem;
  const InterruptHold hold;
  for (const std::string& name : names)
  {
    const std::string from = this->Path + "/" + name;
    const std::string to = this->Directory + "/" + name;
    std::error_code ec;
    int error = 0;
    if (fs::is_directory(from, ec) && fs::is_directory(to, ec))
    {
      // The replaced directory comes back into the staging directory,
      // which goes with it.
      error = exchangePaths(from, to);
      if (renameUnsupported(error))
      {
        fs::remove_all(to, ec);
        error = std::rename(from.c_str(), to.c_str()) == 0 ? 0 : errno;
      }
    }
    else if (std::rename(from.c_str(), to.c_str()) != 0)
    {
      error = errno;
    }
    if (error != 0)
    {
      writeFailed(to, std::strerror(error));
    }
  }
}

} // namespace surfacemap
