// Moving sources at a receiver and the pass-by levels, Eqs. (P1)-(E3) of passby.hpp.
#include "acoustics/passby.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>

#include "acoustics/a_weighting.hpp"
#include "core/constants.hpp"
#include "core/errors.hpp"
#include "core/task_pool.hpp"

namespace rollnoise::acoustics {

namespace {

constexpr double kReferencePressure = 20e-6;  // p_0 (Pa)

// (P2) per unit power: rho c / (4 pi) [D(u) / r^2 + Q D(u') / r'^2] for a source at (x, y, z)
// and the receiver at (0, d, h).
double spreading(const Eigen::Vector3d& source, Directivity d, const PassbyGeometry& g,
                 const Fluid& fluid) {
  const Eigen::Vector3d receiver(0.0, g.distance, g.height);
  const Eigen::Vector3d direct = receiver - source;
  Eigen::Vector3d image_source = source;
  image_source.z() = 2.0 * g.ground_level - source.z();
  const Eigen::Vector3d reflected = receiver - image_source;
  const double r2 = direct.squaredNorm(), i2 = reflected.squaredNorm();
  double sum = directivity(d, direct / std::sqrt(r2)) / r2;
  if (g.reflection > 0.0) {
    // the image of a dipole along z points the other way: D = 3 (u . a)^2 is even in a
    sum += g.reflection * directivity(d, reflected / std::sqrt(i2)) / i2;
  }
  return fluid.impedance() / (4.0 * kPi) * sum;
}

// (L1)'s integral per unit power for a line centred at x = X:
//   g(X) = Int_0^inf beta e^{-2 beta s} [K(X + s) + K(X - s)] ds,  K = spreading,
// by GSL's adaptive QAGIU (relative 1e-7).
struct LineArgs {
  double X, beta;
  const Eigen::Vector3d* at;
  Directivity d;
  const PassbyGeometry* g;
  const Fluid* fluid;
};

double line_integrand(double s, void* p) {
  const LineArgs& a = *static_cast<const LineArgs*>(p);
  const double k = spreading(Eigen::Vector3d(a.X + s, a.at->y(), a.at->z()), a.d, *a.g, *a.fluid) +
                   spreading(Eigen::Vector3d(a.X - s, a.at->y(), a.at->z()), a.d, *a.g, *a.fluid);
  return a.beta * std::exp(-2.0 * a.beta * s) * k;
}

double line_spreading(double X, const Eigen::Vector3d& at, Directivity d, double beta,
                      const PassbyGeometry& g, const Fluid& fluid,
                      gsl_integration_workspace* ws, std::size_t limit) {
  LineArgs args{X, beta, &at, d, &g, &fluid};
  gsl_function F{&line_integrand, &args};
  // the scale: a monopole at the receiver's distance
  const double epsabs = 1e-10 * fluid.impedance() / (4.0 * kPi * g.distance * g.distance);
  double result = 0.0, error = 0.0;  // GSL's error handler is off (passby_history)
  const int status = gsl_integration_qagiu(&F, 0.0, epsabs, 1e-7, limit, ws, &result, &error);
  if (status != GSL_SUCCESS && !(error <= 1e-5 * std::abs(result) + 10.0 * epsabs))
    throw NumericalError(std::string("passby: the line source's integral failed (") +
                         gsl_strerror(status) + ")");
  return result;
}

// The lines of one shape (y, z, directivity, decays) share their tables g_b(X).
bool same_shape(const MovingLineSource& a, const MovingLineSource& b) {
  return a.at.y() == b.at.y() && a.at.z() == b.at.z() && a.directivity == b.directivity &&
         a.decay == b.decay;
}

void check_sources(const std::vector<MovingPointSource>& points,
                   const std::vector<MovingLineSource>& lines, std::size_t bands) {
  for (const MovingPointSource& p : points)
    if (p.power.size() != bands)
      throw std::invalid_argument("passby_history: every source needs one power per band");
  for (const MovingLineSource& l : lines) {
    if (l.power.size() != bands || l.decay.size() != bands)
      throw std::invalid_argument("passby_history: every line needs a power and a decay per band");
    for (double delta : l.decay)
      if (!(delta > 0.0) || !std::isfinite(delta))
        throw std::invalid_argument("passby_history: a decay rate must be finite and > 0 dB/m");
  }
}

// Adds the lines of one shape (lines[i] for i in `members`) to `out`: g_b tabulated at the
// spacing h over the places the members pass through, read by linear interpolation. The bands on
// `threads` threads (each band its own table and column of `out`: the same result for any number).
void add_lines(const std::vector<MovingLineSource>& lines, const std::vector<std::size_t>& members,
               const PassbyGeometry& g, double speed, double t0, double dt, int steps,
               const Fluid& fluid, int threads, Eigen::MatrixXd& out) {
  // linear interpolation's error |g''| h^2 / 8 ~ h^2 / (4 d^2) |g|: 3e-4 at d = 7 m
  constexpr double h = 0.25;  // m
  const MovingLineSource& shape = lines[members.front()];
  double lo = INFINITY, hi = -INFINITY;
  for (std::size_t i : members) {
    const double x0 = lines[i].at.x();
    lo = std::min({lo, x0 + speed * t0, x0 + speed * (t0 + (steps - 1) * dt)});
    hi = std::max({hi, x0 + speed * t0, x0 + speed * (t0 + (steps - 1) * dt)});
  }
  const int n = static_cast<int>(std::ceil((hi - lo) / h)) + 2;
  constexpr std::size_t kLimit = 1000;
  parallel_for(shape.decay.size(), threads, [&](std::size_t b, int) {
    const std::unique_ptr<gsl_integration_workspace, void (*)(gsl_integration_workspace*)> ws(
        gsl_integration_workspace_alloc(kLimit), &gsl_integration_workspace_free);
    const double beta = shape.decay[b] / (20.0 * std::log10(std::exp(1.0)));
    std::vector<double> table(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i)
      table[static_cast<std::size_t>(i)] =
          line_spreading(lo + i * h, shape.at, shape.directivity, beta, g, fluid, ws.get(), kLimit);
    for (std::size_t m : members)
      for (int k = 0; k < steps; ++k) {
        const double X = lines[m].at.x() + speed * (t0 + k * dt);
        const double t = std::clamp((X - lo) / h, 0.0, n - 1.000001);
        const int i = static_cast<int>(t);
        const double v = table[static_cast<std::size_t>(i)] +
                         (t - i) * (table[static_cast<std::size_t>(i + 1)] -
                                    table[static_cast<std::size_t>(i)]);
        out(k, static_cast<Eigen::Index>(b)) += lines[m].power[b] * v;
      }
  });
}

}  // namespace

double directivity(Directivity d, const Eigen::Vector3d& u) {
  switch (d) {
    case Directivity::kDipoleY:
      return 3.0 * u.y() * u.y();
    case Directivity::kDipoleZ:
      return 3.0 * u.z() * u.z();
    default:
      return 1.0;
  }
}

PassbyHistory passby_history(const std::vector<MovingPointSource>& points,
                             const std::vector<MovingLineSource>& lines,
                             const PassbyGeometry& geometry, double speed, double t0, double dt,
                             int steps, const Fluid& fluid, int threads) {
  if (!(speed > 0.0) || !(dt > 0.0) || steps < 1 || !std::isfinite(t0))
    throw std::invalid_argument("passby_history: needs a speed > 0, a step > 0 and steps >= 1");
  if (!(geometry.distance > 0.0) || !(geometry.height > geometry.ground_level))
    throw std::invalid_argument("passby_history: the receiver must stand off the track, above ground");
  const std::size_t bands =
      !points.empty() ? points.front().power.size() : (lines.empty() ? 0 : lines.front().power.size());
  check_sources(points, lines, bands);
  PassbyHistory out;
  for (int k = 0; k < steps; ++k) out.time.push_back(t0 + k * dt);
  out.mean_square = Eigen::MatrixXd::Zero(steps, static_cast<Eigen::Index>(bands));
  for (const MovingPointSource& p : points) {
    const Eigen::Map<const Eigen::RowVectorXd> W(p.power.data(), static_cast<Eigen::Index>(bands));
    for (int k = 0; k < steps; ++k) {
      const Eigen::Vector3d at(p.at.x() + speed * out.time[static_cast<std::size_t>(k)], p.at.y(),
                               p.at.z());
      out.mean_square.row(k) += spreading(at, p.directivity, geometry, fluid) * W;
    }
  }
  // GSL's error handler off for the lines' integrals (their status is checked), once: the
  // threads of add_lines do not touch the global handler
  gsl_error_handler_t* old = gsl_set_error_handler_off();
  std::vector<bool> done(lines.size(), false);
  for (std::size_t i = 0; i < lines.size(); ++i) {
    if (done[i]) continue;
    std::vector<std::size_t> members;
    for (std::size_t j = i; j < lines.size(); ++j)
      if (!done[j] && same_shape(lines[i], lines[j])) members.push_back(j), done[j] = true;
    try {
      add_lines(lines, members, geometry, speed, t0, dt, steps, fluid, threads, out.mean_square);
    } catch (...) {
      gsl_set_error_handler(old);
      throw;
    }
  }
  gsl_set_error_handler(old);
  return out;
}

std::vector<double> a_weighted_mean_square(const PassbyHistory& history,
                                           const std::vector<double>& band_centres) {
  if (static_cast<Eigen::Index>(band_centres.size()) != history.mean_square.cols())
    throw std::invalid_argument("a_weighted_mean_square: one centre per band");
  Eigen::VectorXd weight(static_cast<Eigen::Index>(band_centres.size()));
  for (std::size_t b = 0; b < band_centres.size(); ++b)
    weight(static_cast<Eigen::Index>(b)) = std::pow(10.0, a_weighting(band_centres[b]) / 10.0);
  const Eigen::VectorXd a = history.mean_square * weight;
  return {a.data(), a.data() + a.size()};
}

std::vector<double> time_weighted(const std::vector<double>& mean_square, double dt, double tau) {
  if (!(dt > 0.0) || !(tau > 0.0))
    throw std::invalid_argument("time_weighted: needs a step and a time constant > 0");
  // y_k = y_{k-1} e^{-dt/tau} + (1 - e^{-dt/tau}) x_k: (E3) with x held over (t_{k-1}, t_k]
  const double decay = std::exp(-dt / tau);
  std::vector<double> out;
  double y = 0.0;
  for (double x : mean_square) out.push_back(y = decay * y + (1.0 - decay) * x);
  return out;
}

double pressure_level(double mean_square) {
  return 10.0 * std::log10(mean_square / (kReferencePressure * kReferencePressure));
}

double equivalent_level(const std::vector<double>& time, const std::vector<double>& mean_square,
                        double t1, double t2, double over) {
  if (time.size() != mean_square.size() || time.size() < 2 || !(t2 > t1))
    throw std::invalid_argument("equivalent_level: needs a grid of >= 2 steps and t2 > t1");
  const double dt = time[1] - time[0];
  double sum = 0.0;
  for (std::size_t k = 0; k < time.size(); ++k)
    if (time[k] >= t1 && time[k] < t2) sum += mean_square[k] * dt;
  return pressure_level(sum / (over > 0.0 ? over : t2 - t1));
}

}  // namespace rollnoise::acoustics
