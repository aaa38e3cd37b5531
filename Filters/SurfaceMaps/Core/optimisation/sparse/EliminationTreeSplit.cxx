// SurfaceMaps engine: splitEliminationTree, which weighs the rows of a
// simplicial factor, chooses the subtrees threads take and links each
// thread's rows into a list CHOLMOD's row factorisation follows.
#include "optimisation/sparse/EliminationTreeSplit.h"

#include <algorithm>

namespace surfacemaps
{

namespace
{
// Work of row k: the updates of the up-looking factorisation, one per entry
// above row k in each column of row k's pattern (found by walking the
// elimination tree up from the entries of S's column k, as CHOLMOD does).
std::vector<double> rowWork(const cholmod_sparse& S, const std::vector<int>& parent)
{
  const int n = static_cast<int>(parent.size());
  std::vector<double> work(n, 1.0);
  const int* Sp = static_cast<const int*>(S.p);
  const int* Si = static_cast<const int*>(S.i);
  std::vector<int> entries(n, 0), visited(n, -1);
  for (int k = 0; k < n; ++k)
  {
    visited[k] = k;
    for (int p = Sp[k]; p < Sp[k + 1]; ++p)
    {
      for (int i = Si[p]; i < k && i >= 0 && visited[i] != k; i = parent[i])
      {
        visited[i] = k;
        work[k] += 1.0 + entries[i]++;
      }
    }
  }
  return work;
}

// Sums the rows' work and counts over subtrees (subtree of j: rows
// j - size[j] + 1 .. j); false if the tree is not postordered.
bool sumOverSubtrees(const std::vector<int>& parent,
  std::vector<double>& work,
  std::vector<int>& size)
{
  for (std::size_t j = 0; j < parent.size(); ++j)
  {
    if (parent[j] >= 0)
    {
      if (parent[j] <= static_cast<int>(j))
      {
        return false;
      }
      work[parent[j]] += work[j];
      size[parent[j]] += size[j];
    }
  }
  return true;
}

// The children of every row: children[start[j] .. start[j + 1]) for row j.
struct ChildLists
{
  std::vector<int> start;
  std::vector<int> children;
};

ChildLists childListsOf(const std::vector<int>& parent)
{
  const int n = static_cast<int>(parent.size());
  ChildLists lists;
  lists.start.assign(n + 1, 0);
  lists.children.resize(n);
  for (int j = 0; j < n; ++j)
  {
    if (parent[j] >= 0)
    {
      ++lists.start[parent[j] + 1];
    }
  }
  for (int j = 0; j < n; ++j)
  {
    lists.start[j + 1] += lists.start[j];
  }
  std::vector<int> at(lists.start.begin(), lists.start.end() - 1);
  for (int j = 0; j < n; ++j)
  {
    if (parent[j] >= 0)
    {
      lists.children[at[parent[j]]++] = j;
    }
  }
  return lists;
}

// The subtrees the threads take (their roots) and the rows left above them.
struct Frontier
{
  std::vector<int> roots;
  std::vector<char> inRemainder;
  double remainderWork = 0.0;
};

// Move the heaviest subtree's root into the remainder while that subtree
// alone is more than one thread's share of the rest. The last row (a
// root) always starts the remainder, so no thread's list spans all rows
// (CHOLMOD restarts the whole factor for a range 0 .. n).
Frontier expandRemainder(const std::vector<int>& parent,
  const std::vector<double>& work,
  int threads)
{
  const int n = static_cast<int>(parent.size());
  const ChildLists tree = childListsOf(parent);
  Frontier result;
  result.inRemainder.assign(n, 0);
  auto byWork = [&](int a, int b) { return work[a] < work[b]; };
  std::vector<int>& frontier = result.roots; // a max-heap by subtree work
  double frontierWork = 0.0;
  auto expand = [&](int j)
  {
    result.inRemainder[j] = 1;
    const double childWork = [&]
    {
      double w = 0.0;
      for (int c = tree.start[j]; c < tree.start[j + 1]; ++c)
      {
        w += work[tree.children[c]];
        frontier.push_back(tree.children[c]);
        std::push_heap(frontier.begin(), frontier.end(), byWork);
      }
      return w;
    }();
    result.remainderWork += work[j] - childWork;
    frontierWork += childWork;
  };
  for (int j = 0; j < n - 1; ++j)
  {
    if (parent[j] < 0)
    {
      frontier.push_back(j);
      std::push_heap(frontier.begin(), frontier.end(), byWork);
      frontierWork += work[j];
    }
  }
  expand(n - 1);
  while (!frontier.empty() && work[frontier.front()] * threads > frontierWork)
  {
    const int j = frontier.front();
    std::pop_heap(frontier.begin(), frontier.end(), byWork);
    frontier.pop_back();
    frontierWork -= work[j];
    expand(j);
  }
  return result;
}

// Largest subtrees first, each to the least loaded thread; `longest` is the
// most loaded thread's work.
std::vector<std::vector<int>> assignSubtrees(std::vector<int>& roots,
  const std::vector<double>& work,
  int threads,
  double& longest)
{
  std::sort(roots.begin(), roots.end(), [&](int a, int b) { return work[a] > work[b]; });
  std::vector<double> load(threads, 0.0);
  std::vector<std::vector<int>> assigned(threads);
  for (int j : roots)
  {
    const int t = static_cast<int>(std::min_element(load.begin(), load.end()) - load.begin());
    load[t] += work[j];
    assigned[t].push_back(j);
  }
  longest = *std::max_element(load.begin(), load.end());
  return assigned;
}

// Links `rows` (ascending) into the next list of `split`.
void appendList(EliminationTreeSplit& split, const std::vector<int>& rows)
{
  for (std::size_t k = 0; k + 1 < rows.size(); ++k)
  {
    split.next[rows[k]] = rows[k + 1];
  }
  split.next[rows.back()] = rows.back() + 1;
  split.lists.push_back({ rows.front(), rows.back() + 1 });
}

// One list per thread with subtrees (their rows in order), then the
// remainder's list, which ends at the last row.
void linkLists(EliminationTreeSplit& split,
  std::vector<std::vector<int>>& assigned,
  const std::vector<int>& size,
  const std::vector<char>& inRemainder)
{
  const int n = static_cast<int>(size.size());
  split.next.assign(n, n);
  std::vector<int> rows;
  for (std::vector<int>& roots : assigned)
  {
    if (roots.empty())
    {
      continue;
    }
    std::sort(roots.begin(), roots.end());
    rows.clear();
    for (int j : roots)
    {
      for (int k = j - size[j] + 1; k <= j; ++k)
      {
        rows.push_back(k);
      }
    }
    appendList(split, rows);
  }
  rows.clear();
  for (int k = 0; k < n; ++k)
  {
    if (inRemainder[k])
    {
      rows.push_back(k);
    }
  }
  appendList(split, rows);
  split.lists.back()[1] = n;
  split.remainder = rows;
}
} // namespace

EliminationTreeSplit splitEliminationTree(const cholmod_sparse& S,
  const std::vector<int>& parent,
  int threads)
{
  EliminationTreeSplit split;
  split.valid = true;
  split.threads = threads;
  const int n = static_cast<int>(parent.size());
  std::vector<double> work = rowWork(S, parent);
  double total = 0.0;
  for (int j = 0; j < n; ++j)
  {
    total += work[j];
  }
  // Below this a factorisation takes around a millisecond: waking threads
  // and their workspaces would cost more than the split saves.
  constexpr double minimumWork = 1e6;
  if (threads < 2 || n < 2 || total < minimumWork)
  {
    return split;
  }
  std::vector<int> size(n, 1);
  if (!sumOverSubtrees(parent, work, size))
  {
    return split;
  }
  Frontier frontier = expandRemainder(parent, work, threads);
  double longest = 0.0;
  std::vector<std::vector<int>> assigned = assignSubtrees(frontier.roots, work, threads, longest);
  if (frontier.inRemainder[0] || frontier.remainderWork + longest > 0.9 * total)
  {
    return split; // too little runs at once to pay for the threads
  }
  linkLists(split, assigned, size, frontier.inRemainder);
  split.parent = parent;
  return split;
}

} // namespace surfacemaps
