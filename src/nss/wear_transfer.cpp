#include "nss/wear_transfer.hpp"

#include <algorithm>
#include <cmath>
#include <functional>

#include "contact/halfspace_operator.hpp"
#include "contact/normal_solver.hpp"
#include "core/assert.hpp"
#include "core/constants.hpp"

namespace rollnoise::nss {

double WearLaw::depth_per_energy(double mu) const {
  // (W2): frictional work K = k_w; Archard K = k / (mu H) (header)
  return kind == Kind::frictional_work ? coefficient : coefficient / (mu * hardness);
}

namespace {

// (W1) per element and (W4)'s gathering along the rail for the element fields of `run` (c input
// columns): Y_m = sum_{j + i_a = m} D~_{j,a}, D_j = sum_a D~_{j,a} (W/m^2 per unit input), and the
// geometry of (W3)-(W4).
struct Gathered {
  std::vector<Eigen::RowVectorXd> Y, D;
  double x0 = 0.0, band_width = 0.0;
};

Gathered gather(const LinearContactModel& model, const contact::TangentialSolution& steady,
                int columns,
                const std::function<void(const LinearContactModel::FieldVisitor&)>& run) {
  const contact::Grid& g = model.grid();
  const std::vector<int>& el = model.elements();
  int ix_min = g.nx, iy_min = g.ny, iy_max = -1;
  for (int k : el)
    ix_min = std::min(ix_min, k % g.nx), iy_min = std::min(iy_min, k / g.nx),
    iy_max = std::max(iy_max, k / g.nx);
  Gathered out;
  out.x0 = g.x(ix_min);
  out.band_width = (iy_max - iy_min + 1) * g.dy;
  // The slip elements (the only ones that wear to first order, header), their column offset i_a.
  std::vector<int> slip, column;
  for (int a = 0; a < static_cast<int>(el.size()); ++a)
    if (model.slip_element(a)) slip.push_back(a), column.push_back(el[a] % g.nx - ix_min);
  const int width = g.nx - ix_min;
  const Eigen::RowVectorXd zero = Eigen::RowVectorXd::Zero(columns);
  run([&](int j, const Eigen::MatrixXd& P, const Eigen::MatrixXd& S) {
    if (static_cast<int>(out.Y.size()) < j + width) out.Y.resize(j + width, zero);
    Eigen::RowVectorXd total = zero;
    for (std::size_t i = 0; i < slip.size(); ++i) {
      const int a = slip[i], k = el[a];
      // (W1): D~ = -(s_bar . p~ + p_bar . s~)
      const Eigen::RowVectorXd d = -(steady.sx[k] * P.row(2 * a) + steady.sy[k] * P.row(2 * a + 1) +
                                     steady.px[k] * S.row(2 * a) + steady.py[k] * S.row(2 * a + 1));
      out.Y[j + column[i]] += d;
      total += d;
    }
    out.D.push_back(total);
  });
  return out;
}

// sum_m z^m y_m at z = e^{-i w dt} (Horner)
Eigen::RowVectorXcd power_series(const std::vector<Eigen::RowVectorXd>& y, double w, double dt) {
  const std::complex<double> z = std::polar(1.0, -w * dt);
  Eigen::RowVectorXcd s = Eigen::RowVectorXcd::Zero(y.empty() ? 0 : y.front().size());
  for (auto it = y.rbegin(); it != y.rend(); ++it) s = s * z + it->cast<std::complex<double>>();
  return s;
}

std::vector<Eigen::RowVector4d> fixed4(const std::vector<Eigen::RowVectorXd>& y) {
  std::vector<Eigen::RowVector4d> out(y.size());
  for (std::size_t i = 0; i < y.size(); ++i) out[i] = y[i];
  return out;
}

}  // namespace

WearTransfer::WearTransfer(const LinearContactModel& model,
                           const contact::TangentialSolution& steady, double speed, double mu,
                           const WearLaw& law)
    : dt_(model.time_step()),
      speed_(speed),
      area_(model.grid().element_area()),
      K_(law.depth_per_energy(mu)),
      sampling_(model.sampling()) {
  const Gathered gathered =
      gather(model, steady, 4,
             [&](const LinearContactModel::FieldVisitor& v) { model.element_impulse_response(v); });
  Y_ = fixed4(gathered.Y);
  D_ = fixed4(gathered.D);
  x0_ = gathered.x0;
  band_width_ = gathered.band_width;
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

namespace {

// U of the header: an orthonormal basis of the column weights' span for 0 <= k <= k_max, from the
// vectors 1, cos(k_j x), sin(k_j x) at k_j = j k_max / J, J = 4 (k_max L / pi + 10) (several
// samples per unit of the band's rank), to 1e-10 of the largest singular value.
Eigen::MatrixXd weight_basis(const std::vector<double>& x, double k_max) {
  const int c = static_cast<int>(x.size());
  const double L = x.back() - x.front();
  const int J = static_cast<int>(std::ceil(4.0 * (k_max * L / kPi + 10.0)));
  Eigen::MatrixXd E(c, 2 * J + 1);
  for (int i = 0; i < c; ++i) {
    E(i, 0) = 1.0;
    for (int j = 1; j <= J; ++j) {
      const double kx = k_max * j / J * x[i];
      E(i, 2 * j - 1) = std::cos(kx), E(i, 2 * j) = std::sin(kx);
    }
  }
  const Eigen::BDCSVD<Eigen::MatrixXd> svd(E, Eigen::ComputeThinU);
  const Eigen::VectorXd& sigma = svd.singularValues();
  int rank = 0;
  while (rank < sigma.size() && sigma(rank) > 1e-10 * sigma(0)) ++rank;
  return svd.matrixU().leftCols(rank);
}

}  // namespace

RoughnessWearTransfer::RoughnessWearTransfer(const contact::ContactPatch& patch,
                                             const LinearContactModel& model,
                                             const contact::TangentialSolution& steady,
                                             double speed, double mu, const WearLaw& law,
                                             double k_max)
    : dt_(model.time_step()), speed_(speed), k_max_(k_max) {
  // The columns i of the frozen area C, and their weights dx dy 1' v_i, v_i = A_CC^{-1} 1_(column
  // i) (W7): A_CC is symmetric, so 1' v_i = 1_(column i)' A_CC^{-1} 1, one solve for all columns.
  const contact::Grid& g = patch.grid;
  const contact::HalfSpaceOperator op(patch.influence, contact::Problem::Normal);
  std::vector<int> column_of(g.nx, -1);
  for (int ix = 0; ix < g.nx; ++ix)
    for (int iy = 0; iy < g.ny; ++iy)
      if (patch.normal.pn[g.index(ix, iy)] > 0.0 && column_of[ix] < 0) {
        column_of[ix] = static_cast<int>(x_.size());
        x_.push_back(g.x(ix));
      }
  const contact::GridField ones(g.size(), 1.0);
  const contact::GridField w = contact::frozen_area_solve(g, op, patch.normal, ones).x;
  weight_.assign(x_.size(), 0.0);
  for (int e = 0; e < g.size(); ++e)
    if (patch.normal.pn[e] > 0.0) weight_[column_of[e % g.nx]] += g.element_area() * w[e];
  // the patterns v~_l = sum_i U_il v_i = A_CC^{-1} sum_i U_il 1_(column i) (header): one solve each
  basis_ = weight_basis(x_, k_max);
  std::vector<contact::GridField> patterns;
  for (Eigen::Index l = 0; l < basis_.cols(); ++l) {
    contact::GridField load(g.size(), 0.0);
    for (int e = 0; e < g.size(); ++e)
      if (patch.normal.pn[e] > 0.0) load[e] = basis_(column_of[e % g.nx], l);
    patterns.push_back(contact::frozen_area_solve(g, op, patch.normal, load).x);
  }
  const Gathered gathered = gather(model, steady, static_cast<int>(patterns.size()),
                                   [&](const LinearContactModel::FieldVisitor& f) {
                                     model.element_pressure_response(patterns, f);
                                   });
  Y_ = gathered.Y;
  x0_ = gathered.x0;
  scale_ = law.depth_per_energy(mu) * g.element_area() / (gathered.band_width * speed);
}

std::vector<std::complex<double>> RoughnessWearTransfer::depth(
    const std::vector<double>& wavenumbers) const {
  std::vector<std::complex<double>> out;
  out.reserve(wavenumbers.size());
  double stiffness = 0.0;  // k_N = dx dy 1' A_CC^{-1} 1 = sum_i dx dy 1' v_i (N1)
  for (double s : weight_) stiffness += s;
  const Eigen::Index c = static_cast<Eigen::Index>(x_.size());
  for (double k : wavenumbers) {
    ROLLNOISE_ASSERT(k >= 0.0 && k <= k_max_ * (1.0 + 1e-12),
                     "RoughnessWearTransfer::depth: a wavenumber beyond the basis's k_max");
    // (W6) by columns: H = sum_i dx dy 1' v_i e^{ik x_i} / k_N
    std::complex<double> H = 0.0;
    for (Eigen::Index i = 0; i < c; ++i) H += weight_[i] * std::polar(1.0, k * x_[i]);
    H /= stiffness;
    // (W8) on the patterns: T_r = sum_l (U' w)_l T~_l, w_i = H - e^{ik x_i}
    Eigen::VectorXcd w(c);
    for (Eigen::Index i = 0; i < c; ++i) w(i) = H - std::polar(1.0, k * x_[i]);
    const Eigen::VectorXcd a = basis_.transpose().cast<std::complex<double>>() * w;
    const Eigen::RowVectorXcd Tl =
        power_series(Y_, k * speed_, dt_) * (scale_ * std::polar(1.0, -k * x0_));
    out.push_back(Tl * a);
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
