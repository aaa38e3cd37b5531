// SurfaceMaps engine: the PLY header's parser.
#include "io/PlyHeader.h"

#include "base/Error.h"
#include "io/TextFile.h"

#include <sstream>

namespace surfacemaps
{
namespace ply
{

namespace
{

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

} // namespace

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

namespace
{

// Reads the header line by line; format, element and property lines matter.
class HeaderParser
{
public:
  explicit HeaderParser(const std::string& name)
    : Name(name)
  {
  }

  Header parse(const std::string& bytes);

private:
  [[noreturn]] void fail(const std::string& what) const
  {
    failAtLine(this->Name, this->LineNumber, what);
  }

  void readFormat(std::istringstream& words);
  void readElement(std::istringstream& words, const std::string& line);
  void readProperty(std::istringstream& words, const std::string& line);

  const std::string& Name;
  Header Result;
  bool HaveFormat = false;
  int LineNumber = 0;
};

Header HeaderParser::parse(const std::string& bytes)
{
  if (bytes.compare(0, 3, "ply") != 0 || bytes.size() < 4 || (bytes[3] != '\n' && bytes[3] != '\r'))
  {
    throw InputError(this->Name + ": not a PLY file (it does not start with 'ply')");
  }
  const std::size_t headerEnd = bytes.find("end_header");
  if (headerEnd == std::string::npos)
  {
    throw InputError(
      this->Name + ": the PLY header has no end_header line; the file looks truncated");
  }
  const std::size_t newline = bytes.find('\n', headerEnd);
  this->Result.bodyStart = newline == std::string::npos ? bytes.size() : newline + 1;

  std::istringstream header(bytes.substr(0, headerEnd));
  std::string line;
  while (std::getline(header, line))
  {
    ++this->LineNumber;
    std::istringstream words(line);
    std::string keyword;
    words >> keyword;
    if (keyword == "format")
    {
      this->readFormat(words);
    }
    else if (keyword == "element")
    {
      this->readElement(words, line);
    }
    else if (keyword == "property")
    {
      this->readProperty(words, line);
    }
    // ply, comment, obj_info: nothing to do.
  }
  if (!this->HaveFormat)
  {
    throw InputError(this->Name + ": the PLY header has no format line");
  }
  return std::move(this->Result);
}

void HeaderParser::readFormat(std::istringstream& words)
{
  std::string f;
  words >> f;
  if (f == "ascii")
    this->Result.format = Format::Ascii;
  else if (f == "binary_little_endian")
    this->Result.format = Format::BinaryLittle;
  else if (f == "binary_big_endian")
    this->Result.format = Format::BinaryBig;
  else
    this->fail("unknown PLY format '" + f + "'");
  this->HaveFormat = true;
}

void HeaderParser::readElement(std::istringstream& words, const std::string& line)
{
  Element e;
  if (!(words >> e.name >> e.count) || e.count < 0)
  {
    this->fail("bad element declaration '" + line + "'");
  }
  this->Result.elements.push_back(e);
}

void HeaderParser::readProperty(std::istringstream& words, const std::string& line)
{
  if (this->Result.elements.empty())
  {
    this->fail("property before any element");
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
      this->fail("bad list count type '" + countType + "'");
    }
  }
  else
  {
    words >> p.name;
    p.type = typeFromName(type);
  }
  if (p.type == Type::Invalid || p.name.empty())
  {
    this->fail("bad property declaration '" + line + "'");
  }
  this->Result.elements.back().properties.push_back(p);
}

} // namespace

Header parseHeader(const std::string& bytes, const std::string& name)
{
  return HeaderParser(name).parse(bytes);
}

} // namespace ply
} // namespace surfacemaps
