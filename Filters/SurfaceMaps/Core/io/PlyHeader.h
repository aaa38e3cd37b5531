// SurfaceMaps engine: the header of a PLY file. Owns the header's model
// (elements, their properties and types, the format) and its parser; the
// body is read by PlyReader.cxx.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace surfacemaps
{
namespace ply
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

struct Header
{
  Format format = Format::Ascii;
  std::vector<Element> elements;
  /// Offset of the first byte after the end_header line.
  std::size_t bodyStart = 0;
};

/// Bytes of one value of type t.
int sizeOf(Type t);

/// The header of a PLY file's bytes; throws InputError naming `name` and
/// the line on a defect.
Header parseHeader(const std::string& bytes, const std::string& name);

} // namespace ply
} // namespace surfacemaps
