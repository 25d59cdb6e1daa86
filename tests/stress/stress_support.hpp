// Shared helpers of the stress tests: Hertzian patches of any aspect ratio and grid, the
// independent check of a steady tangential solution against Coulomb's law, the Newton Jacobian of
// the tangential problem, passivity of creep coefficients, seeds and timing.
//
// Everything here recomputes what it checks from the public tables (InfluenceTable, SlipOperator,
// solve_coulomb_element), so the checks stay independent of the solvers' internals.
#pragma once

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "contact/coulomb.hpp"
#include "contact/forces.hpp"
#include "contact/hertz.hpp"
#include "contact/patch.hpp"
#include "contact/slip_operator.hpp"
#include "contact/steady_rolling.hpp"
#include "nss/linear_model.hpp"

// Under AddressSanitizer (the second build of .ci/run, -O1) dense O(n^3) work is ~10x slower: the
// tests skip their single most expensive case there (and say so).
#if defined(__SANITIZE_ADDRESS__)
#define ROLLNOISE_STRESS_SANITIZED 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define ROLLNOISE_STRESS_SANITIZED 1
#endif
#endif

namespace rollnoise::stress {

#ifdef ROLLNOISE_STRESS_SANITIZED
inline constexpr bool kSanitized = true;
#else
inline constexpr bool kSanitized = false;
#endif

using namespace rollnoise::contact;

// The paper's Hertzian case (docs/conventions.md Sec. 4): E = 210 GPa, nu = 0.28, N = 98.1 kN, V = 50 km/h,
// c = sqrt(a b) with a = 7.18 mm, b = 5.29 mm. Other aspect ratios keep c (and so the area).
inline const Material kSteel{210e9, 0.28};
inline constexpr double kSpeed = 13.8888888888889, kN = 98100, kPaperRatio = 7.18 / 5.29;
inline const double kC = std::sqrt(7.18e-3 * 5.29e-3);

/// Seconds since `t0`.
inline double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

/// The seed of the random tests: ROLLNOISE_STRESS_SEED from the environment (to explore or to
/// reproduce a failure), else the fixed default. Always printed by the tests that use it.
inline std::uint64_t stress_seed(std::uint64_t fallback) {
  if (const char* s = std::getenv("ROLLNOISE_STRESS_SEED")) return std::strtoull(s, nullptr, 10);
  return fallback;
}

/// The margin around the ellipse: the paper's 34/30, or at least ~1.25 elements on each side on
/// coarse grids (as rollnoise bench), so that the contact area never reaches the border.
inline double grid_scale(int nx, int ny) {
  return std::max(34.0 / 30.0, 1.0 + 2.5 / std::min(nx, ny));
}

/// Hertzian patch with semi-axes a = c sqrt(r), b = c / sqrt(r) (r = a/b), load N, on nx x ny
/// elements around the ellipse.
inline ContactPatch hertz_patch(double a_over_b, int nx, int ny, const Material& m = kSteel,
                                double scale = 0.0) {
  const double a = kC * std::sqrt(a_over_b), b = kC / std::sqrt(a_over_b);
  if (scale <= 0.0) scale = grid_scale(nx, ny);
  const Grid g = Grid::around_ellipse(nx, ny, a, b, scale);
  const HertzContact h = hertz_from_semi_axes(a, b, kN, m);
  return solve_patch(g, m, quadratic_distance(g, h.A, h.B), kN);
}

inline std::string describe(const Creepage& c) {
  char s[96];
  std::snprintf(s, sizeof s, "(%.3g, %.3g, %.3g rad/m)", c.xi_x, c.xi_y, c.phi);
  return s;
}

/// The contact elements (pn > 0) in grid order.
inline std::vector<int> contact_elements(const ContactPatch& p) {
  std::vector<int> e;
  for (int k = 0; k < p.grid.size(); ++k)
    if (p.normal.pn[k] > 0.0) e.push_back(k);
  return e;
}

/// S = V (A - A0)/dx (the steady slip operator) on the contact elements, dense, unknowns
/// interleaved (x, y) per element.
inline Eigen::MatrixXd dense_steady_operator(const SlipOperator& S, const std::vector<int>& el) {
  const Grid& g = S.grid();
  const int m = static_cast<int>(el.size());
  Eigen::MatrixXd M(2 * m, 2 * m);
  for (int b = 0; b < m; ++b)
    for (int a = 0; a < m; ++a) {
      const int k = S.offset_index(el[a] % g.nx - el[b] % g.nx, el[a] / g.nx - el[b] / g.nx);
      M(2 * a, 2 * b) = S.xx(k);
      M(2 * a, 2 * b + 1) = S.xy(k);
      M(2 * a + 1, 2 * b) = S.xy(k);
      M(2 * a + 1, 2 * b + 1) = S.yy(k);
    }
  return M;
}

/// Everything the physical checks of a steady solution need, recomputed independently.
struct SteadyCheck {
  int adhesion = 0, slip = 0;
  double bound_excess = 0.0;    ///< max over elements of |p|/(mu pn) - 1 (<= 0 up to rounding)
  double slip_bound_gap = 0.0;  ///< max over slip elements of ||p|/(mu pn) - 1|
  double sigma = 0.0;           ///< slip-velocity scale: max |w| + |S|_inf max |p| (m/s)
  double adhesion_slip = 0.0;   ///< max |s| over adhesion elements / sigma (s = w + S p recomputed)
  double misalignment = 0.0;    ///< max |s + |s| p/|p|| over slip elements / sigma
  double max_cosine = -1.0;     ///< slip elements with |s| > 1e-6 sigma: max cos(p, s) (-1 ideal)
  double returned_slip = 0.0;   ///< max |s_returned - s_recomputed| / sigma
  double dissipation = 0.0;     ///< -dx dy sum p.s (W), >= 0
  double friction_force = 0.0;  ///< mu sum pn dx dy (N)
  TangentialForces F;
  bool finite = true;
};

inline SteadyCheck check_steady(const ContactPatch& patch, const TangentialSolution& s, double mu,
                                double speed, const Creepage& c, double spin_offset) {
  const Grid& g = patch.grid;
  const SlipOperator S = SlipOperator::steady(patch.influence, speed);
  GridField wx, wy;
  rigid_slip(g, speed, c, spin_offset, wx, wy);
  const std::vector<int> el = contact_elements(patch);
  const int m = static_cast<int>(el.size());
  SteadyCheck r;
  double p_max = 0.0, w_max = 0.0, row_max = 0.0;
  for (int k : el) {
    p_max = std::max(p_max, std::hypot(s.px[k], s.py[k]));
    w_max = std::max(w_max, std::hypot(wx[k], wy[k]));
  }
  std::vector<double> sx(m), sy(m);
  for (int a = 0; a < m; ++a) {
    double ux = wx[el[a]], uy = wy[el[a]], rx = 0.0, ry = 0.0;
    for (int b = 0; b < m; ++b) {
      const int k = S.offset_index(el[a] % g.nx - el[b] % g.nx, el[a] / g.nx - el[b] / g.nx);
      const double px = s.px[el[b]], py = s.py[el[b]];
      ux += S.xx(k) * px + S.xy(k) * py;
      uy += S.xy(k) * px + S.yy(k) * py;
      rx += std::abs(S.xx(k)) + std::abs(S.xy(k));
      ry += std::abs(S.xy(k)) + std::abs(S.yy(k));
    }
    sx[a] = ux, sy[a] = uy;
    row_max = std::max({row_max, rx, ry});
  }
  r.sigma = w_max + row_max * p_max;
  const double sigma = r.sigma > 0.0 ? r.sigma : 1.0;
  for (int a = 0; a < m; ++a) {
    const int k = el[a];
    const double g_e = mu * patch.normal.pn[k];
    const double px = s.px[k], py = s.py[k], pl = std::hypot(px, py), sl = std::hypot(sx[a], sy[a]);
    r.finite = r.finite && std::isfinite(px) && std::isfinite(py) && std::isfinite(s.sx[k]) &&
               std::isfinite(s.sy[k]);
    r.bound_excess = std::max(r.bound_excess, pl / g_e - 1.0);
    r.returned_slip =
        std::max(r.returned_slip, std::hypot(s.sx[k] - sx[a], s.sy[k] - sy[a]) / sigma);
    r.dissipation -= (px * sx[a] + py * sy[a]) * g.element_area();
    if (s.state[k] == static_cast<std::int8_t>(ElementState::slip)) {
      ++r.slip;
      r.slip_bound_gap = std::max(r.slip_bound_gap, std::abs(pl / g_e - 1.0));
      if (pl > 0.0)
        r.misalignment = std::max(r.misalignment,
                                  std::hypot(sx[a] + sl * px / pl, sy[a] + sl * py / pl) / sigma);
    } else if (s.state[k] == static_cast<std::int8_t>(ElementState::adhesion)) {
      ++r.adhesion;
      r.adhesion_slip = std::max(r.adhesion_slip, std::hypot(sx[a], sy[a]) / sigma);
    }
  }
  // the largest cosine between traction and slip over clearly slipping elements (ideal: -1)
  double cos_max = -1.0;
  for (int a = 0; a < m; ++a) {
    const int k = el[a];
    if (s.state[k] != static_cast<std::int8_t>(ElementState::slip)) continue;
    const double pl = std::hypot(s.px[k], s.py[k]), sl = std::hypot(sx[a], sy[a]);
    if (sl > 1e-6 * sigma && pl > 0.0)
      cos_max = std::max(cos_max, (s.px[k] * sx[a] + s.py[k] * sy[a]) / (pl * sl));
  }
  r.max_cosine = cos_max;
  r.F = total_forces(g, s.px, s.py);
  r.finite = r.finite && std::isfinite(r.F.Fx) && std::isfinite(r.F.Fy) && std::isfinite(r.F.Mz);
  r.friction_force = mu * patch.normal.force;
  return r;
}

/// The physical assertions on a steady solution (Coulomb's law, element by element, and in total).
/// Tolerances:
///  - |p| <= mu pn within 1e-14: slip tractions are set to -g c/|c| (|p| = g up to ~4 ulp),
///    adhesion tractions pass the test |p|^2 <= g^2 exactly.
///  - |s| in adhesion and |s + |s| p/|p|| in slip <= 1e-8 sigma: the Newton solver stops at a
///    relative fixed-point residual |R| <= 1e-11 max|p|, which moves the recomputed slip by at most
///    |S - D|_inf |R| <= 1e-11 sigma (twice that for the direction in slip); the rest of the 1000x
///    margin covers the O(m eps) rounding of the sums (m <= 1e4 elements).
///  - |F| <= mu N (1 + 1e-12): the triangle inequality over elements each within 1e-14 of their
///    bound, plus O(m eps) summation rounding.
///  - cos(p, s) <= -1 + 1e-4 where |s| > 1e-6 sigma: a misalignment of 1e-8 sigma turns the
///    direction of such a slip by at most 1e-2 rad, i.e. 1 + cos <= 5e-5.
///  - dissipation -sum p.s >= -1e-8 sigma mu N: every element contributes mu pn |s| >= 0 (slip) or
///    0 (adhesion), up to the same slip tolerance.
inline void expect_physical(const SteadyCheck& r, const std::string& what) {
  SCOPED_TRACE(what);
  EXPECT_TRUE(r.finite);
  EXPECT_LE(r.bound_excess, 1e-14) << "|p| above mu pn";
  EXPECT_LE(r.slip_bound_gap, 1e-14) << "slip traction not on the Coulomb bound";
  EXPECT_LE(r.adhesion_slip, 1e-8) << "adhesion element slips (relative to " << r.sigma << " m/s)";
  EXPECT_LE(r.misalignment, 1e-8) << "slip traction not opposite to the slip";
  EXPECT_LE(r.returned_slip, 1e-8) << "returned slip differs from w + S p";
  if (r.max_cosine > -1.0) {
    EXPECT_LE(r.max_cosine, -1.0 + 1e-4) << "traction not opposite to a clearly non-zero slip";
  }
  EXPECT_LE(std::hypot(r.F.Fx, r.F.Fy), r.friction_force * (1 + 1e-12)) << "|F| above mu N";
  EXPECT_GE(r.dissipation, -1e-8 * r.sigma * r.friction_force) << "negative frictional power";
}

/// The Jacobian of the semismooth Newton method at a converged solution (coulomb_newton.hpp):
/// J = I - dPi/db (S - D), with dPi/db from the exact element solution at b = s - D p.
inline Eigen::MatrixXd newton_jacobian(const ContactPatch& patch, const TangentialSolution& s,
                                       double mu, double speed, const Creepage& c,
                                       double spin_offset) {
  const Grid& g = patch.grid;
  const SlipOperator S = SlipOperator::steady(patch.influence, speed);
  const std::vector<int> el = contact_elements(patch);
  const int m = static_cast<int>(el.size());
  const Eigen::MatrixXd Sd = dense_steady_operator(S, el);
  GridField wx, wy;
  rigid_slip(g, speed, c, spin_offset, wx, wy);
  Eigen::VectorXd p(2 * m), w(2 * m);
  for (int a = 0; a < m; ++a) {
    p(2 * a) = s.px[el[a]], p(2 * a + 1) = s.py[el[a]];
    w(2 * a) = wx[el[a]], w(2 * a + 1) = wy[el[a]];
  }
  const Eigen::VectorXd slip = w + Sd * p;
  const int k0 = S.offset_index(0, 0);
  const double d1 = S.xx(k0), d2 = S.yy(k0);
  Eigen::MatrixXd J = Eigen::MatrixXd::Identity(2 * m, 2 * m);
  Eigen::MatrixXd SmD = Sd;
  for (int a = 0; a < m; ++a) SmD(2 * a, 2 * a) -= d1, SmD(2 * a + 1, 2 * a + 1) -= d2;
  for (int a = 0; a < m; ++a) {
    const ElementTraction e =
        solve_coulomb_element(slip(2 * a) - d1 * p(2 * a), slip(2 * a + 1) - d2 * p(2 * a + 1), d1,
                              d2, mu * patch.normal.pn[el[a]]);
    const Eigen::Matrix2d G =
        Eigen::Map<const Eigen::Matrix<double, 2, 2, Eigen::RowMajor>>(e.dp_db);
    J.middleRows(2 * a, 2) -= G * SmD.middleRows(2 * a, 2);
  }
  return J;
}

/// Passivity of creep coefficients (F~ = -f xi~): the mean power the creepage variation puts into
/// the contact is (V/2) xi~^H Herm(f) xi~ >= 0 (docs/stability.md). Returns the smallest eigenvalue
/// of the Hermitian part of f, made dimensionless (rows Fx, Fy, Mz/c, columns xi_x, xi_y, c phi, a
/// congruence that keeps the sign) and relative to |f|; `translational` restricts it to the
/// (xi_x, xi_y) block.
inline double passivity_margin(const nss::CreepMatrix& f, double c, bool translational) {
  const Eigen::Vector3cd d(1.0, 1.0, 1.0 / c);
  const Eigen::Matrix3cd fs = d.asDiagonal() * f * d.asDiagonal();
  const int n = translational ? 2 : 3;
  const Eigen::MatrixXcd h = 0.5 * (fs + fs.adjoint()).topLeftCorner(n, n);
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXcd> es(h, Eigen::EigenvaluesOnly);
  return es.eigenvalues()(0) / fs.norm();
}

}  // namespace rollnoise::stress
