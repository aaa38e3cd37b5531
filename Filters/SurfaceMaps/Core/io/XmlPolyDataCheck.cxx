#include "io/XmlPolyDataCheck.h"

#include "base/InputError.h"
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
  const std::size_t length = end - begin;
  const std::string_view file = xml.substr(0, xml.find('>'));
  const std::size_t headerSize = attribute(file, "header_type", found) == "UInt64" ? 8 : 4;
  const bool big = attribute(file, "byte_order", found) == "BigEndian";
  attribute(file, "compressor", found);
  const bool compressed = found;
  std::vector<std::pair<std::uint64_t, std::uint64_t>> blocks; // [offset, end)
  for (const auto& [element, offset] : offsets)
  {
    auto fail = [&](const std::string& what)
    {
      throw InputError(name + ": the appended data of " + std::string(element) + " at offset " +
        std::to_string(offset) + " " + what);
    };
    const std::uint64_t headerEnd = offset + (compressed ? 3 : 1) * headerSize;
    if (headerEnd > length)
    {
      fail("lies beyond the appended data (" + std::to_string(length) + " bytes)");
    }
    std::uint64_t blockEnd = headerEnd;
    if (!compressed)
    {
      blockEnd += readUnsigned(bytes, begin + offset, headerSize, big);
    }
    else
    {
      const std::uint64_t count = readUnsigned(bytes, begin + offset, headerSize, big);
      if (count > (length - headerEnd) / headerSize)
      {
        fail("declares " + std::to_string(count) + " compressed blocks, more than it can hold");
      }
      blockEnd += count * headerSize;
      for (std::uint64_t b = 0; b < count; ++b)
      {
        blockEnd += readUnsigned(bytes, begin + headerEnd + b * headerSize, headerSize, big);
        if (blockEnd > length)
        {
          break;
        }
      }
    }
    if (blockEnd > length)
    {
      fail("declares more bytes than the appended data holds (a truncated or corrupt file)");
    }
    blocks.emplace_back(offset, blockEnd);
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

} // namespace

void checkXmlPolyDataCounts(const std::string& bytes, const std::string& name)
{
  // Only the XML part: appended raw data may contain anything.
  const std::string_view xml =
    std::string_view(bytes).substr(0, std::min(bytes.size(), bytes.find("<AppendedData")));
  const double limit = MaxItemsPerXmlByte * static_cast<double>(bytes.size());
  std::vector<std::pair<std::string_view, std::uint64_t>> appendedOffsets;
  for (std::size_t at = xml.find('<'); at != std::string_view::npos; at = xml.find('<', at + 1))
  {
    const std::string_view tag = xml.substr(at, xml.find('>', at) - at);
    const std::string_view element = tag.substr(0, tag.find(' '));
    const bool piece = element == "<Piece";
    const bool array = element == "<DataArray" || element == "<Array";
    if (!piece && !array)
    {
      continue;
    }
    bool found;
    if (array && attribute(tag, "format", found) == "appended")
    {
      const std::string_view offset = attribute(tag, "offset", found);
      long long value;
      if (!parseInt(offset, value) || value < 0)
      {
        throw InputError(name + ": " + std::string(element.substr(1)) + " " +
          std::string(attribute(tag, "Name", found)) + " has offset=\"" + std::string(offset) +
          "\", not an offset into the appended data");
      }
      appendedOffsets.emplace_back(attribute(tag, "Name", found), static_cast<std::uint64_t>(value));
    }
    const char* const pieceCounts[] = { "NumberOfPoints", "NumberOfVerts", "NumberOfLines",
      "NumberOfStrips", "NumberOfPolys" };
    const char* const arrayCounts[] = { "NumberOfTuples", "NumberOfComponents" };
    for (const char* key : piece ? std::vector<const char*>(std::begin(pieceCounts), std::end(pieceCounts))
                                 : std::vector<const char*>(std::begin(arrayCounts), std::end(arrayCounts)))
    {
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
        throw InputError(name + ": " + std::string(element.substr(1)) + " declares " + key +
          "=\"" + std::string(value) + "\", " +
          (!parsed           ? std::string("not a count")
              : components ? "outside 1 to " + std::to_string(MaxXmlComponents)
                           : "more than a file of " + std::to_string(bytes.size()) +
                  " bytes can hold"));
      }
    }
  }
  checkAppendedBlocks(bytes, xml, appendedOffsets, name);
}

} // namespace surfacemaps
