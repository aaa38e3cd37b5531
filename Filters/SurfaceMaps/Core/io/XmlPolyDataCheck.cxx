#include "io/XmlPolyDataCheck.h"

#include "base/InputError.h"
#include "io/TextFile.h"

#include <algorithm>
#include <string_view>

namespace surfacemaps
{

void checkXmlPolyDataCounts(const std::string& bytes, const std::string& name)
{
  // Only the XML part: appended raw data may contain anything.
  const std::string_view xml =
    std::string_view(bytes).substr(0, std::min(bytes.size(), bytes.find("<AppendedData")));
  const double limit = MaxItemsPerXmlByte * static_cast<double>(bytes.size());
  int piece = 0;
  for (std::size_t at = xml.find("<Piece"); at != std::string_view::npos;
       at = xml.find("<Piece", at + 1), ++piece)
  {
    const std::string_view tag = xml.substr(at, xml.find('>', at) - at);
    for (const char* attribute :
      { "NumberOfPoints", "NumberOfVerts", "NumberOfLines", "NumberOfStrips", "NumberOfPolys" })
    {
      const std::string key = std::string(" ") + attribute + "=\"";
      const std::size_t begin = tag.find(key);
      if (begin == std::string_view::npos)
      {
        continue;
      }
      const std::size_t valueBegin = begin + key.size();
      const std::size_t valueEnd = tag.find('"', valueBegin);
      const std::string_view value = tag.substr(valueBegin,
        valueEnd == std::string_view::npos ? std::string_view::npos : valueEnd - valueBegin);
      long long count;
      if (!parseInt(value, count) || count < 0 || static_cast<double>(count) > limit)
      {
        throw InputError(name + ": piece " + std::to_string(piece) + " declares " + attribute +
          "=\"" + std::string(value) + "\", " +
          (parseInt(value, count) && count >= 0
              ? "more than a file of " + std::to_string(bytes.size()) + " bytes can hold"
              : "not a count"));
      }
    }
  }
}

} // namespace surfacemaps
