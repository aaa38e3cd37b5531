#include "io/ObjReader.h"

#include "base/InputError.h"
#include "io/TextFile.h"

#include <limits>

namespace surfacemaps
{

namespace
{

[[noreturn]] void fail(const std::string& name, const TextScanner& scanner, const std::string& what)
{
  std::string message = name + ":" + std::to_string(scanner.lineNumber()) + ": " + what;
  throw InputError(message);
}

// Resolves a 1-based (or negative, relative) OBJ index against the `count`
// entries defined so far; returns -1 if it refers to none of them.
long long resolveIndex(long long index, std::size_t count)
{
  if (index > 0 && static_cast<std::size_t>(index) <= count)
  {
    return index - 1;
  }
  if (index < 0 && static_cast<std::size_t>(-index) <= count)
  {
    return static_cast<long long>(count) + index;
  }
  return -1;
}

} // namespace

PolygonMesh parseObj(const std::string& text, const std::string& name)
{
  PolygonMesh mesh;
  std::vector<Eigen::Vector2d> texCoords;
  std::vector<long long> cornerTex; // index into texCoords per corner, -1 none
  std::vector<int> corners;
  bool anyTex = false;

  TextScanner scanner(text);
  while (scanner.nextLine())
  {
    const std::string_view keyword = scanner.nextToken();
    if (keyword.empty())
    {
      continue;
    }
    if (keyword == "v")
    {
      double xyz[3];
      int n = 0;
      for (std::string_view token = scanner.nextToken(); !token.empty();
           token = scanner.nextToken())
      {
        double value;
        if (!parseDouble(token, value))
        {
          fail(name, scanner, "bad vertex coordinate '" + std::string(token) + "'");
        }
        if (n < 3)
        {
          xyz[n] = value;
        }
        ++n;
      }
      // 3 coordinates, optionally w or an RGB colour.
      if (n != 3 && n != 4 && n != 6 && n != 7)
      {
        fail(name,
          scanner,
          "vertex has " + std::to_string(n) + " coordinates (3 expected)" +
            (scanner.truncatedHere() ? "; the file ends without a newline and looks truncated"
                                     : ""));
      }
      mesh.points.emplace_back(xyz[0], xyz[1], xyz[2]);
    }
    else if (keyword == "vt")
    {
      double uv[2] = { 0.0, 0.0 };
      int n = 0;
      for (std::string_view token = scanner.nextToken(); !token.empty();
           token = scanner.nextToken())
      {
        double value;
        if (!parseDouble(token, value))
        {
          fail(name, scanner, "bad texture coordinate '" + std::string(token) + "'");
        }
        if (n < 2)
        {
          uv[n] = value;
        }
        ++n;
      }
      if (n < 1 || n > 3)
      {
        fail(name, scanner, "texture coordinate has " + std::to_string(n) + " values");
      }
      texCoords.emplace_back(uv[0], uv[1]);
    }
    else if (keyword == "f")
    {
      corners.clear();
      for (std::string_view token = scanner.nextToken(); !token.empty();
           token = scanner.nextToken())
      {
        const std::size_t slash = token.find('/');
        long long v;
        if (!parseInt(token.substr(0, slash), v))
        {
          fail(name, scanner, "bad face corner '" + std::string(token) + "'");
        }
        const long long vi = resolveIndex(v, mesh.points.size());
        if (vi < 0)
        {
          fail(name,
            scanner,
            "face refers to vertex " + std::to_string(v) + ", but " +
              std::to_string(mesh.points.size()) + " vertices are defined before it");
        }
        long long ti = -1;
        if (slash != std::string_view::npos)
        {
          std::string_view rest = token.substr(slash + 1);
          const std::string_view tex = rest.substr(0, rest.find('/'));
          if (!tex.empty())
          {
            long long t;
            if (!parseInt(tex, t) || (ti = resolveIndex(t, texCoords.size())) < 0)
            {
              fail(name, scanner, "bad texture index in face corner '" + std::string(token) + "'");
            }
            anyTex = true;
          }
        }
        corners.push_back(static_cast<int>(vi));
        cornerTex.push_back(ti);
      }
      if (corners.size() < 3)
      {
        std::string what = "face has " + std::to_string(corners.size()) +
          (corners.size() == 1 ? " vertex" : " vertices") + " (at least 3 needed)";
        if (scanner.truncatedHere())
        {
          what += "; the file ends without a newline and looks truncated";
        }
        fail(name, scanner, what);
      }
      mesh.addFace(corners.begin(), corners.end());
    }
    else if (keyword == "l" || keyword == "p")
    {
      ++mesh.nonPolygonCells;
    }
    // vn, vp, o, g, s, usemtl, mtllib and others carry nothing we use.
  }

  if (scanner.endsWithoutNewline() && mesh.numberOfFaces() == 0 && !mesh.points.empty())
  {
    throw InputError(name + ": the file ends in the vertex list without faces; it looks truncated");
  }

  if (anyTex)
  {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    mesh.cornerTexCoords.reserve(cornerTex.size());
    for (long long t : cornerTex)
    {
      mesh.cornerTexCoords.push_back(t >= 0 ? texCoords[t] : Eigen::Vector2d(nan, nan));
    }
  }
  return mesh;
}

PolygonMesh readObj(const std::string& path)
{
  return parseObj(readTextFile(path), path);
}

} // namespace surfacemaps
