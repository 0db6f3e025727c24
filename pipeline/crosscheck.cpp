#include "skinfem/pipeline/crosscheck.hpp"

#include "skinfem/green/kfit.hpp"
#include "skinfem/pipeline/progress.hpp"

namespace skinfem::pipeline {

validation::Crosscheck crosscheck_run(const Scene& scene, const AdjointSetup& adjoints,
                                      const ContactSetup& contact, const DefectRun& defect, double force_N,
                                      double k_best, const contact::MeridianContactResult* meridian) {
  progress("crosscheck: the paper's model against FE, one assumption at a time");
  validation::CrosscheckInput in;
  in.mesh = &contact.mesh();
  in.solver = contact.solver.get();
  in.fe = adjoints.fe.get();
  in.sensors = scene.sensors;
  for (const auto& s : scene.sensors.positions) in.thickness.push_back(thickness_at(scene, adjoints.mesh, s));
  in.E = scene.material.E;
  in.nu = scene.material.nu;
  in.force = force_N;
  in.center = contact_center(scene);
  in.center_thickness = thickness_at(scene, adjoints.mesh, in.center);
  in.equivalent_radius = equivalent_sphere_radius(scene);
  in.k_paper = green::kPaperK;
  in.k_best = k_best;
  in.sweeps = &defect.sweeps;
  in.frames = &defect.frames;
  in.sweep = *scene.contact->sweep;
  in.meridian = meridian;
  return validation::crosscheck(in);
}

}  // namespace skinfem::pipeline
