#include "io/PlyReader.h"

#include "io/PlyHeader.h"

#include "base/Error.h"
#include "io/TextFile.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <limits>
#include <optional>
#include <sstream>
#include <vector>

namespace surfacemaps
{

namespace
{
using namespace ply;

// A binary value of type T in host byte order, as a double.
template<typename T>
double decode(const unsigned char* raw)
{
  T v;
  std::memcpy(&v, raw, sizeof(T));
  return v;
}

// Reads values of the body, ASCII or binary, with a clear message on running out.
class BodyReader
{
public:
  BodyReader(const std::string& bytes, std::size_t start, Format format, const std::string& name)
    : Bytes(bytes)
    , Position(start)
    , Fmt(format)
    , Name(name)
  {
    if (format == Format::Ascii)
    {
      this->Scanner.emplace(std::string_view(bytes).substr(start));
    }
  }

  /// Reads one value; false at the end of the data.
  bool read(Type type, double& value)
  {
    return this->Fmt == Format::Ascii ? this->readAscii(value) : this->readBinary(type, value);
  }

  /// True when data follows the values read: another token (ASCII) or a byte
  /// other than a space or line end (binary).
  bool moreData()
  {
    if (this->Fmt == Format::Ascii)
    {
      return !this->Scanner->nextToken().empty() || !this->Scanner->firstTokenOfNextLine().empty();
    }
    return std::any_of(this->Bytes.begin() + static_cast<std::ptrdiff_t>(this->Position),
      this->Bytes.end(),
      [](char c) { return c != '\n' && c != '\r' && c != ' '; });
  }

private:
  // The next token, across lines: ASCII bodies put elements on lines freely.
  bool readAscii(double& value)
  {
    std::string_view token = this->Scanner->nextToken();
    if (token.empty())
    {
      token = this->Scanner->firstTokenOfNextLine();
    }
    if (token.empty())
    {
      return false;
    }
    if (!parseDouble(token, value))
    {
      throw InputError(this->Name + ": bad number '" + std::string(token) + "' in the data");
    }
    return true;
  }

  bool readBinary(Type type, double& value)
  {
    const int size = sizeOf(type);
    if (this->Position + size > this->Bytes.size())
    {
      return false;
    }
    unsigned char raw[8];
    std::memcpy(raw, this->Bytes.data() + this->Position, size);
    this->Position += size;
    const bool little = this->Fmt == Format::BinaryLittle;
    const std::uint16_t probe = 1;
    const bool hostLittle = *reinterpret_cast<const unsigned char*>(&probe) == 1;
    if (little != hostLittle)
    {
      std::reverse(raw, raw + size);
    }
    switch (type)
    {
      case Type::Int8:
        value = decode<std::int8_t>(raw);
        return true;
      case Type::UInt8:
        value = decode<std::uint8_t>(raw);
        return true;
      case Type::Int16:
        value = decode<std::int16_t>(raw);
        return true;
      case Type::UInt16:
        value = decode<std::uint16_t>(raw);
        return true;
      case Type::Int32:
        value = decode<std::int32_t>(raw);
        return true;
      case Type::UInt32:
        value = decode<std::uint32_t>(raw);
        return true;
      case Type::Float32:
        value = decode<float>(raw);
        return true;
      case Type::Float64:
        value = decode<double>(raw);
        return true;
      default:
        return false;
    }
  }

  const std::string& Bytes;
  std::size_t Position;
  Format Fmt;
  const std::string& Name;
  std::optional<TextScanner> Scanner;
};

// The type of a property's own point array (see readPly): uchar, float and
// double stay; uint becomes Int64 (Int32 cannot hold it), other integers Int32.
PolygonMeshPointArray::Type arrayTypeOf(Type type)
{
  switch (type)
  {
    case Type::UInt8:
      return PolygonMeshPointArray::Type::UInt8;
    case Type::UInt32:
      return PolygonMeshPointArray::Type::Int64;
    case Type::Float32:
      return PolygonMeshPointArray::Type::Float32;
    case Type::Float64:
      return PolygonMeshPointArray::Type::Float64;
    default:
      return PolygonMeshPointArray::Type::Int32;
  }
}

// Groups the vertex element's scalar properties into point arrays: colour,
// normals and texture coordinates first, then each remaining property on its
// own. A property goes into one array at most; x, y and z into none.
class PointArrayPlanner
{
public:
  PointArrayPlanner(const Element& e,
    std::vector<PolygonMeshPointArray>& arrays,
    std::vector<std::vector<int>>& arrayProperties)
    : E(e)
    , Arrays(arrays)
    , ArrayProperties(arrayProperties)
    , Used(e.properties.size(), false)
  {
    for (const char* c : { "x", "y", "z" })
    {
      const int k = this->find(c);
      if (k >= 0)
      {
        this->Used[k] = true;
      }
    }
  }

  void addColour()
  {
    std::vector<int> colour = this->group({ "red", "green", "blue" });
    if (colour.empty())
    {
      return;
    }
    const std::vector<int> alpha = this->group({ "alpha" });
    colour.insert(colour.end(), alpha.begin(), alpha.end());
    bool bytes = true;
    for (int k : colour)
    {
      bytes = bytes && this->E.properties[k].type == Type::UInt8;
    }
    this->add(colour.size() == 4 ? "RGBA" : "RGB",
      colour,
      bytes ? PolygonMeshPointArray::Type::UInt8 : PolygonMeshPointArray::Type::Float32);
  }

  void addNormals()
  {
    const std::vector<int> normals = this->group({ "nx", "ny", "nz" });
    if (!normals.empty())
    {
      this->add("Normals", normals, PolygonMeshPointArray::Type::Float32);
    }
  }

  // The first of the usual names for texture coordinates that is complete.
  void addTexCoords()
  {
    for (const auto& names : std::vector<std::vector<std::string>>{
           { "u", "v" }, { "s", "t" }, { "texture_u", "texture_v" }, { "texture_s", "texture_t" } })
    {
      const std::vector<int> tcoords = this->group(names);
      if (!tcoords.empty())
      {
        this->add("TCoords", tcoords, PolygonMeshPointArray::Type::Float32);
        break;
      }
    }
  }

  void addRemaining()
  {
    for (std::size_t k = 0; k < this->E.properties.size(); ++k)
    {
      const Property& p = this->E.properties[k];
      if (this->Used[k] || p.isList)
      {
        continue;
      }
      this->add(p.name, { static_cast<int>(k) }, arrayTypeOf(p.type));
    }
  }

private:
  // The position of the scalar property `name`, or -1.
  int find(const std::string& name) const
  {
    for (std::size_t k = 0; k < this->E.properties.size(); ++k)
    {
      if (!this->E.properties[k].isList && this->E.properties[k].name == name)
      {
        return static_cast<int>(k);
      }
    }
    return -1;
  }

  // A named group: all of its properties present and unused, as VTK's reader
  // needs them; empty otherwise.
  std::vector<int> group(const std::vector<std::string>& names) const
  {
    std::vector<int> properties;
    for (const std::string& n : names)
    {
      const int k = this->find(n);
      if (k < 0 || this->Used[k])
      {
        return std::vector<int>();
      }
      properties.push_back(k);
    }
    return properties;
  }

  void add(const std::string& name,
    const std::vector<int>& properties,
    PolygonMeshPointArray::Type type)
  {
    for (const PolygonMeshPointArray& a : this->Arrays)
    {
      if (a.name == name)
      {
        return; // the first of two same-named arrays wins
      }
    }
    PolygonMeshPointArray array;
    array.name = name;
    array.components = static_cast<int>(properties.size());
    array.type = type;
    this->Arrays.push_back(std::move(array));
    this->ArrayProperties.push_back(properties);
    for (int k : properties)
    {
      this->Used[k] = true;
    }
  }

  const Element& E;
  std::vector<PolygonMeshPointArray>& Arrays;
  std::vector<std::vector<int>>& ArrayProperties;
  std::vector<bool> Used;
};

// Reads the body element by element, in header order, into the mesh: vertex
// x, y, z; face vertex_indices (or vertex_index) and texcoord lists.
class MeshBuilder
{
public:
  MeshBuilder(const std::string& bytes, const Header& header, const std::string& name)
    : Name(name)
    , Body(bytes, header.bodyStart, header.format, name)
  {
  }

  void readElement(const Element& e);
  /// Throws when data follows the last element: the header declares fewer
  /// instances than the file holds (read as they are, the faces left over
  /// would show up as holes, far from their cause).
  void requireEnd(const Header& header);
  PolygonMesh finish();

private:
  [[noreturn]] void truncated(const Element& e, long long i) const
  {
    throw InputError(this->Name + ": the header declares " + std::to_string(e.count) + " " +
      e.name + " elements, but the data ends in element " + std::to_string(i) +
      "; the file looks truncated");
  }

  std::array<int, 3> coordinateProperties(const Element& e) const;
  void planPointArrays(const Element& e);
  void readInstance(const Element& e, long long i, bool isFace, std::vector<double>& values);
  void readList(const Element& e, long long i, const Property& p);
  void addFace(long long i);

  const std::string& Name;
  BodyReader Body;
  PolygonMesh Mesh;
  /// Per point array of the mesh, the vertex properties giving its components.
  std::vector<std::vector<int>> ArrayProperties;
  std::vector<Eigen::Vector2d> TexCoords;
  bool AnyTex = false;
  std::vector<double> List;
};

void MeshBuilder::readElement(const Element& e)
{
  const bool isVertex = e.name == "vertex";
  const bool isFace = e.name == "face";
  const std::array<int, 3> xyz =
    isVertex ? this->coordinateProperties(e) : std::array<int, 3>{ -1, -1, -1 };
  if (e.properties.empty())
  {
    return; // nothing to read however many instances it declares
  }
  if (isVertex)
  {
    this->planPointArrays(e);
  }
  std::vector<double> values(e.properties.size());
  for (long long i = 0; i < e.count; ++i)
  {
    this->readInstance(e, i, isFace, values);
    if (isVertex)
    {
      this->Mesh.points.emplace_back(values[xyz[0]], values[xyz[1]], values[xyz[2]]);
      for (std::size_t a = 0; a < this->ArrayProperties.size(); ++a)
      {
        for (int k : this->ArrayProperties[a])
        {
          this->Mesh.pointArrays[a].values.push_back(values[k]);
        }
      }
    }
  }
}

// The point arrays of the vertex element's scalar properties (see readPly).
void MeshBuilder::planPointArrays(const Element& e)
{
  if (!this->Mesh.pointArrays.empty())
  {
    return; // a second vertex element: its points are read, its arrays not
  }
  PointArrayPlanner plan(e, this->Mesh.pointArrays, this->ArrayProperties);
  plan.addColour();
  plan.addNormals();
  plan.addTexCoords();
  plan.addRemaining();
}

// Positions of the x, y and z properties of the vertex element.
std::array<int, 3> MeshBuilder::coordinateProperties(const Element& e) const
{
  std::array<int, 3> xyz{ -1, -1, -1 };
  for (std::size_t k = 0; k < e.properties.size(); ++k)
  {
    const std::string& p = e.properties[k].name;
    if (p == "x" || p == "y" || p == "z")
    {
      xyz[p[0] - 'x'] = static_cast<int>(k);
    }
  }
  if (xyz[0] < 0 || xyz[1] < 0 || xyz[2] < 0)
  {
    throw InputError(this->Name + ": the vertex element lacks an x, y or z property");
  }
  return xyz;
}

// Instance `i` of element `e`: scalars into `values`, lists used as they come.
void MeshBuilder::readInstance(const Element& e,
  long long i,
  bool isFace,
  std::vector<double>& values)
{
  bool haveFace = false;
  for (std::size_t k = 0; k < e.properties.size(); ++k)
  {
    const Property& p = e.properties[k];
    if (!p.isList)
    {
      if (!this->Body.read(p.type, values[k]))
      {
        this->truncated(e, i);
      }
      continue;
    }
    this->readList(e, i, p);
    if (isFace && (p.name == "vertex_indices" || p.name == "vertex_index") && !haveFace)
    {
      haveFace = true;
      this->addFace(i);
    }
    else if (isFace && p.name == "texcoord")
    {
      this->AnyTex = true;
      for (std::size_t c = 0; c + 1 < this->List.size(); c += 2)
      {
        this->TexCoords.emplace_back(this->List[c], this->List[c + 1]);
      }
    }
  }
}

void MeshBuilder::readList(const Element& e, long long i, const Property& p)
{
  double countValue;
  if (!this->Body.read(p.countType, countValue))
  {
    this->truncated(e, i);
  }
  if (countValue < 0 || countValue > 1e6 || countValue != static_cast<long long>(countValue))
  {
    throw InputError(this->Name + ": " + e.name + " " + std::to_string(i) + " has a list of " +
      std::to_string(countValue) + " entries");
  }
  this->List.resize(static_cast<std::size_t>(countValue));
  for (double& v : this->List)
  {
    if (!this->Body.read(p.type, v))
    {
      this->truncated(e, i);
    }
  }
}

// Face `i` from the list just read.
void MeshBuilder::addFace(long long i)
{
  for (double v : this->List)
  {
    // In range first: only then is the conversion to an integer defined.
    if (!(v >= 0 && v < static_cast<double>(this->Mesh.points.size())) ||
      v != static_cast<long long>(v))
    {
      std::ostringstream index;
      index.precision(17);
      index << v;
      throw InputError(this->Name + ": face " + std::to_string(i) + " refers to vertex " +
        index.str() + ", but the file has " + std::to_string(this->Mesh.points.size()) +
        " vertices");
    }
    this->Mesh.faceVertices.push_back(static_cast<int>(v));
  }
  this->Mesh.faceOffsets.push_back(static_cast<int>(this->Mesh.faceVertices.size()));
}

void MeshBuilder::requireEnd(const Header& header)
{
  if (!this->Body.moreData())
  {
    return;
  }
  std::string counts;
  for (const Element& e : header.elements)
  {
    counts += (counts.empty() ? "" : ", ") + std::to_string(e.count) + " " + e.name;
  }
  throw InputError(this->Name + ": the data goes on after the elements the header declares (" +
    counts + "): the header's counts do not match the file");
}

PolygonMesh MeshBuilder::finish()
{
  if (this->AnyTex && this->TexCoords.size() == this->Mesh.faceVertices.size())
  {
    this->Mesh.cornerTexCoords = std::move(this->TexCoords);
  }
  return std::move(this->Mesh);
}

} // namespace

PolygonMesh parsePly(const std::string& bytes, const std::string& name)
{
  const Header header = ply::parseHeader(bytes, name);
  MeshBuilder builder(bytes, header, name);
  for (const Element& e : header.elements)
  {
    builder.readElement(e);
  }
  builder.requireEnd(header);
  return builder.finish();
}

PolygonMesh readPly(const std::string& path)
{
  return parsePly(readTextFile(path), path);
}

} // namespace surfacemaps
