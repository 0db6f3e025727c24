#include "skinfem/fem/blas_threads.hpp"

#include <dlfcn.h>

namespace skinfem {

namespace {
// Looked up, not linked: the BLAS is whichever libblas.so.3 the system's alternatives point to.
using Setter = void (*)(int);
using Getter = int (*)();
Setter setter() { return reinterpret_cast<Setter>(dlsym(RTLD_DEFAULT, "openblas_set_num_threads")); }
Getter getter() { return reinterpret_cast<Getter>(dlsym(RTLD_DEFAULT, "openblas_get_num_threads")); }
}  // namespace

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
