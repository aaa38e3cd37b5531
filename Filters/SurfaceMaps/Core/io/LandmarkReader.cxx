#include "io/LandmarkReader.h"

#include "base/InputError.h"
#include "io/TextFile.h"

#include <limits>

namespace surfacemaps
{

std::vector<int> parseLandmarks(const std::string& text, const std::string& name)
{
  std::vector<int> indices;
  TextScanner scanner(text);
  while (scanner.nextLine())
  {
    std::string_view token = scanner.nextToken();
    if (token.empty())
    {
      continue;
    }
    if (token == "lk")
    {
      token = scanner.nextToken();
    }
    long long index;
    if (!parseInt(token, index) || index < 0 || index > std::numeric_limits<int>::max())
    {
      failAtLine(name,
        scanner.lineNumber(),
        "expected a 0-based vertex index, got '" + std::string(token) + "'");
    }
    // The rest of a .vts line is the vertex position, which we do not need;
    // it must still be numbers, or this is not a landmark file.
    for (token = scanner.nextToken(); !token.empty(); token = scanner.nextToken())
    {
      double ignored;
      if (!parseDouble(token, ignored))
      {
        failAtLine(name,
          scanner.lineNumber(),
          "unexpected '" + std::string(token) + "' after the vertex index");
      }
    }
    indices.push_back(static_cast<int>(index));
  }
  return indices;
}

std::vector<int> readLandmarks(const std::string& path)
{
  std::vector<int> indices = parseLandmarks(readTextFile(path), path);
  if (indices.empty())
  {
    throw InputError(path + ": the landmark file lists no vertices");
  }
  return indices;
}

std::vector<int> landmarkIdsFromIndices(const std::vector<int>& indices,
  std::size_t numberOfVertices,
  const std::string& name)
{
  std::vector<int> ids(numberOfVertices, -1);
  for (std::size_t k = 0; k < indices.size(); ++k)
  {
    const int v = indices[k];
    if (v < 0 || static_cast<std::size_t>(v) >= numberOfVertices)
    {
      throw InputError(name + ": landmark " + std::to_string(k) + " is vertex " +
        std::to_string(v) + ", out of range for a mesh with " + std::to_string(numberOfVertices) +
        " vertices");
    }
    if (ids[v] >= 0)
    {
      throw InputError(name + ": vertex " + std::to_string(v) + " is listed twice (landmarks " +
        std::to_string(ids[v]) + " and " + std::to_string(k) + ")");
    }
    ids[v] = static_cast<int>(k);
  }
  return ids;
}

} // namespace surfacemaps
