#include "skinfem/fem/blas_threads.hpp"

#include <dlfcn.h>

#include <cstdlib>

namespace skinfem {

namespace {
// Looked up, not linked: the BLAS is whichever libblas.so.3 the system's alternatives point to.
using Setter = void (*)(int);
using Getter = int (*)();
Setter setter() { return reinterpret_cast<Setter>(dlsym(RTLD_DEFAULT, "openblas_set_num_threads")); }
Getter getter() { return reinterpret_cast<Getter>(dlsym(RTLD_DEFAULT, "openblas_get_num_threads")); }
}  // namespace

void blas_threads_sleep_when_idle() {
  if (std::getenv("OPENBLAS_THREAD_TIMEOUT")) return;  // the user's choice stands
  // OpenBLAS reads the timeout from the environment when it loads, and its pool takes it when it starts: the
  // environment read again, the pool ended here starts again at the next threaded call.
  using ReadEnv = void (*)();
  using Shutdown = int (*)();
  const auto read_env = reinterpret_cast<ReadEnv>(dlsym(RTLD_DEFAULT, "openblas_read_env"));
  const auto shutdown = reinterpret_cast<Shutdown>(dlsym(RTLD_DEFAULT, "blas_thread_shutdown_"));
  if (!read_env || !shutdown) return;
  setenv("OPENBLAS_THREAD_TIMEOUT", "4", 0);
  read_env();
  shutdown();
}

BlasThreads::BlasThreads(int n) {
  const Setter set = setter();
  const Getter get = getter();
  if (!set || !get) return;
  before_ = get();
  set(n);
}

BlasThreads::~BlasThreads() {
  if (before_ > 0) setter()(before_);
}

}  // namespace skinfem
