// The `surfacemap` command line: creating, checking and removing a
// command's output directory.
#include "OutputDirectory.h"

#include "AtomicFiles.h"
#include "Terminal.h"

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

} // namespace surfacemap
