// The bonded skin condensed onto the contact multipliers: one factorization, block right-hand sides.
//
// With the mortar load of multipliers λ (contact/mortar.hpp) and a friction traction ratio·p along the
// unit sliding direction t, the weighted gaps and the sensor readings are linear in λ:
//   g = gap0 − δ·area + (C_zz + ratio·C_zt) λ,      readings = (S_p + ratio·S_t) λ.
// C_zz(i, j) = −∫ψ_i u_z for the pressure of multiplier j (symmetric positive definite: the compliance of
// the bonded skin), C_zt(i, j) = −∫ψ_i u_z for its tangential traction. Both come from the n_c solves of
// the pressure loads alone: by Maxwell–Betti, C_zt = (D·[u_t of the pressure loads])ᵀ. S_p, S_t are the
// sensor readings for each multiplier's pressure and traction, from one adjoint solve per reading
// (reading = y·f, fem/sensor_reading.hpp). Rows of S: sensor k's σ_z at 2k, σ_x at 2k + 1 (MPa per MPa).
#pragma once

#include <Eigen/Dense>
#include <functional>
#include <optional>
#include <string>

#include "skinfem/contact/holes/cut.hpp"
#include "skinfem/contact/indenter.hpp"
#include "skinfem/contact/mortar.hpp"
#include "skinfem/fem/elastic_model.hpp"
#include "skinfem/fem/sensor_reading.hpp"

namespace skinfem::contact {

struct CondensedContact {
  MortarZone zone;
  Eigen::Vector2d direction{1, 0};  // sliding direction t in the (x, y) plane
  Eigen::MatrixXd C_zz, C_zt;       // n_c × n_c, mm³/MPa (weighted gap per unit multiplier)
  Eigen::VectorXd gap0;             // n_c: ∫ψ_i (z_touch + φ − s) dx dy, mm³
  Eigen::MatrixXd S_p, S_t;         // 2·sensors × n_c
  // The skin's answer at the P2 nodes a swept hole can reach, for holes that cut the hats
  // (contact/holes/cut.hpp); absent unless condense was given the faces to watch.
  std::optional<PathCompliance> path;
  double solve_seconds = 0;  // block solves (multipliers and adjoints), or reading the bordered products
  int block_solves = 0;      // right-hand sides solved (0 from a bordered factorization)
};

// Every load and readout of the condensation as one set of columns, each a load (F) or prescribed base
// values (U_fixed) on the skin: order [a | b | ez | et | c]:
//   a: the multipliers' pressures, −D_zᵀ e_j (n_c)      b: their tractions along t, D_tᵀ e_j (n_c)
//   ez: a unit downward force at each watched node (n_w) et: a unit force along t there (n_w)
//   c: the sensors' adjoints, base displacement −w with no load (2·sensors; fem/sensor_reading.hpp).
// All condense() needs are products G(i, j) = F_iᵀ u_j (MixedSolver::coupling_products) of a readout i in
// [a | b | ez | et] and a source j in a, ez or c: by block solves of the sources (n_c + n_w + 2·sensors
// right-hand sides), or all at once from a factorization bordered by these columns (MUMPS's Schur
// complement: ElasticModel with ModelOptions::coupling = &columns.coupling).
struct CondenseColumns {
  MixedSolver::Coupling coupling;  // 3N × (2n_c + 2n_w + 2·sensors)
  int nc = 0, nw = 0, nr = 0;      // multipliers, watched nodes, readings (2·sensors)
  std::vector<int> watched;        // the watched mesh nodes, in the order of PathCompliance::nodes
  int size() const { return 2 * nc + 2 * nw + nr; }
};
// weights: the sensors' reading weights (SensorReadings::weight_block, 3N × 2·sensors); watch_faces as in
// condense. Needs the mesh only: the columns can border the skin's first factorization.
CondenseColumns condense_columns(const TetMesh& mesh, const MortarZone& zone, const Eigen::MatrixXd& weights,
                                 const Vec2& direction, const std::vector<int>& watch_faces);

// progress(fraction done, message) is called between blocks. watch_faces: top faces of the zone a swept
// hole can cut (contact/holes/cut.hpp, watch_path); their P2 nodes get one more solve each. When the model
// was factored with the coupling of condense_columns(…) of these same arguments, pass it as `bordered`:
// its products replace every block solve (where MUMPS's estimates chose the plain factorization instead,
// MixedSolver::border_choice, the block solves run). before_path, with watched faces: called with the
// hole-free problem (no path) before the watched nodes' solves, so that a caller can check it (the zone's
// size) before paying for them; it may throw.
CondensedContact condense(const ElasticModel& model, const MortarZone& zone, const Indenter& indenter,
                          const SensorReadings& readings, const Vec2& direction,
                          const std::function<void(double, const std::string&)>& progress = {},
                          const std::vector<int>& watch_faces = {}, const CondenseColumns* bordered = nullptr,
                          const std::function<void(const CondensedContact&)>& before_path = {});

// The same on any factored skin: solver, the skin's (or a finite-strain tangent's,
// contact/finite_contact.hpp) factorization on mesh m with its held DOFs `fixed` (3N).
CondensedContact condense(const TetMesh& m, const MixedSolver& solver, const std::vector<bool>& fixed,
                          const MortarZone& zone, const Indenter& indenter, const SensorReadings& readings,
                          const Vec2& direction,
                          const std::function<void(double, const std::string&)>& progress = {},
                          const std::vector<int>& watch_faces = {}, const CondenseColumns* bordered = nullptr,
                          const std::function<void(const CondensedContact&)>& before_path = {});

// The condensed problem with a hole that cuts the hats (holes/cut.hpp): the hole-free one with the rows and
// columns of the multipliers the hole touches (T) replaced. Shapes: |T| × n for rows, 2·sensors × |T| for
// reading columns; C_zz' is symmetric, so its columns T are its rows T transposed. zt* only when
// `tangential`. Needs c.path.
struct CutProblem {
  std::vector<int> rows;       // T, ascending
  Eigen::MatrixXd zz;          // C_zz'(T, :)
  Eigen::MatrixXd zt_rows;     // C_zt'(T, :): gaps of the cut rows under every cut hat's traction
  Eigen::MatrixXd zt_cols;     // C_zt'(:, T)ᵀ: every gap under the cut hats' traction
  Eigen::MatrixXd zt_whole;    // gaps of the cut rows under whole hats' traction (a lumped shear)
  Eigen::MatrixXd sp, st;      // S_p'(:, T), S_t'(:, T)
  Eigen::VectorXd gap0, area;  // n: outside the hole
};
CutProblem cut_problem(const CondensedContact& c, const HoleCut& cut, bool tangential);
// C (n × n) with its rows `rows` replaced by new_rows (|rows| × n), then its columns by new_colsᵀ: how a cut
// problem's patch becomes a full matrix (patched(C_zz, p.rows, p.zz, p.zz); C_zt with zt_rows, zt_cols).
Eigen::MatrixXd patched(Eigen::MatrixXd C, const std::vector<int>& rows, const Eigen::MatrixXd& new_rows,
                        const Eigen::MatrixXd& new_cols);

}  // namespace skinfem::contact
