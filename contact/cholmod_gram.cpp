// S = A A^T + beta I with CHOLMOD; see cholmod_gram.hpp for ownership, reuse and regularisation.
// Pivot test: the simplicial LDL^T factor of P S P^T keeps D_jj at the head of column j; the row r = Perm[j]
// is singular to working precision when D_jj <= 1e-12 S_rr (for a positive semi-definite S, a pivot that
// small means the row is a combination of others, and its multiplier would be noise times 1e12).
#include "contact/cholmod_gram.hpp"

#include <cholmod.h>

#include <algorithm>
#include <cstring>
#include <string>

namespace radx::contact {

namespace {

constexpr double kPivotTolerance = 1e-12;
constexpr double kBetaFactor = 1e-9;

std::string status_text(int status) {
  switch (status) {
    case CHOLMOD_OK: return "ok";
    case CHOLMOD_NOT_INSTALLED: return "a method that is not installed";
    case CHOLMOD_OUT_OF_MEMORY: return "out of memory";
    case CHOLMOD_TOO_LARGE: return "integer overflow (the problem is too large)";
    case CHOLMOD_INVALID: return "invalid input";
    case CHOLMOD_GPU_PROBLEM: return "a GPU problem";
    case CHOLMOD_NOT_POSDEF: return "matrix not positive definite";
    case CHOLMOD_DSMALL: return "a diagonal entry below the threshold";
    default: return "status " + std::to_string(status);
  }
}

}  // namespace

struct GramFactor::Impl {
  cholmod_common c{};
  bool started = false;
  cholmod_sparse* A = nullptr;
  cholmod_factor* L = nullptr;
  cholmod_dense *B = nullptr, *X = nullptr, *Y = nullptr, *E = nullptr;
  std::vector<int> pattern_ptr, pattern_index;  // pattern of the analysed A
  int pattern_rows = -1;
  std::vector<double> diag;  // S_rr without beta
  double beta = 0;
  GramCounters counters;

  Impl() {
    if (!cholmod_start(&c)) throw CholmodError("CHOLMOD could not start (cholmod_start failed)");
    started = true;
    c.print = 0;  // errors become exceptions with their own message
    c.error_handler = nullptr;
    c.supernodal = CHOLMOD_SIMPLICIAL;  // no BLAS: thread-independent, and fast for contact patterns
    c.final_ll = 0;                     // keep LDL^T: D is the pivot test
    c.nmethods = 1;
    c.method[0].ordering = CHOLMOD_AMD;
    c.postorder = 1;
  }
  ~Impl() {
    free_factor();
    free_dense();
    if (A) cholmod_free_sparse(&A, &c);
    if (started) cholmod_finish(&c);
  }
  Impl(const Impl&) = delete;
  Impl& operator=(const Impl&) = delete;

  void free_factor() {
    if (L) cholmod_free_factor(&L, &c);
  }
  void free_dense() {
    for (auto** d : {&B, &X, &Y, &E})
      if (*d) cholmod_free_dense(d, &c);
  }

  void check(bool ok, const char* call) {
    if (!ok || c.status < CHOLMOD_OK)
      throw CholmodError(std::string("CHOLMOD ") + call + " failed: " + status_text(c.status));
  }

  // The numeric factorisation with the given beta; returns false when a pivot is not positive.
  bool numeric(double b) {
    double beta2[2] = {b, 0.0};
    const int ok = cholmod_factorize_p(A, beta2, nullptr, 0, L, &c);
    ++counters.factorizations;
    if (c.status == CHOLMOD_NOT_POSDEF) return false;
    check(ok != 0, "cholmod_factorize_p");
    const auto* Lp = static_cast<const int*>(L->p);
    const auto* Lx = static_cast<const double*>(L->x);
    const auto* perm = static_cast<const int*>(L->Perm);
    for (std::size_t j = 0; j < L->n; ++j) {
      const double d = L->is_ll ? Lx[Lp[j]] * Lx[Lp[j]] : Lx[Lp[j]];
      const auto r = perm ? static_cast<std::size_t>(perm[j]) : j;
      if (!(d > kPivotTolerance * (diag[r] + b))) return false;
    }
    return true;
  }
};

GramFactor::GramFactor() : impl_(std::make_unique<Impl>()) {}
GramFactor::~GramFactor() = default;

bool GramFactor::factorize(const SparseColumns& a) {
  auto& s = *impl_;
  if (a.nrows <= 0 || a.ncols < 0 || a.col_ptr.size() != static_cast<std::size_t>(a.ncols) + 1)
    throw CholmodError("CHOLMOD factorisation: invalid matrix shape (" + std::to_string(a.nrows) + " rows, " +
                       std::to_string(a.ncols) + " columns)");
  const std::size_t nnz = static_cast<std::size_t>(a.col_ptr.back());
  const bool same = a.nrows == s.pattern_rows && a.col_ptr == s.pattern_ptr && a.row_index == s.pattern_index;
  if (!same) {
    s.free_factor();
    if (s.A) cholmod_free_sparse(&s.A, &s.c);
    s.A = cholmod_allocate_sparse(static_cast<std::size_t>(a.nrows), static_cast<std::size_t>(a.ncols),
                                  std::max<std::size_t>(nnz, 1), 1, 1, 0, CHOLMOD_REAL, &s.c);
    s.check(s.A != nullptr, "cholmod_allocate_sparse");
    std::memcpy(s.A->p, a.col_ptr.data(), a.col_ptr.size() * sizeof(int));
    std::memcpy(s.A->i, a.row_index.data(), nnz * sizeof(int));
  }
  std::memcpy(s.A->x, a.value.data(), nnz * sizeof(double));
  if (!same) {
    s.L = cholmod_analyze(s.A, &s.c);
    s.check(s.L != nullptr, "cholmod_analyze");
    s.pattern_rows = a.nrows;
    s.pattern_ptr = a.col_ptr;
    s.pattern_index = a.row_index;
    ++s.counters.analyses;
  } else {
    ++s.counters.reuses;
  }
  s.diag.assign(static_cast<std::size_t>(a.nrows), 0.0);
  for (std::size_t k = 0; k < nnz; ++k)
    s.diag[static_cast<std::size_t>(a.row_index[k])] += a.value[k] * a.value[k];
  s.beta = 0;
  if (!s.numeric(0.0)) {
    const double dmax = *std::max_element(s.diag.begin(), s.diag.end());
    s.beta = kBetaFactor * (dmax > 0 ? dmax : 1.0);
    if (!s.numeric(s.beta))
      throw CholmodError("CHOLMOD factorisation: not positive definite even with the regularisation beta = " +
                         std::to_string(s.beta));
    ++s.counters.regularisations;
    s.counters.beta_max = std::max(s.counters.beta_max, s.beta);
  }
  return same;
}

void GramFactor::solve(std::span<const double> b, std::span<double> x) {
  auto& s = *impl_;
  if (!s.L || !s.A || b.size() != s.A->nrow || x.size() != s.A->nrow)
    throw CholmodError("CHOLMOD solve: no factor, or a right-hand side of the wrong size");
  if (!s.B || s.B->nrow != s.A->nrow) {
    if (s.B) cholmod_free_dense(&s.B, &s.c);
    s.B = cholmod_allocate_dense(s.A->nrow, 1, s.A->nrow, CHOLMOD_REAL, &s.c);
    s.check(s.B != nullptr, "cholmod_allocate_dense");
  }
  std::copy(b.begin(), b.end(), static_cast<double*>(s.B->x));
  const int ok = cholmod_solve2(CHOLMOD_A, s.L, s.B, nullptr, &s.X, nullptr, &s.Y, &s.E, &s.c);
  s.check(ok != 0 && s.X != nullptr, "cholmod_solve2");
  const auto* xs = static_cast<const double*>(s.X->x);
  std::copy(xs, xs + x.size(), x.begin());
}

double GramFactor::beta() const {
  return impl_->beta;
}

const GramCounters& GramFactor::counters() const {
  return impl_->counters;
}

}  // namespace radx::contact
