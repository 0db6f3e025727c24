#include "app/animation.hpp"

#include <filesystem>
#include <sstream>

#include "app/common.hpp"
#include "skinfem/scene/parallel.hpp"

namespace skinfem::app {

std::string write_animation_frames(const std::string& out_dir, const std::vector<AnimationFrame>& frames,
                                   const std::function<void(std::size_t, const std::string&)>& write) {
  prepare_output_dir(out_dir + "/frames");
  for (const auto& f : std::filesystem::directory_iterator(out_dir + "/frames"))
    if (f.is_regular_file() && f.path().extension() == ".vtp") std::filesystem::remove(f.path());
  std::ostringstream pvd;
  pvd << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n<Collection>\n";
  for (const AnimationFrame& f : frames)
    pvd << "<DataSet timestep=\"" << f.timestep << "\" part=\"" << f.part << "\" file=\"frames/" << f.file
        << "\"/>\n";
  pvd << "</Collection>\n</VTKFile>\n";
  for_each_index(frames.size(), [&](std::size_t i) { write(i, out_dir + "/frames/" + frames[i].file); });
  return pvd.str();
}

}  // namespace skinfem::app
