#include "nss/validation.hpp"

#include <algorithm>
#include <limits>

#include <cmath>

#include "linalg/multisine_fit.hpp"

namespace rollnoise::nss {

std::size_t analysed_samples(const std::vector<double>& time, double t_start) {
  std::size_t n = 0;
  for (double t : time)
    if (t >= t_start) ++n;
  return n;
}

ValidationErrors compare_linear_unsteady(const std::vector<double>& time,
                                         const std::vector<Eigen::Vector3d>& unsteady,
                                         const std::vector<Eigen::Vector3d>& linear, double t_start,
                                         const std::vector<double>& frequencies, double dt) {
  ValidationErrors v;
  std::array<std::vector<double>, 3> qu, ql;  // the analysed window per component
  Eigen::Vector3d sq_err = Eigen::Vector3d::Zero(), sq_var = Eigen::Vector3d::Zero(),
                  mean_u = Eigen::Vector3d::Zero();
  for (size_t k = 0; k < time.size(); ++k)
    if (time[k] >= t_start) {
      v.time.push_back(time[k]);
      for (int j = 0; j < 3; ++j) qu[j].push_back(unsteady[k](j)), ql[j].push_back(linear[k](j));
      mean_u += unsteady[k];
    }
  const std::vector<double>& ta = v.time;
  mean_u /= double(ta.size());
  for (size_t i = 0; i < ta.size(); ++i)
    for (int j = 0; j < 3; ++j) {
      sq_err(j) += std::pow(qu[j][i] - ql[j][i], 2);
      sq_var(j) += std::pow(qu[j][i] - mean_u(j), 2);
    }
  // excited components: RMS variation above 1e-9 of the force scale (header)
  const double n_samples = double(ta.size());
  const double scale = std::max({std::abs(mean_u(0)), std::abs(mean_u(1)), std::sqrt(sq_var(0) / n_samples),
                                 std::sqrt(sq_var(1) / n_samples)});
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (int j = 0; j < 3; ++j) {
    v.excited[j] = std::sqrt(sq_var(j) / n_samples) > 1e-9 * scale;
    v.rms_relative(j) = v.excited[j] ? std::sqrt(sq_err(j) / sq_var(j)) : nan;
  }

  for (int j = 0; j < 3; ++j) {
    v.unsteady_spectrum[j] = amplitude_spectrum(qu[j], dt);
    v.linear_spectrum[j] = amplitude_spectrum(ql[j], dt);
  }

  const auto& fr = frequencies;
  if (!fr.empty() && ta.size() > 2 * fr.size() + 1) {
    // several frequencies: the record must resolve their spacing; one: cover at least one period
    const double spacing = fr.size() > 1 ? fr[1] - fr[0] : fr[0];
    if ((ta.back() - ta.front()) * spacing >= 1.0) {
      for (int j = 0; j < 3; ++j) {
        const auto au = linalg::fit_multisine(ta, qu[j], fr), al = linalg::fit_multisine(ta, ql[j], fr);
        for (size_t k = 0; k < fr.size(); ++k) {
          const bool meaningful = v.excited[j] && std::abs(au[k]) > 0;
          v.amplitude_error.push_back(meaningful ? std::abs(al[k]) / std::abs(au[k]) - 1 : nan);
          v.phase_error.push_back(meaningful ? std::remainder(std::arg(al[k]) - std::arg(au[k]), 2 * M_PI) * 180 / M_PI
                                             : nan);
        }
      }
      v.fitted = true;
    }
  }
  return v;
}

}  // namespace rollnoise::nss
