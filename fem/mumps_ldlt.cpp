#include "skinfem/fem/mumps_ldlt.hpp"

#include <dmumps_c.h>

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <exception>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "skinfem/fem/dense_rate.hpp"
#include "skinfem/fem/memory.hpp"

namespace skinfem {

namespace {
constexpr int kUseCommWorld = -987654;
std::mutex mumps_mutex;  // sequential MUMPS keeps global state in its fake MPI layer
}  // namespace

struct MumpsLdlt::Impl {
  mutable DMUMPS_STRUC_C id{};
  std::vector<MUMPS_INT> irn, jcn;
  std::vector<double> a;
  mutable std::vector<double> rhs;
  int schur_size = 0;
  bool factored = false;
  std::vector<MUMPS_INT> schur_vars;
  std::vector<MUMPS_INT> perm_in;
  Eigen::MatrixXd schur;
  bool keep_pattern = false;  // irn and jcn then stay after the factorization (refactor())

  void call(int job) const {
    id.job = job;
    dmumps_c(&id);
    if (id.infog[0] < 0)
      throw std::runtime_error("MUMPS job " + std::to_string(job) + " failed: INFOG(1) = " +
                               std::to_string(id.infog[0]) + ", INFOG(2) = " + std::to_string(id.infog[1]));
  }
};

namespace {
// MUMPS's factorization rate over Eigen's single-threaded dense Cholesky rate, and the work outside the
// counted flops (assembling the fronts, moving the factors) as flops per unknown at that rate, which takes
// most of the time on small meshes. Fitted (2026-12, 2-core development machine) on the report's four
// factorizations of the paper's cap, 25k-125k unknowns and 4.3e9-1.7e11 flops: quiet, they took 0.61-6.0 s,
// 0.64-0.89 of the estimate; beside a 2-core build, 0.88-9.3 s, up to 1.6 times it. (Flops alone at a ratio
// of 1.75 had the smallest take 4.9 times its estimate.)
constexpr double kMumpsOverDenseRate = 2.5;
constexpr double kFlopsPerUnknown = 1e6;

// Calls `progress` every `every_s` seconds from its own thread until destroyed.
class Watcher {
 public:
  Watcher(const FactorProgress& progress, double flops, double unknowns, double every_s)
      : progress_(progress), start_(std::chrono::steady_clock::now()) {
    status_.estimated_flops = flops;
    status_.estimated_s = (flops + kFlopsPerUnknown * unknowns) / (kMumpsOverDenseRate * dense_flop_rate());
    if (progress_) thread_ = std::thread([this, every_s] { run(every_s); });
  }
  ~Watcher() {
    {
      std::lock_guard<std::mutex> lock(m_);
      done_ = true;
    }
    cv_.notify_all();
    if (thread_.joinable()) thread_.join();
    if (progress_ && std::uncaught_exceptions() == 0) {
      status_.fraction = 1;
      status_.elapsed_s = elapsed();
      progress_(status_);
    }
  }

 private:
  double elapsed() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  }
  void run(double every_s) {
    std::unique_lock<std::mutex> lock(m_);
    while (!cv_.wait_for(lock, std::chrono::duration<double>(every_s), [this] { return done_; })) {
      status_.elapsed_s = elapsed();
      status_.fraction = std::min(0.99, status_.elapsed_s / status_.estimated_s);
      progress_(status_);
    }
  }
  const FactorProgress& progress_;
  std::chrono::steady_clock::time_point start_;
  FactorStatus status_;
  std::mutex m_;
  std::condition_variable cv_;
  bool done_ = false;
  std::thread thread_;
};
}  // namespace

MumpsLdlt::MumpsLdlt(const Eigen::SparseMatrix<double>& K, const FactorProgress& progress, double every_s)
    : MumpsLdlt(static_cast<int>(K.rows()), lower_triangle(K), progress, every_s) {}

MumpsLdlt::Triplets MumpsLdlt::lower_triangle(const Eigen::SparseMatrix<double>& K) {
  Triplets t;
  for (int c = 0; c < K.outerSize(); ++c)
    for (Eigen::SparseMatrix<double>::InnerIterator it(K, c); it; ++it)
      if (it.row() >= c) {
        t.row.push_back(static_cast<int>(it.row()));
        t.col.push_back(c);
        t.value.push_back(it.value());
      }
  return t;
}

// Below this, approximate minimum fill (see the constructor).
constexpr int kPordMinUnknowns = 5000;

MumpsLdlt::MumpsLdlt(int n, Triplets lower, const FactorProgress& progress, double every_s)
    : MumpsLdlt(n, std::move(lower), 0, progress, every_s) {}

MumpsLdlt::MumpsLdlt(int n, Triplets lower, int schur_size, const FactorProgress& progress, double every_s,
                     bool factor_now, const std::vector<int>& leading_order)
    : MumpsLdlt(n, std::move(lower), schur_size, progress, every_s, factor_now, leading_order, -1) {}

std::vector<int> MumpsLdlt::min_degree_order(int n, const Triplets& lower) {
  Triplets leading;
  for (size_t t = 0; t < lower.row.size(); ++t)
    if (lower.row[t] < n && lower.col[t] < n)
      leading.row.push_back(lower.row[t]), leading.col.push_back(lower.col[t]),
          leading.value.push_back(lower.value[t]);
  return MumpsLdlt(n, std::move(leading), 0, {}, 5, false, {}, 6).pivot_order();
}

MumpsLdlt::MumpsLdlt(int n, Triplets lower, int schur_size, const FactorProgress& progress, double every_s,
                     bool factor_now, const std::vector<int>& leading_order, int icntl7)
    : impl_(new Impl) {
  if (schur_size < 0 || schur_size >= n)
    throw std::invalid_argument("MumpsLdlt: Schur size " + std::to_string(schur_size) + " outside [0, " +
                                std::to_string(n) + ")");
  if (!leading_order.empty() && static_cast<int>(leading_order.size()) != n - schur_size)
    throw std::invalid_argument("MumpsLdlt: a leading pivot order of " +
                                std::to_string(leading_order.size()) + " unknowns for a leading block of " +
                                std::to_string(n - schur_size));
  std::lock_guard<std::mutex> lock(mumps_mutex);
  Impl& s = *impl_;
  // MUMPS counts from 1; the value array is taken over without a copy.
  s.irn = std::move(lower.row);
  s.jcn = std::move(lower.col);
  s.a = std::move(lower.value);
  for (auto& i : s.irn) ++i;
  for (auto& j : s.jcn) ++j;
  s.id.par = 1;
  s.id.sym = 2;  // general symmetric (indefinite): LDLᵀ with 2×2 pivots
  s.id.comm_fortran = kUseCommWorld;
  s.call(-1);
  s.id.icntl[0] = -1;  // no error, diagnostic or global output
  s.id.icntl[1] = -1;
  s.id.icntl[2] = -1;
  s.id.icntl[3] = 0;
  // ICNTL(7) = 4, PORD (MUMPS's own nested dissection + minimum degree, no random generator): bitwise
  // reproducible within and across processes. On candelier2011's 101k-DOF half, against approximate
  // minimum fill (2): 19 % fewer factor entries, 41 % fewer flops, peak RSS 0.97 against 1.11 GB; METIS
  // (5) and SCOTCH (3) need about as much but two factorizations of one matrix in one process differ in
  // the last bits (their generators' state carries over). PORD ends the process on graphs it cannot split
  // (a dense 300 × 300 block: "no valid number of stages in multisector"), so small systems, where the
  // ordering costs nothing anyway, keep approximate minimum fill (2), also reproducible.
  s.id.icntl[6] = icntl7 >= 0 ? icntl7 : n >= kPordMinUnknowns ? 4 : 2;
  if (!leading_order.empty()) {
    // ICNTL(7) = 1: the given order (PERM_IN, 1-based positions), the Schur unknowns last. MUMPS orders a
    // matrix with a Schur block by approximate minimum degree whatever ICNTL(7) asks; on candelier2011's
    // contact half (95,898 unknowns, 495 border columns) that factor had 1.7× the entries of the plain
    // matrix's PORD factor, and the plain matrix's PORD order with the border appended last fills less.
    s.perm_in.resize(n);
    for (int i = 0; i < n; ++i) s.perm_in[i] = i < n - schur_size ? leading_order[i] + 1 : i + 1;
    s.id.icntl[6] = 1;
    s.id.perm_in = s.perm_in.data();
  }
  s.id.icntl[13] = 60;  // ICNTL(14): +60 % working-space relaxation for delayed pivots
  s.id.n = static_cast<MUMPS_INT>(n);
  s.id.nnz = static_cast<MUMPS_INT8>(s.a.size());
  s.id.irn = s.irn.data();
  s.id.jcn = s.jcn.data();
  s.id.a = s.a.data();
  if (schur_size > 0) {
    // Centralized on the host (ICNTL(19) = 1), into a buffer of ours; for a symmetric matrix MUMPS fills
    // one triangle of it, completed below.
    s.schur_size = schur_size;
    for (int i = n - schur_size; i < n; ++i) s.schur_vars.push_back(i + 1);
    s.schur = Eigen::MatrixXd::Zero(schur_size, schur_size);
    s.id.icntl[18] = 1;
    s.id.size_schur = schur_size;
    s.id.listvar_schur = s.schur_vars.data();
    s.id.schur = s.schur.data();
  }
  try {
    s.call(1);  // analysis: ordering, symbolic factorization, flop and memory estimates
  } catch (...) {
    s.id.job = -2;
    dmumps_c(&s.id);
    throw;
  }
  if (factor_now) factor_locked(progress, every_s);
}

MumpsLdlt::Estimate MumpsLdlt::analysis() const {
  const auto& id = impl_->id;
  // INFOG(20) counts in millions when negative.
  return {id.rinfog[0], id.infog[19] < 0 ? -1e6 * id.infog[19] : id.infog[19],
          static_cast<double>(id.infog[16])};
}

void MumpsLdlt::factor(const FactorProgress& progress, double every_s) {
  std::lock_guard<std::mutex> lock(mumps_mutex);
  factor_locked(progress, every_s);
}

void MumpsLdlt::factor_locked(const FactorProgress& progress, double every_s) {
  Impl& s = *impl_;
  if (s.factored) throw std::logic_error("MumpsLdlt: factored twice");
  // INFOG(17): the factorization's estimated memory, MB (in-core, all of MUMPS's data).
  const double need_mb = s.id.infog[16], avail_mb = available_memory_mb();
  if (avail_mb > 0 && need_mb > avail_mb) {
    char buf[200];
    std::snprintf(buf, sizeof buf,
                  "the factorization of %lld unknowns would need about %.3g GB (MUMPS analysis), more than "
                  "the %.3g GB available; coarsen the mesh",
                  static_cast<long long>(s.id.n), need_mb / 1024, avail_mb / 1024);
    throw std::runtime_error(buf);
  }
  {
    Watcher watcher(progress, s.id.rinfog[0], s.id.n, every_s);
    s.call(2);
  }
  s.factored = true;
  if (s.schur_size > 0) {
    // MUMPS returns a symmetric matrix's Schur complement as its lower triangle by rows, i.e. the upper
    // triangle of our column-major buffer; what it leaves in the other triangle is not specified.
    Eigen::MatrixXd& S = s.schur;
    S.triangularView<Eigen::StrictlyLower>() = S.transpose();
    s.id.schur = nullptr;
    s.id.listvar_schur = nullptr;
  }
  // The solve phase needs only the factors (no iterative refinement or error analysis is requested):
  // release the matrix, or its values alone when its pattern is kept for refactor().
  if (!s.keep_pattern) {
    std::vector<MUMPS_INT>().swap(s.irn);
    std::vector<MUMPS_INT>().swap(s.jcn);
    s.id.irn = s.id.jcn = nullptr;
  }
  std::vector<double>().swap(s.a);
  s.id.a = nullptr;
}

void MumpsLdlt::keep_pattern() {
  if (impl_->factored) throw std::logic_error("MumpsLdlt: keep_pattern after the factorization");
  impl_->keep_pattern = true;
}

bool MumpsLdlt::same_pattern(const Triplets& lower, size_t entries) const {
  const Impl& s = *impl_;
  const size_t nnz = s.keep_pattern ? s.irn.size() : 0;
  if (nnz == 0 || entries != nnz || lower.row.size() < nnz || lower.col.size() < nnz ||
      lower.value.size() < nnz)
    return false;
  for (size_t k = 0; k < nnz; ++k)
    if (lower.row[k] + 1 != s.irn[k] || lower.col[k] + 1 != s.jcn[k]) return false;
  return true;
}

void MumpsLdlt::refactor(Triplets lower, const FactorProgress& progress, double every_s) {
  std::lock_guard<std::mutex> lock(mumps_mutex);
  Impl& s = *impl_;
  if (!s.keep_pattern || s.irn.empty()) throw std::logic_error("MumpsLdlt: refactor without a kept pattern");
  if (lower.value.size() != s.irn.size() || !same_pattern(lower, lower.value.size()))
    throw std::invalid_argument("MumpsLdlt::refactor: the matrix's pattern is not the analysed one");
  s.a = std::move(lower.value);
  s.id.a = s.a.data();
  std::vector<int>().swap(lower.row);  // the kept pattern's copy: gone before the factors take their memory
  std::vector<int>().swap(lower.col);
  if (s.schur_size > 0) {
    s.id.listvar_schur = s.schur_vars.data();
    s.id.schur = s.schur.data();
  }
  s.factored = false;
  factor_locked(progress, every_s);
}

MumpsLdlt::~MumpsLdlt() {
  std::lock_guard<std::mutex> lock(mumps_mutex);
  impl_->id.job = -2;
  dmumps_c(&impl_->id);
}

Eigen::VectorXd MumpsLdlt::solve(const Eigen::VectorXd& b) const {
  std::lock_guard<std::mutex> lock(mumps_mutex);
  Impl& s = *impl_;
  if (!s.factored) throw std::logic_error("MumpsLdlt: solve before factor");
  // With a Schur complement the right-hand side still has MUMPS's order n; ICNTL(26) = 0 solves the
  // interior problem A₁₁ x = b and leaves the Schur rows out.
  s.rhs.assign(s.id.n, 0.0);
  std::copy(b.data(), b.data() + b.size(), s.rhs.begin());
  s.id.rhs = s.rhs.data();
  s.id.nrhs = 1;
  s.id.lrhs = s.id.n;
  s.id.icntl[19] = 0;  // ICNTL(20): dense right-hand side
  s.id.icntl[20] = 0;  // ICNTL(21): centralized solution, written over rhs
  s.id.icntl[25] = 0;
  s.call(3);
  return Eigen::Map<const Eigen::VectorXd>(s.rhs.data(), b.size());
}

Eigen::MatrixXd MumpsLdlt::solve(Eigen::MatrixXd X) const {
  std::lock_guard<std::mutex> lock(mumps_mutex);
  Impl& s = *impl_;
  if (!s.factored) throw std::logic_error("MumpsLdlt: solve before factor");
  if (s.schur_size > 0) {  // MUMPS's order n: the Schur rows appended (and ignored, ICNTL(26) = 0)
    Eigen::MatrixXd padded = Eigen::MatrixXd::Zero(s.id.n, X.cols());
    padded.topRows(X.rows()) = X;
    X = std::move(padded);
  }
  // column-major, leading dimension n: MUMPS's dense multi-RHS layout
  s.id.rhs = X.data();
  s.id.nrhs = static_cast<MUMPS_INT>(X.cols());
  s.id.lrhs = s.id.n;
  s.id.icntl[19] = 0;
  s.id.icntl[20] = 0;
  s.id.icntl[26] = 32;  // ICNTL(27): blocking factor of the solve phase
  s.id.icntl[25] = 0;
  s.call(3);
  if (s.schur_size > 0) X.conservativeResize(s.id.n - s.schur_size, Eigen::NoChange);
  return X;
}

const Eigen::MatrixXd& MumpsLdlt::schur() const { return impl_->schur; }

double MumpsLdlt::factor_entries() const {
  const auto& id = impl_->id;
  return id.infog[28];  // INFOG(29); negative would mean millions (×−10⁶), not reached here
}

std::vector<int> MumpsLdlt::pivot_order() const {
  const DMUMPS_STRUC_C& id = impl_->id;
  if (id.sym_perm == nullptr) throw std::logic_error("MumpsLdlt: no pivot order before the analysis");
  std::vector<int> order(id.n);
  for (int i = 0; i < id.n; ++i) order[i] = id.sym_perm[i] - 1;
  return order;
}

double MumpsLdlt::estimated_flops() const { return impl_->id.rinfog[0]; }
double MumpsLdlt::estimated_memory_mb() const { return impl_->id.infog[16]; }

}  // namespace skinfem
