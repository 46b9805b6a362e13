//! @file Cell-linked list and fixed-stride neighbour lists (O(N) search).
#pragma once
#include <cstddef>
#include <vector>

namespace hvi::sph {

//! Points binned into square cells, row-major with x fastest, and sorted by cell, so that the
//! cells of one row around a point are one contiguous range of the sorted order.
class CellGrid {
 public:
  //! Bins points [0, n) into cells of side `cellSize` (the list builder uses half the largest
  //! search radius and scans 5 x 5 cells). The grid covers
  //! the points' bounding box; if that would need more than ~4 n cells, the cells are enlarged.
  void build(const double* x, const double* z, const double* h, std::size_t n, double cellSize);

  [[nodiscard]] int nx() const { return nx_; }
  [[nodiscard]] int nz() const { return nz_; }
  [[nodiscard]] int cellX(double x) const;
  [[nodiscard]] int cellZ(double z) const;
  //! Sorted-order range [begin(c), begin(c + 1)) of cell c = k * nx + i.
  [[nodiscard]] int begin(int cell) const { return start_[static_cast<std::size_t>(cell)]; }
  //! Original index, x, z, h of the point at sorted position s.
  [[nodiscard]] const int* order() const { return order_.data(); }
  [[nodiscard]] const double* sortedX() const { return sx_.data(); }
  [[nodiscard]] const double* sortedZ() const { return sz_.data(); }
  [[nodiscard]] const double* sortedH() const { return sh_.data(); }

  //! Exchanges the storage of the sorted x, z, h with three of the caller's arrays (the
  //! stepper lends the grid arrays that are dead during the list build: docs/performance.md,
  //! "SPH memory"). The next build() sizes them.
  void swapSorted(std::vector<double>& x, std::vector<double>& z, std::vector<double>& h) {
    sx_.swap(x);
    sz_.swap(z);
    sh_.swap(h);
  }
  //! Frees the arrays; the next build() allocates them again.
  void release() { *this = CellGrid(); }

 private:
  int nx_ = 0, nz_ = 0;
  double x0_ = 0.0, z0_ = 0.0, inv_ = 1.0;
  std::vector<int> start_, order_;
  std::vector<double> sx_, sz_, sh_;
};

//! Neighbours of each real particle i in slots [start[i], start[i] + count[i]), its row's
//! capacity start[i + 1] - start[i] (a CSR with spare slots per row, so the rows are filled in
//! parallel without a counting pass; a row that overflows is widened, alone, and the list
//! redone). The capacities follow each row's own count: one compressed particle does not widen
//! every row. With `cacheW`, with each neighbour the kernel value W_ij
//! found when the list was built (the mass iteration reuses it over many sweeps); the stepper's
//! list holds only the indices (4 B per slot instead of 12) and its passes recompute W_ij from
//! the positions, the same bits (docs/performance.md, "SPH memory").
struct NeighbourList {
  std::vector<std::size_t> start;  //!< nReal + 1 row offsets
  std::size_t stride = 0;          //!< the largest row capacity (scratch rows of the passes)
  bool cacheW = true;
  //! The points never move while the list is used (the mass iteration): a new list's rows are
  //! sized to the longest row exactly instead of with room for compression.
  bool fixedPoints = false;
  //! Half rows (the stepper's planar lane passes, docs/performance.md): row i lists only its
  //! neighbours j > i (every ghost, and each real pair once), in the full row's order, and
  //! the capacities follow these counts. Not with cacheW.
  bool half = false;
  //! Half rows: the capacity of the build's scratch row, which holds a whole row.
  std::size_t scanStride = 0;
  std::vector<int> count;
  std::vector<int> index;
  std::vector<double> w;  //!< empty without cacheW
  //! Half rows: per row the largest real neighbour index + 1 (i + 1 if none), which bounds
  //! where a block of rows adds its pairs' other ends.
  std::vector<int> reach;
  //! Half rows: the passes' accumulators for the other ends beyond a block (work space, kept
  //! between steps so that the step loop does not allocate).
  mutable std::vector<std::vector<double>> spill;
  mutable std::vector<std::size_t> spillSpan;  //!< per block: the other ends past it it reaches
  mutable std::vector<std::vector<int>> farJ;      //!< per block: other ends beyond the spill
  mutable std::vector<std::vector<double>> farV;   //!< and their terms
  mutable std::vector<double> sums;
  //! Half rows: arrays of at least the real particles' count, dead during a pass, that the
  //! stepper lends for the spills (one per accumulated field; used when there are enough for
  //! the pass), instead of `spill` (docs/performance.md, "SPH memory").
  mutable double* lentSpill[5] = {};
  mutable int lentSpillCount = 0;
};

//! Brute-force-checkable entry point: lists, for the first `nReal` of `n` points, every other
//! point j with |x_i - x_j| < radiusFactor * (h_i + h_j) / 2, in cell-sweep order.
void buildNeighbourList(const double* x, const double* z, const double* h, std::size_t n,
                        std::size_t nReal, double radiusFactor, CellGrid& grid,
                        NeighbourList& list);

}  // namespace hvi::sph
