#include "io/PlyReader.h"

#include "base/InputError.h"
#include "io/TextFile.h"

#include <algorithm>
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

enum class Type
{
  Int8,
  UInt8,
  Int16,
  UInt16,
  Int32,
  UInt32,
  Float32,
  Float64,
  Invalid
};

Type typeFromName(const std::string& name)
{
  if (name == "char" || name == "int8")
    return Type::Int8;
  if (name == "uchar" || name == "uint8")
    return Type::UInt8;
  if (name == "short" || name == "int16")
    return Type::Int16;
  if (name == "ushort" || name == "uint16")
    return Type::UInt16;
  if (name == "int" || name == "int32")
    return Type::Int32;
  if (name == "uint" || name == "uint32")
    return Type::UInt32;
  if (name == "float" || name == "float32")
    return Type::Float32;
  if (name == "double" || name == "float64")
    return Type::Float64;
  return Type::Invalid;
}

int sizeOf(Type t)
{
  switch (t)
  {
    case Type::Int8:
    case Type::UInt8:
      return 1;
    case Type::Int16:
    case Type::UInt16:
      return 2;
    case Type::Int32:
    case Type::UInt32:
    case Type::Float32:
      return 4;
    case Type::Float64:
      return 8;
    default:
      return 0;
  }
}

struct Property
{
  std::string name;
  Type type = Type::Invalid;
  bool isList = false;
  Type countType = Type::Invalid;
};

struct Element
{
  std::string name;
  long long count = 0;
  std::vector<Property> properties;
};

enum class Format
{
  Ascii,
  BinaryLittle,
  BinaryBig
};

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
    if (this->Fmt == Format::Ascii)
    {
      std::string_view token;
      while ((token = this->Scanner->nextToken()).empty())
      {
        if (!this->Scanner->nextLine())
        {
          return false;
        }
      }
      if (!parseDouble(token, value))
      {
        throw InputError(this->Name + ": bad number '" + std::string(token) + "' in the data");
      }
      return true;
    }
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
      {
        std::int8_t v;
        std::memcpy(&v, raw, 1);
        value = v;
        break;
      }
      case Type::UInt8:
      {
        std::uint8_t v;
        std::memcpy(&v, raw, 1);
        value = v;
        break;
      }
      case Type::Int16:
      {
        std::int16_t v;
        std::memcpy(&v, raw, 2);
        value = v;
        break;
      }
      case Type::UInt16:
      {
        std::uint16_t v;
        std::memcpy(&v, raw, 2);
        value = v;
        break;
      }
      case Type::Int32:
      {
        std::int32_t v;
        std::memcpy(&v, raw, 4);
        value = v;
        break;
      }
      case Type::UInt32:
      {
        std::uint32_t v;
        std::memcpy(&v, raw, 4);
        value = v;
        break;
      }
      case Type::Float32:
      {
        float v;
        std::memcpy(&v, raw, 4);
        value = v;
        break;
      }
      case Type::Float64:
      {
        double v;
        std::memcpy(&v, raw, 8);
        value = v;
        break;
      }
      default:
        return false;
    }
    return true;
  }

private:
  const std::string& Bytes;
  std::size_t Position;
  Format Fmt;
  const std::string& Name;
  std::optional<TextScanner> Scanner;
};

} // namespace

PolygonMesh parsePly(const std::string& bytes, const std::string& name)
{
  if (bytes.compare(0, 3, "ply") != 0 || bytes.size() < 4 || (bytes[3] != '\n' && bytes[3] != '\r'))
  {
    throw InputError(name + ": not a PLY file (it does not start with 'ply')");
  }
  const std::size_t headerEnd = bytes.find("end_header");
  if (headerEnd == std::string::npos)
  {
    throw InputError(name + ": the PLY header has no end_header line; the file looks truncated");
  }
  std::size_t bodyStart = bytes.find('\n', headerEnd);
  bodyStart = bodyStart == std::string::npos ? bytes.size() : bodyStart + 1;

  Format format = Format::Ascii;
  bool haveFormat = false;
  std::vector<Element> elements;
  std::istringstream header(bytes.substr(0, headerEnd));
  std::string line;
  int lineNumber = 0;
  while (std::getline(header, line))
  {
    ++lineNumber;
    std::istringstream words(line);
    std::string keyword;
    words >> keyword;
    auto fail = [&](const std::string& what)
    { throw InputError(name + ":" + std::to_string(lineNumber) + ": " + what); };
    if (keyword == "format")
    {
      std::string f;
      words >> f;
      if (f == "ascii")
        format = Format::Ascii;
      else if (f == "binary_little_endian")
        format = Format::BinaryLittle;
      else if (f == "binary_big_endian")
        format = Format::BinaryBig;
      else
        fail("unknown PLY format '" + f + "'");
      haveFormat = true;
    }
    else if (keyword == "element")
    {
      Element e;
      if (!(words >> e.name >> e.count) || e.count < 0)
      {
        fail("bad element declaration '" + line + "'");
      }
      elements.push_back(e);
    }
    else if (keyword == "property")
    {
      if (elements.empty())
      {
        fail("property before any element");
      }
      Property p;
      std::string type;
      words >> type;
      if (type == "list")
      {
        std::string countType, itemType;
        words >> countType >> itemType >> p.name;
        p.isList = true;
        p.countType = typeFromName(countType);
        p.type = typeFromName(itemType);
        if (p.countType == Type::Invalid || p.countType == Type::Float32 ||
          p.countType == Type::Float64)
        {
          fail("bad list count type '" + countType + "'");
        }
      }
      else
      {
        words >> p.name;
        p.type = typeFromName(type);
      }
      if (p.type == Type::Invalid || p.name.empty())
      {
        fail("bad property declaration '" + line + "'");
      }
      elements.back().properties.push_back(p);
    }
    // ply, comment, obj_info: nothing to do.
  }
  if (!haveFormat)
  {
    throw InputError(name + ": the PLY header has no format line");
  }

  PolygonMesh mesh;
  std::vector<Eigen::Vector2d> texCoords;
  bool anyTex = false;
  BodyReader body(bytes, bodyStart, format, name);
  std::vector<double> list;
  for (const Element& e : elements)
  {
    const bool isVertex = e.name == "vertex";
    const bool isFace = e.name == "face";
    int xyz[3] = { -1, -1, -1 };
    for (std::size_t k = 0; k < e.properties.size(); ++k)
    {
      const std::string& p = e.properties[k].name;
      if (isVertex && (p == "x" || p == "y" || p == "z"))
      {
        xyz[p[0] - 'x'] = static_cast<int>(k);
      }
    }
    if (isVertex && (xyz[0] < 0 || xyz[1] < 0 || xyz[2] < 0))
    {
      throw InputError(name + ": the vertex element lacks an x, y or z property");
    }
    std::vector<double> values(e.properties.size());
    for (long long i = 0; i < e.count; ++i)
    {
      bool haveFace = false;
      for (std::size_t k = 0; k < e.properties.size(); ++k)
      {
        const Property& p = e.properties[k];
        auto truncated = [&]()
        {
          throw InputError(name + ": the header declares " + std::to_string(e.count) + " " +
            e.name + " elements, but the data ends in element " + std::to_string(i) +
            "; the file looks truncated");
        };
        if (!p.isList)
        {
          if (!body.read(p.type, values[k]))
          {
            truncated();
          }
          continue;
        }
        double countValue;
        if (!body.read(p.countType, countValue))
        {
          truncated();
        }
        if (countValue < 0 || countValue > 1e6 || countValue != static_cast<long long>(countValue))
        {
          throw InputError(name + ": " + e.name + " " + std::to_string(i) + " has a list of " +
            std::to_string(countValue) + " entries");
        }
        list.resize(static_cast<std::size_t>(countValue));
        for (double& v : list)
        {
          if (!body.read(p.type, v))
          {
            truncated();
          }
        }
        if (isFace && (p.name == "vertex_indices" || p.name == "vertex_index") && !haveFace)
        {
          haveFace = true;
          for (double v : list)
          {
            if (v < 0 || v >= static_cast<double>(mesh.points.size()) ||
              v != static_cast<long long>(v))
            {
              throw InputError(name + ": face " + std::to_string(i) + " refers to vertex " +
                std::to_string(static_cast<long long>(v)) + ", but the file has " +
                std::to_string(mesh.points.size()) + " vertices");
            }
            mesh.faceVertices.push_back(static_cast<int>(v));
          }
          mesh.faceOffsets.push_back(static_cast<int>(mesh.faceVertices.size()));
        }
        else if (isFace && p.name == "texcoord")
        {
          anyTex = true;
          for (std::size_t c = 0; c + 1 < list.size(); c += 2)
          {
            texCoords.emplace_back(list[c], list[c + 1]);
          }
        }
      }
      if (isVertex)
      {
        mesh.points.emplace_back(values[xyz[0]], values[xyz[1]], values[xyz[2]]);
      }
    }
  }
  if (anyTex && texCoords.size() == mesh.faceVertices.size())
  {
    mesh.cornerTexCoords = std::move(texCoords);
  }
  return mesh;
}

PolygonMesh readPly(const std::string& path)
{
  return parsePly(readTextFile(path), path);
}

} // namespace surfacemaps
