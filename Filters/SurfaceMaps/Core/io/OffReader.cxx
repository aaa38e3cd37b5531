#include "io/OffReader.h"

#include "base/InputError.h"
#include "io/TextFile.h"

#include <vector>

namespace surfacemaps
{

namespace
{

[[noreturn]] void fail(const std::string& name, const TextScanner& scanner, const std::string& what)
{
  throw InputError(name + ":" + std::to_string(scanner.lineNumber()) + ": " + what);
}

// Next line that has a token; returns its first token (empty at end of text).
std::string_view firstTokenOfNextLine(TextScanner& scanner)
{
  while (scanner.nextLine())
  {
    std::string_view token = scanner.nextToken();
    if (!token.empty())
    {
      return token;
    }
  }
  return {};
}

} // namespace

PolygonMesh parseOff(const std::string& text, const std::string& name)
{
  TextScanner scanner(text);
  std::string_view token = firstTokenOfNextLine(scanner);
  if (token.empty())
  {
    throw InputError(name + ": the file is empty");
  }
  const bool hasHeader = token.size() >= 3 && token.substr(token.size() - 3) == "OFF";
  if (hasHeader)
  {
    if (token != "OFF" && token != "COFF" && token != "NOFF" && token != "CNOFF")
    {
      fail(name, scanner, "unsupported OFF variant '" + std::string(token) + "'");
    }
    if (!scanner.lineExhausted())
    {
      token = scanner.nextToken();
      if (token == "BINARY")
      {
        fail(name, scanner, "binary OFF is not supported; convert the file to ASCII");
      }
    }
    else
    {
      token = firstTokenOfNextLine(scanner);
    }
  }
  else
  {
    long long probe;
    if (!parseInt(token, probe))
    {
      fail(name, scanner, "not an OFF file: it starts with '" + std::string(token) + "'");
    }
  }

  long long counts[3] = { 0, 0, 0 };
  for (int i = 0; i < 3; ++i)
  {
    if (token.empty() && i == 2)
    {
      break; // the edge count is optional
    }
    if (!parseInt(token, counts[i]) || counts[i] < 0)
    {
      fail(
        name, scanner, "expected vertex, face and edge counts, got '" + std::string(token) + "'");
    }
    token = scanner.nextToken();
  }
  const long long nv = counts[0];
  const long long nf = counts[1];

  PolygonMesh mesh;
  mesh.points.reserve(static_cast<std::size_t>(nv));
  for (long long v = 0; v < nv; ++v)
  {
    token = firstTokenOfNextLine(scanner);
    if (token.empty())
    {
      throw InputError(name + ": the header declares " + std::to_string(nv) +
        " vertices, but the file ends after " + std::to_string(v) + "; it looks truncated");
    }
    double xyz[3];
    for (int k = 0; k < 3; ++k)
    {
      if (!parseDouble(token, xyz[k]))
      {
        fail(name,
          scanner,
          token.empty() ? "vertex has " + std::to_string(k) + " coordinates (3 expected)" +
              (scanner.truncatedHere() ? "; the file looks truncated" : "")
                        : "bad vertex coordinate '" + std::string(token) + "'");
      }
      token = scanner.nextToken();
    }
    mesh.points.emplace_back(xyz[0], xyz[1], xyz[2]);
  }

  std::vector<int> corners;
  for (long long f = 0; f < nf; ++f)
  {
    token = firstTokenOfNextLine(scanner);
    if (token.empty())
    {
      throw InputError(name + ": the header declares " + std::to_string(nf) +
        " faces, but the file ends after " + std::to_string(f) + "; it looks truncated");
    }
    long long n;
    if (!parseInt(token, n) || n < 1)
    {
      fail(name, scanner, "bad face vertex count '" + std::string(token) + "'");
    }
    corners.clear();
    for (long long k = 0; k < n; ++k)
    {
      token = scanner.nextToken();
      long long index;
      if (token.empty())
      {
        fail(name,
          scanner,
          "face declares " + std::to_string(n) + " vertices but lists " + std::to_string(k) +
            (scanner.truncatedHere() ? "; the file looks truncated" : ""));
      }
      if (!parseInt(token, index))
      {
        fail(name, scanner, "bad vertex index '" + std::string(token) + "'");
      }
      if (index < 0 || index >= nv)
      {
        fail(name,
          scanner,
          "face refers to vertex " + std::to_string(index) + ", but the file has " +
            std::to_string(nv) + " vertices");
      }
      corners.push_back(static_cast<int>(index));
    }
    if (n < 3)
    {
      fail(name, scanner, "face has " + std::to_string(n) + " vertices (at least 3 needed)");
    }
    mesh.addFace(corners.begin(), corners.end());
    // Anything left on the line is a face colour.
  }
  return mesh;
}

PolygonMesh readOff(const std::string& path)
{
  return parseOff(readTextFile(path), path);
}

} // namespace surfacemaps
