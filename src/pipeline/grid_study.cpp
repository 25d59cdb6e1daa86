#include "pipeline/grid_study.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <utility>

#include "contact/forces.hpp"
#include "core/errors.hpp"
#include "contact/hertz.hpp"
#include "contact/patch.hpp"
#include "contact/rolling_history.hpp"
#include "contact/transient_rolling.hpp"
#include "linalg/harmonic_fit.hpp"
#include "nss/extrapolation.hpp"

namespace rollnoise::pipeline {

// the model layer this harness drives
using nss::CreepMatrix;
using nss::LinearContactModel;
using nss::LinearSolver;
using nss::richardson;
using nss::RichardsonResult;

namespace {

using Clock = std::chrono::steady_clock;
double seconds(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}
const double kNaN = std::numeric_limits<double>::quiet_NaN();

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

double rel_err(const Eigen::Vector2cd& v, const Eigen::Vector2cd& ref) {
  return (v - ref).norm() / ref.norm();
}

// f at the study frequencies the grid resolves, NaN above its Nyquist limit.
void measure_creep(const LinearContactModel& m, const GridStudySettings& s, GridMeasurement& r) {
  std::vector<double> ok;
  for (double f : s.frequencies)
    if (f <= m.nyquist_frequency()) ok.push_back(f);
  const auto fk = m.creep_coefficients(ok);
  for (size_t i = 0; i < s.frequencies.size(); ++i)
    r.f.push_back(i < fk.size() ? fk[i] : CreepMatrix::Constant(kNaN));
}

// Kalker's C11 = -Fx / (G a b xi_x) in the full-adhesion limit xi_x = 1e-6 (Kalker's linear
// theory, F_x = -G a b C11 xi_x).
double full_adhesion_c11(const GridStudyCase& c, const contact::ContactPatch& patch) {
  contact::SteadyRollingInput lin = c.steady;
  lin.creepage = {1e-6, 0.0, 0.0};
  const auto sk = contact::solve_steady_rolling(patch.influence, patch.normal.pn, lin, c.tangential);
  const double G = c.material.shear_modulus();
  return -contact::total_forces(patch.grid, sk.px, sk.py).Fx / (G * c.a * c.b * 1e-6);
}

// The transient run from the steady state `steady` (forces F0), its fitted amplitudes, the linear
// model's -f(w) xi^, and its recursion from rest fitted the same way (window_error).
void measure_transient(const GridStudyCase& c, const GridStudySettings& s, const GridStudyExcitation& e,
                       const contact::ContactPatch& patch, const contact::TangentialSolution& steady,
                       const LinearContactModel& m, GridMeasurement& r) {
  const double dt = m.time_step();
  r.steps = std::lround(std::ceil(e.duration / dt));
  const auto t = Clock::now();
  contact::TransientRolling rolling(patch.influence, patch.normal.pn, c.steady.mu, c.steady.speed,
                                    c.steady.spin_offset, c.backend, c.tangential);
  rolling.set_falling_friction(c.steady.falling);
  rolling.set_tractions(steady.px, steady.py);
  const auto F = contact::rolling_forces(rolling, patch.grid, e.history, c.sampling, dt, r.steps);
  std::vector<double> time = {0.0}, fx = {r.force(0)}, fy = {r.force(1)};
  for (long k = 1; k <= r.steps; ++k)
    time.push_back(k * dt), fx.push_back(F[k - 1](0)), fy.push_back(F[k - 1](1));
  r.t_transient = seconds(t);
  const double f = s.transient_frequency;
  r.transient << fit_last_periods(time, fx, f, s.fit_periods), fit_last_periods(time, fy, f, s.fit_periods);
  // the linear model on the same grid: F~ = -f(w) xi^ (paper Eqs. 28-30) ...
  const CreepMatrix fw = m.creep_coefficients({f})[0];
  r.linear = -(fw * e.xi_hat).head<2>();
  // ... and its recursion from rest over the same run, fitted the same way: what is left of the
  // start transient in the fit window
  std::vector<Eigen::Vector3d> xi;
  for (size_t k = 0; k < time.size(); ++k) {
    const auto v = e.history.step_variation(c.sampling, static_cast<long>(k), dt);
    xi.emplace_back(v[0], v[1], v[2]);
  }
  const auto Fl = m.time_response(xi);
  std::vector<double> lx, ly;
  for (const auto& v : Fl) lx.push_back(v(0)), ly.push_back(v(1));
  const Eigen::Vector2cd Xl(fit_last_periods(time, lx, f, s.fit_periods),
                            fit_last_periods(time, ly, f, s.fit_periods));
  r.window_error = rel_err(Xl, r.linear);
}

// The half-step lead removed: the correction for CONTACT's sampling, nothing for midstep and
// average (whose creepage is already centred at t_k - dt/2).
std::complex<double> lead_correction(double freq, double dx, double speed, contact::CreepageSampling sampling) {
  return sampling == contact::CreepageSampling::contact ? half_step_phase_correction(freq, dx, speed) : 1.0;
}

// Largest relative error of the entries (j, k) of f at frequency i against the reference grid (NaN
// where neither resolves it), optionally phase-corrected.
using Entries = std::vector<std::pair<int, int>>;
double creep_error(const GridMeasurement& r, const GridMeasurement& ref, double freq, size_t i,
                   const Entries& entries, bool corrected, double speed, contact::CreepageSampling sampling) {
  const std::complex<double> c = corrected ? lead_correction(freq, r.dx, speed, sampling) : 1.0;
  const std::complex<double> c_ref = corrected ? lead_correction(freq, ref.dx, speed, sampling) : 1.0;
  double e = kNaN;
  for (auto [j, k] : entries) {
    const std::complex<double> q = c * r.f[i](j, k), q_ref = c_ref * ref.f[i](j, k);
    const double d = std::abs(q - q_ref) / std::abs(q_ref);
    if (std::isfinite(d)) e = std::isfinite(e) ? std::max(e, d) : d;
  }
  return e;
}

}  // namespace

contact::Grid study_grid(const GridStudyCase& c, int nx, int* ny) {
  *ny = std::max(4, static_cast<int>(std::lround(nx * c.b / c.a)));
  const double s_i = std::max(c.scale, 1.0 + 2.5 / std::min(nx, *ny));
  return contact::Grid::around_ellipse(nx, *ny, c.a, c.b, s_i);
}


GridStudyExcitation grid_study_excitation(const GridStudyCase& c, const GridStudySettings& s) {
  GridStudyExcitation e;
  const contact::Creepage& mean = c.steady.creepage;
  e.amplitude = {s.relative_amplitude * std::abs(mean.xi_x), s.relative_amplitude * std::abs(mean.xi_y),
                 s.relative_amplitude * std::abs(mean.phi)};
  if (e.amplitude[0] == 0 && e.amplitude[1] == 0 && e.amplitude[2] == 0) e.amplitude[0] = 5e-5;
  e.phase = {-M_PI / 2, -M_PI / 2, -M_PI / 2};
  e.history = contact::CreepageHistory::harmonic(mean, e.amplitude, s.transient_frequency, e.phase);
  e.xi_hat = Eigen::Vector3cd(std::polar(e.amplitude[0], e.phase[0]), std::polar(e.amplitude[1], e.phase[1]),
                              std::polar(e.amplitude[2], e.phase[2]));
  e.duration = s.settle_lengths * 2 * c.a / c.steady.speed + s.fit_periods / s.transient_frequency;
  return e;
}

void check_study_grids(const GridStudyCase& c, const std::vector<int>& grids) {
  std::string list;
  for (int nx : grids) list += (list.empty() ? "" : ",") + std::to_string(nx);
  auto refuse = [&](const std::string& what) { throw InputError("--nx", "--nx " + list + ": " + what); };
  if (grids.size() < 2) refuse("needs at least two grids, coarse to fine (the finest is the reference)");
  for (std::size_t i = 0; i < grids.size(); ++i) {
    const int nx = grids[i];
    if (i > 0 && nx <= grids[i - 1])
      refuse("grids must be given coarse to fine, strictly increasing: " + std::to_string(grids[i - 1]) + " then " +
           std::to_string(nx));
    if (nx < 1 || nx > 4000) refuse("a grid needs 1 to 4000 elements in x, got " + std::to_string(nx));
    int ny = 0;
    const contact::Grid g = study_grid(c, nx, &ny);
    if (2.0 * c.a / g.dx < 4.0 || 2.0 * c.b / g.dy < 4.0)
      refuse(std::to_string(nx) + " x " + std::to_string(ny) +
           " is too coarse for the patch: fewer than 4 elements across 2a or 2b");
  }
}

GridMeasurement measure_grid(const GridStudyCase& c, const GridStudySettings& s,
                             const GridStudyExcitation& e, int nx) {
  GridMeasurement r;
  r.nx = nx;
  const contact::Grid g = study_grid(c, nx, &r.ny);
  r.dx = g.dx;
  const contact::HertzContact hz = contact::hertz_from_semi_axes(c.a, c.b, c.normal_force, c.material);
  auto t = Clock::now();
  const contact::ContactPatch patch =
      contact::solve_patch(g, c.material, contact::quadratic_distance(g, hz.A, hz.B), c.normal_force);
  r.t_normal = seconds(t);
  const auto steady = contact::solve_steady_rolling(patch.influence, patch.normal.pn, c.steady, c.tangential);
  r.t_steady = seconds(t);
  r.contact = patch.normal.contact_elements();
  const auto F = contact::total_forces(g, steady.px, steady.py);
  r.force << F.Fx, F.Fy, F.Mz;
  t = Clock::now();
  const LinearContactModel m(patch, steady, {c.steady.mu, c.steady.speed, c.steady.spin_offset, c.steady.falling,
                                             LinearSolver::automatic, c.sampling});
  measure_creep(m, s, r);
  r.t_creep = seconds(t);
  t = Clock::now();
  r.c11 = full_adhesion_c11(c, patch);
  r.t_kalker = seconds(t);
  // transient response: unsteady rolling from the steady state at the mean creepage
  if (s.transient_frequency <= m.nyquist_frequency()) measure_transient(c, s, e, patch, steady, m, r);
  measure_sampling_sweeps(c, s, patch, steady, r);
  return r;
}

GridStudyErrors grid_study_errors(const std::vector<GridMeasurement>& res, const GridStudySettings& s,
                                  double speed, double c11_table, contact::CreepageSampling sampling) {
  GridStudyErrors err;
  const GridMeasurement& ref = res.back();
  const Entries all = {{0, 0}, {1, 1}, {1, 2}}, direct = {{0, 0}, {1, 1}}, f23 = {{1, 2}};
  const size_t nf = s.frequencies.size();
  err.f.resize(nf), err.f_direct_corrected.resize(nf), err.f23.resize(nf);
  for (size_t i = 0; i < nf; ++i)
    for (const auto& r : res) {
      const double freq = s.frequencies[i];
      err.f[i].push_back(creep_error(r, ref, freq, i, all, false, speed, sampling));
      err.f_direct_corrected[i].push_back(creep_error(r, ref, freq, i, direct, true, speed, sampling));
      err.f23[i].push_back(creep_error(r, ref, freq, i, f23, false, speed, sampling));
    }
  const double ft = s.transient_frequency;
  for (const auto& r : res) {
    err.dx.push_back(r.dx);
    err.force.push_back((r.force.head<2>() - ref.force.head<2>()).norm() / ref.force.head<2>().norm());
    err.mz.push_back(std::abs(r.force(2) - ref.force(2)) / std::abs(ref.force(2)));
    err.transient.push_back(rel_err(r.transient, ref.transient));
    err.transient_corrected.push_back(rel_err(lead_correction(ft, r.dx, speed, sampling) * r.transient,
                                              lead_correction(ft, ref.dx, speed, sampling) * ref.transient));
    err.c11.push_back(std::abs(r.c11 / ref.c11 - 1));
    err.transient_vs_linear.push_back(rel_err(r.transient, r.linear));
    err.c11_table.push_back(std::abs(r.c11 / c11_table - 1));
    if (std::isfinite(r.window_error)) err.window_error = std::max(err.window_error, r.window_error);
  }
  return err;
}

// ---- the sampling study ----

void measure_sampling_sweeps(const GridStudyCase& c, const GridStudySettings& s, const contact::ContactPatch& patch,
                             const contact::TangentialSolution& steady, GridMeasurement& r) {
  for (size_t i = 0; i < kStudySamplings.size(); ++i) {
    SamplingSweep& sw = r.sampling[i];
    const auto t = Clock::now();
    const LinearContactModel m(patch, steady,
                               {c.steady.mu, c.steady.speed, c.steady.spin_offset, kStudySamplings[i]});
    // a rolling-noise axis: log-spaced over [100 Hz, 5 kHz], capped at the grid's Nyquist limit
    const double f_max = std::min(5000.0, m.nyquist_frequency());
    std::vector<double> sweep(s.sweep_count);
    for (int k = 0; k < s.sweep_count; ++k)
      sweep[k] = 100.0 * std::pow(f_max / 100.0, s.sweep_count > 1 ? k / (s.sweep_count - 1.0) : 1.0);
    (void)m.creep_coefficients(sweep);
    sw.seconds = seconds(t);
    sw.f.clear();
    for (double f : s.accuracy_frequencies)
      sw.f.push_back(f <= m.nyquist_frequency() ? m.creep_coefficients({f})[0] : CreepMatrix::Constant(kNaN));
  }
}

SamplingAccuracy sampling_accuracy(const std::vector<GridMeasurement>& grids, const GridStudySettings& s) {
  const int entry[3][2] = {{0, 0}, {1, 1}, {1, 2}};  // f11, f22, f23
  constexpr size_t ns = kStudySamplings.size();
  SamplingAccuracy a;
  for (auto& e : a.error) e.resize(s.accuracy_frequencies.size());
  for (size_t i = 0; i < s.accuracy_frequencies.size(); ++i) {
    // the three finest grids that resolve this frequency
    std::vector<const GridMeasurement*> fine;
    for (auto it = grids.rbegin(); it != grids.rend() && fine.size() < 3; ++it)
      if (std::isfinite(std::abs((*it).sampling[0].f[i](0, 0)))) fine.insert(fine.begin(), &*it);
    std::vector<double> h;
    for (const auto* g : fine) h.push_back(g->dx);
    // every sampling's extrapolation (contact: fall-back order 1; midstep, average: 2)
    std::array<CreepMatrix, ns> conv;
    std::array<Eigen::Matrix3d, ns> conv_err;
    std::array<Eigen::Vector3d, ns> order;
    for (size_t sm = 0; sm < ns; ++sm) {
      conv[sm] = CreepMatrix::Constant(kNaN), conv_err[sm] = Eigen::Matrix3d::Constant(kNaN);
      order[sm] = Eigen::Vector3d::Constant(kNaN);
      const double assumed = kStudySamplings[sm] == contact::CreepageSampling::contact ? 1.0 : 2.0;
      for (int j = 0; j < 3 && fine.size() >= 2; ++j)
        for (int k = 0; k < 3; ++k) {
          std::vector<std::complex<double>> v;
          for (const auto* g : fine) v.push_back(g->sampling[sm].f[i](j, k));
          const RichardsonResult r = richardson(h, v, {assumed});
          conv[sm](j, k) = r.value, conv_err[sm](j, k) = r.error;
          for (int q = 0; q < 3; ++q)
            if (entry[q][0] == j && entry[q][1] == k) order[sm](q) = r.order;
        }
    }
    // the reference: the second-order sampling with the smaller estimated error
    auto estimated = [&](size_t sm) {
      double e = 0.0;
      for (const auto& q : entry) e = std::max(e, conv_err[sm](q[0], q[1]) / std::abs(conv[sm](q[0], q[1])));
      return e;
    };
    size_t ref = 1;
    for (size_t sm = 1; sm < ns; ++sm)
      if (estimated(sm) < estimated(ref)) ref = sm;
    a.converged.push_back(conv[ref]);
    a.converged_error.push_back(conv_err[ref]);
    a.order.push_back(order[ref]);
    a.reference.push_back(static_cast<int>(ref));
    for (size_t sm = 0; sm < ns; ++sm) {
      Eigen::Vector3d spread;
      for (int q = 0; q < 3; ++q) {
        const std::complex<double> r = conv[ref](entry[q][0], entry[q][1]);
        spread(q) = std::abs(conv[sm](entry[q][0], entry[q][1]) - r) / std::abs(r);
      }
      a.spread[sm].push_back(spread);
      for (int q = 0; q < 3; ++q)
        for (const auto& g : grids) {
          const std::complex<double> r = conv[ref](entry[q][0], entry[q][1]);
          a.error[sm][i][q].push_back(std::abs(g.sampling[sm].f[i](entry[q][0], entry[q][1]) - r) / std::abs(r));
        }
    }
  }
  return a;
}

}  // namespace rollnoise::pipeline
