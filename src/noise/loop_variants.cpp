#include "noise/loop_variants.hpp"

#include <cmath>

#include "core/assert.hpp"
#include "core/errors.hpp"

namespace rollnoise::noise {
namespace {

// alpha_c of one contact per frequency; g = 0 when `coupling` is off or the contact has none.
std::vector<Receptance4> receptances(const std::vector<double>& frequency,
                                     const LoopVariantsInput& in, const ContactCoefficients& c,
                                     bool coupling) {
  ROLLNOISE_ASSERT(
      c.creep.size() == frequency.size() && (c.load.empty() || c.load.size() == frequency.size()),
      "noise loop: one creep matrix (and load vector) per frequency is needed");
  if (coupling && !c.load.empty())
    return contact_receptances(frequency, in.normal_stiffness, in.speed, c.creep, c.load);
  return contact_receptances(frequency, in.normal_stiffness, in.speed, c.creep);
}

}  // namespace

ContactCoefficients constant_coefficients(const Eigen::Matrix3cd& creep,
                                          const LoadCoefficients& load, std::size_t n) {
  return {std::vector<Eigen::Matrix3cd>(n, creep), std::vector<LoadCoefficients>(n, load)};
}

ContactCoefficients quasi_steady_coefficients(const Eigen::Matrix3cd& f0,
                                              const LoadCoefficients& g0, std::size_t n) {
  if (f0.imag().norm() > 1e-8 * f0.norm() || g0.imag().norm() > 1e-8 * g0.norm())
    throw NumericalError("quasi-steady contact: f(0) or g(0) is not real");
  return constant_coefficients(f0.real().cast<cdouble>(), g0.real().cast<cdouble>(), n);
}

ContactVariants contact_variants(const std::vector<double>& frequency,
                                 const LoopVariantsInput& in) {
  ContactVariants v;
  v.main = receptances(frequency, in, in.model, in.normal_coupling);
  if (in.normal_coupling && !in.model.load.empty())
    v.uncoupled = receptances(frequency, in, in.model, false);
  if (!in.baseline.empty())
    v.baseline = receptances(frequency, in, in.baseline, in.normal_coupling);
  return v;
}

LoopVariants solve_loop_variants(const ContactSetStructures& s,
                                 const std::vector<ContactVariants>& contacts,
                                 const Eigen::MatrixXd& sources, int threads) {
  // One variant's alpha_c of every contact; empty unless every contact has it.
  auto variant = [&](std::vector<Receptance4> ContactVariants::*which) {
    std::vector<std::vector<Receptance4>> alpha;
    for (const ContactVariants& c : contacts) {
      if ((c.*which).empty()) return std::vector<std::vector<Receptance4>>{};
      alpha.push_back(c.*which);
    }
    return alpha;
  };
  LoopVariants v;
  v.main = solve_contact_set_loop(s, variant(&ContactVariants::main), sources, true, threads);
  if (auto u = variant(&ContactVariants::uncoupled); !u.empty())
    v.uncoupled = solve_contact_set_loop(s, u, sources, true, threads);
  if (auto b = variant(&ContactVariants::baseline); !b.empty())
    v.baseline = solve_contact_set_loop(s, b, sources, true, threads);
  return v;
}

std::vector<std::array<double, 4>> force_level_difference(const BandLevels& a,
                                                          const BandLevels& b) {
  ROLLNOISE_ASSERT(a.centre == b.centre, "level difference of different bands");
  std::vector<std::array<double, 4>> d(a.centre.size());
  for (std::size_t i = 0; i < d.size(); ++i)
    for (int j = 0; j < 4; ++j) d[i][j] = a.force_level[i][j] - b.force_level[i][j];
  return d;
}

}  // namespace rollnoise::noise
