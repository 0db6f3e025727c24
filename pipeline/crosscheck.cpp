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

nlohmann::json front_sensor_json(const validation::FrontSensorAnswer& a) {
  nlohmann::json j;
  std::string front;
  for (const int k : a.front) front += (front.empty() ? "#" : ", #") + std::to_string(k + 1);
  j["front_sensors"] = front;
  if (!a.front.empty()) {
    j["coupling_amplitude_factor_z"] = {a.coupling_lo[0], a.coupling_hi[0]};
    j["coupling_amplitude_factor_x"] = {a.coupling_lo[1], a.coupling_hi[1]};
  }
  if (a.model_lo) {
    j["fe_over_paper_model_amplitude_z"] = {(*a.model_lo)[0], (*a.model_hi)[0]};
    j["fe_over_paper_model_amplitude_x"] = {(*a.model_lo)[1], (*a.model_hi)[1]};
  }
  j["answer"] = a.answer;
  return j;
}

}  // namespace skinfem::pipeline
