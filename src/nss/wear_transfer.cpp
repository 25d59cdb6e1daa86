#include "nss/wear_transfer.hpp"

#include <algorithm>
#include <cmath>

#include "contact/halfspace_operator.hpp"
#include "contact/normal_solver.hpp"
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

std::vector<std::complex<double>> rail_roughness_filter(const contact::ContactPatch& patch,
                                                        const std::vector<double>& wavenumbers) {
  const contact::Grid& g = patch.grid;
  const contact::HalfSpaceOperator op(patch.influence, contact::Problem::Normal);
  const contact::NormalLoadSensitivity s = contact::normal_load_sensitivity(g, op, patch.normal);
  std::vector<std::complex<double>> H(wavenumbers.size(), 0.0);
  for (int e = 0; e < g.size(); ++e) {
    if (s.dpn_dN[e] == 0.0) continue;
    const double w = s.dpn_dN[e] * g.element_area(), x = g.x(e % g.nx);
    for (std::size_t i = 0; i < wavenumbers.size(); ++i)
      H[i] += w * std::polar(1.0, wavenumbers[i] * x);  // (W6)
  }
  return H;
}

std::vector<WearRow> WearTransfer::depth(const std::vector<double>& frequencies) const {
  return series_sum(Y_, frequencies, true);
}

std::vector<WearRow> WearTransfer::power(const std::vector<double>& frequencies) const {
  return series_sum(D_, frequencies, false);
}

}  // namespace rollnoise::nss
