#include "io/XmlPolyDataCheck.h"

#include "base/Error.h"
#include "io/TextFile.h"

#include <algorithm>
#include <cstdint>
#include <iterator>
#include <string_view>
#include <vector>

namespace surfacemaps
{

namespace
{

// The value of attribute `key` in `tag`, or an empty view with found false.
std::string_view attribute(std::string_view tag, const std::string& key, bool& found)
{
  const std::string pattern = " " + key + "=\"";
  const std::size_t begin = tag.find(pattern);
  found = begin != std::string_view::npos;
  if (!found)
  {
    return {};
  }
  const std::size_t valueBegin = begin + pattern.size();
  const std::size_t valueEnd = tag.find('"', valueBegin);
  return tag.substr(valueBegin,
    valueEnd == std::string_view::npos ? std::string_view::npos : valueEnd - valueBegin);
}

// An unsigned integer of `size` bytes at `at` in the given byte order.
std::uint64_t readUnsigned(const std::string& bytes, std::size_t at, std::size_t size, bool big)
{
  std::uint64_t value = 0;
  for (std::size_t k = 0; k < size; ++k)
  {
    const std::size_t index = big ? at + k : at + size - 1 - k;
    value = (value << 8) | static_cast<unsigned char>(bytes[index]);
  }
  return value;
}

// Decodes base64 `text` (whitespace skipped, stops at '=' or a non-base64
// character).
std::string decodeBase64(std::string_view text)
{
  std::string out;
  unsigned buffer = 0;
  int bits = 0;
  for (const char c : text)
  {
    int value;
    if (c >= 'A' && c <= 'Z')
      value = c - 'A';
    else if (c >= 'a' && c <= 'z')
      value = c - 'a' + 26;
    else if (c >= '0' && c <= '9')
      value = c - '0' + 52;
    else if (c == '+')
      value = 62;
    else if (c == '/')
      value = 63;
    else if (c == ' ' || c == '\n' || c == '\r' || c == '\t')
      continue;
    else
      break;
    buffer = (buffer << 6) | static_cast<unsigned>(value);
    bits += 6;
    if (bits >= 8)
    {
      bits -= 8;
      out += static_cast<char>((buffer >> bits) & 0xFF);
    }
  }
  return out;
}

// The layout VTK writes data blocks in: header word size, byte order and
// whether the blocks are compressed.
struct BlockLayout
{
  std::size_t headerSize = 4;
  bool big = false;
  bool compressed = false;
};

// Bytes a block whose header starts at `at` in `data` spans (header and
// payload), or 0 when its header does not fit or declares an uncompressed
// size beyond `maxUncompressed`; `header` receives the header's size.
std::uint64_t blockSpan(const std::string& data,
  std::size_t at,
  const BlockLayout& layout,
  double maxUncompressed,
  std::uint64_t& header)
{
  const std::size_t h = layout.headerSize;
  header = (layout.compressed ? 3 : 1) * h;
  if (at > data.size() || header > data.size() - at)
  {
    return 0;
  }
  if (!layout.compressed)
  {
    const std::uint64_t n = readUnsigned(data, at, h, layout.big);
    return static_cast<double>(n) > maxUncompressed ? 0 : header + n;
  }
  const std::uint64_t count = readUnsigned(data, at, h, layout.big);
  const std::uint64_t blockSize = readUnsigned(data, at + h, h, layout.big);
  const std::uint64_t lastSize = readUnsigned(data, at + 2 * h, h, layout.big);
  if (count > (data.size() - at - header) / h || lastSize > blockSize ||
    static_cast<double>(count) * static_cast<double>(blockSize) > maxUncompressed)
  {
    return 0;
  }
  header += count * h;
  std::uint64_t span = header;
  for (std::uint64_t b = 0; b < count && span <= data.size(); ++b)
  {
    span += readUnsigned(data, at + 3 * h + b * h, h, layout.big);
  }
  return span;
}

// Inline binary data (base64): the bytes of its block as VTK reads them.
// Uncompressed blocks are encoded with their header in one piece; compressed
// ones have the header encoded on its own, then the blocks.
std::string inlineBlock(std::string_view content, const BlockLayout& layout)
{
  std::string text;
  for (const char c : content)
  {
    if (c != ' ' && c != '\n' && c != '\r' && c != '\t')
    {
      text += c;
    }
  }
  if (!layout.compressed)
  {
    return decodeBase64(text);
  }
  const std::size_t h = layout.headerSize;
  const std::string first = decodeBase64(text.substr(0, 4 * ((h + 2) / 3)));
  if (first.size() < h)
  {
    return first;
  }
  const std::uint64_t count = readUnsigned(first, 0, h, layout.big);
  if (count > text.size())
  {
    return first; // blockSpan finds the header too short
  }
  const std::size_t headerChars = 4 * (((3 + count) * h + 2) / 3);
  return decodeBase64(text.substr(0, std::min(headerChars, text.size()))) +
    (headerChars < text.size() ? decodeBase64(text.substr(headerChars)) : std::string());
}

const std::string_view NumericTypes[] = { "Int8",
  "UInt8",
  "Int16",
  "UInt16",
  "Int32",
  "UInt32",
  "Int64",
  "UInt64",
  "Float32",
  "Float64" };

BlockLayout layoutOf(std::string_view xml)
{
  bool found;
  const std::string_view file = xml.substr(0, xml.find('>'));
  BlockLayout layout;
  layout.headerSize = attribute(file, "header_type", found) == "UInt64" ? 8 : 4;
  layout.big = attribute(file, "byte_order", found) == "BigEndian";
  attribute(file, "compressor", found);
  layout.compressed = found;
  return layout;
}

// Raw appended data: every array's block (its header and the bytes the
// header announces) lies inside the data section and blocks do not overlap.
// VTK's reader follows offsets and block headers without checking them and
// corrupts memory on a bad one.
void checkAppendedBlocks(const std::string& bytes,
  std::string_view xml,
  const std::vector<std::pair<std::string_view, std::uint64_t>>& offsets,
  const std::string& name)
{
  const std::size_t tag = bytes.find("<AppendedData");
  if (tag == std::string::npos)
  {
    return;
  }
  const std::size_t end = bytes.rfind("</AppendedData>");
  const std::size_t underscore = bytes.find('_', tag);
  bool found;
  const std::string_view encoding =
    attribute(std::string_view(bytes).substr(tag, bytes.find('>', tag) - tag), "encoding", found);
  if (underscore == std::string::npos || end == std::string::npos || end < underscore ||
    encoding != "raw")
  {
    return; // base64 or a broken section: VTK decodes and reports it itself
  }
  const std::size_t begin = underscore + 1;
  const std::string data = bytes.substr(begin, end - begin);
  const BlockLayout layout = layoutOf(xml);
  std::vector<std::pair<std::uint64_t, std::uint64_t>> blocks; // [offset, end)
  for (const auto& [element, offset] : offsets)
  {
    std::uint64_t header;
    const std::uint64_t span = blockSpan(data,
      static_cast<std::size_t>(std::min<std::uint64_t>(offset, data.size() + 1)),
      layout,
      MaxUncompressedPerXmlByte * static_cast<double>(bytes.size()),
      header);
    if (span == 0 || span > data.size() - offset)
    {
      throw InputError(name + ": the appended data of " + std::string(element) + " at offset " +
        std::to_string(offset) + " lies beyond the " + std::to_string(data.size()) +
        " bytes of appended data or declares more than it holds (a truncated or corrupt file)");
    }
    blocks.emplace_back(offset, offset + span);
  }
  std::sort(blocks.begin(), blocks.end());
  for (std::size_t k = 1; k < blocks.size(); ++k)
  {
    if (blocks[k].first < blocks[k - 1].second)
    {
      throw InputError(name + ": the appended data blocks at offsets " +
        std::to_string(blocks[k - 1].first) + " and " + std::to_string(blocks[k].first) +
        " overlap (a corrupt file)");
    }
  }
}

// A DataArray or Array of a type VTK's reader does not know (it crashes on one).
void checkArrayType(std::string_view tag, std::string_view element, const std::string& name)
{
  bool found;
  const std::string_view type = attribute(tag, "type", found);
  if (type != "String" &&
    std::find(std::begin(NumericTypes), std::end(NumericTypes), type) == std::end(NumericTypes))
  {
    throw InputError(name + ": " + std::string(element.substr(1)) + " " +
      std::string(attribute(tag, "Name", found)) + " has type \"" + std::string(type) +
      "\", not a numeric VTK XML data type");
  }
}

// The offset="..." of an appended array: an integer >= 0.
std::uint64_t appendedOffset(std::string_view tag,
  std::string_view element,
  const std::string& name)
{
  bool found;
  const std::string_view offset = attribute(tag, "offset", found);
  long long value;
  if (!parseInt(offset, value) || value < 0)
  {
    throw InputError(name + ": " + std::string(element.substr(1)) + " " +
      std::string(attribute(tag, "Name", found)) + " has offset=\"" + std::string(offset) +
      "\", not an offset into the appended data");
  }
  return static_cast<std::uint64_t>(value);
}

// The inline binary block of the array whose start tag `tag` is at `at` in
// `xml` holds what its header declares.
void checkInlineBlock(const std::string& bytes,
  std::string_view xml,
  std::size_t at,
  std::string_view tag,
  std::string_view element,
  const std::string& name)
{
  bool found;
  const std::size_t contentBegin = at + tag.size() + 1;
  const std::string block = inlineBlock(
    xml.substr(contentBegin, xml.find('<', contentBegin) - contentBegin), layoutOf(xml));
  std::uint64_t header;
  const std::uint64_t span = blockSpan(
    block, 0, layoutOf(xml), MaxUncompressedPerXmlByte * static_cast<double>(bytes.size()), header);
  if (span == 0 || span > block.size())
  {
    throw InputError(name + ": the binary data of " + std::string(element.substr(1)) + " " +
      std::string(attribute(tag, "Name", found)) +
      " declares more than it holds (a truncated or corrupt file)");
  }
}

// The counts a Piece or an array declares, which VTK's reader allocates by:
// each at most what a file of this size can hold.
void checkDeclaredCounts(const std::string& bytes,
  std::string_view tag,
  std::string_view element,
  bool piece,
  const std::string& name)
{
  const double limit = MaxItemsPerXmlByte * static_cast<double>(bytes.size());
  const char* const pieceCounts[] = {
    "NumberOfPoints", "NumberOfVerts", "NumberOfLines", "NumberOfStrips", "NumberOfPolys"
  };
  const char* const arrayCounts[] = { "NumberOfTuples", "NumberOfComponents" };
  for (const char* key : piece
      ? std::vector<const char*>(std::begin(pieceCounts), std::end(pieceCounts))
      : std::vector<const char*>(std::begin(arrayCounts), std::end(arrayCounts)))
  {
    bool found;
    const std::string_view value = attribute(tag, key, found);
    if (!found)
    {
      continue;
    }
    long long count;
    const bool parsed = parseInt(value, count) && count >= 0;
    // A component count is small (tensors have 9); one in the billions
    // makes VTK's reader loop for ever.
    const bool components = std::string_view(key) == "NumberOfComponents";
    if (!parsed || static_cast<double>(count) > limit ||
      (components && !(count >= 1 && count <= MaxXmlComponents)))
    {
      throw InputError(name + ": " + std::string(element.substr(1)) + " declares " + key + "=\"" +
        std::string(value) + "\", " +
        (!parsed ? std::string("not a count")
            : components
            ? "outside 1 to " + std::to_string(MaxXmlComponents)
            : "more than a file of " + std::to_string(bytes.size()) + " bytes can hold"));
    }
  }
}

} // namespace

std::string withoutStringArrays(const std::string& bytes)
{
  const std::size_t xmlEnd = std::min(bytes.size(), bytes.find("<AppendedData"));
  std::string result;
  result.reserve(bytes.size());
  std::size_t copied = 0;
  for (std::size_t at = bytes.find('<'); at < xmlEnd; at = bytes.find('<', at + 1))
  {
    const std::size_t close = bytes.find('>', at);
    if (close == std::string::npos || close >= xmlEnd)
    {
      break;
    }
    const std::string_view tag = std::string_view(bytes).substr(at, close - at);
    const std::string_view element = tag.substr(0, tag.find(' '));
    bool found;
    if ((element != "<Array" && element != "<DataArray") ||
      attribute(tag, "type", found) != "String")
    {
      continue;
    }
    // The element with its content: up to its end tag unless it closes itself.
    std::size_t end = close + 1;
    if (tag.back() != '/')
    {
      const std::string endTag = "</" + std::string(element.substr(1)) + ">";
      const std::size_t endAt = bytes.find(endTag, close);
      end = endAt == std::string::npos || endAt >= xmlEnd ? xmlEnd : endAt + endTag.size();
    }
    result.append(bytes, copied, at - copied);
    copied = end;
    at = end - 1;
  }
  result.append(bytes, copied, std::string::npos);
  return result;
}

void checkXmlPolyDataCounts(const std::string& bytes, const std::string& name)
{
  // Only the XML part: appended raw data may contain anything.
  const std::string_view xml =
    std::string_view(bytes).substr(0, std::min(bytes.size(), bytes.find("<AppendedData")));
  std::vector<std::pair<std::string_view, std::uint64_t>> appendedOffsets;
  for (std::size_t at = xml.find('<'); at != std::string_view::npos; at = xml.find('<', at + 1))
  {
    const std::size_t close = xml.find('>', at);
    if (close == std::string_view::npos)
    {
      break; // an unterminated tag: VTK's XML parser reports it
    }
    const std::string_view tag = xml.substr(at, close - at);
    const std::string_view element = tag.substr(0, tag.find(' '));
    const bool piece = element == "<Piece";
    const bool array = element == "<DataArray" || element == "<Array";
    if (!piece && !array)
    {
      continue;
    }
    if (array)
    {
      checkArrayType(tag, element, name);
      bool found;
      const std::string_view format = attribute(tag, "format", found);
      if (format == "appended")
      {
        const std::uint64_t offset = appendedOffset(tag, element, name);
        appendedOffsets.emplace_back(attribute(tag, "Name", found), offset);
      }
      if (format == "binary")
      {
        checkInlineBlock(bytes, xml, at, tag, element, name);
      }
    }
    checkDeclaredCounts(bytes, tag, element, piece, name);
  }
  checkAppendedBlocks(bytes, xml, appendedOffsets, name);
}

} // namespace surfacemaps
