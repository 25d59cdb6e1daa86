// rollnoise bench: run time against error under grid refinement for a Hertzian case (issue 7).
//
// For each grid (nx elements in x, ny = nx b/a rounded, the case's grid.scale) it times and
// measures:
//  - the steady forces at the case's mean creepage (paper Eq. 3);
//  - f11, f22, f23 at 100 Hz, 1 kHz and 5 kHz (fast sweep of the linear model, paper Eq. 28-30;
//    NaN above the grid's Nyquist limit V/(2 dx));
//  - the transient force response: the unsteady solver (paper Eq. 2, contact::TransientRolling)
//    started from the steady state, with the creepages varied harmonically by 5 % of their means at
//    1 kHz (paper Sec. 3.2: amplitudes (5e-5, 5e-5, 0.0027 rad/m) on the paper's case), and the
//    complex amplitudes of Fx and Fy at 1 kHz fitted by least squares (linalg::fit_harmonic);
//  - Kalker's C11 in the full-adhesion limit (creepage 1e-6) against his table.
// Errors are relative to the finest grid (for C11 to Kalker's table); the transient response is
// also compared with the linear model's prediction -f(w) xi^ on the same grid (paper Eq. 28-30: the
// linear model must agree with the unsteady solver to ~0.1 % at non-zero mean creepage, measured
// in the linear-model tests), a consistency check that should not depend on the grid. Prints the table with the
// observed orders of convergence (observed_order: a fit that accounts for the finest grid's own
// error) and writes it as CSV (postprocess/plot_bench.py draws it). The errors of f_jk at 1 kHz and
// above and of the transient response are dominated by a half-step phase lead of the time
// discretisation (see "The half-step phase lead" below); the columns marked * have it removed.
//
// Length of the transient runs. The grid moves one element per step (dt = dx/V), so the cost is
// (steps) x (cost per step) with steps ~ 1/dx and the cost per step growing faster than the number
// of contact elements: the finest grid dominates. The run is
//   kSettleLengths = 5 contact lengths (2a/V each) for the start transient to decay, then
//   kFitPeriods = 3 periods of the excitation, fitted (an integer number of periods, so the
//   harmonics that the nonlinear response generates at 2w, 3w, ... do not leak into the fit);
// on the paper's case 8.2 ms: 59 steps on 10x7, 391 on 56x41 (0.04-0.1 s per step there while
// this was written and the step was being sped up: 16-40 s of the default bench's 31-52 s). The
// variation starts from zero (phase -90 deg, xi~ = amplitude sin(w t)) so the creepage does not
// jump at t = 0. The start transient decays as the material passes through the contact (it carries
// the memory of the tractions), by about 10x per contact length: the linear model's own recursion
// (the discrete-time form M0 Q_k = M1 Q_{k-1} + W_k, docs/conventions.md Sec. 3, started from rest like the
// unsteady run), fitted over the same window, differs from its exact harmonic response -f(w) xi^
// by 1.4e-2, 1.6e-3, 1.8e-4, 3.6e-6 and 1.2e-8 after 1, 2, 3, 5 and 8 contact lengths
// (grids 10..34; printed as "fit window error"). After 5 it is far below the discretisation errors
// measured here (>= 1e-3) and below the 0.1 % agreement expected between linear model and unsteady
// solver; after 3 (25 % less run time) it would mask that agreement.
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <complex>
#include <cstdio>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>
#include <string>

#include "cli/commands.hpp"
#include "contact/creepage_history.hpp"
#include "contact/forces.hpp"
#include "contact/hertz.hpp"
#include "contact/patch.hpp"
#include "contact/steady_rolling.hpp"
#include "contact/transient_rolling.hpp"
#include "core/errors.hpp"
#include "io/contact_case.hpp"
#include "linalg/harmonic_fit.hpp"
#include "noise/kalker_linear.hpp"
#include "nss/linear_model.hpp"

namespace rollnoise::cli {
namespace {

using Clock = std::chrono::steady_clock;
double seconds(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}
const double kNaN = std::numeric_limits<double>::quiet_NaN();

const std::vector<double> kFreq = {100.0, 1000.0, 5000.0};
// the transient run (see the header comment)
const double kTransientFreq = 1000.0;  // Hz, as paper Sec. 3.1/3.2
const double kRelAmplitude = 0.05;     // variation / mean creepage, paper Sec. 3.2
const double kSettleLengths = 5.0;     // contact lengths 2a/V before the fit window
const int kFitPeriods = 3;             // periods in the fit window

struct GridResult {
  int nx = 0, ny = 0, contact = 0;
  double dx = 0.0;
  double t_normal = 0.0, t_steady = 0.0, t_creep = 0.0, t_kalker = 0.0, t_transient = 0.0;
  Eigen::Vector3d force = Eigen::Vector3d::Zero();
  std::vector<nss::CreepMatrix> f;  // at kFreq
  double c11 = 0.0;
  long steps = 0;
  // complex amplitudes X of (Fx, Fy) at kTransientFreq, F(t) ~ mean + Re(X e^{i w t}) (N)
  Eigen::Vector2cd transient = Eigen::Vector2cd::Constant(kNaN);
  Eigen::Vector2cd linear = Eigen::Vector2cd::Constant(kNaN);  // -f(w) xi^, the linear model
  double window_err = kNaN;  // linear recursion fitted over the window against -f(w) xi^
};

// Complex amplitude of the harmonic at `freq` in q(t_k), least squares over t_k in the last
// `periods` periods: q ~ mean + A cos(w t + phase) = mean + Re(A e^{i phase} e^{i w t}).
std::complex<double> fit_last_periods(const std::vector<double>& t, const std::vector<double>& q,
                                      double freq, int periods) {
  const double t0 = t.back() - periods / freq + 1e-9 * (t[1] - t[0]);
  std::vector<double> tw, qw;
  for (size_t k = 0; k < t.size(); ++k)
    if (t[k] > t0) tw.push_back(t[k]), qw.push_back(q[k]);
  const auto h = linalg::fit_harmonic(tw, qw, freq);
  return std::polar(h.amplitude, h.phase);
}

// Observed order of convergence. With q_h = q + c dx^p (one leading error term), the error against
// the finest grid is e_i = |q_i - q_ref| / |q_ref| = C (dx_i^p - dx_ref^p), which falls faster than
// dx^p near the reference: a straight log-log slope through all grids overestimates p (by 0.4 on
// the paper's case, f_jk at 1 kHz). So fit that model to all grids but the finest, least squares
// in log e: for each p (scanned), log C is the mean of log e_i - log(dx_i^p - dx_ref^p). Also gives
// the estimated error of every grid itself, C dx^p, including the finest grid's. `scatter` =
// exp(RMS residual of log e): ~1 for a clean power law, >1.3 where the errors jump about with the
// grid (steady forces: the set of elements in contact changes irregularly with dx).
struct Order {
  double p = kNaN, C = kNaN, scatter = kNaN;
  int points = 0;
  double error_at(double dx) const { return C * std::pow(dx, p); }
};

Order observed_order(const std::vector<double>& dx, const std::vector<double>& err) {
  Order o;
  const double href = dx.back();
  std::vector<double> h, le;
  for (size_t i = 0; i + 1 < dx.size(); ++i)
    if (std::isfinite(err[i]) && err[i] > 0 && dx[i] > href)
      h.push_back(dx[i]), le.push_back(std::log(err[i]));
  o.points = static_cast<int>(h.size());
  if (o.points < 2) return o;
  double best = std::numeric_limits<double>::infinity();
  for (double p = 0.2; p <= 4.0 + 1e-12; p += 0.002) {
    double m = 0.0, ss = 0.0;
    std::vector<double> y(h.size());
    for (size_t i = 0; i < h.size(); ++i)
      m += (y[i] = le[i] - std::log(std::pow(h[i], p) - std::pow(href, p)));
    m /= h.size();
    for (double v : y) ss += (v - m) * (v - m);
    if (ss < best) best = ss, o.p = p, o.C = std::exp(m);
  }
  o.scatter = std::exp(std::sqrt(best / h.size()));
  if (o.p < 0.2 + 1e-9 || o.p > 4.0 - 1e-9) o.p = o.C = kNaN;  // at the scan's end: no power law
  return o;
}

double rel_err(const Eigen::Vector2cd& v, const Eigen::Vector2cd& ref) {
  return (v - ref).norm() / ref.norm();
}

}  // namespace

int run_bench(const CommonOptions& o, const std::vector<int>& grids, const std::string& csv) {
  const io::CaseReader reader = io::CaseReader::from_file(o.case_file, o.overrides);
  const io::ContactCase base = io::read_contact_case(reader);
  if (base.geometry != "hertz") reader.fail("contact.geometry", "bench needs a Hertzian case");
  if (grids.empty()) throw InputError("--nx", "needs at least one grid");
  const double scale = reader.real("grid.scale");
  const contact::HertzContact hz =
      contact::hertz_from_semi_axes(base.a, base.b, base.normal_force, base.material);

  // The harmonic creepage variation of the transient runs: 5 % of each mean component (paper
  // Sec. 3.2); at zero mean creepage 5e-5 in xi_x (paper Sec. 3.1's amplitude). Phase -90 deg:
  // xi~(t) = amplitude sin(w t), no jump at t = 0.
  std::array<double, 3> amp = {kRelAmplitude * std::abs(base.creepage.xi_x),
                               kRelAmplitude * std::abs(base.creepage.xi_y),
                               kRelAmplitude * std::abs(base.creepage.phi)};
  if (amp[0] == 0 && amp[1] == 0 && amp[2] == 0) amp[0] = 5e-5;
  const std::array<double, 3> phase = {-M_PI / 2, -M_PI / 2, -M_PI / 2};
  const auto history =
      contact::CreepageHistory::harmonic(base.creepage, amp, kTransientFreq, phase);
  const Eigen::Vector3cd xi_hat(std::polar(amp[0], phase[0]), std::polar(amp[1], phase[1]),
                                std::polar(amp[2], phase[2]));
  const double t_run = kSettleLengths * 2 * base.a / base.speed + kFitPeriods / kTransientFreq;

  std::vector<GridResult> res;
  std::printf(
      "%s: grid refinement, mean creepage (%g, %g, %g rad/m); transient: variation "
      "(%g, %g, %g rad/m) at %g Hz for %.3g ms (%g contact lengths + %d periods, fitted over "
      "the periods)\n",
      reader.name().c_str(), base.creepage.xi_x, base.creepage.xi_y, base.creepage.phi, amp[0],
      amp[1], amp[2], kTransientFreq, t_run * 1e3, kSettleLengths, kFitPeriods);
  for (int nx : grids) {
    GridResult r;
    r.nx = nx;
    r.ny = std::max(4, static_cast<int>(std::lround(nx * base.b / base.a)));
    // coarse grids need a wider margin around the ellipse (at least ~1.25 elements each side)
    const double s_i = std::max(scale, 1.0 + 2.5 / std::min(r.nx, r.ny));
    const contact::Grid g = contact::Grid::around_ellipse(r.nx, r.ny, base.a, base.b, s_i);
    r.dx = g.dx;
    auto t = Clock::now();
    const contact::ContactPatch patch = contact::solve_patch(
        g, base.material, contact::quadratic_distance(g, hz.A, hz.B), base.normal_force);
    r.t_normal = seconds(t);
    const auto s = contact::solve_steady_rolling(patch.influence, patch.normal.pn,
                                                 base.steady_input(), base.tangential);
    r.t_steady = seconds(t);
    r.contact = patch.normal.contact_elements();
    const auto F = contact::total_forces(g, s.px, s.py);
    r.force << F.Fx, F.Fy, F.Mz;
    t = Clock::now();
    const nss::LinearContactModel m(patch, s, {base.mu, base.speed, base.spin_offset});
    std::vector<double> ok;
    for (double f : kFreq)
      if (f <= m.nyquist_frequency()) ok.push_back(f);
    const auto fk = m.creep_coefficients(ok);
    r.t_creep = seconds(t);
    for (size_t i = 0; i < kFreq.size(); ++i)
      r.f.push_back(i < fk.size() ? fk[i] : nss::CreepMatrix::Constant(kNaN));
    t = Clock::now();
    contact::SteadyRollingInput lin = base.steady_input();
    lin.creepage = {1e-6, 0.0, 0.0};
    const auto sk =
        contact::solve_steady_rolling(patch.influence, patch.normal.pn, lin, base.tangential);
    const double G = base.material.shear_modulus();
    r.c11 = -contact::total_forces(g, sk.px, sk.py).Fx / (G * base.a * base.b * 1e-6);
    r.t_kalker = seconds(t);

    // transient response: unsteady rolling from the steady state at the mean creepage
    if (kTransientFreq <= m.nyquist_frequency()) {
      const double dt = m.time_step();
      r.steps = std::lround(std::ceil(t_run / dt));
      t = Clock::now();
      contact::TransientRolling rolling(patch.influence, patch.normal.pn, base.mu, base.speed,
                                        base.spin_offset, base.backend, base.tangential);
      rolling.set_tractions(s.px, s.py);
      std::vector<double> time = {0.0}, fx = {F.Fx}, fy = {F.Fy};
      for (long k = 1; k <= r.steps; ++k) {
        const auto& st = rolling.step(history.at(k * dt));  // creepage of step k at t_k = k dt
        const auto Fk = contact::total_forces(g, st.px, st.py);
        time.push_back(k * dt), fx.push_back(Fk.Fx), fy.push_back(Fk.Fy);
      }
      r.t_transient = seconds(t);
      r.transient << fit_last_periods(time, fx, kTransientFreq, kFitPeriods),
          fit_last_periods(time, fy, kTransientFreq, kFitPeriods);
      // the linear model on the same grid: F~ = -f(w) xi^ (paper Eq. 28-30) ...
      const nss::CreepMatrix fw = m.creep_coefficients({kTransientFreq})[0];
      r.linear = -(fw * xi_hat).head<2>();
      // ... and its recursion from rest over the same run, fitted the same way: what is left of the
      // start transient in the fit window
      std::vector<Eigen::Vector3d> xi;
      for (double tk : time) {
        const auto v = history.variation(tk);
        xi.emplace_back(v[0], v[1], v[2]);
      }
      const auto Fl = m.time_response(xi);
      std::vector<double> lx, ly;
      for (const auto& v : Fl) lx.push_back(v(0)), ly.push_back(v(1));
      const Eigen::Vector2cd Xl(fit_last_periods(time, lx, kTransientFreq, kFitPeriods),
                                fit_last_periods(time, ly, kTransientFreq, kFitPeriods));
      r.window_err = rel_err(Xl, r.linear);
    }
    res.push_back(std::move(r));
    std::fprintf(stderr, "  %d x %d done\n", res.back().nx, res.back().ny);
  }
  const GridResult& ref = res.back();
  const double c11_table = noise::kalker_coefficients(base.a / base.b, base.material.nu).C11;
  // The half-step phase lead. The displacement difference (A p_k - A0 p_{k-1})/dt of paper Eq. 2 is
  // a one-step difference, centred at t_k - dt/2, while the creepage is taken at t_k (CONTACT's
  // convention, docs/conventions.md Sec. 3): the discrete response leads the grid-converged one by dt/2, a
  // phase error of w dt/2 = pi f dx/V, first order in dx (10.9 deg at 1 kHz on 20x15, 2.6 deg on
  // 80x59; the phase of f11 at 1 kHz minus that shift is -85.3 +- 0.1 deg on all grids from 28x21
  // to 80x59 (-85.05 on 20x15), while the raw phase runs from -74.2 (20x15) to -82.6 deg (80x59)).
  // It dominates the errors of f_jk at 1 kHz and above and of the transient response. The
  // "phase-corrected" errors remove it, q e^{-i w dt/2}, to show what is left (the amplitude's and
  // the rest of the phase's errors).
  auto shift = [](double freq, double dx, double speed) {
    return std::polar(1.0, -M_PI * freq * dx / speed);
  };
  // largest relative error of the entries (j, k) of f at kFreq[i] (NaN above the grid's Nyquist
  // limit), optionally phase-corrected
  using Entries = std::vector<std::pair<int, int>>;
  const Entries all = {{0, 0}, {1, 1}, {1, 2}}, direct = {{0, 0}, {1, 1}}, f23 = {{1, 2}};
  auto ferr = [&](const GridResult& r, size_t i, const Entries& entries, bool corrected) {
    const std::complex<double> c = corrected ? shift(kFreq[i], r.dx, base.speed) : 1.0;
    const std::complex<double> c_ref = corrected ? shift(kFreq[i], ref.dx, base.speed) : 1.0;
    double e = kNaN;
    for (auto [j, k] : entries) {
      const std::complex<double> q = c * r.f[i](j, k), q_ref = c_ref * ref.f[i](j, k);
      const double d = std::abs(q - q_ref) / std::abs(q_ref);
      if (std::isfinite(d)) e = std::isfinite(e) ? std::max(e, d) : d;
    }
    return e;
  };
  // the quantities whose errors are tabulated: name, CSV column, shown in the printed table
  struct Quantity {
    std::string name, column, header;
  };
  std::vector<Quantity> quantities = {{"steady forces (Fx, Fy)", "err_force_rel", "err F"},
                                      {"steady Mz", "err_mz_rel", "err Mz"}};
  const char* fname[] = {"100Hz", "1kHz", "5kHz"};
  const char* fpretty[] = {"100 Hz", "1 kHz", "5 kHz"};
  std::map<std::string, std::vector<double>> err;  // by CSV column
  for (size_t i = 0; i < kFreq.size(); ++i) {
    quantities.push_back({std::string("f11/f22/f23 at ") + fpretty[i],
                          std::string("err_f_") + fname[i] + "_rel", std::string("f ") + fname[i]});
    quantities.push_back({std::string("f11/f22 at ") + fpretty[i] + ", phase-corrected",
                          std::string("err_f11f22_") + fname[i] + "_pc_rel",
                          i == 1 ? "f11/22 1k*" : ""});
    quantities.push_back({std::string("f23 at ") + fpretty[i],
                          std::string("err_f23_") + fname[i] + "_rel", i == 1 ? "f23 1kHz" : ""});
    for (const auto& r : res) {
      err[std::string("err_f_") + fname[i] + "_rel"].push_back(ferr(r, i, all, false));
      err[std::string("err_f11f22_") + fname[i] + "_pc_rel"].push_back(ferr(r, i, direct, true));
      err[std::string("err_f23_") + fname[i] + "_rel"].push_back(ferr(r, i, f23, false));
    }
  }
  quantities.push_back({"transient (Fx, Fy) at 1 kHz", "err_transient_rel", "transient"});
  quantities.push_back({"transient, phase-corrected", "err_transient_pc_rel", "transient*"});
  quantities.push_back({"C11 (against the finest grid)", "err_C11_rel", ""});
  std::vector<double> dx, e_lin, e_kalker;
  double window_err = 0.0;
  for (const auto& r : res) {
    dx.push_back(r.dx);
    err["err_force_rel"].push_back((r.force.head<2>() - ref.force.head<2>()).norm() /
                                   ref.force.head<2>().norm());
    err["err_mz_rel"].push_back(std::abs(r.force(2) - ref.force(2)) / std::abs(ref.force(2)));
    err["err_transient_rel"].push_back(rel_err(r.transient, ref.transient));
    err["err_transient_pc_rel"].push_back(
        rel_err(shift(kTransientFreq, r.dx, base.speed) * r.transient,
                shift(kTransientFreq, ref.dx, base.speed) * ref.transient));
    err["err_C11_rel"].push_back(std::abs(r.c11 / ref.c11 - 1));
    e_lin.push_back(rel_err(r.transient, r.linear));
    e_kalker.push_back(std::abs(r.c11 / c11_table - 1));
    if (std::isfinite(r.window_err)) window_err = std::max(window_err, r.window_err);
  }

  // printed: the grids and times, then the errors
  std::printf("%5s %5s %8s %7s %10s %10s %10s %6s %8s %9s\n", "nx", "ny", "dx [mm]", "contact",
              "steady [s]", "creep [s]", "trans. [s]", "steps", "C11", "err C11");
  for (size_t i = 0; i < res.size(); ++i) {
    const GridResult& r = res[i];
    std::printf("%5d %5d %8.4f %7d %10.3f %10.3f %10.3f %6ld %8.4f %9.2e\n", r.nx, r.ny, r.dx * 1e3,
                r.contact, r.t_steady, r.t_creep, r.t_transient, r.steps, r.c11, e_kalker[i]);
  }
  std::printf(
      "  (steady: normal + steady problem; creep: linear model set-up + f at %g, %g, %g Hz; "
      "trans.: %g contact lengths + %d periods of unsteady rolling; err C11: against "
      "Kalker's table, %.4f at a/b = %.3f, nu = %.2f)\n",
      kFreq[0], kFreq[1], kFreq[2], kSettleLengths, kFitPeriods, c11_table, base.a / base.b,
      base.material.nu);
  std::printf("%5s", "nx");
  for (const auto& q : quantities)
    if (!q.header.empty()) std::printf(" %10s", q.header.c_str());
  std::printf(" %10s\n", "tr-lin");
  for (size_t i = 0; i < res.size(); ++i) {
    std::printf("%5d", res[i].nx);
    for (const auto& q : quantities)
      if (!q.header.empty()) std::printf(" %10.2e", err[q.column][i]);
    std::printf(" %10.2e\n", e_lin[i]);
  }
  std::printf(
      "  (relative errors against the finest grid; f: largest of f11, f22, f23; transient: complex "
      "amplitudes of Fx, Fy at %g Hz; *: phase-corrected by w dt/2; tr-lin: transient against the "
      "linear model -f(w) xi^ on the same grid; fit window error %.1e)\n",
      kTransientFreq, window_err);
  std::vector<Order> orders;
  for (const auto& q : quantities) orders.push_back(observed_order(dx, err[q.column]));
  if (res.size() >= 3) {
    std::printf(
        "observed order of convergence, fitting err = C (dx^p - dx_%d^p) to grids %d..%d:\n",
        ref.nx, res[0].nx, res[res.size() - 2].nx);
    const std::string own = "own error " + std::to_string(ref.nx) + "x" + std::to_string(ref.ny);
    std::printf("  %-36s %6s %8s %18s\n", "", "order", "scatter", own.c_str());
    for (size_t q = 0; q < quantities.size(); ++q)
      std::printf("  %-36s %6.2f %8.2f %18.2e\n", quantities[q].name.c_str(), orders[q].p,
                  orders[q].scatter, orders[q].error_at(ref.dx));
  }
  if (csv.empty())
    std::printf("(--csv FILE writes the table; postprocess/plot_bench.py FILE draws it)\n");
  if (!csv.empty()) {
    std::ofstream out(csv);
    if (!out) throw InputError("--csv", "cannot write " + csv);
    out << "# rollnoise bench " << o.case_file
        << ": errors relative to the finest grid (nx = " << ref.nx
        << "); err_C11_kalker against Kalker's table (" << c11_table
        << "); err_f: largest of f11, f22, f23; err_transient: complex amplitudes of Fx, Fy at "
        << kTransientFreq
        << " Hz; _pc: phase-corrected by w dt/2; times in s (t_steady: normal + steady problem, "
           "t_C11: normal + C11 solve)\n";
    out << "nx,ny,dx_m,contact_elements,t_steady_s,t_creep_s,t_transient_s,t_C11_s,"
           "transient_steps,Fx_N,Fy_N,Mz_Nm,C11,err_C11_kalker_rel";
    for (const auto& q : quantities) out << "," << q.column;
    out << ",err_transient_vs_linear_rel\n";
    out.precision(8);
    for (size_t i = 0; i < res.size(); ++i) {
      const GridResult& r = res[i];
      out << r.nx << "," << r.ny << "," << r.dx << "," << r.contact << "," << r.t_steady << ","
          << r.t_creep << "," << r.t_transient << "," << r.t_normal + r.t_kalker << "," << r.steps
          << "," << r.force(0) << "," << r.force(1) << "," << r.force(2) << "," << r.c11 << ","
          << e_kalker[i];
      for (const auto& q : quantities) out << "," << err[q.column][i];
      out << "," << e_lin[i] << "\n";
    }
    const std::string png =
        (csv.size() > 4 && csv.substr(csv.size() - 4) == ".csv" ? csv.substr(0, csv.size() - 4)
                                                                : csv) +
        ".png";
    std::printf(
        "wrote %s\ndraw it (from the source tree): /usr/bin/python3 postprocess/plot_bench.py %s "
        "-o %s\n",
        csv.c_str(), csv.c_str(), png.c_str());
  }
  return 0;
}

}  // namespace rollnoise::cli
