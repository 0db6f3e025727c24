// The paper's convolution model against full FE, one assumption at a time (validation/crosscheck.hpp), on
// set-ups a run already has: the skin's 3D adjoints (the FE Green maps), its condensed contact and the hole
// sweeps of `defect` (pipeline/defect.hpp). Units: mm, N, MPa.
#pragma once

#include <nlohmann/json.hpp>

#include "skinfem/pipeline/adjoint_setup.hpp"
#include "skinfem/pipeline/contact_setup.hpp"
#include "skinfem/pipeline/defect.hpp"
#include "skinfem/validation/crosscheck.hpp"

namespace skinfem::pipeline {

// force_N: the indenter's force (the scene's when it prescribes one, else the contact's); k_best: the best
// fit of k (kfit's k_lsq_line of sensor #1); meridian: the frictionless contact on the meridian when the
// scene has one (ContactRun::meridian_check), for its edge-resolved pressure profile. Throws SceneError when
// a sensor or the contact centre has no skin above it.
validation::Crosscheck crosscheck_run(const Scene& scene, const AdjointSetup& adjoints,
                                      const ContactSetup& contact, const DefectRun& defect, double force_N,
                                      double k_best,
                                      const contact::MeridianContactResult* meridian = nullptr);

// report.json's front_sensors entry (validation::front_sensor_answer).
nlohmann::json front_sensor_json(const validation::FrontSensorAnswer& a);

}  // namespace skinfem::pipeline
