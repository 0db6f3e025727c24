#include "skinfem/contact/finite_contact.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>

#include "skinfem/contact/condensed.hpp"
#include "skinfem/contact/contact_solver.hpp"
#include "skinfem/contact/lcp.hpp"
#include "skinfem/fem/finite_strain.hpp"

namespace skinfem::contact {

namespace {

constexpr int kFiniteBlock = 64;   // right-hand sides per block solve where the plain factorization is chosen
constexpr double kRoundOff = 1e3;  // how far above the tolerance a stalled residual is taken as round-off

struct FiniteState {
  Eigen::VectorXd u, p, lambda;
  Eigen::VectorXd shear;  // n_c nodal shear-strength traction along t, MPa (empty: none)
  int partial_shear = 0;
  std::vector<int> active;
  double depth = 0, complementarity = 0;
  FiniteStrainSystem system;  // assembled at (u, p), with its tangent
  // Under a sphere: its gaps at (u, depth), with the pressures' turning at λ; built once per state.
  std::optional<MortarZone::SphereGaps> sphere;
};

// What every iteration shares: the multipliers' load columns, the gaps at rest and the residual's scales.
struct FiniteProblem {
  FiniteProblem(const TetMesh& m, double mu_shear, const std::vector<bool>& held, const MortarZone& z,
                const Eigen::Vector2d& direction)
      : mesh(m), mu(mu_shear), fixed(held), zone(z), t(direction) {}
  const TetMesh& mesh;
  double mu;
  const std::vector<bool>& fixed;
  const MortarZone& zone;
  Eigen::Vector2d t;
  MixedSolver::Coupling columns;  // [a | b]: the multipliers' pressures −D_zᵀ e_j, their tractions D_tᵀ e_j
  Eigen::VectorXd gap0;
  double volume = 0;
  MixedSolver::Reuse* factors = nullptr;  // the tangents' one analysis, handed from iterate to iterate
  // A sphere: its centre at first touch (it descends by the depth) and radius; its gaps are the normal
  // gaps on the displaced top (MortarZone::sphere_gaps), opened by `opening`.
  bool sphere = false, sliding = false;  // sliding: a friction traction along the sphere's tangent
  Eigen::Vector3d centre0 = Eigen::Vector3d::Zero();
  double R = 0;
  Eigen::VectorXd opening;

  int nc() const { return zone.size(); }
  MortarZone::SphereGaps sphere_gaps(const Eigen::VectorXd& u, double depth,
                                     const Eigen::VectorXd* lambda = nullptr) const {
    MortarZone::SphereGaps sg = zone.sphere_gaps(mesh, u, centre0 - depth * Eigen::Vector3d::UnitZ(), R,
                                                 lambda, sliding ? &t : nullptr);
    if (opening.size()) sg.g += opening;
    return sg;
  }
  // A sphere's load on the skin: pressures λ along its normals, ratio·λ and a shear strength's nodal
  // traction (empty: none) along its tangents.
  Eigen::VectorXd sphere_load(const MortarZone::SphereGaps& sg, const Eigen::VectorXd& lambda, double ratio,
                              const Eigen::VectorXd& shear) const {
    Eigen::VectorXd drag = ratio * lambda;
    if (shear.size()) drag += shear;
    Eigen::VectorXd f = sg.Dn.transpose() * lambda;
    if (sliding) f += sg.Dt.transpose() * drag;
    return f;
  }
  // D u_z: the multipliers' weighted downward displacements, mm³.
  Eigen::VectorXd weighted_uz(const Eigen::VectorXd& u) const {
    Eigen::VectorXd uz(u.size() / 3);
    for (int i = 0; i < uz.size(); ++i) uz[i] = u[3 * i + 2];
    return zone.D * uz;
  }
};

// C_zz and C_zt on the tangent the solver factored (condensed.hpp's definitions): from the bordered
// factorization's products, or by block solves of the pressure columns where MUMPS chose the plain one.
// columns: [a | b]: a plane's, or a sphere's [Dnᵀ | Dtᵀ] when it slides; or a frictionless sphere's Dnᵀ
// alone (then C_zt is 0).
std::pair<Eigen::MatrixXd, Eigen::MatrixXd> compliances(const FiniteProblem& P,
                                                        const MixedSolver::Coupling& columns,
                                                        const MixedSolver& solver) {
  const int nc = P.nc();
  const bool tangential = columns.F.cols() == 2 * nc;
  const Eigen::MatrixXd& G = solver.coupling_products();
  if (G.size() > 0)
    return {0.5 * (G.topLeftCorner(nc, nc) + G.topLeftCorner(nc, nc).transpose()),
            tangential ? Eigen::MatrixXd(G.topRightCorner(nc, nc)) : Eigen::MatrixXd::Zero(nc, nc)};
  Eigen::MatrixXd zz(nc, nc), zt = Eigen::MatrixXd::Zero(nc, nc);
  const Eigen::SparseMatrix<double> Ft = columns.F.transpose();
  for (int j0 = 0; j0 < nc; j0 += kFiniteBlock) {
    const int k = std::min(kFiniteBlock, nc - j0);
    const Eigen::MatrixXd U = solver.solve_block(Eigen::MatrixXd(columns.F.middleCols(j0, k)));
    const Eigen::MatrixXd R = Ft * U;  // (2 n_c) × k: the readouts a and b of sources a
    zz.middleCols(j0, k) = R.topRows(nc);
    if (tangential)
      zt.middleRows(j0, k) = R.bottomRows(nc).transpose();  // Maxwell–Betti: C_zt(j, i) = b_i · u(a_j)
  }
  return {0.5 * (zz + zz.transpose()), zt};
}

// The iterate's complementarity problem under a shear strength τ wherever the skin touches: on the
// tangent it is the linear coupled contact (contact_solver.hpp) with compliances zz, zt and gaps q at rest,
// whose touched set ContactSolver iterates to a fixed point (an edge multiplier that lifts under its own
// shear holding the fraction at which it just touches).
// weights: the force's weight per multiplier, the zone's areas under a plane, a sphere's m (its gaps close by
// m per mm of descent): the solver's "areas".
ContactResult shear_contact(const FiniteProblem& P, const Eigen::MatrixXd& zz, const Eigen::MatrixXd& zt,
                            const Eigen::VectorXd& q, double force, double ratio, double tau,
                            const std::vector<int>& warm, const Eigen::VectorXd& weights) {
  CondensedContact c;
  c.zone = P.zone;
  c.zone.area = weights;
  c.direction = P.t;
  c.C_zz = zz;
  c.C_zt = zt;
  c.gap0 = q;
  c.S_p = c.S_t = Eigen::MatrixXd::Zero(0, P.nc());
  ContactLoad load;
  load.force = force;
  load.mu = ratio;
  load.law = ratio > 0 ? FrictionLaw::mixed : FrictionLaw::shear_strength;
  load.tau0 = tau;
  return ContactSolver(c, load).solve(FrictionMode::coupled, std::vector<char>{}, warm);
}

// One load step's Newton iteration from `s` to (force, ratio, tau); nullopt when it fails (s is then
// undefined), with why it failed in `why`.
std::optional<FiniteContactStep> contact_newton(const FiniteProblem& P, double force, double ratio,
                                                double tau, const NewtonOptions& o, FiniteState& s,
                                                int& factorizations, std::string& why) {
  FiniteContactStep step{force, ratio, tau, {}, {}, {}};
  const Lame incompressible{P.mu, 0.0};
  for (int it = 0; it < o.max_iterations; ++it) {
    Eigen::VectorXd minus_internal = -s.system.internal_force;
    for (size_t d = 0; d < P.fixed.size(); ++d)
      if (P.fixed[d]) minus_internal[d] = 0;
    LcpSolution lcp;
    MixedSolution dx;
    Eigen::VectorXd shear;
    int partial_shear = 0;
    try {
      // A sphere's columns are its pressures along its normals at this iterate (they turn with the surface).
      MixedSolver::Coupling normal_columns;
      if (P.sphere && !s.sphere) s.sphere = P.sphere_gaps(s.u, s.depth, &s.lambda);
      const std::optional<MortarZone::SphereGaps>& sg = s.sphere;
      if (sg) {
        // The tangent less the pressures' turning at this iterate's λ (MortarZone::sphere_gaps's G, within
        // the skin's pattern: the nodes of one top face share a tet), so that Newton stays quadratic.
        for (int c = 0; c < sg->G.outerSize(); ++c)
          for (Eigen::SparseMatrix<double>::InnerIterator it(sg->G, c); it; ++it)
            s.system.tangent.A.coeffRef(it.row(), it.col()) -= it.value();
        // With friction, [Dnᵀ | Dtᵀ]: C_zt = Dn K⁻¹ Dtᵀ, the gaps' answer to the tangential tractions.
        if (P.sliding) {
          const int nc = P.nc();
          normal_columns.F.resize(sg->Dn.cols(), 2 * nc);
          normal_columns.F.leftCols(nc) = sg->Dn.transpose();
          normal_columns.F.rightCols(nc) = sg->Dt.transpose();
        } else {
          normal_columns.F = sg->Dn.transpose();
        }
        normal_columns.solves_instead = P.columns.solves_instead;
        normal_columns.memory_limit_mb = P.columns.memory_limit_mb;
      }
      const MixedSolver::Coupling& columns = sg ? normal_columns : P.columns;
      const MixedSolver solver(s.system.tangent, incompressible, P.fixed, SolverKind::direct_ldlt, 1e-9, {},
                               &columns, P.factors);
      ++factorizations;
      const auto [zz, zt] = compliances(P, columns, solver);
      const MixedSolution rest = solver.solve(minus_internal, {}, -s.system.constraint);
      // The LCP's gaps q, its force weights (a plane's hat areas, a sphere's m) and the force they carry.
      Eigen::VectorXd q;
      double pressures_force = force;
      if (sg) {
        // g ≈ g_k + Dn du − m (δ − δ_k): the LCP's q − δ m + M λ with du = du_r + K⁻¹ Dnᵀ λ.
        q = sg->g + s.depth * sg->m + sg->Dn * rest.u;
        // The force is the sphere's whole downward load, the drag's part included: that part at this
        // iterate's λ and shear (lagged, exact once they settle) comes off the pressures' share.
        pressures_force -= ratio * sg->mt.dot(s.lambda);
        if (s.shear.size()) pressures_force -= sg->mt.dot(s.shear);
      } else {
        q = P.gap0 - P.weighted_uz(s.u + rest.u);
      }
      const Eigen::VectorXd& weights = sg ? sg->m : P.zone.area;
      if (tau > 0) {
        const ContactResult c = shear_contact(P, zz, zt, q, pressures_force, ratio, tau, s.active, weights);
        lcp.lambda = c.lambda;
        lcp.active = c.active;
        lcp.delta = c.depth_mm;
        lcp.complementarity = c.complementarity;
        shear = c.shear;
        partial_shear = c.partial_shear;
      } else {
        lcp = ContactLcp(zz + ratio * zt, q, weights).solve_force(pressures_force, {}, s.active);
      }
      const Eigen::VectorXd load =
          sg ? P.sphere_load(*sg, lcp.lambda, ratio, shear) : P.zone.load(lcp.lambda, P.t, ratio, shear);
      dx = solver.solve(load + minus_internal, {}, -s.system.constraint);
    } catch (const std::runtime_error& e) {  // SolverError, or an LCP without a consistent set
      why = e.what();
      return std::nullopt;
    }
    std::vector<int> changed;
    std::set_symmetric_difference(lcp.active.begin(), lcp.active.end(), s.active.begin(), s.active.end(),
                                  std::back_inserter(changed));
    s.u += dx.u;
    s.p += dx.p;
    s.lambda = lcp.lambda;
    s.shear = shear;
    s.partial_shear = partial_shear;
    s.active = lcp.active;
    s.depth = lcp.delta;
    s.complementarity = lcp.complementarity;
    try {
      s.system = assemble_finite_strain(P.mesh, P.mu, s.u, s.p);
    } catch (const std::domain_error&) {
      why = "an element folded (det F <= 0)";
      return std::nullopt;
    }
    if (P.sphere) s.sphere = P.sphere_gaps(s.u, s.depth, &s.lambda);  // the next iterate's, too
    const Eigen::VectorXd f = s.sphere ? P.sphere_load(*s.sphere, s.lambda, ratio, s.shear)
                                       : P.zone.load(s.lambda, P.t, ratio, s.shear);  // the indenter's load
    step.residuals.push_back(equilibrium_residual(s.system, f, P.fixed, f.norm(), P.volume));
    step.active_sizes.push_back(static_cast<int>(s.active.size()));
    step.set_changes.push_back(static_cast<int>(changed.size()));
    const bool same_set = changed.empty();
    // Converged: the set repeats and the residual is below the tolerance, or has reached round-off (below
    // kRoundOff times it and no longer halving: a load on a few vertices leaves a floor above 1e-10).
    const std::vector<double>& r = step.residuals;
    if (same_set && (r.back() <= o.tolerance || (r.size() > 1 && r.back() <= kRoundOff * o.tolerance &&
                                                 r.back() > 0.5 * r[r.size() - 2])))
      return step;
  }
  char buf[120];
  std::snprintf(buf, sizeof buf, "no convergence in %d iterations (residual %.1e)", o.max_iterations,
                step.residuals.empty() ? 0.0 : step.residuals.back());
  why = buf;
  return std::nullopt;
}

}  // namespace

FiniteContactResult solve_finite_contact(const TetMesh& mesh, double mu, const std::vector<bool>& fixed,
                                         const MortarZone& zone, const Indenter& indenter,
                                         const FiniteContactLoad& load, const NewtonOptions& o,
                                         const FiniteContactStepSink& on_step,
                                         const FiniteContactResult* from) {
  if (!(load.force > 0) || !(load.ratio >= 0))
    throw std::invalid_argument("solve_finite_contact: force must be > 0 and ratio ≥ 0");
  if ((load.tau && !(*load.tau >= 0)) || !(load.tau_mu >= 0))
    throw std::invalid_argument("solve_finite_contact: the shear strength must be ≥ 0");
  const bool sphere = indenter.kind() == IndenterKind::sphere;
  const bool shearing = load.tau ? *load.tau > 0 : load.tau_mu > 0;
  if (!(o.first_step > 0 && o.first_step <= 1))
    throw std::invalid_argument("NewtonOptions::first_step must be in (0, 1]");
  FiniteProblem P(mesh, mu, fixed, zone, load.direction.normalized());
  const int nc = zone.size();
  // condense's columns without watched nodes or sensors: [a | b], solves_instead = n_c.
  P.columns =
      condense_columns(mesh, zone, Eigen::MatrixXd(3 * mesh.num_nodes(), 0), {P.t.x(), P.t.y()}, {}).coupling;
  P.gap0 = zone.weighted(mesh, [&](const Eigen::Vector3d& x) { return indenter.gap_at_rest(x); });
  if (load.opening.size() > 0) {
    if (load.opening.size() != nc)
      throw std::invalid_argument("solve_finite_contact: an opening of " +
                                  std::to_string(load.opening.size()) + " gaps for " + std::to_string(nc) +
                                  " multipliers");
    P.gap0 += load.opening;
  }
  if (sphere) {
    P.sphere = true;
    P.R = indenter.R();
    P.centre0 = {indenter.center()[0], indenter.center()[1], indenter.z_touch() + indenter.R()};
    P.opening = load.opening;
    P.sliding = load.ratio > 0 || shearing;
  }
  P.volume = pressure_mass(mesh).sum();
  MixedSolver::Reuse factors;
  P.factors = &factors;

  FiniteContactResult out;
  FiniteState s;
  s.u = Eigen::VectorXd::Zero(3 * mesh.num_nodes());
  s.p = Eigen::VectorXd::Zero(mesh.num_vertices);
  s.lambda = Eigen::VectorXd::Zero(nc);
  // The path s ∈ (0, 1]: the force to F without friction; s ∈ (1, 2]: the ratio and τ to their values at F.
  const double end = load.ratio > 0 || shearing ? 2 : 1;
  double tau = load.tau.value_or(0.0);  // from tau_mu once the frictionless contact at F is known
  const auto frictionless_at_force = [&](double area) {
    out.frictionless_area_mm2 = area;
    if (!load.tau && load.tau_mu > 0) tau = area > 0 ? load.tau_mu * load.force / area : 0.0;
  };
  const auto area_of = [&](const std::vector<int>& active) {
    double a = 0;
    for (int i : active) a += zone.area[i];
    return a;
  };
  const auto force_at = [&](double x) { return load.force * std::min(x, 1.0); };
  const auto ratio_at = [&](double x) { return load.ratio * std::max(x - 1, 0.0); };
  const auto tau_at = [&](double x) { return tau * std::max(x - 1, 0.0); };
  double reached = 0, step = o.first_step;
  if (from) {  // a converged state of this force: one step to the new gaps, or on along the ratio's path
    if (from->solution.u.size() != s.u.size() || from->lambda.size() != nc)
      throw std::invalid_argument("solve_finite_contact: the starting state is not of this mesh and zone");
    const bool frictionless = from->ratio == 0 && from->tau == 0;
    frictionless_at_force(frictionless ? area_of(from->active) : from->frictionless_area_mm2);
    // How far along the friction path `from` is, by its ratio and its τ (the same fraction of each).
    const double by_ratio = load.ratio > 0 ? from->ratio / load.ratio : 1;
    const double by_tau = tau > 0 ? from->tau / tau : 1;
    if (!(by_ratio <= 1) || !(by_tau <= 1 + 1e-12))
      throw std::invalid_argument("solve_finite_contact: the starting state's friction is above the load's");
    if (!frictionless && load.ratio > 0 && tau > 0 && std::abs(by_ratio - by_tau) > 1e-9)
      throw std::invalid_argument(
          "solve_finite_contact: the starting state's ratio and shear strength are not on the load's path");
    s.u = from->solution.u;
    s.p = from->solution.p;
    s.lambda = from->lambda;
    s.active = from->active;
    s.depth = from->depth_mm;
    const double along = load.ratio > 0 ? by_ratio : by_tau;
    reached = frictionless && end == 2 ? 1 : along >= 1 ? std::nextafter(end, 0.0) : 1 + along;
    step = 1;
  }
  s.system = assemble_finite_strain(mesh, mu, s.u, s.p);
  const double smallest = o.first_step / std::pow(2.0, o.max_halvings);
  std::string why;  // the last step's failure
  while (reached < end) {
    // A step stops at the end of the force ramp, so that friction starts from the full frictionless contact.
    const double target = std::min(reached < 1 ? 1.0 : end, reached + step);
    FiniteState trial = s;
    if (auto done = contact_newton(P, force_at(target), ratio_at(target), tau_at(target), o, trial,
                                   out.factorizations, why)) {
      s = std::move(trial);
      reached = target;
      if (reached == 1) frictionless_at_force(area_of(s.active));
      out.steps.push_back(std::move(*done));
      if (on_step) on_step(out.steps.back());
      if (out.steps.back().residuals.size() <= 5) step = std::min(1.0, 2 * step);
      continue;
    }
    ++out.rejected_steps;
    step *= 0.5;
    if (step < smallest) {
      char buf[240], shear[64] = "";
      if (tau > 0) std::snprintf(shear, sizeof shear, ", shear strength %.4g kPa", 1e3 * tau_at(reached));
      std::snprintf(
          buf, sizeof buf,
          "finite-strain contact: Newton failed beyond %.4g N and friction ratio %.4g%s (steps down "
          "to %.3g of the load path; the last: ",
          force_at(reached), ratio_at(reached), shear, 2 * step);
      throw SolverError(buf + why + ")");
    }
  }
  out.solution.u = s.u;
  out.solution.p = s.p;
  out.solution.residual = out.steps.back().residuals.back();
  out.internal_force = s.system.internal_force;
  out.lambda = s.lambda;
  out.depth_mm = s.depth;
  out.ratio = load.ratio;
  out.tau = tau;
  out.shear = s.shear.size() ? s.shear : Eigen::VectorXd::Zero(nc);
  out.partial_shear = s.partial_shear;
  if (s.sphere) {
    out.load = P.sphere_load(*s.sphere, s.lambda, load.ratio, out.shear);
    out.gap = s.sphere->g;
  } else {
    out.load = zone.load(s.lambda, P.t, load.ratio, out.shear);
    out.gap = P.gap0 - s.depth * zone.area - P.weighted_uz(s.u);
  }
  out.active = s.active;
  out.complementarity = s.complementarity;
  return out;
}

ContactZoneFrame zone_frame(const TetMesh& mesh, const MortarZone& zone, const FiniteContactResult& r,
                            const Vec2& center, const Eigen::Vector2d& direction, bool current) {
  return zone_frame(mesh, zone, r.active, r.lambda, current ? &r.solution.u : nullptr, center, direction);
}

ContactZoneFrame zone_frame(const TetMesh& mesh, const MortarZone& zone, const std::vector<int>& active,
                            const Eigen::VectorXd& lambda, const Eigen::VectorXd* u, const Vec2& center,
                            const Eigen::Vector2d& direction) {
  const Eigen::Vector2d t = direction.normalized(), n(-t.y(), t.x()), c(center[0], center[1]);
  ContactZoneFrame z;
  double force = 0;
  Eigen::Vector2d zone_sum = Eigen::Vector2d::Zero(), force_sum = Eigen::Vector2d::Zero();
  z.front_mm = -1e300;
  z.back_mm = 1e300;
  // Each active vertex's position in the frame, once: the sums below and the moments about their centroid.
  std::vector<Eigen::Vector2d> at;
  at.reserve(active.size());
  for (int i : active) {
    const int v = zone.vertices[i];
    Eigen::Vector2d x(mesh.nodes(v, 0), mesh.nodes(v, 1));
    if (u) x += Eigen::Vector2d((*u)[3 * v], (*u)[3 * v + 1]);
    at.push_back(x);
  }
  for (size_t k = 0; k < active.size(); ++k) {
    const int i = active[k];
    const Eigen::Vector2d& x = at[k];
    const double a = zone.area[i], along = (x - c).dot(t);
    z.area_mm2 += a;
    zone_sum += a * x;
    force += lambda[i] * a;
    force_sum += lambda[i] * a * x;
    z.front_mm = std::max(z.front_mm, along);
    z.back_mm = std::min(z.back_mm, along);
    z.half_width_mm = std::max(z.half_width_mm, std::abs((x - c).dot(n)));
  }
  if (active.empty()) return ContactZoneFrame{};
  z.back_mm = -z.back_mm;
  const Eigen::Vector2d zc = zone_sum / z.area_mm2, fc = force_sum / force;
  z.zone_centroid = {zc.x(), zc.y()};
  z.force_centroid = {fc.x(), fc.y()};
  double along = 0, across = 0;
  for (size_t k = 0; k < active.size(); ++k) {
    const double w = lambda[active[k]] * zone.area[active[k]] / force;
    along += w * std::pow((at[k] - fc).dot(t), 2);
    across += w * std::pow((at[k] - fc).dot(n), 2);
  }
  z.moment_radius_mm = std::sqrt(2.5 * (along + across));
  z.moment_anisotropy = across > 0 ? std::sqrt(along / across) : 0.0;
  return z;
}

CondensedContact tangent_contact(const TetMesh& mesh, double mu, const std::vector<bool>& fixed,
                                 const MortarZone& zone, const Indenter& indenter,
                                 const SensorReadings& readings, const FiniteContactLoad& load,
                                 const FiniteContactResult& r) {
  if (indenter.kind() != IndenterKind::plane)
    throw std::invalid_argument("tangent_contact: a plane's contact (a sphere's gaps turn with the surface)");
  const Eigen::Vector2d t = load.direction.normalized();
  const FiniteStrainSystem system = assemble_finite_strain(mesh, mu, r.solution.u, r.solution.p);
  const CondenseColumns columns = condense_columns(mesh, zone, readings.weight_block(), {t.x(), t.y()}, {});
  const MixedSolver solver(system.tangent, Lame{mu, 0.0}, fixed, SolverKind::direct_ldlt, 1e-9, {},
                           &columns.coupling);
  CondensedContact c =
      condense(mesh, solver, fixed, zone, indenter, readings, {t.x(), t.y()}, {}, {}, &columns);
  // g = r.gap + (δ_r − δ)·area + M (λ − λ_r) with M = C_zz + ratio·C_zt.
  c.gap0 = r.gap + r.depth_mm * zone.area - (c.C_zz + load.ratio * c.C_zt) * r.lambda;
  if (r.shear.size()) c.gap0 -= c.C_zt * r.shear;
  return c;
}

}  // namespace skinfem::contact
