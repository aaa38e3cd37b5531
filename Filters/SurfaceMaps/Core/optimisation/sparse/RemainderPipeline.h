// SurfaceMaps engine: RemainderPipeline, the rows of a simplicial LL^T factor
// near the elimination tree's root (the remainder of an EliminationTreeSplit)
// computed on two threads at once, the serial factor bit for bit.
#pragma once

#include <cholmod.h>

#include <array>
#include <atomic>
#include <cstddef>
#include <memory>
#include <vector>

namespace surfacemaps
{

// The remainder's rows (about half of the work, mostly one chain of rows
// near the root that form a dense block) on two threads at once: the threads
// take the rows in turn, and a row goes on while the row before it is still
// being computed. Neither CHOLMOD nor Eigen factorises a chain of dependent
// rows in parallel (CHOLMOD's rows are serial; its supernodal factorisation
// is slower on these systems, see EliminationTreeSplit), hence this code.
// Row k's numbers are those cholmod_rowfac computes for an
// LL^T factor, in its order: k's pattern in the order of its row-subtree
// walk (the elimination tree's parent stands for the first off-diagonal
// entry of a column, which is the parent once the rows below are done), then
// for each column i of it the same divisions and subtractions. What row k
// reads of the row before it is that row's entries in the columns of k's
// pattern and its diagonal, so a thread waits, column by column, until the
// row before has stored its entry in that column (LastRow) if that row's
// pattern holds the column (PendingRow, published in row order). Entries
// reach each column in row order, as in the serial factorisation, so the
// factor is the serial one bit for bit.
class RemainderPipeline
{
public:
  /// Whether the pipeline can factorise the remainder of L from S: an LL^T
  /// factor, S packed, sorted and upper, every column with room for its final
  /// count (the analysis allocated exactly that).
  static bool applies(const cholmod_sparse& S, const cholmod_factor& L);

  /// Rows `rows` (ascending, their descendants done) of L; false if a pivot
  /// is not positive (L.minor then below L.n, as cholmod_rowfac leaves it).
  bool factorise(const cholmod_sparse& S,
    const std::vector<int>& parent,
    const std::vector<int>& rows,
    cholmod_factor& L);

private:
  struct Workspace
  {
    std::vector<double> values;
    std::vector<int> flag;
    std::vector<int> stack;
    std::vector<char> wait;
  };
  // The arrays of S and L the rows read and write, and the rows themselves.
  struct Arrays
  {
    const int* Sp;
    const int* Si;
    const double* Sx;
    const int* Lp;
    int* Li;
    double* Lx;
    int* Lnz;
    std::size_t* minor;
    const std::vector<int>& parent;
    const std::vector<int>& rows;
    int n;
  };

  void reset(int n, int m);
  void factoriseRow(Workspace& w, const Arrays& a, int j);
  int scatterRow(Workspace& w, const Arrays& a, int j, int k) const;
  void publishPattern(Workspace& w, const Arrays& a, int j, int k, int previous, int top);
  double eliminateColumns(Workspace& w, const Arrays& a, int k, int previous, int top, double dk);
  void storeDiagonal(const Arrays& a, int k, double dk);

  std::array<Workspace, 2> Threads;
  std::unique_ptr<std::atomic<int>[]> PendingRow;
  std::unique_ptr<std::atomic<int>[]> LastRow;
  // Per remainder row: its pattern is published.
  std::unique_ptr<std::atomic<int>[]> Published;
  std::size_t Size = 0;
};

} // namespace surfacemaps
