// Independent work items on the machine's cores, for the stages whose items share only read-only data.
#pragma once

#include <functional>

namespace skinfem::pipeline {

// Threads a stage may use: the CPUs this process may run on, at most OMP_NUM_THREADS when that is set (a
// sweep's member declares its threads that way).
int worker_threads();

// Calls item(i) for i = 0 … n−1, on worker_threads() threads when `parallel`, else in order on this one.
// done(k) is called on this thread only, with k items finished, before each item it takes and once at the
// end. The first item's exception (in index order) is rethrown after every thread has ended.
void run_indexed(int n, bool parallel, const std::function<void(int)>& item,
                 const std::function<void(int)>& done = {});

}  // namespace skinfem::pipeline
