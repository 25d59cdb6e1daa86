// rollnoise response: the linear model's force response to the case's creepage history, by the
// discrete-time recursion M0 Q_k = M1 Q_{k-1} + W_k (any history) and by harmonic synthesis
// (paper Eqs. 33-34, harmonic and multiharmonic histories).
// rollnoise validate: the same against the unsteady solver (paper Eq. 2) on the same history, with
// spectra and error figures.
#include <chrono>
#include <cmath>
#include <cstdio>

#include "cli/commands.hpp"
#include "cli/contact_setup.hpp"
#include "cli/progress.hpp"
#include "contact/forces.hpp"
#include "contact/transient_rolling.hpp"
#include "io/contact_output.hpp"
#include "io/excitation.hpp"
#include "linalg/multisine_fit.hpp"
#include "nss/spectrum.hpp"

namespace rollnoise::cli {
namespace {

using Series = std::vector<Eigen::Vector3d>;

std::vector<double> flatten(const Series& s) {
  std::vector<double> out;
  for (const auto& v : s) out.insert(out.end(), {v(0), v(1), v(2)});
  return out;
}

struct LinearRun {
  std::vector<double> time;
  Series creepage, recursion, synthesis;  // forces incl. the mean
  std::vector<double> normal_force;        // N_mean + dN (N)
  bool has_synthesis = false;
};

LinearRun linear_response(const MeanState& ms, const contact::CreepageHistory& h, long steps) {
  const nss::LinearContactModel& m = *ms.model;
  const double dt = m.time_step();
  const auto fbar = contact::total_forces(ms.patch->grid, ms.steady.px, ms.steady.py);
  const Eigen::Vector3d Fbar(fbar.Fx, fbar.Fy, fbar.Mz);
  LinearRun r;
  Series xi;
  std::vector<double> dN;  // normal-load variation (N), input g of the linear model
  for (long k = 0; k <= steps; ++k) {
    r.time.push_back(k * dt);
    const auto c = h.at(k * dt);
    r.creepage.emplace_back(c.xi_x, c.xi_y, c.phi);
    const auto v = h.variation(k * dt);
    xi.emplace_back(v[0], v[1], v[2]);
    dN.push_back(h.normal_variation(k * dt));
    r.normal_force.push_back(ms.contact.normal_force + dN.back());
  }
  for (const auto& F : m.time_response(xi, dN)) r.recursion.push_back(Fbar + F);
  r.has_synthesis = !h.frequencies().empty();
  if (r.has_synthesis) {
    // F = F_bar + Re sum_n (-f(w_n) xi^_n + g(w_n) N^_n) e^{i w_n t}  (paper Eqs. 33-34 with G2)
    const auto f = m.creep_coefficients(h.frequencies());
    const auto g = h.has_normal_variation() ? m.normal_load_coefficients(h.frequencies())
                                            : std::vector<nss::LoadVector>(f.size(), nss::LoadVector::Zero());
    std::vector<Eigen::Vector3cd> fx(f.size());  // f(w_n) xi^_n - g(w_n) N^_n
    for (size_t n = 0; n < f.size(); ++n) {
      Eigen::Vector3cd x;
      for (int j = 0; j < 3; ++j) x(j) = h.amplitude()[j] * std::polar(1.0, h.phases()[j][n]);
      fx[n] = f[n] * x;
      if (h.has_normal_variation()) fx[n] -= g[n] * h.normal_amplitude() * std::polar(1.0, h.normal_phases()[n]);
    }
    for (long k = 0; k <= steps; ++k) {
      Eigen::Vector3d F = Fbar;
      for (size_t n = 0; n < f.size(); ++n)
        F -= (fx[n] * std::polar(1.0, 2 * M_PI * h.frequencies()[n] * k * dt)).real();
      r.synthesis.push_back(F);
    }
  }
  return r;
}

void write_linear(io::Hdf5Writer& w, const std::string& g, const LinearRun& r) {
  const std::size_t n = r.time.size();
  w.write(g + "/time", r.time, {n}, "s");
  w.write(g + "/creepage", flatten(r.creepage), {n, 3}, "-, -, rad/m");
  w.write(g + "/normal_force", r.normal_force, {n}, "N");
  w.write(g + "/force", flatten(r.recursion), {n, 3}, "N, N, N m");
  if (r.has_synthesis) w.write(g + "/force_synthesis", flatten(r.synthesis), {n, 3}, "N, N, N m");
}

void check_excitation_resolved(const io::CaseReader& r, const contact::CreepageHistory& h,
                               const nss::LinearContactModel& m) {
  for (double f : h.frequencies())
    if (f > m.nyquist_frequency())
      r.fail(h.frequencies().size() == 1 ? "excitation.frequency" : "excitation.f_max",
             std::to_string(f) + " Hz is above the grid's Nyquist limit V/(2 dx) = " +
                 std::to_string(m.nyquist_frequency()) + " Hz");
}

long steps_of(const io::CaseReader& reader, double dt) {
  const double duration = reader.real("transient.duration");
  const long steps = std::lround(std::floor(duration / dt + 1e-9));
  if (steps < 1) reader.fail("transient.duration", "shorter than one time step dx/V");
  return steps;
}

}  // namespace

int run_response(const CommonOptions& o) {
  const io::CaseReader reader = io::CaseReader::from_file(o.case_file, o.overrides);
  const contact::CreepageHistory h = io::read_excitation(reader);
  MeanState ms = solve_mean_state(reader, true);
  check_excitation_resolved(reader, h, *ms.model);
  const long steps = steps_of(reader, ms.model->time_step());
  io::normal_load_series(reader, h, ms.contact.normal_force, ms.model->time_step(), steps);  // N_k > 0
  const auto t0 = std::chrono::steady_clock::now();
  const LinearRun r = linear_response(ms, h, steps);
  const double ms_run = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  const std::string out = output_path(o, reader.name());
  io::Hdf5Writer w(out);
  io::write_mean_state(w, reader, *ms.patch, ms.contact.creepage, ms.steady);
  write_linear(w, "/response", r);
  io::write_excitation(w, "/response/excitation", h);
  w.commit();
  std::printf("%s: linear response, %ld steps of %.4g s, in %.0f ms (recursion%s)\n", reader.name().c_str(),
              steps, ms.model->time_step(), ms_run, r.has_synthesis ? " and harmonic synthesis" : "");
  if (r.has_synthesis) {
    const double t_start = reader.real("transient.analysis_start");
    double d = 0, a = 0;
    for (size_t k = 0; k < r.time.size(); ++k)
      if (r.time[k] >= t_start) {
        d = std::max(d, (r.recursion[k] - r.synthesis[k]).head<2>().cwiseAbs().maxCoeff());
        a = std::max(a, (r.synthesis[k] - r.synthesis[0]).head<2>().cwiseAbs().maxCoeff());
      }
    std::printf("  recursion vs synthesis after %.4g s: max |difference| %.3g N (variation %.3g N)\n",
                t_start, d, a);
  }
  std::printf("wrote %s\n", out.c_str());
  return 0;
}

int run_validate(const CommonOptions& o) {
  const io::CaseReader reader = io::CaseReader::from_file(o.case_file, o.overrides);
  const contact::CreepageHistory h = io::read_excitation(reader);
  MeanState ms = solve_mean_state(reader, true);
  check_excitation_resolved(reader, h, *ms.model);
  const double dt = ms.model->time_step();
  const long steps = steps_of(reader, dt);
  io::normal_load_series(reader, h, ms.contact.normal_force, dt, steps);  // N_k > 0, else InputError
  const double t_start = reader.real("transient.analysis_start");
  const LinearRun lin = linear_response(ms, h, steps);

  // the unsteady reference from the same steady state
  contact::TransientRolling rolling(ms.patch->influence, ms.patch->normal.pn, ms.contact.mu, ms.contact.speed,
                                    ms.contact.spin_offset, ms.contact.backend, ms.contact.tangential);
  rolling.set_tractions(ms.steady.px, ms.steady.py);
  const bool varying_load = h.has_normal_variation();
  if (varying_load)  // the normal problem is re-solved at every step (transient_rolling.hpp)
    rolling.set_normal_problem(ms.patch->undeformed_distance, ms.contact.normal_force, ms.contact.normal);
  Series unsteady;
  {
    const auto f = contact::total_forces(ms.patch->grid, ms.steady.px, ms.steady.py);
    unsteady.emplace_back(f.Fx, f.Fy, f.Mz);
  }
  const auto t0 = std::chrono::steady_clock::now();
  Progress progress("unsteady", steps, o.quiet);
  for (long k = 1; k <= steps; ++k) {
    const auto& s = varying_load ? rolling.step(h.at(k * dt), lin.normal_force[k]) : rolling.step(h.at(k * dt));
    const auto f = contact::total_forces(ms.patch->grid, s.px, s.py);
    unsteady.emplace_back(f.Fx, f.Fy, f.Mz);
    progress.update(k);
  }
  progress.finish();
  const double ms_unsteady = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();

  // errors after the start transient
  std::vector<double> ta;
  std::array<std::vector<double>, 3> qu, ql;
  Eigen::Vector3d sq_err = Eigen::Vector3d::Zero(), sq_var = Eigen::Vector3d::Zero(), mean_u = Eigen::Vector3d::Zero();
  for (size_t k = 0; k < lin.time.size(); ++k)
    if (lin.time[k] >= t_start) {
      ta.push_back(lin.time[k]);
      for (int j = 0; j < 3; ++j) qu[j].push_back(unsteady[k](j)), ql[j].push_back(lin.recursion[k](j));
      mean_u += unsteady[k];
    }
  if (ta.size() < 8) reader.fail("transient.analysis_start", "leaves fewer than 8 samples to analyse");
  mean_u /= double(ta.size());
  for (size_t i = 0; i < ta.size(); ++i)
    for (int j = 0; j < 3; ++j) {
      sq_err(j) += std::pow(qu[j][i] - ql[j][i], 2);
      sq_var(j) += std::pow(qu[j][i] - mean_u(j), 2);
    }
  Eigen::Vector3d rms_rel;
  for (int j = 0; j < 3; ++j) rms_rel(j) = sq_var(j) > 0 ? std::sqrt(sq_err(j) / sq_var(j)) : 0.0;

  const std::string out = output_path(o, reader.name());
  io::Hdf5Writer w(out);
  io::write_mean_state(w, reader, *ms.patch, ms.contact.creepage, ms.steady);
  write_linear(w, "/validate/linear", lin);
  io::write_excitation(w, "/validate/excitation", h);
  const std::size_t n = lin.time.size();
  w.write("/validate/time", lin.time, {n}, "s");
  w.write("/validate/unsteady/force", flatten(unsteady), {n, 3}, "N, N, N m");
  w.write("/validate/errors/rms_relative", std::vector<double>{rms_rel(0), rms_rel(1), rms_rel(2)}, {3},
          "RMS(linear - unsteady) / RMS(unsteady variation), t >= analysis_start; Fx, Fy, Mz");
  // spectra (Hann window over t >= analysis_start)
  for (int j = 0; j < 3; ++j) {
    const auto su = nss::amplitude_spectrum(qu[j], dt), sl = nss::amplitude_spectrum(ql[j], dt);
    const char* name[] = {"Fx", "Fy", "Mz"};
    const std::string unit = j == 2 ? "N m" : "N";
    w.write(std::string("/validate/spectrum/unsteady_") + name[j], su.amplitude, {su.amplitude.size()}, unit);
    w.write(std::string("/validate/spectrum/linear_") + name[j], sl.amplitude, {sl.amplitude.size()}, unit);
    if (j == 0) w.write("/validate/spectrum/frequency", su.frequency, {su.frequency.size()}, "Hz");
  }
  w.attribute("/validate/spectrum", "window", "Hann over t >= transient.analysis_start, mean removed, amplitude scaled by the coherent gain");
  // amplitude and phase at each excited frequency (least-squares multisine fit), if resolvable
  const auto& fr = h.frequencies();
  bool fitted = false;
  if (!fr.empty() && ta.size() > 2 * fr.size() + 1) {
    // several frequencies: the record must resolve their spacing; one: cover at least one period
    const double spacing = fr.size() > 1 ? fr[1] - fr[0] : fr[0];
    if ((ta.back() - ta.front()) * spacing >= 1.0) {
      std::vector<double> amp_err, ph_err;
      for (int j = 0; j < 3; ++j) {
        const auto au = linalg::fit_multisine(ta, qu[j], fr), al = linalg::fit_multisine(ta, ql[j], fr);
        for (size_t k = 0; k < fr.size(); ++k) {
          amp_err.push_back(std::abs(au[k]) > 0 ? std::abs(al[k]) / std::abs(au[k]) - 1 : 0.0);
          ph_err.push_back(std::remainder(std::arg(al[k]) - std::arg(au[k]), 2 * M_PI) * 180 / M_PI);
        }
      }
      w.write("/validate/errors/frequency", fr, {fr.size()}, "Hz");
      w.write("/validate/errors/amplitude", amp_err, {3, fr.size()}, "relative (linear/unsteady - 1); Fx, Fy, Mz");
      w.write("/validate/errors/phase", ph_err, {3, fr.size()}, "deg (linear - unsteady); Fx, Fy, Mz");
      fitted = true;
      if (fr.size() <= 5)
        for (size_t k = 0; k < fr.size(); ++k)
          std::printf("  %.1f Hz: amplitude error Fx %.3f %%, Fy %.3f %%; phase error Fx %.3f deg, Fy %.3f deg\n",
                      fr[k], 100 * amp_err[k], 100 * amp_err[fr.size() + k], ph_err[k], ph_err[fr.size() + k]);
    }
  }
  w.commit();
  std::printf("%s: unsteady solver %ld steps in %.1f s; linear model RMS error after %.4g s: Fx %.3g %%, "
              "Fy %.3g %%, Mz %.3g %% of the RMS variation%s\nwrote %s\n",
              reader.name().c_str(), steps, ms_unsteady / 1e3, t_start, 100 * rms_rel(0), 100 * rms_rel(1),
              100 * rms_rel(2), fitted ? "" : " (record too short for per-frequency errors)", out.c_str());
  return 0;
}

}  // namespace rollnoise::cli
