#include "io/LegacyVtkCheck.h"

#include "base/Error.h"
#include "io/TextFile.h"

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string_view>

namespace surfacemaps
{

namespace
{

std::string lower(std::string_view text)
{
  std::string result(text);
  std::transform(result.begin(),
    result.end(),
    result.begin(),
    [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return result;
}

// Bytes per value of a legacy data type in a BINARY file; 0 for types whose
// size is not fixed (strings, bits), which this check does not accept.
std::size_t binarySize(const std::string& type)
{
  if (type == "unsigned_char" || type == "char" || type == "vtktypeint8" ||
    type == "vtktypeuint8" || type == "signed_char")
    return 1;
  if (type == "unsigned_short" || type == "short" || type == "vtktypeint16" ||
    type == "vtktypeuint16")
    return 2;
  if (type == "unsigned_int" || type == "int" || type == "float" || type == "vtkidtype" ||
    type == "vtktypeint32" || type == "vtktypeuint32" || type == "vtktypefloat32")
    return 4;
  if (type == "unsigned_long" || type == "long" || type == "double" || type == "vtktypeint64" ||
    type == "vtktypeuint64" || type == "vtktypefloat64" || type == "unsigned_long_long" ||
    type == "long_long")
    return 8;
  return 0;
}

// Walks the file section by section as VTK's reader does (keywords and
// counts are whitespace-separated tokens; BINARY data starts after the
// keyword's line), checking every count before skipping or reading data.
class LegacyChecker
{
public:
  LegacyChecker(const std::string& bytes, const std::string& name)
    : Bytes(bytes)
    , Name(name)
  {
  }

  void check()
  {
    this->readHeader();
    for (std::string keyword = lower(this->token()); !keyword.empty();
         keyword = lower(this->token()))
    {
      this->readSection(keyword);
    }
  }

private:
  [[noreturn]] void fail(const std::string& what) const
  {
    if (this->Binary)
    {
      throw InputError(this->Name + ": byte " + std::to_string(this->Position) + ": " + what);
    }
    failAtLine(this->Name, this->Line, what);
  }

  void advance(std::size_t count)
  {
    for (std::size_t k = 0; k < count; ++k)
    {
      if (this->Bytes[this->Position + k] == '\n')
      {
        ++this->Line;
      }
    }
    this->Position += count;
  }

  // The next whitespace-separated token; empty at the end of the file.
  std::string_view token()
  {
    std::size_t i = this->Position;
    while (i < this->Bytes.size() && std::isspace(static_cast<unsigned char>(this->Bytes[i])))
    {
      ++i;
    }
    this->advance(i - this->Position);
    while (i < this->Bytes.size() && !std::isspace(static_cast<unsigned char>(this->Bytes[i])))
    {
      ++i;
    }
    const std::size_t begin = this->Position;
    this->advance(i - begin);
    return std::string_view(this->Bytes).substr(begin, i - begin);
  }

  void skipRestOfLine()
  {
    const std::size_t end = this->Bytes.find('\n', this->Position);
    this->advance((end == std::string::npos ? this->Bytes.size() : end + 1) - this->Position);
  }

  std::string restOfLine()
  {
    const std::size_t begin = this->Position;
    this->skipRestOfLine();
    return this->Bytes.substr(begin, this->Position - begin);
  }

  long long count(const char* what)
  {
    const std::string_view t = this->token();
    long long value;
    if (!parseInt(t, value) || value < 0)
    {
      this->fail("expected " + std::string(what) + ", got '" + std::string(t) + "'");
    }
    // Every counted item takes at least a byte, so products of two counts
    // below stay far from overflow.
    if (static_cast<unsigned long long>(value) > this->Bytes.size())
    {
      this->fail("declares " + std::string(what) + " of " + std::to_string(value) +
        ", more than the file's " + std::to_string(this->Bytes.size()) + " bytes can hold");
    }
    return value;
  }

  std::string word(const char* what)
  {
    const std::string_view t = this->token();
    if (t.empty())
    {
      this->fail("the file ends where " + std::string(what) + " was expected");
    }
    return std::string(t);
  }

  void expect(const char* keyword)
  {
    const std::string t = lower(this->token());
    if (t != keyword)
    {
      this->fail("expected " + lower(keyword) + ", got '" + t + "'");
    }
  }

  // A data type of `section`; bits are refused, and strings unless
  // `strings` (FIELD arrays only: VTK writes string arrays there).
  std::string dataType(const std::string& section, bool strings = false)
  {
    const std::string type = lower(this->word("a data type"));
    if (strings && (type == "string" || type == "utf8_string"))
    {
      return type;
    }
    if (binarySize(type) == 0)
    {
      this->fail(section + " has data type '" + type +
        "', which this reader does not accept (numeric types only)");
    }
    return type;
  }

  // Refuses `values` values of `type` that the rest of the file cannot hold
  // (ASCII: at least two bytes per value, BINARY: the type's size).
  void requireRoom(unsigned long long values, const std::string& type, const std::string& section)
  {
    const std::size_t remaining = this->Bytes.size() - this->Position;
    const std::size_t perValue = this->Binary ? binarySize(type) : 2;
    if (values > remaining / perValue + (this->Binary ? 0 : 1))
    {
      this->fail(section + " declares " + std::to_string(values) +
        " values, more than the rest of the file can hold; it is truncated or the count is wrong");
    }
  }

  // The next value of `type`, an integer (BINARY: big-endian, as VTK writes).
  long long integer(const std::string& type, const std::string& section)
  {
    if (!this->Binary)
    {
      const std::string_view t = this->token();
      long long value;
      if (!parseInt(t, value))
      {
        this->fail(section + ": expected an integer, got '" + std::string(t) + "'");
      }
      return value;
    }
    const std::size_t size = binarySize(type);
    std::uint64_t raw = 0;
    for (std::size_t k = 0; k < size; ++k)
    {
      raw = (raw << 8) | static_cast<unsigned char>(this->Bytes[this->Position + k]);
    }
    this->Position += size;
    const bool isSigned = type.find("unsigned") == std::string::npos &&
      type.find("uint") == std::string::npos;
    if (isSigned && size < 8 && (raw >> (8 * size - 1)) != 0)
    {
      return static_cast<long long>(raw) - (1ll << (8 * size)); // sign-extend
    }
    if (raw > static_cast<std::uint64_t>(std::numeric_limits<long long>::max()))
    {
      return -1; // out of range either way
    }
    return static_cast<long long>(raw);
  }

  // Where `values` values of `type` start: refused unless the file can hold
  // them, before and (BINARY: data starts on the next line) after the rest
  // of the keyword's line.
  void beginData(unsigned long long values, const std::string& type, const std::string& section)
  {
    this->requireRoom(values, type, section);
    if (this->Binary)
    {
      this->skipRestOfLine();
      this->requireRoom(values, type, section);
    }
  }

  // Skips `values` values of `type` (ASCII: each must be a number).
  void skipValues(unsigned long long values, const std::string& type, const std::string& section)
  {
    this->beginData(values, type, section);
    if (this->Binary)
    {
      this->Position += static_cast<std::size_t>(values) * binarySize(type);
      return;
    }
    for (unsigned long long k = 0; k < values; ++k)
    {
      const std::string_view t = this->token();
      double ignored;
      if (!parseDouble(t, ignored)) // also takes nan and inf, as VTK writes them
      {
        this->fail(section + ": " +
          (t.empty() ? "the file ends after " + std::to_string(k) + " of " +
                 std::to_string(values) + " values; it is truncated"
                     : "expected a number, got '" + std::string(t) + "'"));
      }
    }
  }

  // Skips `values` strings: ASCII one per line; BINARY each behind a
  // big-endian length whose first byte's top two bits give its width
  // (11: 1 byte, 10: 2, 01: 4, 00: 8), as vtkDataWriter writes them.
  void skipStrings(unsigned long long values, const std::string& section)
  {
    if (values > this->Bytes.size() - this->Position)
    {
      this->fail(section + " declares " + std::to_string(values) +
        " strings, more than the rest of the file can hold");
    }
    this->skipRestOfLine();
    for (unsigned long long k = 0; k < values; ++k)
    {
      if (this->Position >= this->Bytes.size())
      {
        this->fail(section + ": the file ends after " + std::to_string(k) + " of " +
          std::to_string(values) + " strings");
      }
      if (!this->Binary)
      {
        this->skipRestOfLine();
        continue;
      }
      const unsigned char first = static_cast<unsigned char>(this->Bytes[this->Position]);
      const std::size_t width = std::size_t(1) << (3 - (first >> 6));
      if (width > this->Bytes.size() - this->Position)
      {
        this->fail(section + ": string " + std::to_string(k) + " has a truncated length");
      }
      std::uint64_t length = first & (width == 8 ? 0xFF : 0x3F);
      for (std::size_t b = 1; b < width; ++b)
      {
        length = (length << 8) | static_cast<unsigned char>(this->Bytes[this->Position + b]);
      }
      this->Position += width;
      if (length > this->Bytes.size() - this->Position)
      {
        this->fail(section + ": string " + std::to_string(k) + " declares " +
          std::to_string(length) + " bytes, more than the rest of the file holds");
      }
      this->Position += static_cast<std::size_t>(length);
    }
  }

  void readHeader()
  {
    const std::string first = this->restOfLine();
    if (first.rfind("# vtk DataFile Version", 0) != 0)
    {
      this->fail("not a legacy VTK file (no '# vtk DataFile Version' line)");
    }
    // "X.Y" exactly: VTK's reader falls back to the pre-5 cell layout on a
    // version it cannot parse, and the layouts differ.
    std::string version = first.substr(std::strlen("# vtk DataFile Version"));
    version.erase(0, version.find_first_not_of(" \t"));
    version.erase(version.find_last_not_of(" \t\r\n") + 1);
    const std::size_t dot = version.find('.');
    long long major, minor;
    if (dot == std::string::npos || !parseInt(std::string_view(version).substr(0, dot), major) ||
      !parseInt(std::string_view(version).substr(dot + 1), minor) || major < 0 || minor < 0 ||
      version.find_first_not_of("0123456789.") != std::string::npos)
    {
      this->fail("unreadable file version '" + version + "'");
    }
    // VTK 9.1 writes and knows versions up to 5.1 and reads them as ints.
    if (major > 5 || minor > 99)
    {
      this->fail("file version " + version + " is not one VTK 9.1 knows (up to 5.1)");
    }
    this->Version = static_cast<int>(major);
    this->skipRestOfLine(); // title
    const std::string format = lower(this->token());
    if (format != "ascii" && format != "binary")
    {
      this->fail("expected ASCII or BINARY, got '" + format + "'");
    }
    this->expect("dataset");
    this->expect("polydata");
    this->Binary = format == "binary";
  }

  void readSection(const std::string& keyword)
  {
    if (keyword == "points")
    {
      this->NumberOfPoints = this->count("a point count");
      this->skipValues(3ull * static_cast<unsigned long long>(this->NumberOfPoints),
        this->dataType("POINTS"), "POINTS");
    }
    else if (keyword == "vertices" || keyword == "lines" || keyword == "polygons" ||
      keyword == "triangle_strips")
    {
      this->readCells(lower(keyword));
    }
    else if (keyword == "point_data" || keyword == "cell_data")
    {
      const long long n = this->count("a tuple count");
      const long long expected =
        keyword == "point_data" ? this->NumberOfPoints : this->NumberOfCells;
      if (n != expected)
      {
        this->fail(keyword + " declares " + std::to_string(n) + " tuples for " +
          std::to_string(expected) + (keyword == "point_data" ? " points" : " cells"));
      }
      this->Tuples = n;
    }
    else if (keyword == "field")
    {
      this->readField();
    }
    else if (keyword == "metadata")
    {
      this->skipMetadata();
    }
    else if (this->Tuples >= 0)
    {
      this->readAttribute(keyword);
    }
    else
    {
      this->fail("unexpected '" + keyword + "'");
    }
  }

  // Cells of one kind: "KIND cells size" then the cells' point counts and
  // indices (files before version 5), or OFFSETS and CONNECTIVITY arrays.
  void readCells(const std::string& kind)
  {
    const long long first = this->count("a cell count");
    const long long second = this->count("a size");
    if (this->Version < 5)
    {
      this->beginData(static_cast<unsigned long long>(second), "int", kind);
      long long used = 0;
      for (long long c = 0; c < first; ++c)
      {
        if (used >= second)
        {
          this->fail(kind + " declares " + std::to_string(first) + " cells in " +
            std::to_string(second) + " values, but cell " + std::to_string(c) + " does not fit");
        }
        const long long n = this->integer("int", kind);
        ++used;
        if (n < 0 || n > second - used)
        {
          this->fail(kind + " cell " + std::to_string(c) + " declares " + std::to_string(n) +
            " points, more than the section's size leaves");
        }
        for (long long k = 0; k < n; ++k)
        {
          this->requirePoint(this->integer("int", kind), kind, c);
        }
        used += n;
      }
      if (used != second)
      {
        this->fail(kind + " declares a size of " + std::to_string(second) + " values, but its " +
          std::to_string(first) + " cells use " + std::to_string(used));
      }
      this->NumberOfCells += first;
      return;
    }
    // Version 5: `first` offsets (cells + 1, or 0) and `second` point ids.
    this->expect("offsets");
    const std::string offsetType = this->dataType(kind + " OFFSETS");
    this->beginData(static_cast<unsigned long long>(first), offsetType, kind + " OFFSETS");
    long long previous = 0;
    for (long long k = 0; k < first; ++k)
    {
      const long long offset = this->integer(offsetType, kind + " OFFSETS");
      if ((k == 0 && offset != 0) || offset < previous || offset > second)
      {
        this->fail(kind + " offset " + std::to_string(k) + " is " + std::to_string(offset) +
          " (offsets start at 0, never decrease and end at the connectivity size " +
          std::to_string(second) + ")");
      }
      previous = offset;
    }
    if (first > 0 ? previous != second : second != 0)
    {
      this->fail(kind + " offsets end at " + std::to_string(previous) +
        ", not at the connectivity size " + std::to_string(second));
    }
    this->expect("connectivity");
    const std::string idType = this->dataType(kind + " CONNECTIVITY");
    this->beginData(static_cast<unsigned long long>(second), idType, kind + " CONNECTIVITY");
    for (long long k = 0; k < second; ++k)
    {
      this->requirePoint(this->integer(idType, kind + " CONNECTIVITY"), kind, -1, k);
    }
    this->NumberOfCells += std::max(first - 1, 0ll);
  }

  void requirePoint(long long index, const std::string& kind, long long cell, long long entry = 0)
  {
    if (index < 0 || index >= this->NumberOfPoints)
    {
      const std::string where = cell >= 0 ? "cell " + std::to_string(cell)
                                          : "connectivity entry " + std::to_string(entry);
      this->fail(kind + " " + where + " uses point index " + std::to_string(index) +
        ", out of range for " + std::to_string(this->NumberOfPoints) + " points");
    }
  }

  // FIELD name arrays, then per array "name components tuples type" and data.
  void readField()
  {
    this->word("a field name");
    const long long arrays = this->count("an array count");
    for (long long a = 0; a < arrays; ++a)
    {
      const std::string name = this->word("an array name");
      if (lower(name) == "null_array")
      {
        continue;
      }
      const long long components = this->count("a component count");
      const long long tuples = this->count("a tuple count");
      const std::string section = "FIELD array " + name;
      const std::string type = this->dataType(section, true);
      if (tuples != 0 && static_cast<unsigned long long>(components) >
          std::numeric_limits<unsigned long long>::max() / static_cast<unsigned long long>(tuples))
      {
        this->fail(section + " declares " + std::to_string(components) + " x " +
          std::to_string(tuples) + " values");
      }
      const unsigned long long values =
        static_cast<unsigned long long>(components) * static_cast<unsigned long long>(tuples);
      if (binarySize(type) == 0)
      {
        this->skipStrings(values, section);
      }
      else
      {
        this->skipValues(values, type, section);
      }
      this->skipMetadataIfPresent();
    }
  }

  // One attribute of POINT_DATA / CELL_DATA with this->Tuples tuples.
  void readAttribute(const std::string& keyword)
  {
    const unsigned long long n = static_cast<unsigned long long>(this->Tuples);
    const std::string section = keyword == "lookup_table" ? "LOOKUP_TABLE"
                                                          : lower(keyword) + " " + this->word("a name");
    if (keyword == "scalars")
    {
      const std::string type = this->dataType(section);
      std::string next = lower(this->token());
      long long components = 1;
      if (next != "lookup_table")
      {
        if (!parseInt(next, components) || components < 1 || components > 4)
        {
          this->fail(section + ": expected 1 to 4 components, got '" + next + "'");
        }
        next = lower(this->token());
      }
      if (next != "lookup_table")
      {
        this->fail(section + ": expected LOOKUP_TABLE, got '" + next + "'");
      }
      this->word("a lookup table name");
      this->skipValues(n * static_cast<unsigned long long>(components), type, section);
    }
    else if (keyword == "lookup_table")
    {
      this->word("a lookup table name");
      const long long size = this->count("a table size");
      this->skipValues(4ull * static_cast<unsigned long long>(size),
        this->Binary ? "unsigned_char" : "float", section);
    }
    else if (keyword == "color_scalars")
    {
      const long long components = this->count("a component count");
      if (components > 4)
      {
        this->fail(section + " declares " + std::to_string(components) + " components");
      }
      this->skipValues(n * static_cast<unsigned long long>(components),
        this->Binary ? "unsigned_char" : "float", section);
    }
    else if (keyword == "vectors" || keyword == "normals" || keyword == "tensors" ||
      keyword == "tensors6" || keyword == "global_ids" || keyword == "pedigree_ids")
    {
      const unsigned long long components = keyword == "tensors" ? 9
        : keyword == "tensors6"                                  ? 6
        : (keyword == "global_ids" || keyword == "pedigree_ids") ? 1
                                                                 : 3;
      this->skipValues(n * components, this->dataType(section), section);
    }
    else if (keyword == "texture_coordinates")
    {
      const long long dimension = this->count("a dimension");
      if (dimension < 1 || dimension > 3)
      {
        this->fail(section + " has dimension " + std::to_string(dimension));
      }
      this->skipValues(
        n * static_cast<unsigned long long>(dimension), this->dataType(section), section);
    }
    else
    {
      this->fail("unexpected '" + keyword + "'");
    }
    this->skipMetadataIfPresent();
  }

  // METADATA blocks (file version 5) end at an empty line.
  void skipMetadata()
  {
    this->skipRestOfLine();
    while (this->Position < this->Bytes.size())
    {
      const std::string line = this->restOfLine();
      if (line.find_first_not_of(" \t\r\n") == std::string::npos)
      {
        return;
      }
    }
  }

  void skipMetadataIfPresent()
  {
    const std::size_t position = this->Position;
    const int line = this->Line;
    if (lower(this->token()) == "metadata")
    {
      this->skipMetadata();
      return;
    }
    this->Position = position;
    this->Line = line;
  }

  const std::string& Bytes;
  const std::string& Name;
  std::size_t Position = 0;
  int Line = 1;
  int Version = 0;
  bool Binary = false;
  long long NumberOfPoints = 0;
  long long NumberOfCells = 0;
  long long Tuples = -1; // inside POINT_DATA / CELL_DATA: their tuple count
};

} // namespace

void checkLegacyVtkPolyData(const std::string& bytes, const std::string& name)
{
  LegacyChecker(bytes, name).check();
}

} // namespace surfacemaps
