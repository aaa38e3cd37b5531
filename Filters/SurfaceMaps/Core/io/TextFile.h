// SurfaceMaps engine: line-oriented reading of small text formats.
#pragma once

#include <string>
#include <string_view>

namespace surfacemaps
{

/// Throws InputError naming `path` when it exists but is not a regular file
/// (a directory, a device such as /dev/zero, a FIFO): reading one would say
/// "empty" or never end. Symbolic links are followed.
void requireRegularFile(const std::string& path);

/// Reads a whole regular file into memory. Throws InputError naming the file when it
/// cannot be opened or read.
std::string readTextFile(const std::string& path);

/// Walks a text buffer line by line and token by token (whitespace separated),
/// keeping the 1-based line number for messages. '#' starts a comment.
class TextScanner
{
public:
  /// A UTF-8 byte order mark at the start is skipped: it would glue itself to
  /// the first keyword (an OBJ's first "v" would go unread).
  explicit TextScanner(std::string_view text)
    : Text(text.substr(text.rfind("\xEF\xBB\xBF", 0) == 0 ? 3 : 0))
  {
  }

  /// Advances to the next line; false at the end of the text.
  bool nextLine();
  /// Advances to the next line that has a token and returns that token; empty
  /// at the end of the text.
  std::string_view firstTokenOfNextLine();
  /// The next token of the current line, empty when the line is exhausted.
  std::string_view nextToken();
  /// True when the current line has no more tokens.
  bool lineExhausted();
  /// 1-based number of the current line.
  int lineNumber() const { return this->LineNumber; }
  /// True when the text does not end with a newline (a hint of truncation).
  bool endsWithoutNewline() const { return !this->Text.empty() && this->Text.back() != '\n'; }
  /// True on an unterminated last line: a file cut off in the middle of it.
  bool truncatedHere() const
  {
    return this->Next > this->Text.size() && this->endsWithoutNewline();
  }

private:
  std::string_view Text;
  std::string_view Line;
  std::size_t Next = 0;
  int LineNumber = 0;
};

/// Throws InputError "name:line: what", the form of every located message of
/// the text readers.
[[noreturn]] void failAtLine(const std::string& name, int line, const std::string& what);

/// Strict number parsing: the whole token must be a number.
bool parseDouble(std::string_view token, double& value);
bool parseInt(std::string_view token, long long& value);

} // namespace surfacemaps
