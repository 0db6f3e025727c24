#include "skinfem/contact/meridian_contact.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>

#include "skinfem/contact/lcp.hpp"
#include "skinfem/contact/metrics.hpp"
#include "skinfem/green/meridian_mode.hpp"
#include "skinfem/mesh/gauss_legendre.hpp"

namespace skinfem::contact {

MeridianContactSizes MeridianContactSizes::for_zone(double zone_radius, double h, double scale) {
  MeridianContactSizes z;
  z.zone_cell = zone_radius / 30 * scale;
  z.edge_cell = zone_radius / 30000 * scale;
  z.growth = 1 + 0.2 * scale;
  z.max_cell = 4 * h / 3 * scale;
  z.top_cell = zone_radius / 1100 * scale;
  z.base_cell = h / 36 * scale;
  z.layer_cell = h / 12 * scale;
  return z;
}

namespace {
double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// Vertex radii from the axis to `radius`: zone_cell inside the zone (graded down to edge_cell at `edge` when
// edge > 0), growing beyond it up to max_cell.
std::vector<double> radial_rows(double zone_radius, double radius, const MeridianContactSizes& z,
                                double edge) {
  const auto cell = [&](double r) {
    double c = z.zone_cell;
    if (edge > 0) c = std::min(c, z.edge_cell + (z.growth - 1) * std::abs(r - edge));
    if (r > zone_radius)
      c = std::min(z.max_cell, std::max(c, z.zone_cell + (z.growth - 1) * (r - zone_radius)));
    return c;
  };
  std::vector<double> x{0};
  while (x.back() + 1.5 * cell(x.back()) < radius) x.push_back(x.back() + cell(x.back()));
  x.push_back(radius);
  return x;
}

// A sensor's disc as quadrature points about the axis: radius ρ, cos θ, sin θ, weight (summing to 1). Polar
// Gauss, 12 radii × 32 angles (fem/base_traction.hpp's disc mean); a disc of diameter 0 is its centre.
struct DiscPoint {
  double rho, c, s, w;
};
std::vector<DiscPoint> disc_points(const ReadingSite& site) {
  std::vector<DiscPoint> out;
  const auto add = [&](double x, double y, double w) {
    const double rho = std::hypot(x, y);
    out.push_back({rho, rho > 0 ? x / rho : 1, rho > 0 ? y / rho : 0, w});
  };
  if (site.diameter <= 0) {
    add(site.center[0], site.center[1], 1);
    return out;
  }
  const double a = 0.5 * site.diameter;
  const GaussRule1d g = gauss_legendre01(12);
  for (size_t i = 0; i < g.x.size(); ++i)
    for (int k = 0; k < 32; ++k) {
      const double rr = a * g.x[i], phi = 2 * M_PI * k / 32;
      // ∫∫ f ρ' dρ' dφ / (π a²) with ρ' = a x: weight 2 x w_i / 32.
      add(site.center[0] + rr * std::cos(phi), site.center[1] + rr * std::sin(phi), 2 * g.x[i] * g.w[i] / 32);
    }
  return out;
}

// One pass: the mesh, its mode-0 system and the condensed problem.
struct Pass {
  MeridianMesh mesh;
  std::vector<int> vertex;  // per multiplier: its position in mesh.top
  std::vector<double> r;    // per multiplier
  Eigen::MatrixXd D;        // n_c × |top|: ∫ψ_i φ_k 2πr dr, mm²
  Eigen::VectorXd area, gap0;
  Eigen::MatrixXd C;  // n_c × n_c compliance, mm³/MPa
  std::optional<MeridianMode> mode0;
};

// The readings as weights on a mode's base traction amplitudes: σ = Wr·T_r + Wt·T_θ + Wz·T_z, each
// 2·sensors × |base| (σ_z of sensor k in row 2k, σ_x in row 2k + 1). Mode 1 is the field of a traction along
// +x; along t = (cos α, sin α) it is that field turned by α: read at the point turned back by α, its vector
// turned by α.
struct ReadingWeights {
  Eigen::MatrixXd Wr, Wt, Wz;
  Eigen::MatrixXd of(const Eigen::MatrixXd& Tr, const Eigen::MatrixXd& Tt, const Eigen::MatrixXd& Tz) const {
    Eigen::MatrixXd out = Wr * Tr + Wz * Tz;
    if (Tt.size()) out += Wt * Tt;
    return out;
  }
};

ReadingWeights reading_weights(const MeridianTrace& trace, const std::vector<std::vector<DiscPoint>>& discs,
                               int mode, const Eigen::Vector2d& t = {1, 0}) {
  const std::vector<double>& r = trace.radii();
  const Eigen::Index rows = 2 * static_cast<Eigen::Index>(discs.size()),
                     nb = static_cast<Eigen::Index>(r.size());
  ReadingWeights w{Eigen::MatrixXd::Zero(rows, nb), Eigen::MatrixXd::Zero(rows, nb),
                   Eigen::MatrixXd::Zero(rows, nb)};
  for (size_t k = 0; k < discs.size(); ++k)
    for (const DiscPoint& q : discs[k]) {
      double L[3];
      const size_t e = meridian_p2_weights(r, q.rho, L);
      // σ_z = t_z, σ_x = −t_x with t_x = t_r cos θ − t_θ sin θ; mode 1: t_r = T_r cos θ', t_θ = T_θ sin θ',
      // t_z = T_z cos θ' at θ' = θ − α.
      double zr = 0, zz = 1, xr = q.c, xt = 0;
      if (mode == 1) {
        const double c = q.c * t.x() + q.s * t.y(), s = q.s * t.x() - q.c * t.y();
        zz = c;
        xr = t.x() * c * c - t.y() * s * c;
        xt = -t.x() * s * s - t.y() * s * c;
      }
      for (int a = 0; a < 3; ++a) {
        const Eigen::Index j = static_cast<Eigen::Index>(e) + a;
        w.Wr(2 * k, j) += q.w * L[a] * zr;
        w.Wz(2 * k, j) += q.w * L[a] * zz;
        w.Wr(2 * k + 1, j) -= q.w * L[a] * xr;
        w.Wt(2 * k + 1, j) -= q.w * L[a] * xt;
      }
    }
  return w;
}

Pass condense_pass(const MeridianContactSkin& skin, double zone_radius,
                   const std::function<double(double)>& gap0, const MeridianContactSizes& sizes, double edge,
                   MeridianContactResult::Cost& cost) {
  auto clock = std::chrono::steady_clock::now();
  Pass p;
  std::vector<double> tau;
  for (double t : graded_points(skin.h, sizes.base_cell, sizes.top_cell, sizes.growth, sizes.layer_cell)) {
    if (!tau.empty()) tau.push_back(0.5 * (tau.back() + t / skin.h));
    tau.push_back(t / skin.h);
  }
  p.mesh = meridian_mesh(skin.top, radial_rows(zone_radius, skin.radius, sizes, edge), tau);
  const MeridianMesh& m = p.mesh;
  const int ntop = static_cast<int>(m.top.size());
  std::vector<double> rt(ntop);
  for (int k = 0; k < ntop; ++k) rt[k] = m.nodes(m.top[k], 0);
  for (int k = 0; k + 1 < ntop; k += 2)  // vertices, the side's excepted
    if (rt[k] <= zone_radius) p.vertex.push_back(k), p.r.push_back(rt[k]);
  const int n = static_cast<int>(p.vertex.size());
  // Hats: on top edge (s, s+1, s+2), ψ = 1 − u for the vertex s and u for s + 2.
  p.D = Eigen::MatrixXd::Zero(n, ntop);
  p.area = p.gap0 = Eigen::VectorXd::Zero(n);
  const GaussRule1d g = gauss_legendre01(4);
  for (int i = 0; i < n; ++i)
    for (int side = 0; side < 2; ++side) {
      const int s = side == 0 ? p.vertex[i] - 2 : p.vertex[i];  // the edge before or after the vertex
      if (s < 0 || s + 2 >= ntop) continue;
      for (size_t q = 0; q < g.x.size(); ++q) {
        double L[3], dL[3];
        meridian_p2_line(g.x[q], L, dL);
        const double r = L[0] * rt[s] + L[1] * rt[s + 1] + L[2] * rt[s + 2];
        const double w = g.w[q] * (dL[0] * rt[s] + dL[1] * rt[s + 1] + dL[2] * rt[s + 2]) * 2 * M_PI * r;
        const double psi = side == 0 ? g.x[q] : 1 - g.x[q];
        p.area[i] += w * psi;
        p.gap0[i] += w * psi * gap0(r);
        for (int a = 0; a < 3; ++a) p.D(i, s + a) += w * psi * L[a];
      }
    }
  cost.mesh_s += seconds_since(clock);

  // The zone's top nodes (those a multiplier's hat reaches): the factorization returns their W compliance
  // as a Schur complement, and C = D G Dᵀ needs no solve.
  std::vector<int> zone_top, zone_column;  // node, and its column of D
  for (int k = 0; k < ntop; ++k)
    if (p.D.col(k).cwiseAbs().maxCoeff() > 0) zone_top.push_back(m.top[k]), zone_column.push_back(k);
  const double mu = skin.E / (2 * (1 + skin.nu));
  const MeridianMode& mode0 = p.mode0.emplace(m, 0, skin.nu, mu, skin.side, m.base, zone_top);
  cost.assemble_s += mode0.cost().assemble_s;
  cost.factor_s += mode0.cost().factor_s;
  clock = std::chrono::steady_clock::now();
  Eigen::MatrixXd Dz(n, zone_top.size());
  for (size_t c = 0; c < zone_column.size(); ++c)
    Dz.col(static_cast<Eigen::Index>(c)) = p.D.col(zone_column[c]);
  // The pressure pushes the top down and the gap opens as it moves down: C = −D (G (−Dᵀ)).
  p.C = Dz * mode0.compliance() * Dz.transpose();
  // C is symmetric up to round-off (Maxwell–Betti); the LCP's frictionless theory wants it exactly so.
  p.C = 0.5 * (p.C + p.C.transpose()).eval();
  cost.condense_s += seconds_since(clock);
  return p;
}
}  // namespace

double MeridianContactResult::pressure_at(double radius) const {
  const auto hi = std::upper_bound(r.begin(), r.end(), radius);
  if (hi == r.begin()) return r.empty() ? 0.0 : lambda[0];
  if (hi == r.end()) return radius == r.back() ? lambda[lambda.size() - 1] : 0.0;
  const size_t j = hi - r.begin();
  const double u = (radius - r[j - 1]) / (r[j] - r[j - 1]);
  return (1 - u) * lambda[j - 1] + u * lambda[j];
}

ZoneTooSmall::ZoneTooSmall(double r)
    : std::runtime_error("the contact reaches the zone's last multiplier at r = " + std::to_string(r) +
                         " mm"),
      last_multiplier_mm(r) {}

MeridianContactResult meridian_contact(const MeridianContactSkin& skin, double zone_radius,
                                       const std::function<double(double)>& gap0,
                                       const MeridianContactLoad& load, const std::vector<ReadingSite>& sites,
                                       const MeridianContactSizes& sizes) {
  if (!(load.force_N > 0 || (load.force_N == 0 && load.depth_mm > 0)) || !(zone_radius > 0) ||
      !(zone_radius < skin.radius))
    throw std::invalid_argument(
        "meridian_contact: need a force > 0 or a depth > 0, 0 < zone radius < radius");
  std::vector<std::vector<DiscPoint>> discs;
  for (const ReadingSite& s : sites) {
    if (s.post()) throw std::invalid_argument("meridian_contact: reads disc sensors only");
    discs.push_back(disc_points(s));
  }
  MeridianContactResult out;
  double edge = 0;
  for (int pass = 0; pass < 2; ++pass) {
    Pass p = condense_pass(skin, zone_radius, gap0, sizes, edge, out.cost);
    auto clock = std::chrono::steady_clock::now();
    Eigen::MatrixXd M = p.C;
    if (skin.interface_K > 0) M.diagonal() += p.area / skin.interface_K;
    const ContactLcp lcp(std::move(M), p.gap0, p.area);
    const LcpSolution s = load.force_N > 0 ? lcp.solve_force(load.force_N) : lcp.solve_depth(load.depth_mm);
    out.cost.lcp_s += seconds_since(clock);
    const int n = static_cast<int>(p.r.size());
    if (s.lambda[n - 1] > 0) throw ZoneTooSmall(p.r.back());
    if (skin.interface_K > 0) {
      // Through an interface p vanishes like a − r (with logarithmic terms: metrics.hpp's global fit is off
      // by ~1 %): extrapolate the last two active multipliers, the second pass's cells there being fine.
      int last = 0;
      for (int i = 0; i < n; ++i)
        if (s.lambda[i] > 0) last = i;
      out.contact_radius_mm = last == 0
                                  ? p.r[0]
                                  : p.r[last] + s.lambda[last] * (p.r[last] - p.r[last - 1]) /
                                                    std::max(s.lambda[last - 1] - s.lambda[last], 1e-300);
    } else {
      std::vector<double> radii, values;
      for (int i = 0; i < n; ++i)
        if (s.lambda[i] > 0) radii.push_back(p.r[i]), values.push_back(s.lambda[i]);
      out.contact_radius_mm = edge_fit_radius(radii, values, radii.empty() ? 0 : radii.back());
    }
    edge = out.contact_radius_mm;
    if (pass == 0) continue;
    out.r = p.r;
    out.lambda = s.lambda;
    out.gap = s.gap;
    out.depth_mm = s.delta;
    out.force_N = p.area.dot(s.lambda);
    out.p0_MPa = p.r.front() == 0 ? s.lambda[0] : 0;
    out.complementarity = s.complementarity, out.min_lambda = s.min_lambda, out.min_gap = s.min_gap;
    out.pivots = s.pivots;
    out.multipliers = n;
    clock = std::chrono::steady_clock::now();
    {
      // The readings of the pressure found: one solve (not a reading per multiplier, of which the first
      // pass needs none).
      const int N = static_cast<int>(p.mesh.nodes.rows());
      MeridianMode::Fields load;
      load.W = Eigen::MatrixXd::Zero(N, 1);
      const Eigen::VectorXd nodal = p.D.transpose() * s.lambda;
      for (size_t k = 0; k < p.mesh.top.size(); ++k) load.W(p.mesh.top[k], 0) = -nodal[k];
      const MeridianMode::Fields R = p.mode0->reactions(p.mode0->solve({}, load, 1), load);
      const MeridianTrace trace(p.mesh, p.mesh.base, 2 * M_PI);
      out.readings = reading_weights(trace, discs, 0).of(trace.traction(R.U), {}, trace.traction(R.W)).col(0);
    }
    out.dofs = p.mode0->dofs();
    p.mode0.reset();  // its factor is not needed any more: mode 1 factors without it alive
    if (load.direction.norm() > 0) {
      // p_t = p along +x: mode 1, U = π∫pφr dr = (Dᵀλ)/2 and V = −U (header); turned to the direction.
      const MeridianMode mode1(p.mesh, 1, skin.nu, skin.E / (2 * (1 + skin.nu)), skin.side, p.mesh.base);
      out.cost.assemble_s += mode1.cost().assemble_s;
      out.cost.factor_s += mode1.cost().factor_s;
      out.dofs += mode1.dofs();
      const Eigen::VectorXd nodal = 0.5 * (p.D.transpose() * s.lambda);
      MeridianMode::Fields shear;
      const int N = static_cast<int>(p.mesh.nodes.rows());
      shear.U = shear.V = Eigen::MatrixXd::Zero(N, 1);
      for (size_t k = 0; k < p.mesh.top.size(); ++k)
        shear.U(p.mesh.top[k], 0) = nodal[k], shear.V(p.mesh.top[k], 0) = -nodal[k];
      const MeridianMode::Fields R = mode1.reactions(mode1.solve({}, shear, 1), shear);
      const MeridianTrace trace(p.mesh, p.mesh.base, M_PI);
      out.readings_per_ratio = reading_weights(trace, discs, 1, load.direction.normalized())
                                   .of(trace.traction(R.U), trace.traction(R.V), trace.traction(R.W))
                                   .col(0);
    }
    out.cost.readings_s += seconds_since(clock);
  }
  return out;
}

}  // namespace skinfem::contact
