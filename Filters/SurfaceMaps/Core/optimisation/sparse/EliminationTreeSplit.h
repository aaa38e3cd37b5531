// SurfaceMaps engine: EliminationTreeSplit, the rows of a simplicial Cholesky
// factor divided along its elimination tree into complete subtrees that
// threads factorise at once, and the remainder of rows above them.
#pragma once

#include <cholmod.h>

#include <array>
#include <vector>

namespace surfacemaps
{

// The rows of a simplicial factor split over threads along the elimination
// tree. Row k of L depends only on the rows of k's subtree, and with a
// postordered tree (CHOLMOD's default) a subtree is a contiguous range of
// rows. So complete subtrees can be factorised by different threads at once,
// and the rows above them (the remainder, closed under taking parents) after
// them. CHOLMOD computes every row the same way whoever computes it, in the
// same order within each column, so the factor is the serial one bit for bit.
// CHOLMOD's simplicial factorisation runs on one thread. Its supernodal one
// can use threads inside BLAS, but the map's Newton systems (about 115 flops
// per factor entry) factorise faster simplicial than supernodal; Eigen's
// Cholesky factorisations are serial too. With AMD orderings the rows near
// the root (the remainder) hold about half of the work; RemainderPipeline
// computes them on two threads.
struct EliminationTreeSplit
{
  /// Each list's rows, ascending and linked through `next` (CHOLMOD's
  /// RLinkUp): first row and one past the last. Lists [0, threads) run at
  /// once; the last list is the remainder.
  std::vector<std::array<int, 2>> lists;
  std::vector<int> next;
  /// The elimination tree and the remainder's rows, ascending.
  std::vector<int> parent;
  std::vector<int> remainder;
  /// The thread count it was made for; whether it is up to date.
  int threads = 0;
  bool valid = false;
};

/// Elimination-tree split of the rows of S = triu(A(p, p)) (elimination tree
/// `parent`) for `threads` threads; an empty split (no lists) when it would
/// not pay.
EliminationTreeSplit splitEliminationTree(const cholmod_sparse& S,
  const std::vector<int>& parent,
  int threads);

} // namespace surfacemaps
