// The BLAS's own thread pool, where the BLAS has one (OpenBLAS, which Debian's MUMPS calls): its threads help
// a large 3D factorization, but on small fronts (the meridian's 2D solves) they only spin, taking the core
// another process or thread of ours could use. Its rounding may depend on its thread count, so work that
// must give the same numbers however it is spread fixes the count.
#pragma once

namespace skinfem {

// The BLAS at n threads for this object's lifetime (inherited by processes forked meanwhile), then as it
// was; nothing when the loaded BLAS has no such control.
class BlasThreads {
 public:
  explicit BlasThreads(int n);
  ~BlasThreads();
  BlasThreads(const BlasThreads&) = delete;
  BlasThreads& operator=(const BlasThreads&) = delete;

 private:
  int before_ = 0;  // 0: no control
};

}  // namespace skinfem
