#include "NumpyArchive.h"

#include "vtk_zlib.h"

#include <cstring>
#include <limits>
#include <stdexcept>

namespace surfacemap
{

namespace
{

// The .npy header is padded so that the data starts at a multiple of this
// (what numpy writes, for aligned memory maps).
constexpr std::size_t HeaderAlignment = 64;

template <typename Unsigned>
void putLittleEndian(std::string& out, Unsigned value)
{
  for (std::size_t k = 0; k < sizeof(Unsigned); ++k)
  {
    out.push_back(static_cast<char>((value >> (8 * k)) & 0xFFu));
  }
}

template <typename Value>
std::string littleEndianBytes(const std::vector<Value>& values)
{
  static_assert(sizeof(Value) == 8, "8-byte values");
  std::string data;
  data.reserve(values.size() * 8);
  for (const Value value : values)
  {
    std::uint64_t bits = 0;
    std::memcpy(&bits, &value, 8);
    putLittleEndian(data, bits);
  }
  return data;
}

std::size_t elementCount(const std::vector<std::size_t>& shape)
{
  std::size_t count = 1;
  for (const std::size_t extent : shape)
  {
    count *= extent;
  }
  return count;
}

// The shape as numpy writes it: "(3,)", "(2, 5, 3)".
std::string shapeText(const std::vector<std::size_t>& shape)
{
  std::string text = "(";
  for (std::size_t k = 0; k < shape.size(); ++k)
  {
    text += (k ? ", " : "") + std::to_string(shape[k]);
  }
  return text + (shape.size() == 1 ? ",)" : ")");
}

// Decodes UTF-8 into code points; an invalid sequence gives U+FFFD.
std::vector<std::uint32_t> codePoints(const std::string& text)
{
  std::vector<std::uint32_t> points;
  for (std::size_t k = 0; k < text.size();)
  {
    const auto lead = static_cast<unsigned char>(text[k]);
    // The number of continuation bytes the lead byte announces (-1: none can follow it).
    const int extra = lead < 0x80 ? 0
      : (lead >> 5) == 0x6        ? 1
      : (lead >> 4) == 0xE        ? 2
      : (lead >> 3) == 0x1E       ? 3
                                  : -1;
    std::uint32_t point = lead & (0x7Fu >> (extra > 0 ? extra + 1 : 0));
    bool valid = extra >= 0 && k + extra < text.size();
    for (int j = 1; valid && j <= extra; ++j)
    {
      const auto next = static_cast<unsigned char>(text[k + j]);
      valid = (next >> 6) == 0x2;
      point = (point << 6) | (next & 0x3Fu);
    }
    points.push_back(valid && point <= 0x10FFFF ? point : 0xFFFDu);
    k += valid ? extra + 1 : 1;
  }
  return points;
}

std::uint32_t narrow(std::size_t size)
{
  if (size >= std::numeric_limits<std::uint32_t>::max())
  {
    throw std::length_error("an .npz member of 4 GiB or more (the archive has no Zip64)");
  }
  return static_cast<std::uint32_t>(size);
}

} // namespace

void NumpyArchive::addDoubles(
  const std::string& name, const std::vector<std::size_t>& shape, const std::vector<double>& values)
{
  if (elementCount(shape) != values.size())
  {
    throw std::invalid_argument(name + ": " + std::to_string(values.size()) +
      " values for the shape " + shapeText(shape));
  }
  this->addMember(name, "<f8", shape, littleEndianBytes(values));
}

void NumpyArchive::addIntegers(const std::string& name,
  const std::vector<std::size_t>& shape,
  const std::vector<std::int64_t>& values)
{
  if (elementCount(shape) != values.size())
  {
    throw std::invalid_argument(name + ": " + std::to_string(values.size()) +
      " values for the shape " + shapeText(shape));
  }
  this->addMember(name, "<i8", shape, littleEndianBytes(values));
}

void NumpyArchive::addStrings(const std::string& name, const std::vector<std::string>& values)
{
  std::vector<std::vector<std::uint32_t>> decoded;
  std::size_t width = 1; // numpy has no '<U0'
  for (const std::string& value : values)
  {
    decoded.push_back(codePoints(value));
    width = std::max(width, decoded.back().size());
  }
  std::string data;
  for (const auto& points : decoded)
  {
    for (std::size_t k = 0; k < width; ++k)
    {
      putLittleEndian(data, k < points.size() ? points[k] : std::uint32_t{ 0 });
    }
  }
  this->addMember(name, "<U" + std::to_string(width), { values.size() }, data);
}

void NumpyArchive::addMember(const std::string& name,
  const std::string& descr,
  const std::vector<std::size_t>& shape,
  const std::string& data)
{
  std::string header = "{'descr': '" + descr + "', 'fortran_order': False, 'shape': " +
    shapeText(shape) + ", }";
  const std::size_t preamble = 10; // magic (6), version (2), header length (2)
  header.append(HeaderAlignment - (preamble + header.size() + 1) % HeaderAlignment, ' ');
  header.push_back('\n');
  std::string npy = "\x93NUMPY";
  npy.push_back('\x01');
  npy.push_back('\x00');
  putLittleEndian(npy, static_cast<std::uint16_t>(header.size()));
  npy += header;
  npy += data;
  this->Members.push_back({ name + ".npy", std::move(npy) });
}

std::string NumpyArchive::bytes() const
{
  // Zip format (PKWARE APPNOTE 6.3): per member a local header and the data
  // stored as is, then the central directory and its end record. DOS date
  // 1980-01-01 00:00 (numpy.load ignores it; the same bytes for the same
  // arrays, so the map directory's checksum depends on the content only).
  constexpr std::uint16_t version = 20, stored = 0, time = 0, date = (1 << 5) | 1;
  std::string archive, directory;
  for (const Member& member : this->Members)
  {
    const std::uint32_t crc = static_cast<std::uint32_t>(crc32(crc32(0L, Z_NULL, 0),
      reinterpret_cast<const Bytef*>(member.data.data()),
      narrow(member.data.size())));
    const std::uint32_t size = narrow(member.data.size());
    const std::uint32_t offset = narrow(archive.size());
    const auto nameLength = static_cast<std::uint16_t>(member.name.size());
    putLittleEndian(archive, std::uint32_t{ 0x04034b50 });
    for (const std::uint16_t field : { version, std::uint16_t{ 0 }, stored, time, date })
    {
      putLittleEndian(archive, field);
    }
    for (const std::uint32_t field : { crc, size, size })
    {
      putLittleEndian(archive, field);
    }
    putLittleEndian(archive, nameLength);
    putLittleEndian(archive, std::uint16_t{ 0 }); // extra field
    archive += member.name;
    archive += member.data;

    putLittleEndian(directory, std::uint32_t{ 0x02014b50 });
    for (const std::uint16_t field : { version, version, std::uint16_t{ 0 }, stored, time, date })
    {
      putLittleEndian(directory, field);
    }
    for (const std::uint32_t field : { crc, size, size })
    {
      putLittleEndian(directory, field);
    }
    // Name, extra field and comment lengths, disk, internal and external attributes.
    for (const std::uint16_t field : { nameLength, std::uint16_t{ 0 }, std::uint16_t{ 0 },
           std::uint16_t{ 0 }, std::uint16_t{ 0 } })
    {
      putLittleEndian(directory, field);
    }
    putLittleEndian(directory, std::uint32_t{ 0 });
    putLittleEndian(directory, offset);
    directory += member.name;
  }
  const std::uint32_t directoryOffset = narrow(archive.size());
  const auto count = static_cast<std::uint16_t>(this->Members.size());
  archive += directory;
  putLittleEndian(archive, std::uint32_t{ 0x06054b50 });
  for (const std::uint16_t field : { std::uint16_t{ 0 }, std::uint16_t{ 0 }, count, count })
  {
    putLittleEndian(archive, field);
  }
  putLittleEndian(archive, narrow(directory.size()));
  putLittleEndian(archive, directoryOffset);
  putLittleEndian(archive, std::uint16_t{ 0 }); // comment
  return archive;
}

} // namespace surfacemap
