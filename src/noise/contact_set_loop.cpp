#include "noise/contact_set_loop.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "core/assert.hpp"
#include "core/errors.hpp"
#include "core/task_pool.hpp"
#include "dynamics/rail_model.hpp"

namespace rollnoise::noise {

ContactSetStructures contact_set_structures(const dynamics::WheelModel& wheel,
                                            const dynamics::RailModel& rail,
                                            const std::vector<ContactPoint>& contacts,
                                            const std::vector<double>& frequencies,
                                            const CrossCoupling& cross, int threads) {
  ContactSetStructures s;
  s.frequency = frequencies;
  s.contacts = contacts;
  s.cross = cross;
  for (double f : frequencies)
    if (!(f > 0.0) || !std::isfinite(f))
      throw InputError("frequency", "the noise loop needs positive frequencies");
  validate_contacts(contacts);
  const ContactModeTables tables = contact_mode_tables(wheel, contacts);  // once, not per frequency
  // the rail between the contact points on the whole grid at once (RailModel::contact_transfers)
  const std::vector<std::vector<Receptance6>> rail_pairs =
      rail.contact_transfers(frequencies, contact_set_rail_pairs(contacts, cross).points);
  s.receptance.resize(frequencies.size());
  for_slices(frequencies.size(), threads, [&](std::size_t, std::size_t lo, std::size_t hi) {
    for (std::size_t k = lo; k < hi; ++k)
      s.receptance[k] = contact_set_receptance(wheel, rail_pairs[k], contacts, tables, frequencies[k], cross);
  });
  return s;
}

Eigen::MatrixXd independent_sources(const std::vector<bool>& excited) {
  const Eigen::Index n = static_cast<Eigen::Index>(excited.size());
  Eigen::Index e = 0;
  for (bool x : excited) e += x ? 1 : 0;
  Eigen::MatrixXd rho = Eigen::MatrixXd::Zero(n, e);
  e = 0;
  for (Eigen::Index a = 0; a < n; ++a)
    if (excited[a]) rho(a, e++) = 1.0;
  return rho;
}

namespace {
std::string singular_message(const Eigen::MatrixXcd& A) {
  std::ostringstream s;
  s << "noise loop with several contacts: the total receptance matrix is singular or not finite:\n" << A;
  return s.str();
}
}  // namespace

Eigen::MatrixXcd solve_contact_set_forces(const Eigen::MatrixXcd& A, const Eigen::MatrixXd& rho) {
  const Eigen::Index m = A.rows();
  if (A.cols() != m || m != 4 * rho.rows())
    throw InputError("sources",
                     "noise loop: one roughness amplitude per contact and source is needed");
  // Diagonal equilibration D A D, D_i = |A_ii|^{-1/2} (as loop.cpp), then LU with partial
  // pivoting (after the equilibration the pivots need no column search: FullPivLU's search took
  // a complex modulus, a hypot, per entry and step, 5 % of a four-wheel run); singular where the
  // reciprocal condition estimate is below round-off.
  Eigen::VectorXd d(m);
  for (Eigen::Index i = 0; i < m; ++i) {
    const double v = std::abs(A(i, i));
    d(i) = v > 0.0 && std::isfinite(v) ? 1.0 / std::sqrt(v) : 1.0;
  }
  const Eigen::MatrixXcd D = d.cast<cdouble>().asDiagonal();
  const Eigen::MatrixXcd As = D * A * D;
  Eigen::MatrixXcd rhs = Eigen::MatrixXcd::Zero(m, rho.cols());
  for (Eigen::Index a = 0; a < rho.rows(); ++a)
    rhs.row(4 * a) = -d(4 * a) * rho.row(a).cast<cdouble>();
  if (!As.allFinite()) throw NumericalError(singular_message(A));
  const Eigen::PartialPivLU<Eigen::MatrixXcd> lu(As);
  if (!(lu.rcond() > std::numeric_limits<double>::epsilon() * double(m))) {
    throw NumericalError(singular_message(A));
  }
  return D * lu.solve(rhs);
}

ContactSetLoopResult solve_contact_set_loop(const ContactSetStructures& s,
                                            const std::vector<std::vector<Receptance4>>& contact,
                                            const Eigen::MatrixXd& rho, bool velocities, int threads) {
  const std::size_t n = s.contacts.size(), nf = s.frequency.size();
  if (contact.size() != n)
    throw InputError("contacts", "noise loop: one contact receptance series per contact is needed");
  for (const auto& c : contact)
    if (c.size() != nf)
      throw InputError("frequency", "noise loop: one contact receptance per frequency is needed");
  if (static_cast<std::size_t>(rho.rows()) != n)
    throw InputError("sources",
                     "noise loop: one roughness amplitude per contact and source is needed");
  ContactSetLoopResult r;
  r.frequency = s.frequency;
  r.rho = rho;
  r.force.resize(nf);
  if (velocities) r.wheel_velocity.resize(nf), r.rail_velocity.resize(nf);
  for_slices(nf, threads, [&](std::size_t, std::size_t lo, std::size_t hi) {
    for (std::size_t k = lo; k < hi; ++k) {
      const ContactSetReceptance& rec = s.receptance[k];
      Eigen::MatrixXcd A = rec.wheel + rec.rail;  // (M3)
      for (std::size_t a = 0; a < n; ++a) A.block<4, 4>(4 * a, 4 * a) += contact[a][k];
      const Eigen::MatrixXcd F = solve_contact_set_forces(A, rho);
      r.force[k] = F;
      if (!velocities) continue;
      const cdouble iw(0.0, dynamics::angular(s.frequency[k]));
      const Eigen::MatrixXcd vw = iw * (rec.wheel6 * F), vr = -iw * (rec.rail6 * F);  // 6N x E
      Eigen::MatrixXcd w4(4 * n, F.cols()), r4(4 * n, F.cols());
      for (std::size_t a = 0; a < n; ++a)
        for (int i = 0; i < 4; ++i) {
          w4.row(4 * a + i) = vw.row(6 * a + kSixOfFour[i]);
          r4.row(4 * a + i) = vr.row(6 * a + kSixOfFour[i]);
        }
      r.wheel_velocity[k] = std::move(w4);
      r.rail_velocity[k] = std::move(r4);
    }
  });
  return r;
}

LoopResult contact_response(const ContactSetLoopResult& result, int a, int e) {
  if (a < 0 || a >= result.contacts() || e < 0 || e >= result.sources())
    throw InputError("contacts", "no such contact or source in the loop's result");
  LoopResult r;
  r.frequency = result.frequency;
  for (std::size_t k = 0; k < result.frequency.size(); ++k) {
    r.force.push_back(result.force[k].block(4 * a, e, 4, 1));
    if (result.wheel_velocity.empty()) continue;
    r.wheel_velocity.push_back(result.wheel_velocity[k].block(4 * a, e, 4, 1));
    r.rail_velocity.push_back(result.rail_velocity[k].block(4 * a, e, 4, 1));
  }
  return r;
}

namespace {
double power_add(double level_sum, double level) {  // 10 log10(10^(a/10) + 10^(b/10)), -inf as 0
  if (!std::isfinite(level_sum)) return level;
  if (!std::isfinite(level)) return level_sum;
  const double hi = std::max(level_sum, level), lo = std::min(level_sum, level);
  return hi + 10.0 * std::log10(1.0 + std::pow(10.0, (lo - hi) / 10.0));
}
}  // namespace

BandLevels contact_band_levels(const ContactSetLoopResult& result, int a,
                               const std::vector<double>& centres,
                               const std::vector<std::vector<double>>& roughness_levels) {
  ROLLNOISE_ASSERT(static_cast<int>(roughness_levels.size()) == result.sources(),
                   "one roughness level spectrum per source");
  BandLevels sum;
  const double minus_inf = -std::numeric_limits<double>::infinity();
  for (int e = 0; e < result.sources(); ++e) {
    BandLevels b = band_levels(contact_response(result, a, e), centres, roughness_levels[e]);
    if (e == 0) {  // shape and -inf everywhere
      sum = b;
      for (auto& l : sum.roughness_level) l = minus_inf;
      for (auto& l : sum.force_level) l.fill(minus_inf);
      for (auto& v : sum.velocity_level)
        for (auto& l : v) l.fill(minus_inf);
    }
    // (M4); the roughness of the sources that drive contact a directly
    for (std::size_t j = 0; j < b.centre.size(); ++j) {
      const double rho = std::abs(result.rho(a, e));
      if (rho != 0.0)
        sum.roughness_level[j] =
            power_add(sum.roughness_level[j], b.roughness_level[j] + 20.0 * std::log10(rho));
      for (int i = 0; i < 4; ++i)
        sum.force_level[j][i] = power_add(sum.force_level[j][i], b.force_level[j][i]);
      if (j < b.velocity_level.size())
        for (int p = 0; p < 2; ++p)
          for (int i = 0; i < 4; ++i)
            sum.velocity_level[j][p][i] =
                power_add(sum.velocity_level[j][p][i], b.velocity_level[j][p][i]);
    }
  }
  return sum;
}

}  // namespace rollnoise::noise
