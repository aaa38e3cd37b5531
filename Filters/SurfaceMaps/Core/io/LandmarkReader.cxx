#include "io/LandmarkReader.h"

#include "base/Error.h"
#include "io/TextFile.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <map>

namespace surfacemaps
{

namespace
{

std::string lowercase(std::string text)
{
  std::transform(text.begin(),
    text.end(),
    text.begin(),
    [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

bool endsWith(const std::string& text, const std::string& suffix)
{
  return text.size() >= suffix.size() &&
    text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

std::string trimmed(std::string_view text)
{
  const char* spaces = " \t\r\f\v";
  const std::size_t first = text.find_first_not_of(spaces);
  if (first == std::string_view::npos)
  {
    return {};
  }
  const std::size_t last = text.find_last_not_of(spaces);
  return std::string(text.substr(first, last - first + 1));
}

// A coordinate token: a finite number, or a located error.
double coordinate(std::string_view token, const std::string& name, int line)
{
  double value;
  if (!parseDouble(token, value))
  {
    failAtLine(name, line, "expected a coordinate, got '" + std::string(token) + "'");
  }
  if (!std::isfinite(value))
  {
    failAtLine(name, line, "the coordinate '" + std::string(token) + "' is not finite");
  }
  return value;
}

// A 0-based vertex index, or a located error.
int vertexIndex(std::string_view token, const std::string& name, int line)
{
  long long index;
  if (!parseInt(token, index) || index < 0 || index > std::numeric_limits<int>::max())
  {
    failAtLine(name, line, "expected a 0-based vertex index, got '" + std::string(token) + "'");
  }
  return static_cast<int>(index);
}

// Lines `index`, `lk index`, `index x y z`, `x y z` or `-1 x y z`.
std::vector<LandmarkRecord> parseWhitespaceLandmarks(const std::string& text,
  const std::string& name)
{
  std::vector<LandmarkRecord> records;
  TextScanner scanner(text);
  while (scanner.nextLine())
  {
    std::vector<std::string_view> tokens;
    for (std::string_view token = scanner.nextToken(); !token.empty(); token = scanner.nextToken())
    {
      tokens.push_back(token);
    }
    if (tokens.empty())
    {
      continue;
    }
    const int line = scanner.lineNumber();
    LandmarkRecord record;
    record.Line = line;
    if (tokens[0] == "lk")
    {
      if (tokens.size() != 2)
      {
        failAtLine(name, line, "expected 'lk' and one 0-based vertex index");
      }
      record.Vertex = vertexIndex(tokens[1], name, line);
    }
    else if (tokens.size() == 1)
    {
      record.Vertex = vertexIndex(tokens[0], name, line);
    }
    else if (tokens.size() == 3 || (tokens.size() == 4 && tokens[0] == "-1"))
    {
      const std::size_t first = tokens.size() - 3;
      for (int k = 0; k < 3; ++k)
      {
        record.Point[k] = coordinate(tokens[first + k], name, line);
      }
    }
    else if (tokens.size() == 4)
    {
      record.Vertex = vertexIndex(tokens[0], name, line);
      // The coordinates beside a given index are not used, but they must be
      // numbers, or this is not a landmark file.
      for (std::size_t k = 1; k < 4; ++k)
      {
        double ignored;
        if (!parseDouble(tokens[k], ignored))
        {
          failAtLine(
            name, line, "unexpected '" + std::string(tokens[k]) + "' after the vertex index");
        }
      }
    }
    else
    {
      failAtLine(name,
        line,
        "expected 'index', 'index x y z' or 'x y z', got " + std::to_string(tokens.size()) +
          " values");
    }
    records.push_back(record);
  }
  finishLandmarkIds(records, std::vector<long long>(records.size(), -1), name);
  return records;
}

// One line of a CSV file split into fields; double quotes may enclose a
// field (with "" for a quote inside). Throws for an unterminated quote.
std::vector<std::string> csvFields(std::string_view line, const std::string& name, int lineNumber)
{
  std::vector<std::string> fields;
  std::string field;
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i)
  {
    const char c = line[i];
    if (quoted)
    {
      if (c == '"' && i + 1 < line.size() && line[i + 1] == '"')
      {
        field += '"';
        ++i;
      }
      else if (c == '"')
      {
        quoted = false;
      }
      else
      {
        field += c;
      }
    }
    else if (c == '"')
    {
      quoted = true;
    }
    else if (c == ',')
    {
      fields.push_back(trimmed(field));
      field.clear();
    }
    else
    {
      field += c;
    }
  }
  if (quoted)
  {
    failAtLine(name, lineNumber, "a quoted field is not closed");
  }
  fields.push_back(trimmed(field));
  return fields;
}

// Where the columns a point needs are, from their names (-1 if absent).
struct Columns
{
  int Id = -1, X = -1, Y = -1, Z = -1, Label = -1;
  std::size_t Count = 0;

  static Columns named(const std::vector<std::string>& names)
  {
    Columns columns;
    columns.Count = names.size();
    for (std::size_t k = 0; k < names.size(); ++k)
    {
      const std::string n = lowercase(names[k]);
      int* slot = n == "id" ? &columns.Id
        : n == "x"          ? &columns.X
        : n == "y"          ? &columns.Y
        : n == "z"          ? &columns.Z
        : n == "label"      ? &columns.Label
                            : nullptr;
      if (slot && *slot < 0)
      {
        *slot = static_cast<int>(k);
      }
    }
    return columns;
  }
  bool hasPoint() const { return this->X >= 0 && this->Y >= 0 && this->Z >= 0; }
};

// Splits `text` into lines (1-based numbers), without a UTF-8 byte order mark
// and carriage returns.
template<typename Visit>
void forEachLine(const std::string& text, Visit visit)
{
  std::string_view rest(text);
  if (rest.rfind("\xEF\xBB\xBF", 0) == 0)
  {
    rest.remove_prefix(3);
  }
  int number = 0;
  while (!rest.empty())
  {
    const std::size_t end = rest.find('\n');
    std::string_view line = rest.substr(0, end);
    rest.remove_prefix(end == std::string_view::npos ? rest.size() : end + 1);
    ++number;
    visit(std::string_view(trimmed(line)), number);
  }
}

// A point of a CSV-like line; `strictId`: the id column must hold a
// non-negative integer (plain CSV), otherwise it holds a Slicer id
// (markupLandmarkId: a node name counts as no id).
void addCsvPoint(const std::vector<std::string>& fields,
  const Columns& columns,
  bool strictId,
  const std::string& name,
  int line,
  std::vector<LandmarkRecord>& records,
  std::vector<long long>& ids,
  std::vector<std::string>& idTexts)
{
  // The label is optional: hand-written files stop after the coordinates.
  const int needed = std::max({ columns.X, columns.Y, columns.Z, columns.Id }) + 1;
  if (fields.size() < static_cast<std::size_t>(needed))
  {
    failAtLine(name,
      line,
      "expected at least " + std::to_string(needed) + " comma-separated values, got " +
        std::to_string(fields.size()));
  }
  LandmarkRecord record;
  record.Line = line;
  record.Point = { { coordinate(fields[columns.X], name, line),
    coordinate(fields[columns.Y], name, line),
    coordinate(fields[columns.Z], name, line) } };
  if (columns.Label >= 0 && static_cast<std::size_t>(columns.Label) < fields.size())
  {
    record.Label = fields[columns.Label];
  }
  long long id = -1;
  if (columns.Id >= 0 && !strictId)
  {
    id = markupLandmarkId(fields[columns.Id], "this point", name, line);
  }
  else if (columns.Id >= 0)
  {
    long long value;
    if (!parseInt(fields[columns.Id], value) || value < 0 ||
      value > std::numeric_limits<int>::max())
    {
      failAtLine(
        name, line, "expected a landmark id (an integer >= 0), got '" + fields[columns.Id] + "'");
    }
    id = value;
  }
  records.push_back(record);
  ids.push_back(id);
  idTexts.push_back(columns.Id >= 0 ? fields[columns.Id] : std::string());
}

// 3D Slicer's markups CSV: '#' lines are comments, "# columns = ..." names
// the columns.
std::vector<LandmarkRecord> parseFcsv(const std::string& text, const std::string& name)
{
  Columns columns = Columns::named({ "id",
    "x",
    "y",
    "z",
    "ow",
    "ox",
    "oy",
    "oz",
    "vis",
    "sel",
    "lock",
    "label",
    "desc",
    "associatedNodeID" });
  std::vector<LandmarkRecord> records;
  std::vector<long long> ids;
  std::vector<std::string> idTexts;
  forEachLine(text,
    [&](std::string_view line, int number)
    {
      if (line.empty())
      {
        return;
      }
      if (line.front() == '#')
      {
        const std::string comment = trimmed(line.substr(1));
        if (lowercase(comment).rfind("columns", 0) == 0 && comment.find('=') != std::string::npos)
        {
          columns = Columns::named(csvFields(comment.substr(comment.find('=') + 1), name, number));
          if (!columns.hasPoint())
          {
            failAtLine(name, number, "the columns line names no x, y and z columns");
          }
        }
        return;
      }
      addCsvPoint(
        csvFields(line, name, number), columns, false, name, number, records, ids, idTexts);
    });
  finishLandmarkIds(records, ids, name, idTexts);
  return records;
}

bool isNumber(const std::string& field)
{
  double value;
  return parseDouble(field, value);
}

// `x,y,z[,id]` lines, or columns named by a header line.
std::vector<LandmarkRecord> parseCsv(const std::string& text, const std::string& name)
{
  std::vector<LandmarkRecord> records;
  std::vector<long long> ids;
  std::vector<std::string> idTexts;
  bool first = true;
  Columns header;
  forEachLine(text,
    [&](std::string_view line, int number)
    {
      if (line.empty() || line.front() == '#')
      {
        return;
      }
      const std::vector<std::string> fields = csvFields(line, name, number);
      if (first && !isNumber(fields[0]))
      {
        first = false;
        header = Columns::named(fields);
        if (!header.hasPoint())
        {
          failAtLine(name,
            number,
            "the header names no x, y and z columns (expected x,y,z[,id] or a header naming "
            "them)");
        }
        return;
      }
      first = false;
      Columns columns = header;
      if (!columns.hasPoint())
      {
        if (fields.size() != 3 && fields.size() != 4)
        {
          failAtLine(name,
            number,
            "expected x,y,z or x,y,z,id, got " + std::to_string(fields.size()) + " values");
        }
        columns.X = 0;
        columns.Y = 1;
        columns.Z = 2;
        columns.Id = fields.size() == 4 ? 3 : -1;
      }
      else if (fields.size() != columns.Count)
      {
        failAtLine(name,
          number,
          "expected " + std::to_string(columns.Count) + " values as the header names, got " +
            std::to_string(fields.size()));
      }
      addCsvPoint(fields, columns, true, name, number, records, ids, idTexts);
    });
  // A plain CSV gives ids on every line or on none.
  const auto given = std::count_if(ids.begin(), ids.end(), [](long long id) { return id >= 0; });
  if (given > 0 && given < static_cast<long>(ids.size()))
  {
    const auto missing = std::find(ids.begin(), ids.end(), -1) - ids.begin();
    failAtLine(name,
      records[missing].Line,
      "this line gives no id, but others do (give an id on every line or on none)");
  }
  finishLandmarkIds(records, ids, name);
  return records;
}

} // namespace

void finishLandmarkIds(std::vector<LandmarkRecord>& records,
  const std::vector<long long>& givenIds,
  const std::string& name,
  const std::vector<std::string>& idTexts)
{
  const auto hasId = [](long long id) { return id >= 0; };
  const auto firstWith = std::find_if(givenIds.begin(), givenIds.end(), hasId);
  const auto firstWithout = std::find_if_not(givenIds.begin(), givenIds.end(), hasId);
  const bool given = !records.empty() && firstWithout == givenIds.end();
  if (firstWith != givenIds.end() && firstWithout != givenIds.end())
  {
    // Numbering the rest in file order would silently drop the ids given.
    const std::size_t k = firstWithout - givenIds.begin();
    const std::size_t g = firstWith - givenIds.begin();
    const std::string text = k < idTexts.size() ? idTexts[k] : std::string();
    failAtLine(name,
      records[k].Line,
      (text.empty() ? std::string("this point gives no landmark id")
                    : "the id '" + text + "' is no landmark id (an integer >= 0)") +
        ", but line " + std::to_string(records[g].Line) + " gives one (" +
        std::to_string(givenIds[g]) +
        "): give an integer id to every point or to none (the file order then numbers them)");
  }
  std::map<int, int> lineOfId;
  for (std::size_t k = 0; k < records.size(); ++k)
  {
    records[k].Id = given ? static_cast<int>(givenIds[k]) : static_cast<int>(k);
    const auto [where, inserted] = lineOfId.emplace(records[k].Id, records[k].Line);
    if (!inserted)
    {
      failAtLine(name,
        records[k].Line,
        "landmark id " + std::to_string(records[k].Id) + " is given twice (also on line " +
          std::to_string(where->second) + ")");
    }
  }
}

long long markupLandmarkId(const std::string& text,
  const std::string& what,
  const std::string& name,
  int line)
{
  long long id;
  double number;
  const bool integer = parseInt(text, id);
  if (integer && id >= 0 && id <= std::numeric_limits<int>::max())
  {
    return id;
  }
  if (integer || parseDouble(text, number))
  {
    failAtLine(name,
      line,
      what + " has the id '" + text + "', which is no landmark id (an integer from 0 to " +
        std::to_string(std::numeric_limits<int>::max()) + ")");
  }
  return -1;
}

std::vector<LandmarkRecord> parseLandmarkRecords(const std::string& text, const std::string& name)
{
  const std::string lower = lowercase(name);
  if (endsWith(lower, ".fcsv"))
  {
    return parseFcsv(text, name);
  }
  if (endsWith(lower, ".csv"))
  {
    return parseCsv(text, name);
  }
  return parseWhitespaceLandmarks(text, name);
}

std::vector<LandmarkRecord> readLandmarkRecords(const std::string& path)
{
  std::vector<LandmarkRecord> records = parseLandmarkRecords(readTextFile(path), path);
  if (records.empty())
  {
    throw InputError(path + ": the landmark file lists no landmarks");
  }
  return records;
}

std::vector<int> parseLandmarks(const std::string& text, const std::string& name)
{
  std::vector<int> indices;
  for (const LandmarkRecord& record : parseWhitespaceLandmarks(text, name))
  {
    if (record.Vertex < 0)
    {
      failAtLine(name, record.Line, "a point, where a vertex index is needed");
    }
    indices.push_back(record.Vertex);
  }
  return indices;
}

std::vector<int> readLandmarks(const std::string& path)
{
  std::vector<int> indices = parseLandmarks(readTextFile(path), path);
  if (indices.empty())
  {
    throw InputError(path + ": the landmark file lists no vertices");
  }
  return indices;
}

std::vector<int> landmarkIdsFromIndices(const std::vector<int>& indices,
  std::size_t numberOfVertices,
  const std::string& name)
{
  std::vector<int> ids(numberOfVertices, -1);
  for (std::size_t k = 0; k < indices.size(); ++k)
  {
    const int v = indices[k];
    if (v < 0 || static_cast<std::size_t>(v) >= numberOfVertices)
    {
      throw InputError(name + ": landmark " + std::to_string(k) + " is vertex " +
        std::to_string(v) + ", out of range for a mesh with " + std::to_string(numberOfVertices) +
        " vertices");
    }
    if (ids[v] >= 0)
    {
      throw InputError(name + ": vertex " + std::to_string(v) + " is listed twice (landmarks " +
        std::to_string(ids[v]) + " and " + std::to_string(k) + ")");
    }
    ids[v] = static_cast<int>(k);
  }
  return ids;
}

std::vector<int> landmarkIdsFromRecords(const std::vector<LandmarkRecord>& records,
  std::size_t numberOfVertices,
  const std::string& name)
{
  std::vector<int> ids(numberOfVertices, -1);
  std::vector<int> lineOf(numberOfVertices, 0);
  for (const LandmarkRecord& record : records)
  {
    const int v = record.Vertex;
    if (v < 0 || static_cast<std::size_t>(v) >= numberOfVertices)
    {
      throw InputError(name + ":" + std::to_string(record.Line) + ": landmark " +
        std::to_string(record.Id) + " is vertex " + std::to_string(v) +
        ", out of range for a mesh with " + std::to_string(numberOfVertices) + " vertices");
    }
    if (ids[v] >= 0)
    {
      throw InputError(name + ":" + std::to_string(record.Line) + ": landmark " +
        std::to_string(record.Id) + " falls on vertex " + std::to_string(v) +
        ", which already carries landmark " + std::to_string(ids[v]) + " (line " +
        std::to_string(lineOf[v]) + ")");
    }
    ids[v] = record.Id;
    lineOf[v] = record.Line;
  }
  return ids;
}

} // namespace surfacemaps
