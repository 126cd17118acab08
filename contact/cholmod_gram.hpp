// Sparse factorisation of S = A A^T + beta I with CHOLMOD (SuiteSparse), for the Lagrange-multiplier
// system of switched contact pairs (docs/theory/type7-lagdt.md section 6): A = L M^-1/2, so S = L M^-1 L^T is
// formed by CHOLMOD itself (cholmod_factorize_p on an unsymmetric A
// factors beta I + A A^T) and never assembled.
//
// Ownership: the object owns its cholmod_common (cholmod_start / cholmod_finish), the matrix A, the
// factor and the solve workspaces; nothing is shared between objects, so two solvers may run side by side.
// Every CHOLMOD status is checked: a failure throws CholmodError with a message naming the call and what
// CHOLMOD reported (out of memory, invalid input, ...). A singular or nearly singular S (a pivot of the
// LDL^T factor not above 1e-12 of its diagonal entry of S, or CHOLMOD's own "not positive definite") is
// factorised again with a regularisation beta = 1e-9 max_r S_rr, which is reported (beta()).
//
// The symbolic analysis (ordering and pattern of the factor) is kept and reused as long as the pattern of A
// (column pointers and row indices) is the same as in the previous call. The factor is simplicial LDL^T
// (no BLAS): its result does not depend on the number of threads.
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <stdexcept>
#include <vector>

namespace radx::contact {

class CholmodError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A in compressed-column form: column c holds rows row_index[col_ptr[c] .. col_ptr[c+1]) (ascending) with
// the values value[...]. Sizes: col_ptr ncols + 1, row_index and value col_ptr[ncols].
struct SparseColumns {
  int nrows = 0, ncols = 0;
  std::vector<int> col_ptr{0};
  std::vector<int> row_index;
  std::vector<double> value;
};

struct GramCounters {
  std::int64_t analyses = 0;         // symbolic analyses (pattern changed)
  std::int64_t reuses = 0;           // numeric factorisations on a kept analysis
  std::int64_t factorizations = 0;   // numeric factorisations, regularised ones included
  std::int64_t regularisations = 0;  // factorisations that needed beta > 0
  double beta_max = 0;               // largest beta used
};

class GramFactor {
 public:
  GramFactor();
  ~GramFactor();
  GramFactor(const GramFactor&) = delete;
  GramFactor& operator=(const GramFactor&) = delete;

  // Factorises A A^T (+ beta I when needed). Returns true when the symbolic analysis was reused.
  // Precondition: a.nrows > 0, the pattern is valid (checked by CHOLMOD: an invalid one throws).
  bool factorize(const SparseColumns& a);
  // x = S^-1 b with the last factor; b and x have a.nrows entries (they may not alias).
  void solve(std::span<const double> b, std::span<double> x);
  // Regularisation of the last factorisation (0: none was needed).
  [[nodiscard]] double beta() const;
  [[nodiscard]] const GramCounters& counters() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace radx::contact
