// A ParaView animation of a command's frames: DIR/frames/<file> per frame and the collection listing them.
#pragma once

#include <functional>
#include <string>
#include <vector>

namespace skinfem::app {

struct AnimationFrame {
  std::string file;  // under DIR/frames
  double timestep = 0;
  int part = 0;
};

// Removes the .vtp frames an earlier run left in DIR/frames (the folder is the command's: a longer run's
// frames would outlive this one's), writes each frame by write(i, path) on the machine's cores (VTK's
// compression is most of the time) and returns the collection (.pvd text) listing them, for the caller to
// write last.
std::string write_animation_frames(const std::string& out_dir, const std::vector<AnimationFrame>& frames,
                                   const std::function<void(std::size_t, const std::string&)>& write);

}  // namespace skinfem::app
