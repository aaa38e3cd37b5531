// The `surfacemap` command line: reading a command's arguments.
#include "Arguments.h"

#include "Commands.h"

namespace surfacemap
{

bool isOption(const std::string& argument)
{
  return !argument.empty() && argument[0] == '-';
}

bool isOutputDirOption(const std::string& argument)
{
  return argument == "-o" || argument == "--output-dir";
}

const std::string& optionValue(const std::vector<std::string>& args,
  std::size_t& i,
  const char* what)
{
  if (i + 1 >= args.size())
  {
    throw UsageError{ args[i] + " needs " + what };
  }
  return args[++i];
}

void unknownOption(const std::string& argument)
{
  throw UsageError{ "unknown option '" + argument + "'" };
}

} // namespace surfacemap
