// What a post changes, on the meridian of the scene's skin at its axis (the unbounded layer of a flat scene's
// thickness, or a spherical cap's apex): the Green tensor of an isolated post (no others around it: each is a
// rigid inclusion that changes its neighbours' readings) against a disc of the same diameter at the same
// place (peak, width at half maximum, integral of g_zz and g_xx), and a design sweep of post height and
// diameter. Every design is two 2D solves (green/meridian.hpp), not a 3D mesh; each number carries the change
// from the level at twice every mesh size as its error.
#pragma once

#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "skinfem/green/meridian.hpp"
#include "skinfem/scene/parallel.hpp"
#include "skinfem/scene/scene.hpp"

namespace skinfem::pipeline {

// One sensor design and its Green tensor's shape (MeridianGreen::Shape; 1/mm², mm, mm, 1).
struct SensorDesign {
  double diameter = 0, height = 0;  // mm; height 0: the disc of that diameter
  MeridianGreen::Shape zz, xx;
  // |this level − the level at twice every size| over the value, for the peak, the half width and the
  // integral: the larger of zz's and xx's.
  double peak_change = 0, half_width_change = 0, integral_change = 0;
};

struct PostDesign {
  std::string skin;                 // what was solved, one sentence
  SensorDesign disc, post;          // the scene's post (its diameter and height) and the disc of its diameter
  std::vector<SensorDesign> sweep;  // every (diameter, height) of the sweep, diameters outer
  double sweep_scale = 0;           // the sweep's mesh scale (MeridianSizes::for_thickness)
  int dofs = 0;                     // the scene's post at scale 1, both modes
  double seconds = 0;               // the designs' CPU seconds, summed (however many processes ran them)
};

// Why the scene's skin has no meridian to compare on (empty: it has one).
std::string post_design_unavailable(const Scene& scene);

// disc and post at mesh scale 1 (changes against scale 2); the sweep over heights × diameters (mm; a height
// 0 is the disc) at sweep_scale, each with its change against 2 × sweep_scale. Throws SceneError where
// post_design_unavailable is not empty.
PostDesign post_design(const Scene& scene, const std::vector<double>& diameters,
                       const std::vector<double>& heights, double sweep_scale = 1.41);

// post_design's work, computed from construction on by `processes` child processes at the lowest priority
// (scene/parallel.hpp's ProcessMap, nice 19: they take the cores the caller leaves idle) while the caller
// goes on with its own, finish() computing here what they have not finished; or (processes 0) by finish()
// on the machine's cores. The numbers are the same either way: each design runs alone with one BLAS thread.
// Call finish() where no other thread of ours is inside the BLAS or MUMPS.
class PostDesignRun {
 public:
  PostDesignRun(const Scene& scene, const std::vector<double>& diameters, const std::vector<double>& heights,
                double sweep_scale, int processes);
  PostDesignRun(PostDesignRun&&) noexcept;
  ~PostDesignRun();
  // Waits for the designs (once).
  PostDesign finish();

 private:
  struct Jobs;
  std::shared_ptr<const Jobs> jobs_;
  std::string skin_;
  double sweep_scale_ = 0;
  std::unique_ptr<ProcessMap> designs_;
};
// The report's: diameters 0.1–0.4 mm, heights 0–1 mm below 0.9 h (the scene's rule for a post).
PostDesignRun report_post_design(const Scene& scene, int processes);
// report.json's post_design entry: each design's shapes and changes, and `answer`, the scene's post against
// its disc and the sweep's ranges in one paragraph from the numbers.
nlohmann::json post_design_json(const PostDesign& p);

}  // namespace skinfem::pipeline
