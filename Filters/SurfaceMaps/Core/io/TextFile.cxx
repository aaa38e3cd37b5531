#include "io/TextFile.h"

#include "base/Error.h"

#include <cerrno>
#include <charconv>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace surfacemaps
{

void requireRegularFile(const std::string& path)
{
  std::error_code error;
  const std::filesystem::file_status status = std::filesystem::status(path, error);
  if (error || !std::filesystem::exists(status) || std::filesystem::is_regular_file(status))
  {
    return; // missing or unreadable files are reported by the open that follows
  }
  throw InputError(path + (std::filesystem::is_directory(status)
                              ? ": is a directory, not a file"
                              : ": is not a regular file (a device, FIFO or socket)"));
}

std::string readTextFile(const std::string& path)
{
  requireRegularFile(path);
  std::ifstream in(path, std::ios::binary);
  if (!in)
  {
    throw InputError("cannot open '" + path + "': " + std::strerror(errno));
  }
  std::ostringstream buffer;
  buffer << in.rdbuf();
  if (in.bad())
  {
    throw InputError("cannot read '" + path + "': " + std::strerror(errno));
  }
  return buffer.str();
}

bool TextScanner::nextLine()
{
  if (this->Next >= this->Text.size())
  {
    return false;
  }
  std::size_t end = this->Text.find('\n', this->Next);
  if (end == std::string_view::npos)
  {
    end = this->Text.size();
  }
  this->Line = this->Text.substr(this->Next, end - this->Next);
  const std::size_t comment = this->Line.find('#');
  if (comment != std::string_view::npos)
  {
    this->Line = this->Line.substr(0, comment);
  }
  this->Next = end + 1;
  ++this->LineNumber;
  return true;
}

std::string_view TextScanner::firstTokenOfNextLine()
{
  while (this->nextLine())
  {
    const std::string_view token = this->nextToken();
    if (!token.empty())
    {
      return token;
    }
  }
  return {};
}

namespace
{
bool isSpace(char c)
{
  return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v';
}
}

std::string_view TextScanner::nextToken()
{
  std::size_t i = 0;
  while (i < this->Line.size() && isSpace(this->Line[i]))
  {
    ++i;
  }
  std::size_t j = i;
  while (j < this->Line.size() && !isSpace(this->Line[j]))
  {
    ++j;
  }
  std::string_view token = this->Line.substr(i, j - i);
  this->Line.remove_prefix(j);
  return token;
}

bool TextScanner::lineExhausted()
{
  std::size_t i = 0;
  while (i < this->Line.size() && isSpace(this->Line[i]))
  {
    ++i;
  }
  this->Line.remove_prefix(i);
  return this->Line.empty();
}

void failAtLine(const std::string& name, int line, const std::string& what)
{
  throw InputError(name + ":" + std::to_string(line) + ": " + what);
}

namespace
{
// The whole token must be the number; from_chars rejects a leading '+',
// which some writers emit.
template<typename T>
bool parseNumber(std::string_view token, T& value)
{
  if (!token.empty() && token.front() == '+')
  {
    token.remove_prefix(1);
  }
  if (token.empty())
  {
    return false;
  }
  const char* end = token.data() + token.size();
  const auto result = std::from_chars(token.data(), end, value);
  return result.ec == std::errc() && result.ptr == end;
}
} // namespace

bool parseDouble(std::string_view token, double& value)
{
  return parseNumber(token, value);
}

bool parseInt(std::string_view token, long long& value)
{
  return parseNumber(token, value);
}

} // namespace surfacemaps
