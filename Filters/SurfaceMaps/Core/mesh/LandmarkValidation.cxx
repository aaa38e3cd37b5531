#include "mesh/LandmarkValidation.h"

#include <map>
#include <set>

namespace surfacemaps
{

std::vector<std::string> checkLandmarkIds(const std::vector<int>& landmarkIds)
{
  std::vector<std::string> defects;
  std::map<int, int> idToVertex;
  for (std::size_t v = 0; v < landmarkIds.size(); ++v)
  {
    const int id = landmarkIds[v];
    if (id < -1)
    {
      defects.push_back("has landmark id " + std::to_string(id) + " at vertex " +
        std::to_string(v) + " (ids are >= 0, -1 means none)");
      break;
    }
    if (id < 0)
    {
      continue;
    }
    auto [it, inserted] = idToVertex.emplace(id, static_cast<int>(v));
    if (!inserted)
    {
      defects.push_back("has landmark id " + std::to_string(id) + " on two vertices (" +
        std::to_string(it->second) + " and " + std::to_string(v) + ")");
      break;
    }
  }
  return defects;
}

std::vector<std::vector<std::string>> checkLandmarkCorrespondence(
  const std::vector<std::vector<int>>& landmarkIds,
  const std::vector<std::string>& names)
{
  std::vector<std::vector<std::string>> defects(landmarkIds.size());
  std::vector<std::map<int, int>> idToVertex(landmarkIds.size());
  for (std::size_t i = 0; i < landmarkIds.size(); ++i)
  {
    for (std::size_t v = 0; v < landmarkIds[i].size(); ++v)
    {
      if (landmarkIds[i][v] >= 0)
      {
        idToVertex[i].emplace(landmarkIds[i][v], static_cast<int>(v));
      }
    }
  }
  for (std::size_t i = 1; i < landmarkIds.size(); ++i)
  {
    const auto& a = idToVertex[0];
    const auto& b = idToVertex[i];
    if (a.size() != b.size())
    {
      defects[i].push_back("landmark counts do not match: " + names[0] + " has " +
        std::to_string(a.size()) + ", " + names[i] + " has " + std::to_string(b.size()));
      continue;
    }
    for (const auto& [id, vertex] : a)
    {
      if (!b.count(id))
      {
        defects[i].push_back("landmark ids do not match: id " + std::to_string(id) + " is on " +
          names[0] + " (vertex " + std::to_string(vertex) + ") but not on " + names[i]);
        break;
      }
    }
  }
  return defects;
}

} // namespace surfacemaps
