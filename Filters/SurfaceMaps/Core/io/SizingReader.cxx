#include "io/SizingReader.h"

#include "base/Error.h"
#include "io/TextFile.h"

#include <cmath>

namespace surfacemaps
{

std::vector<double> parseSizing(const std::string& text,
  const std::string& name,
  std::size_t numberOfVertices)
{
  std::vector<double> sizing;
  TextScanner scanner(text);
  while (scanner.nextLine())
  {
    const std::string_view token = scanner.nextToken();
    if (token.empty())
    {
      continue;
    }
    const int line = scanner.lineNumber();
    double value;
    if (!parseDouble(token, value))
    {
      failAtLine(name, line, "expected a target edge length, got '" + std::string(token) + "'");
    }
    if (!std::isfinite(value) || value <= 0.0)
    {
      failAtLine(name,
        line,
        "the target edge length '" + std::string(token) + "' (vertex " +
          std::to_string(sizing.size()) + ") is not a finite positive number");
    }
    if (!scanner.lineExhausted())
    {
      failAtLine(name, line, "expected one value per line, got '" + std::string(token) + " " +
          std::string(scanner.nextToken()) + "'");
    }
    if (sizing.size() == numberOfVertices)
    {
      failAtLine(name,
        line,
        "more values than the mesh's " + std::to_string(numberOfVertices) +
          " vertices (one target edge length per vertex)");
    }
    sizing.push_back(value);
  }
  if (sizing.size() != numberOfVertices)
  {
    throw InputError(name + ":" + std::to_string(scanner.lineNumber()) + ": the file ends after " +
      std::to_string(sizing.size()) + " values, but the mesh has " +
      std::to_string(numberOfVertices) + " vertices (one target edge length per vertex)");
  }
  return sizing;
}

std::vector<double> readSizing(const std::string& path, std::size_t numberOfVertices)
{
  return parseSizing(readTextFile(path), path, numberOfVertices);
}

} // namespace surfacemaps
