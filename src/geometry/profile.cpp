#include "geometry/profile.hpp"

#include <gsl/gsl_interp.h>

#include <algorithm>
#include <cmath>

#include "core/errors.hpp"
#include "geometry/parabola_fit.hpp"

namespace rollnoise::geometry {

const char* to_string(ProfileKind kind) {
  return kind == ProfileKind::Rail ? "rail" : "wheel";
}

// ---------------------------------------------------------------------------------------------
// The spline: GSL's Steffen interpolation. gsl_interp_eval* is called only inside [y_min, y_max]
// (GSL's error handler would abort otherwise) and without an accelerator (thread safe).
// The Steffen state holds only the knot slopes, which depend on the values of y_ and z_ alone; the
// arrays are passed at each evaluation, so copies of a Profile share the state.
struct Profile::Spline {
  gsl_interp* interp = nullptr;
  ~Spline() { gsl_interp_free(interp); }
};

Profile::Profile(std::vector<double> y, std::vector<double> z, ProfileKind kind, std::string source,
                 bool canted)
    : y_(std::move(y)), z_(std::move(z)), kind_(kind), source_(std::move(source)), canted_(canted) {
  const std::string key = source_.empty() ? "profile" : source_;
  if (y_.size() != z_.size())
    throw InputError(key, key + ": y and z have different numbers of points");
  if (static_cast<int>(y_.size()) < min_points)
    throw InputError(key, key + ": " + std::to_string(y_.size()) + " profile points, at least " +
                              std::to_string(min_points) + " are needed");
  for (std::size_t i = 0; i < y_.size(); ++i) {
    if (!std::isfinite(y_[i]) || !std::isfinite(z_[i]))
      throw InputError(key, key + ": point " + std::to_string(i + 1) + " is not finite");
    if (i > 0 && !(y_[i] > y_[i - 1]))
      throw InputError(key, key + ": point " + std::to_string(i + 1) +
                                ": y is not strictly increasing (a profile must be a function "
                                "z(y) with sorted, distinct y)");
  }
  auto s = std::make_shared<Spline>();
  s->interp = gsl_interp_alloc(gsl_interp_steffen, y_.size());
  gsl_interp_init(s->interp, y_.data(), z_.data(), y_.size());
  spline_ = std::move(s);
}

double Profile::z(double y) const {
  if (y < y_.front()) return z_.front() + slope(y_.front()) * (y - y_.front());
  if (y > y_.back()) return z_.back() + slope(y_.back()) * (y - y_.back());
  return gsl_interp_eval(spline_->interp, y_.data(), z_.data(), y, nullptr);
}

double Profile::z(double y, Cursor& cursor) const {
  if (y < y_.front() || y > y_.back()) return z(y);
  // GSL's accelerator holds the interval index only (gsl_interp_accel_find: the cached interval if
  // it contains y, else the binary search), so a stack copy per call keeps the cursor ours.
  gsl_interp_accel acc{cursor.interval, 0, 0};
  const double v = gsl_interp_eval(spline_->interp, y_.data(), z_.data(), y, &acc);
  cursor.interval = acc.cache;
  return v;
}

double Profile::slope(double y) const {
  y = std::clamp(y, y_.front(), y_.back());
  return gsl_interp_eval_deriv(spline_->interp, y_.data(), z_.data(), y, nullptr);
}

double Profile::second_derivative(double y) const {
  if (!contains(y)) return 0.0;
  return gsl_interp_eval_deriv2(spline_->interp, y_.data(), z_.data(), y, nullptr);
}

double Profile::smoothed_second_derivative(double y, double half_window) const {
  // z'' = 2 c2 of the least-squares parabola through 41 samples in [y - w, y + w]
  return 2.0 * quadratic_coefficient([&](double t) { return z(y + t); }, std::max(half_window, 1e-9));
}

double Profile::curvature(double y, double half_window) const {
  const double s = slope(y);
  return smoothed_second_derivative(y, half_window) / std::pow(1.0 + s * s, 1.5);
}

Profile Profile::rotated(double angle) const {
  // Rotate each point, then keep the points that still increase in y (a vertical flank that
  // folds over under the rotation is hidden from above and cannot carry a wheel-rail contact).
  const double c = std::cos(angle), s = std::sin(angle);
  std::vector<double> yr, zr;
  for (std::size_t i = 0; i < y_.size(); ++i) {
    const double yy = c * y_[i] - s * z_[i];
    const double zz = s * y_[i] + c * z_[i];
    if (!yr.empty() && !(yy > yr.back())) continue;
    yr.push_back(yy);
    zr.push_back(zz);
  }
  return Profile(std::move(yr), std::move(zr), kind_, source_, true);
}

}  // namespace rollnoise::geometry
