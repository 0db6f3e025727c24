#include "app/chain_study.hpp"

#include <cmath>
#include <cstdio>
#include <sstream>

#include "app/common.hpp"
#include "skinfem/validation/richardson.hpp"

namespace skinfem::app {

void write_chain_study(const std::vector<ChainLevel>& levels, const nlohmann::json& study,
                       const std::string& out_dir, bool print_table) {
  const size_t n = levels.size();
  std::ostringstream csv;
  csv.precision(10);
  csv << "stage,level,dofs,seconds,error\n";
  const auto errors = chain_errors(levels);
  for (size_t i = 0; i < errors.size(); ++i) {
    const ChainError& e = errors[i];
    char order[32];
    std::snprintf(order, sizeof order, "observed order %.2f", e.order);
    if (print_table)
      std::printf("%s: %s, reference %.6g; relative errors per level", e.name.c_str(),
                  e.asymptotic
                      ? order
                      : ("no asymptotic regime (" + e.why_not + "; finest level as reference)").c_str(),
                  e.reference);
    for (size_t l = 0; l < n; ++l) {
      const double err = std::abs(levels[l].value[i] - e.reference) / std::abs(e.reference);
      if (print_table) std::printf(" %.2e", err);
      if (e.asymptotic || l + 1 < n)
        csv << e.name << "," << l + 1 << "," << levels[l].dofs << "," << levels[l].seconds[i] << "," << err
            << "\n";
    }
    if (print_table) std::printf("\n");
  }
  if (print_table) {
    std::printf("time-vs-DOFs exponent per stage:");
    for (const auto& [stage, e] : study.at("time_vs_dofs_exponent").items())
      std::printf(" %s %.2f", stage.c_str(), e.get<double>());
    std::printf("\n");
  }
  prepare_output_dir(out_dir);
  write_text_atomic(out_dir + "/chain_study.csv", csv.str());
  write_json(out_dir + "/chain_study.json", study);
  std::printf("  wrote %s/chain_study.csv, chain_study.json\n", out_dir.c_str());
}

}  // namespace skinfem::app
