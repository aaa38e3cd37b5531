#include "io/ObjReader.h"

#include "base/InputError.h"
#include "io/TextFile.h"

#include <limits>

namespace surfacemaps
{

namespace
{

// Resolves a 1-based (or negative, relative) OBJ index against the `count`
// entries defined so far; returns -1 if it refers to none of them.
long long resolveIndex(long long index, std::size_t count)
{
  if (index > 0 && static_cast<std::size_t>(index) <= count)
  {
    return index - 1;
  }
  if (index < 0 && static_cast<std::size_t>(-index) <= count)
  {
    return static_cast<long long>(count) + index;
  }
  return -1;
}

// Reads an OBJ file line by line. Indices are resolved as they come: OBJ
// refers only to vertices and texture coordinates defined before.
class ObjParser
{
public:
  ObjParser(const std::string& text, const std::string& name)
    : Name(name)
    , Scanner(text)
  {
  }

  PolygonMesh parse();

private:
  [[noreturn]] void fail(const std::string& what) const
  {
    failAtLine(this->Name, this->Scanner.lineNumber(), what);
  }

  int readNumbers(const char* what, double* values, int keep);
  void readVertex();
  void readTexCoord();
  void readFace();
  void readCorner(std::string_view token);
  PolygonMesh finish();

  const std::string& Name;
  TextScanner Scanner;
  PolygonMesh Mesh;
  std::vector<Eigen::Vector2d> TexCoords;
  std::vector<long long> CornerTex; // index into TexCoords per corner, -1 none
  std::vector<int> Corners;
  bool AnyTex = false;
};

PolygonMesh ObjParser::parse()
{
  while (this->Scanner.nextLine())
  {
    const std::string_view keyword = this->Scanner.nextToken();
    if (keyword == "v")
    {
      this->readVertex();
    }
    else if (keyword == "vt")
    {
      this->readTexCoord();
    }
    else if (keyword == "f")
    {
      this->readFace();
    }
    else if (keyword == "l" || keyword == "p")
    {
      ++this->Mesh.nonPolygonCells;
    }
    // Empty lines, vn, vp, o, g, s, usemtl, mtllib and others carry nothing we use.
  }
  return this->finish();
}

// The rest of the line as numbers, the first `keep` of them into `values`;
// returns how many there were.
int ObjParser::readNumbers(const char* what, double* values, int keep)
{
  int n = 0;
  for (std::string_view token = this->Scanner.nextToken(); !token.empty();
       token = this->Scanner.nextToken())
  {
    double value;
    if (!parseDouble(token, value))
    {
      this->fail(std::string("bad ") + what + " '" + std::string(token) + "'");
    }
    if (n < keep)
    {
      values[n] = value;
    }
    ++n;
  }
  return n;
}

void ObjParser::readVertex()
{
  double xyz[3];
  const int n = this->readNumbers("vertex coordinate", xyz, 3);
  // 3 coordinates, optionally w or an RGB colour.
  if (n != 3 && n != 4 && n != 6 && n != 7)
  {
    this->fail("vertex has " + std::to_string(n) + " coordinates (3 expected)" +
      (this->Scanner.truncatedHere() ? "; the file ends without a newline and looks truncated"
                                     : ""));
  }
  this->Mesh.points.emplace_back(xyz[0], xyz[1], xyz[2]);
}

void ObjParser::readTexCoord()
{
  double uv[2] = { 0.0, 0.0 };
  const int n = this->readNumbers("texture coordinate", uv, 2);
  if (n < 1 || n > 3)
  {
    this->fail("texture coordinate has " + std::to_string(n) + " values");
  }
  this->TexCoords.emplace_back(uv[0], uv[1]);
}

void ObjParser::readFace()
{
  this->Corners.clear();
  for (std::string_view token = this->Scanner.nextToken(); !token.empty();
       token = this->Scanner.nextToken())
  {
    this->readCorner(token);
  }
  const std::size_t n = this->Corners.size();
  if (n < 3)
  {
    std::string what =
      "face has " + std::to_string(n) + (n == 1 ? " vertex" : " vertices") + " (at least 3 needed)";
    if (this->Scanner.truncatedHere())
    {
      what += "; the file ends without a newline and looks truncated";
    }
    this->fail(what);
  }
  this->Mesh.addFace(this->Corners.begin(), this->Corners.end());
}

// One corner "v", "v/t", "v//n" or "v/t/n"; normals are ignored.
void ObjParser::readCorner(std::string_view token)
{
  const std::size_t slash = token.find('/');
  long long v;
  if (!parseInt(token.substr(0, slash), v))
  {
    this->fail("bad face corner '" + std::string(token) + "'");
  }
  const long long vi = resolveIndex(v, this->Mesh.points.size());
  if (vi < 0)
  {
    this->fail("face refers to vertex " + std::to_string(v) + ", but " +
      std::to_string(this->Mesh.points.size()) + " vertices are defined before it");
  }
  long long ti = -1;
  if (slash != std::string_view::npos)
  {
    std::string_view rest = token.substr(slash + 1);
    const std::string_view tex = rest.substr(0, rest.find('/'));
    if (!tex.empty())
    {
      long long t;
      if (!parseInt(tex, t) || (ti = resolveIndex(t, this->TexCoords.size())) < 0)
      {
        this->fail("bad texture index in face corner '" + std::string(token) + "'");
      }
      this->AnyTex = true;
    }
  }
  this->Corners.push_back(static_cast<int>(vi));
  this->CornerTex.push_back(ti);
}

PolygonMesh ObjParser::finish()
{
  if (this->Scanner.endsWithoutNewline() && this->Mesh.numberOfFaces() == 0 &&
    !this->Mesh.points.empty())
  {
    throw InputError(
      this->Name + ": the file ends in the vertex list without faces; it looks truncated");
  }
  if (this->AnyTex)
  {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    this->Mesh.cornerTexCoords.reserve(this->CornerTex.size());
    for (long long t : this->CornerTex)
    {
      this->Mesh.cornerTexCoords.push_back(t >= 0 ? this->TexCoords[t] : Eigen::Vector2d(nan, nan));
    }
  }
  return std::move(this->Mesh);
}

} // namespace

PolygonMesh parseObj(const std::string& text, const std::string& name)
{
  return ObjParser(text, name).parse();
}

PolygonMesh readObj(const std::string& path)
{
  return parseObj(readTextFile(path), path);
}

} // namespace surfacemaps
