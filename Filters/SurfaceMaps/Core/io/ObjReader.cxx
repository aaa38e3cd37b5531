#include "io/ObjReader.h"

#include "base/Error.h"
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

// Per-corner values: the file's list of values and, per corner read so far,
// an index into it (-1 none).
template<typename Value>
struct CornerValues
{
  std::vector<Value> values;
  std::vector<long long> corners;
  bool any = false;

  // One entry per corner, NaN where a corner has none; empty if no corner has one.
  std::vector<Value> perCorner() const
  {
    std::vector<Value> result;
    if (!this->any)
    {
      return result;
    }
    result.reserve(this->corners.size());
    for (long long i : this->corners)
    {
      result.push_back(
        i >= 0 ? this->values[i] : Value::Constant(std::numeric_limits<double>::quiet_NaN()));
    }
    return result;
  }
};

// Reads an OBJ file line by line. Indices are resolved as they come: OBJ
// refers only to vertices, texture coordinates and normals defined before.
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
  void readNormal();
  void readFace();
  void readCorner(std::string_view token);
  template<typename Value>
  void readCornerIndex(std::string_view part,
    std::string_view token,
    const char* what,
    CornerValues<Value>& into);
  PolygonMesh finish();

  const std::string& Name;
  TextScanner Scanner;
  PolygonMesh Mesh;
  CornerValues<Eigen::Vector2d> TexCoords;
  CornerValues<Eigen::Vector3d> Normals;
  std::vector<int> Corners;
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
    else if (keyword == "vn")
    {
      this->readNormal();
    }
    else if (keyword == "f")
    {
      this->readFace();
    }
    else if (keyword == "l" || keyword == "p")
    {
      ++this->Mesh.nonPolygonCells;
    }
    // Empty lines, vp, o, g, s, usemtl, mtllib and others carry nothing we use.
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
  this->TexCoords.values.emplace_back(uv[0], uv[1]);
}

void ObjParser::readNormal()
{
  double xyz[3];
  const int n = this->readNumbers("normal coordinate", xyz, 3);
  if (n != 3)
  {
    this->fail("normal has " + std::to_string(n) + " coordinates (3 expected)");
  }
  this->Normals.values.emplace_back(xyz[0], xyz[1], xyz[2]);
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

// One corner "v", "v/t", "v//n" or "v/t/n".
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
  std::string_view tex, normal;
  if (slash != std::string_view::npos)
  {
    const std::string_view rest = token.substr(slash + 1);
    const std::size_t second = rest.find('/');
    tex = rest.substr(0, second);
    normal = second == std::string_view::npos ? std::string_view() : rest.substr(second + 1);
  }
  this->readCornerIndex(tex, token, "texture", this->TexCoords);
  this->readCornerIndex(normal, token, "normal", this->Normals);
  this->Corners.push_back(static_cast<int>(vi));
}

// The corner's index `part` (empty: none) into `into`, recorded for this
// corner; an index that is not a number or refers to no value defined
// before fails naming the corner.
template<typename Value>
void ObjParser::readCornerIndex(std::string_view part,
  std::string_view token,
  const char* what,
  CornerValues<Value>& into)
{
  long long index = -1;
  if (!part.empty())
  {
    long long i;
    if (!parseInt(part, i) || (index = resolveIndex(i, into.values.size())) < 0)
    {
      this->fail(std::string("bad ") + what + " index in face corner '" + std::string(token) +
        "' (" + std::to_string(into.values.size()) + " defined before it)");
    }
    into.any = true;
  }
  into.corners.push_back(index);
}

PolygonMesh ObjParser::finish()
{
  if (this->Scanner.endsWithoutNewline() && this->Mesh.numberOfFaces() == 0 &&
    !this->Mesh.points.empty())
  {
    throw InputError(
      this->Name + ": the file ends in the vertex list without faces; it looks truncated");
  }
  this->Mesh.cornerTexCoords = this->TexCoords.perCorner();
  this->Mesh.cornerNormals = this->Normals.perCorner();
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
