#include "skinfem/scene/commands.hpp"

#include <stdexcept>

#include "skinfem/scene/laws.hpp"

namespace skinfem {
namespace {

using K = OptionKind;

std::vector<std::string> friction_choices() {
  std::vector<std::string> choices{"scene"};
  for (const std::string& mode : friction_mode_names()) choices.push_back(mode);
  return choices;
}

// What every command that runs on a scene takes besides its own options.
std::vector<OptionSpec> on_scene(std::vector<OptionSpec> own,
                                 const std::string& out_help = "output directory",
                                 const std::string& out_default = "out") {
  own.push_back({"scene", K::positional, "scene JSON file"});
  own.push_back({"out", K::text, out_help, out_default});
  own.push_back({"max_dofs",
                 K::nonnegative,
                 "refuse scenes whose estimated mesh exceeds this many DOFs (default: available memory only)",
                 "",
                 {},
                 {},
                 true});
  return own;
}

OptionSpec green_path(const std::string& help) {
  return {"path", K::choice, help, "auto", {"auto", "3d", "meridian"}, {}, true};
}

OptionSpec error_scales(const std::string& what) {
  return {"error_scales",
          K::numbers,
          "coarser levels (mesh sizes x s, s > 1) for " + what,
          "2,1.41",
          {},
          {},
          true};
}

std::vector<CommandSpec> table() {
  const std::string kfit_path =
      "Green tensor solver: meridian (2D axisymmetric; flat layers and a cap's apex sensor), 3d, or auto "
      "(the meridian where it applies)";
  return {
      {"mesh", "mesh the scene's skin (writes mesh.vtu, boundary.vtu, summary.json)", on_scene({})},
      {"solve", "solve the scene's loads (writes fields.vtu, sensors.csv, summary.json)",
       on_scene({{"solver", K::choice, "saddle-point solver", "direct_ldlt", {"direct_ldlt", "schur_cg"}}})},
      {"study", "refinement study of the scene's load with both solvers (study.json, study.csv)",
       on_scene(
           {{"chain", K::flag,
             "the whole chain (Green maps and k, contact, hole sweep) per level: chain_study.csv, .json"},
            {"ridges", K::positive_list,
             "ridge study: mesh elements per ridge period, one level each (>= 3, e.g. 4,5,6,8): the "
             "ridged skin against the same mesh with 2 % ridges (ridge_study.json, .csv)"},
            {"scales", K::positive_list, "factors applied to h_min and h_max, coarse to fine", "2,1.41,1"}})},
      {"kfit",
       "fit the k correction of the Green tensor (kfit.json)",
       on_scene({{"load", K::choice, "calibration load model", "punch", {"punch", "point"}, {}, true},
                 green_path(kfit_path)}),
       true,
       "kfit.json",
       {"k_central", "k_lsq_line"}},
      {"green", "FE Green tensors of every sensor (green.csv, green_maps.vtp)",
       on_scene({{"grid",
                  K::positive,
                  "also each sensor's kernel on a regular grid of this spacing (mm) over the top: kernel.h5, "
                  "kernel.vti",
                  "",
                  {},
                  {},
                  true},
                 green_path(kfit_path)}),
       true, "summary.json"},
      {"contact",
       "rigid indenter in contact with the skin (pressure.vtp, fields.vtu, sensors.csv, summary.json)",
       on_scene({{"friction",
                  K::choice,
                  "friction mode (default: the scene's contact.friction.mode)",
                  "scene",
                  friction_choices(),
                  {},
                  true},
                 green_path("contact solver: meridian (2D axisymmetric: a flat layer or a cap's apex, the "
                            "indenter on its axis; frictionless and uncoupled modes), 3d, or auto (the "
                            "meridian where every mode contact reports is exact there)")}),
       true,
       "summary.json",
       {"contact_radius_mm", "p0_kPa", "indentation_um"}},
      {"defect", "hole swept through the contact, static and sliding (defect.csv, defect.pvd, summary.json)",
       on_scene({error_scales("the largest sliding signal's error bar"),
                 {"no_error_bars", K::flag, "skip the coarser levels (no error bar)", "", {}, {}, true}}),
       true, "summary.json"},
      {"scan",
       "a textured plate scanned over the skin, static and sliding, beside the holes' superposition "
       "(scan.csv, scan.pvd, summary.json)",
       on_scene({{"no_superposition",
                  K::flag,
                  "skip the linear prediction (the holes one at a time)",
                  "",
                  {},
                  {},
                  true}}),
       true, "summary.json"},
      {"perceive",
       "how small a hole the array detects under the paper's noise: matched filter, ladder of diameters, ROC "
       "(perception.json, roc.csv)",
       on_scene(
           {{"passages", K::count, "N: the signals are the mean of N passages", "14", {}, {}, true},
            {"noise_z", K::positive, "noise on varsigma_z per sample and passage, kPa", "0.6", {}, {}, true},
            {"noise_x", K::positive, "noise on varsigma_x per sample and passage, kPa", "0.4", {}, {}, true},
            {"sample_mm",
             K::nonnegative,
             "spacing of independent noise samples along the sweep, mm (0: the sweep's step)",
             "0",
             {},
             {},
             true},
            {"scan_mm",
             K::nonnegative,
             "a hole at an unknown place: the filter slides along a scan this long, mm",
             "10",
             {},
             {},
             true},
            {"scan_trials",
             K::nonnegative,
             "Monte Carlo scans checking that filter's rates (0: none)",
             "2000",
             {},
             {},
             true}}),
       true, "perception.json"},
      {"invert",
       "where the holes are: a scan's signals deconvolved over the scene's single-hole responses, the "
       "contact's offset fitted, beside each sensor alone (features.csv, summary.json)",
       on_scene(
           {{"signals", K::positional,
             "signals CSV in scan.csv's columns (u_mm,sensor,varsigma_z_kPa,"
             "varsigma_x_kPa[,case])"},
            {"case", K::choice, "the case the signals are of", "sliding", {"static", "sliding"}},
            {"passages", K::count, "N: the signals are the mean of N passages", "14"},
            {"noise_z", K::positive, "noise on varsigma_z per sample and passage, kPa", "0.6"},
            {"noise_x", K::positive, "noise on varsigma_x per sample and passage, kPa", "0.4"},
            {"offset_range", K::nonnegative,
             "the contact's offset from the sensors is searched in +-this, mm", "1.0"},
            {"dictionary", K::text,
             "reuse the dictionary an earlier invert wrote in this directory (same scene, case, step and "
             "offsets) instead of building it",
             ""}}),
       false},
      {"report",
       "the whole chain on one factorization and the paper's model against it (index.html, report.json)",
       on_scene({error_scales("the headline numbers' error bars"),
                 {"no_error_bars", K::flag, "skip the coarser levels (no error bars)", "", {}, {}, true},
                 {"fast",
                  K::flag,
                  "headline numbers and the paper's figures only: no error bars, no hypothesis budget, no "
                  "post design sweep (the page says what it left out)",
                  "",
                  {},
                  {"no_error_bars"}}},
                "output directory (default: out/<scene name>)", ""),
       true, "report.json"},
      {"sweep",
       "a family of scenes from a sweep spec, one run per member on Snakemake (results.csv, results.h5, "
       "plots/)",
       {{"spec", K::positional, "sweep spec JSON file (format: scene/sweep.cpp, docs/sweeps.md)"},
        {"out", K::text, "output directory (default: out/<sweep name>)"},
        {"cores", K::count, "cores Snakemake may use on this machine, one per member job", "1"},
        {"profile",
         K::text,
         "a Snakemake profile (a cluster, e.g. sweeps/profiles/slurm)",
         "",
         {},
         {"cores"}},
        {"dry_run", K::flag, "write the member scenes and the manifest, run nothing"}}},
  };
}

}  // namespace

const std::vector<CommandSpec>& commands() {
  static const std::vector<CommandSpec> all = table();
  return all;
}

const CommandSpec& command_named(const std::string& name) {
  for (const CommandSpec& c : commands())
    if (c.name == name) return c;
  throw std::out_of_range("no skinfem command named '" + name + "'");
}

std::string option_flag(const std::string& name) {
  std::string flag = "--" + name;
  for (char& c : flag)
    if (c == '_') c = '-';
  return flag;
}

}  // namespace skinfem
