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

// OpenBLAS's idle threads spin (sched_yield) for about 2^28 cycles after every threaded call before they
// sleep. Beside our other threads and processes on a machine's few cores (the report's kfit, figures and post
// design) that spinning takes their time: on the default report, 2 cores, 2-3.5 s of about 30. This makes
// them sleep at once (OPENBLAS_THREAD_TIMEOUT at its least, 4: 2^4 cycles) unless the environment sets the
// timeout itself; the work each thread does, and so every number, is unchanged. Call it once, before any
// thread of ours calls the BLAS; nothing where the BLAS is not OpenBLAS.
void blas_threads_sleep_when_idle();

}  // namespace skinfem
