#include "nss/wear_transfer.hpp"

#include <algorithm>
#include <cmath>

#include "core/constants.hpp"

namespace rollnoise::nss {

double WearLaw::depth_per_energy(double mu) const {
  // (W2): frictional work K = k_w; Archard K = k / (mu H) (header)
  return kind == Kind::frictional_work ? coefficient : coefficient / (mu * hardness);
}

WearTransfer::WearTransfer(const LinearContactModel& model,
                           const contact::TangentialSolution& steady, double speed, double mu,
                           const WearLaw& law)
    : dt_(model.time_step()),
      speed_(speed),
      K_(law.depth_per_energy(mu)),
      sampling_(model.sampling()) {
  const contact::Grid& g = model.grid();
  const std::vector<int>& el = model.elements();
  area_ = g.element_area();
  int ix_min = g.nx, iy_min = g.ny, iy_max = -1;
  for (int k : el)
    ix_min = std::min(ix_min, k % g.nx), iy_min = std::min(iy_min, k / g.nx),
    iy_max = std::max(iy_max, k / g.nx);
  x0_ = g.x(ix_min);
  band_width_ = (iy_max - iy_min + 1) * g.dy;
  // The slip elements (the only ones that wear to first order, header), their column offset i_a.
  std::vector<int> slip, column;
  for (int a = 0; a < static_cast<int>(el.size()); ++a)
    if (model.slip_element(a)) slip.push_back(a), column.push_back(el[a] % g.nx - ix_min);
  const int width = g.nx - ix_min;
  model.element_impulse_response([&](int j, const Eigen::MatrixXd& P, const Eigen::MatrixXd& S) {
    if (static_cast<int>(Y_.size()) < j + width) Y_.resize(j + width, Eigen::RowVector4d::Zero());
    Eigen::RowVector4d total = Eigen::RowVector4d::Zero();
    for (std::size_t i = 0; i < slip.size(); ++i) {
      const int a = slip[i], k = el[a];
      // (W1): D~ = -(s_bar . p~ + p_bar . s~)
      const Eigen::RowVector4d d = -(steady.sx[k] * P.row(2 * a) + steady.sy[k] * P.row(2 * a + 1) +
                                     steady.px[k] * S.row(2 * a) + steady.py[k] * S.row(2 * a + 1));
      Y_[j + column[i]] += d;
      total += d;
    }
    D_.push_back(total);
  });
}

std::vector<WearRow> WearTransfer::series_sum(const std::vector<Eigen::RowVector4d>& y,
                                              const std::vector<double>& frequencies,
                                              bool rail_fixed) const {
  std::vector<WearRow> out;
  out.reserve(frequencies.size());
  const double scale = rail_fixed ? K_ * area_ / (band_width_ * speed_) : area_;
  for (double f : frequencies) {
    const double w = 2.0 * kPi * f;
    const std::complex<double> z = std::polar(1.0, -w * dt_);
    WearRow s = WearRow::Zero();
    for (auto it = y.rbegin(); it != y.rend(); ++it)
      s = s * z + it->cast<std::complex<double>>();  // Horner
    const std::complex<double> sampling = creepage_sampling_factor({0.0, w * dt_}, sampling_);
    s.head<3>() *= sampling;
    s *= scale;
    if (rail_fixed) s *= std::polar(1.0, -w / speed_ * x0_);  // e^{-ik x_0} of (W4)
    out.push_back(s);
  }
  return out;
}

std::vector<WearRow> WearTransfer::depth(const std::vector<double>& frequencies) const {
  return series_sum(Y_, frequencies, true);
}

std::vector<WearRow> WearTransfer::power(const std::vector<double>& frequencies) const {
  return series_sum(D_, frequencies, false);
}

}  // namespace rollnoise::nss
