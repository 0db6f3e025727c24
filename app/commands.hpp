// One function per subcommand; each returns the process exit code.
#pragma once

#include <string>

#include "scene/scene.hpp"

namespace skinfem::app {

int run_mesh(const Scene& scene, const std::string& out_dir);

}  // namespace skinfem::app
