#include "map/MapPairs.h"

namespace surfacemaps
{

std::vector<std::array<int, 2>> mapPairs(PairScheme mode, int n)
{
  std::vector<std::array<int, 2>> pairs;
  switch (mode)
  {
    case PairScheme::Star:
      for (int i = 1; i < n; ++i)
      {
        pairs.push_back({ 0, i });
      }
      break;
    case PairScheme::Sequence:
    case PairScheme::Cycle:
    case PairScheme::Mean:
      for (int i = 0; i + 1 < n; ++i)
      {
        pairs.push_back({ i, i + 1 });
      }
      if (mode != PairScheme::Sequence && n > 2)
      {
        pairs.push_back({ n - 1, 0 });
      }
      break;
    case PairScheme::All:
      for (int i = 0; i < n; ++i)
      {
        for (int j = i + 1; j < n; ++j)
        {
          pairs.push_back({ i, j });
        }
      }
      break;
  }
  return pairs;
}

} // namespace surfacemaps
