// Progress of the long stages (meshing, factoring, condensing, sweeps). The library never writes to the
// terminal itself: a front end installs a sink (the command line prints "[skinfem] …" on stderr); without
// one, progress is dropped.
#pragma once

#include <functional>
#include <string>

namespace skinfem::pipeline {

using ProgressSink = std::function<void(const std::string& message)>;

// Replaces the process's sink (null: silent) and returns the previous one.
ProgressSink set_progress_sink(ProgressSink sink);
void progress(const std::string& message);
// "stage: done/total (P %, S s)".
void progress_step(const std::string& stage, int done, int total, double elapsed_s);

}  // namespace skinfem::pipeline
