#include "pipeline/creep.hpp"

#include <chrono>
#include <cmath>
#include <sstream>

#include "core/errors.hpp"
#include "nss/extrapolation.hpp"

namespace rollnoise::pipeline {

CreepResult run_creep(ContactCase c, const std::vector<double>& freq, bool direct, const std::string& frequency_key) {
  using Clock = std::chrono::steady_clock;
  auto seconds = [](Clock::time_point a, Clock::time_point b) { return std::chrono::duration<double>(b - a).count(); };
  CreepResult r;
  const auto t0 = Clock::now();
  MeanContactOptions options;
  options.frequencies = freq;
  options.frequency_key = frequency_key;
  r.state = mean_contact(c, options);
  const nss::LinearContactModel& model = *r.state.model();
  const auto t1 = Clock::now();
  if (direct) {
    for (double fr : freq) r.f.push_back(model.creep_coefficients_direct(fr));
    for (double fr : freq) r.g.push_back(model.normal_load_coefficients_direct(fr));
  } else {
    r.f = model.creep_coefficients(freq);
    r.g = model.normal_load_coefficients(freq);  // the same sweep (one more Krylov column)
  }
  r.seconds_state = seconds(t0, t1);
  r.seconds_sweep = seconds(t1, Clock::now());
  // g(0) by the same method as the sweep (one more LU when direct; else the same sweep)
  r.g0 = direct ? model.normal_load_coefficients_direct(0.0) : model.normal_load_coefficients(std::vector<double>{0.0})[0];
  return r;
}

namespace {

// The placed case with its grid refined by `factor`: the same potential contact area (the
// Hertzian one, or the one placed around the profiles' contact point), nx and ny scaled; checked
// for size (limits.memory) and resolution.
ContactCase refined_case(const ContactCase& base, double factor, const std::string& key) {
  ContactCase c = base;
  std::ostringstream what;
  what << "grid factor " << factor << ": ";
  try {
    const contact::Grid& g = base.grid;
    c.grid.nx = std::max(1, static_cast<int>(std::lround(g.nx * factor)));
    c.grid.ny = std::max(1, static_cast<int>(std::lround(g.ny * factor)));
    c.grid.dx = g.dx * g.nx / c.grid.nx;
    c.grid.dy = g.dy * g.ny / c.grid.ny;
    c = placed_contact(std::move(c));  // placed: checks the size against limits.memory
  } catch (const InputError& e) {
    throw InputError(key, what.str() + e.what());
  }
  if (2.0 * c.a / c.grid.dx < 4.0 || 2.0 * c.b / c.grid.dy < 4.0) {
    what << c.grid.nx << " x " << c.grid.ny << " is too coarse for the patch: fewer than 4 elements across 2a or 2b";
    throw InputError(key, what.str());
  }
  return c;
}

void check_factors(const std::vector<double>& factors, const std::string& key) {
  std::ostringstream list;
  for (size_t i = 0; i < factors.size(); ++i) list << (i ? "," : "") << factors[i];
  auto refuse = [&](const std::string& what) { throw InputError(key, key + " " + list.str() + ": " + what); };
  if (factors.size() != 2 && factors.size() != 3) refuse("needs two or three grid factors, coarse to fine");
  for (size_t i = 0; i < factors.size(); ++i) {
    if (!(factors[i] > 0.0 && factors[i] <= 8.0)) refuse("factors must lie in (0, 8]");
    if (i > 0 && !(factors[i] > factors[i - 1])) refuse("factors must increase strictly (coarse to fine)");
  }
}

}  // namespace

CreepResult run_creep_extrapolated(ContactCase c, const std::vector<double>& freq, bool direct,
                                   const std::string& frequency_key, const std::vector<double>& factors,
                                   const std::string& factors_key) {
  check_factors(factors, factors_key);
  c = placed_contact(std::move(c));
  std::vector<ContactCase> cases;
  for (double s : factors) cases.push_back(refined_case(c, s, factors_key));
  for (const ContactCase& rc : cases) check_nyquist(rc, freq, frequency_key);  // before any solve

  CreepExtrapolation ex;
  ex.factors = factors;
  ex.assumed_order = c.sampling == contact::CreepageSampling::contact ? 1.0 : 2.0;  // midstep, average: second order
  std::vector<double> with_zero = freq;
  with_zero.push_back(0.0);  // g(0) is extrapolated with the rest
  CreepResult first;
  std::vector<nss::LoadVector> g0;
  for (size_t i = 0; i < cases.size(); ++i) {
    CreepResult r = run_creep(std::move(cases[i]), with_zero, direct, frequency_key);
    const contact::Grid& grid = r.state.contact().grid;
    ex.nx.push_back(grid.nx);
    ex.ny.push_back(grid.ny);
    ex.dx.push_back(grid.dx);
    g0.push_back(r.g.back());
    r.f.pop_back();
    r.g.pop_back();
    ex.f.push_back(r.f);
    ex.g.push_back(r.g);
    if (i == 0)
      first = std::move(r);
    else
      first.seconds_state += r.seconds_state, first.seconds_sweep += r.seconds_sweep;
  }
  for (size_t i = 1; i < ex.dx.size(); ++i)
    if (!(ex.dx[i] < ex.dx[i - 1]))
      throw InputError(factors_key, "the grids do not refine: dx " + std::to_string(ex.dx[i - 1]) + " then " +
                                        std::to_string(ex.dx[i]) + " m");

  const nss::RichardsonSettings settings{ex.assumed_order};
  auto extrapolate = [&](auto value, double& error, double& order) {
    std::vector<std::complex<double>> v;
    for (size_t i = 0; i < ex.dx.size(); ++i) v.push_back(value(i));
    const nss::RichardsonResult r = nss::richardson(ex.dx, v, settings);
    error = r.error, order = r.order;
    ++(r.observed ? ex.observed : ex.assumed);
    return r.value;
  };
  for (size_t n = 0; n < freq.size(); ++n) {
    Eigen::Matrix3d fe, fo;
    Eigen::Vector3d ge, go;
    for (int j = 0; j < 3; ++j) {
      for (int k = 0; k < 3; ++k)
        first.f[n](j, k) = extrapolate([&](size_t i) { return ex.f[i][n](j, k); }, fe(j, k), fo(j, k));
      first.g[n](j) = extrapolate([&](size_t i) { return ex.g[i][n](j); }, ge(j), go(j));
    }
    ex.f_error.push_back(fe), ex.f_order.push_back(fo), ex.g_error.push_back(ge), ex.g_order.push_back(go);
  }
  for (int j = 0; j < 3; ++j) {
    double e = 0.0, o = 0.0;
    first.g0(j) = extrapolate([&](size_t i) { return g0[i](j); }, e, o);
  }
  first.extrapolation = std::move(ex);
  return first;
}

}  // namespace rollnoise::pipeline
