#include "io/OffReader.h"

#include "base/Error.h"
#include "io/TextFile.h"

#include <algorithm>
#include <vector>

namespace surfacemaps
{

namespace
{

// Reads the sections of an OFF file in order: header keyword, counts,
// vertices, faces. Each step leaves the scanner where the next one starts.
class OffParser
{
public:
  OffParser(const std::string& text, const std::string& name)
    : Name(name)
    , Scanner(text)
    , TextSize(text.size())
  {
  }

  PolygonMesh parse()
  {
    this->readCounts(this->readHeader());
    // A count is only a promise: reserve no more than the text can hold
    // (a vertex takes at least 6 bytes, "0 0 0\n"), so a huge count in a
    // small file is reported as truncation instead of allocated.
    this->Mesh.points.reserve(static_cast<std::size_t>(
      std::min<long long>(this->NumberOfVertices, static_cast<long long>(this->TextSize / 6))));
    for (long long v = 0; v < this->NumberOfVertices; ++v)
    {
      this->readVertex(v);
    }
    for (long long f = 0; f < this->NumberOfFaces; ++f)
    {
      this->readFace(f);
    }
    return std::move(this->Mesh);
  }

private:
  [[noreturn]] void fail(const std::string& what) const
  {
    failAtLine(this->Name, this->Scanner.lineNumber(), what);
  }

  std::string_view readHeader();
  void readCounts(std::string_view token);
  void readVertex(long long v);
  void readFace(long long f);

  const std::string& Name;
  TextScanner Scanner;
  std::size_t TextSize;
  PolygonMesh Mesh;
  long long NumberOfVertices = 0;
  long long NumberOfFaces = 0;
  std::vector<int> Corners;
};

// The header keyword is optional; returns the first token of the counts.
std::string_view OffParser::readHeader()
{
  std::string_view token = this->Scanner.firstTokenOfNextLine();
  if (token.empty())
  {
    throw InputError(this->Name + ": the file is empty");
  }
  const bool hasHeader = token.size() >= 3 && token.substr(token.size() - 3) == "OFF";
  if (!hasHeader)
  {
    long long probe;
    if (!parseInt(token, probe))
    {
      this->fail("not an OFF file: it starts with '" + std::string(token) + "'");
    }
    return token;
  }
  if (token != "OFF" && token != "COFF" && token != "NOFF" && token != "CNOFF")
  {
    this->fail("unsupported OFF variant '" + std::string(token) + "'");
  }
  if (this->Scanner.lineExhausted())
  {
    return this->Scanner.firstTokenOfNextLine();
  }
  token = this->Scanner.nextToken();
  if (token == "BINARY")
  {
    this->fail("binary OFF is not supported; convert the file to ASCII");
  }
  return token;
}

// Vertex, face and (optional) edge counts, starting at `token`.
void OffParser::readCounts(std::string_view token)
{
  long long counts[3] = { 0, 0, 0 };
  for (int i = 0; i < 3; ++i)
  {
    if (token.empty() && i == 2)
    {
      break; // the edge count is optional
    }
    if (!parseInt(token, counts[i]) || counts[i] < 0)
    {
      this->fail("expected vertex, face and edge counts, got '" + std::string(token) + "'");
    }
    token = this->Scanner.nextToken();
  }
  this->NumberOfVertices = counts[0];
  this->NumberOfFaces = counts[1];
}

// Vertex `v` of the declared count; anything after x y z is a colour or normal.
void OffParser::readVertex(long long v)
{
  std::string_view token = this->Scanner.firstTokenOfNextLine();
  if (token.empty())
  {
    throw InputError(this->Name + ": the header declares " +
      std::to_string(this->NumberOfVertices) + " vertices, but the file ends after " +
      std::to_string(v) + "; it looks truncated");
  }
  double xyz[3];
  for (int k = 0; k < 3; ++k)
  {
    if (!parseDouble(token, xyz[k]))
    {
      this->fail(token.empty() ? "vertex has " + std::to_string(k) + " coordinates (3 expected)" +
            (this->Scanner.truncatedHere() ? "; the file looks truncated" : "")
                               : "bad vertex coordinate '" + std::string(token) + "'");
    }
    token = this->Scanner.nextToken();
  }
  this->Mesh.points.emplace_back(xyz[0], xyz[1], xyz[2]);
}

// Face `f` of the declared count; anything after its indices is a colour.
void OffParser::readFace(long long f)
{
  std::string_view token = this->Scanner.firstTokenOfNextLine();
  if (token.empty())
  {
    throw InputError(this->Name + ": the header declares " + std::to_string(this->NumberOfFaces) +
      " faces, but the file ends after " + std::to_string(f) + "; it looks truncated");
  }
  long long n;
  if (!parseInt(token, n) || n < 1)
  {
    this->fail("bad face vertex count '" + std::string(token) + "'");
  }
  this->Corners.clear();
  for (long long k = 0; k < n; ++k)
  {
    token = this->Scanner.nextToken();
    long long index;
    if (token.empty())
    {
      this->fail("face declares " + std::to_string(n) + " vertices but lists " + std::to_string(k) +
        (this->Scanner.truncatedHere() ? "; the file looks truncated" : ""));
    }
    if (!parseInt(token, index))
    {
      this->fail("bad vertex index '" + std::string(token) + "'");
    }
    if (index < 0 || index >= this->NumberOfVertices)
    {
      this->fail("face refers to vertex " + std::to_string(index) + ", but the file has " +
        std::to_string(this->NumberOfVertices) + " vertices");
    }
    this->Corners.push_back(static_cast<int>(index));
  }
  if (n < 3)
  {
    this->fail("face has " + std::to_string(n) + " vertices (at least 3 needed)");
  }
  this->Mesh.addFace(this->Corners.begin(), this->Corners.end());
}

} // namespace

PolygonMesh parseOff(const std::string& text, const std::string& name)
{
  return OffParser(text, name).parse();
}

PolygonMesh readOff(const std::string& path)
{
  return parseOff(readTextFile(path), path);
}

} // namespace surfacemaps
