// Steady rolling against CONTACT's results (tests/data/contact, S1-S5, both grids), Kalker's linear
// theory in the full-adhesion limit, full sliding, and robustness over the creepage range.
#include <gtest/gtest.h>

#include <array>
#include <cmath>

#include <map>
#include <memory>

#include "contact/forces.hpp"
#include "contact/hertz.hpp"
#include "contact/patch.hpp"
#include "contact/steady_rolling.hpp"
#include "paper_case.hpp"
#include "reference_data.hpp"

using namespace rollnoise::contact;
using rollnoise::testing::data_path;
using rollnoise::testing::num;
using rollnoise::testing::read_csv;
using namespace rollnoise::testing;

namespace {

struct ContactCase {
  std::string folder, grid;
  int case_number;
};

std::ostream& operator<<(std::ostream& os, const ContactCase& c) {
  return os << c.folder << "/" << c.grid << "/case" << c.case_number;
}

std::vector<ContactCase> all_reference_cases() {
  std::vector<ContactCase> out;
  for (std::string folder : {"S1", "S2", "S2facphi0", "S3", "S4", "S5"})
    for (const auto& row : read_csv(data_path("contact/" + folder + "/forces.csv")))
      out.push_back({folder, row.at("grid"), std::stoi(row.at("case"))});
  return out;
}

class AgainstCONTACT : public ::testing::TestWithParam<ContactCase> {};

}  // namespace

TEST_P(AgainstCONTACT, ForcesAndAdhesionSlipAreas) {
  const ContactCase& c = GetParam();
  std::map<std::string, std::string> ref;
  for (const auto& row : read_csv(data_path("contact/" + c.folder + "/forces.csv")))
    if (row.at("grid") == c.grid && std::stoi(row.at("case")) == c.case_number) ref = row;
  ASSERT_FALSE(ref.empty());
  const ContactPatch& patch = paper_patch(c.grid);
  const Grid& g = patch.grid;
  ASSERT_EQ(patch.normal.contact_elements(), std::stoi(ref.at("n_contact")));

  SteadyRollingInput in;
  in.mu = kMu;
  in.speed = kSpeed;
  in.creepage = {num(ref, "cksi"), num(ref, "ceta"), num(ref, "cphi_rad_per_m")};
  in.spin_offset = c.folder == "S2facphi0" ? 0.0 : 1.0 / 6.0;  // CONTACT's default FACPHI = 1/6
  const TangentialSolution s = solve_steady_rolling(patch.influence, patch.normal.pn, in);
  const TangentialForces f = total_forces(g, s.px, s.py);

  const double Fx = num(ref, "Fx_N"), Fy = num(ref, "Fy_N"), Mz = num(ref, "Mz_Nmm") * 1e-3;
  const double scale = std::hypot(Fx, Fy);  // for components that vanish by symmetry
  EXPECT_NEAR(f.Fx, Fx, 0.005 * std::abs(Fx) + 1e-6 * scale);
  EXPECT_NEAR(f.Fy, Fy, 0.005 * std::abs(Fy) + 1e-6 * scale);
  // Mz of the symmetric cases is zero up to the rounding of CONTACT's 6-digit tractions
  EXPECT_NEAR(f.Mz, Mz, 0.02 * std::abs(Mz) + 1e-5 * scale * 6e-3);

  // element states, where CONTACT's traction file is given
  char name[64];
  std::snprintf(name, sizeof name, "contact/%s/traction_%s_case%02d.csv", c.folder.c_str(),
                c.grid.c_str(), c.case_number);
  std::vector<std::map<std::string, std::string>> field;
  try {
    field = read_csv(data_path(name));
  } catch (const std::exception&) {
    return;  // no traction file for this case
  }
  int compared = 0, same = 0;
  for (const auto& e : field) {
    const int ix = std::stoi(e.at("ix")) - 1, iy = std::stoi(e.at("iy")) - 1;
    if (ix < 0 || iy < 0 || ix >= g.nx || iy >= g.ny) continue;
    const int igs = std::stoi(e.at("igs"));
    if (igs == 0) continue;
    ++compared;
    same += s.state[g.index(ix, iy)] == igs;
  }
  EXPECT_EQ(compared, patch.normal.contact_elements());
  EXPECT_GE(same, 0.98 * compared) << same << " of " << compared << " element states agree";
  EXPECT_EQ(s.count(ElementState::adhesion), std::stoi(ref.at("n_adhesion")));
}

INSTANTIATE_TEST_SUITE_P(ReferenceCases, AgainstCONTACT, ::testing::ValuesIn(all_reference_cases()),
                         [](const auto& info) {
                           return info.param.folder + "_" + info.param.grid + "_" +
                                  std::to_string(info.param.case_number);
                         });

// ---- Kalker's linear theory (full adhesion limit) ----

namespace {

// Kalker's C11, C22, C23 for nu = 0.25 at a/b (tests/data/kalker, exact table rows).
std::array<double, 3> kalker_table(double a_over_b) {
  for (const auto& row : read_csv(data_path("kalker/kalker_linear_theory.csv")))
    if (std::abs(num(row, "a_over_b") - a_over_b) < 1e-9 && num(row, "nu") == 0.25)
      return {num(row, "C11"), num(row, "C22"), num(row, "C23")};
  throw std::runtime_error("no Kalker row");
}

// C11, C22, C23 from tiny creepages on a grid with `across` elements over each axis of the ellipse.
std::array<double, 3> discrete_coefficients(double a_over_b, int across) {
  const Material m{210e9, 0.25};
  const double c = 6e-3, a = c * std::sqrt(a_over_b), b = c / std::sqrt(a_over_b);
  const double scale = 1.08;
  const int n = static_cast<int>(std::ceil(across * scale));
  const Grid g = Grid::around_ellipse(n, n, a, b, scale);
  const HertzContact h = hertz_from_semi_axes(a, b, kN, m);
  const ContactPatch patch = solve_patch(g, m, quadratic_distance(g, h.A, h.B), kN);
  const double G = m.shear_modulus(), xi = 1e-6, phi = 1e-6 / c;
  auto forces = [&](Creepage cr) {
    const auto s = solve_steady_rolling(patch.influence, patch.normal.pn, {kMu, kSpeed, cr, 0.0});
    return total_forces(g, s.px, s.py);
  };
  const TangentialForces fx = forces({xi, 0, 0}), fy = forces({0, xi, 0}), fp = forces({0, 0, phi});
  return {-fx.Fx / (G * c * c * xi), -fy.Fy / (G * c * c * xi), -fp.Fy / (G * c * c * c * phi)};
}

}  // namespace

class KalkerLinearTheory : public ::testing::TestWithParam<double> {};

TEST_P(KalkerLinearTheory, CreepCoefficientsWithin3PercentAndConvergingUnderRefinement) {
  const double ratio = GetParam();
  const auto table = kalker_table(ratio);
  const auto coarse = discrete_coefficients(ratio, 30), fine = discrete_coefficients(ratio, 60);
  const char* names[] = {"C11", "C22", "C23"};
  for (int k = 0; k < 3; ++k) {
    const double e_coarse = std::abs(coarse[k] / table[k] - 1), e_fine = std::abs(fine[k] / table[k] - 1);
    std::printf("a/b = %.2f %s: Kalker %.3f, 30 across %.4f (%.2f %%), 60 across %.4f (%.2f %%)\n",
                ratio, names[k], table[k], coarse[k], 100 * e_coarse, fine[k], 100 * e_fine);
    EXPECT_LT(e_fine, 0.03) << names[k];
    EXPECT_LT(e_fine, e_coarse) << names[k] << ": the error must decrease under refinement";
  }
}

INSTANTIATE_TEST_SUITE_P(AspectRatios, KalkerLinearTheory, ::testing::Values(0.5, 1.0, 2.0));

// ---- limits and robustness ----

TEST(SteadyRolling, FullSlidingTendsToMuNOpposingTheCreepage) {
  const ContactPatch& patch = paper_patch("coarse");
  for (Creepage c : {Creepage{0.05, 0, 0}, Creepage{0, -0.05, 0}, Creepage{0.03, 0.04, 0}}) {
    const auto s = solve_steady_rolling(patch.influence, patch.normal.pn, {kMu, kSpeed, c, 0.0});
    const auto f = total_forces(patch.grid, s.px, s.py);
    EXPECT_EQ(s.count(ElementState::adhesion), 0);
    EXPECT_NEAR(std::hypot(f.Fx, f.Fy), kMu * kN, 0.002 * kMu * kN);
    // opposing: F parallel to -creepage
    const double cn = std::hypot(c.xi_x, c.xi_y);
    EXPECT_NEAR((f.Fx * c.xi_x + f.Fy * c.xi_y) / (cn * std::hypot(f.Fx, f.Fy)), -1.0, 1e-3);
  }
}

TEST(SteadyRolling, ConvergesFromTinyCreepageToLargeSpinAndStaysWithinTheFrictionBound) {
  const ContactPatch& patch = paper_patch("coarse");
  const auto s6 = solve_steady_rolling(patch.influence, patch.normal.pn, {kMu, kSpeed, {1e-6, 0, 0}, 0});
  const auto s8 = solve_steady_rolling(patch.influence, patch.normal.pn, {kMu, kSpeed, {1e-8, 0, 0}, 0});
  const double F6 = total_forces(patch.grid, s6.px, s6.py).Fx, F8 = total_forces(patch.grid, s8.px, s8.py).Fx;
  EXPECT_NEAR(F8 / F6, 1e-2, 1e-4);  // linear in the full-adhesion limit
  for (double phi : {-1.0, -0.3, 0.3, 1.0})
    for (Creepage c : {Creepage{0, 0, phi}, Creepage{0.001, 0.001, phi}}) {
      const auto s = solve_steady_rolling(patch.influence, patch.normal.pn, {kMu, kSpeed, c, 0});
      const auto f = total_forces(patch.grid, s.px, s.py);
      EXPECT_TRUE(std::isfinite(f.Fx) && std::isfinite(f.Fy) && std::isfinite(f.Mz));
      EXPECT_LE(std::hypot(f.Fx, f.Fy), kMu * kN * (1 + 1e-12));
      EXPECT_LT(s.residual, 1e-10);
      if (c.xi_x == 0.0) {
        EXPECT_LT(f.Fy * phi, 0.0) << "pure spin " << phi << ": Fy = -f23 phi, f23 > 0";
      }
    }
}

TEST(SteadyRolling, ZeroCreepageGivesZeroTraction) {
  const ContactPatch& patch = paper_patch("coarse");
  const auto s = solve_steady_rolling(patch.influence, patch.normal.pn, {kMu, kSpeed, {0, 0, 0}, 0});
  for (double v : s.px) EXPECT_EQ(v, 0.0);
  EXPECT_EQ(s.count(ElementState::adhesion), patch.normal.contact_elements());
}

// One steady-rolling solver for a pressure iterated on a grid (contact::SteadyRollingSolver, as a
// wheel's lowering uses it): on the paper's coarse grid near saturation (xi = 2e-3, 1e-3, spin 0.1
// rad/m), three pressures (pn scaled by 1, 1.03, 0.97: the same contact elements) give the
// tractions of a fresh solve_steady_rolling each time within 1e-10 of the largest traction (the LU
// factors only precondition), and the kept solver factorises fewer times than a fresh one per
// pressure does.
TEST(SteadyRollingSolver, KeepsItsFactorsAcrossPressuresAndGivesTheFreshSolution) {
  const ContactPatch& patch = coarse_patch();
  const SteadyRollingInput in(kMu, kSpeed, {2e-3, 1e-3, 0.1});
  SteadyRollingSolver kept(patch.influence);
  int fresh_factorisations = 0;
  const TangentialSolution* start = nullptr;
  TangentialSolution previous;
  for (double scale : {1.0, 1.03, 0.97}) {
    GridField pn = patch.normal.pn;
    for (double& p : pn) p *= scale;
    const TangentialSolution a = kept.solve(pn, in, {}, start);
    const TangentialSolution b = solve_steady_rolling(patch.influence, pn, in, {}, start);
    SteadyRollingSolver fresh(patch.influence);
    fresh.solve(pn, in, {}, start);
    fresh_factorisations += fresh.factorisations();
    double largest = 0.0, diff = 0.0;
    for (std::size_t k = 0; k < pn.size(); ++k) {
      largest = std::max({largest, std::abs(b.px[k]), std::abs(b.py[k])});
      diff = std::max({diff, std::abs(a.px[k] - b.px[k]), std::abs(a.py[k] - b.py[k])});
    }
    EXPECT_LE(diff, 1e-10 * largest) << "pn x " << scale;
    previous = a;
    start = &previous;
  }
  ASSERT_GT(fresh_factorisations, 0) << "the case must need factors for the check to mean anything";
  EXPECT_LT(kept.factorisations(), fresh_factorisations);
}

// Another solver started with a nearby state's factors (SteadyRollingSolver::precondition_with,
// as the bogie equilibrium's kept-grid contacts are): on the same case, the first solver's factors
// at pn, handed to a new solver for pn x 1.03 (the same contact elements), give the fresh solution
// within 1e-10 of the largest traction with no factorisation of its own; factors made for other
// elements (pn cut to zero on an edge element) are not used.
TEST(SteadyRollingSolver, AnotherSolverPreconditionedByANearbyStatesFactorsNeedsNoneOfItsOwn) {
  const ContactPatch& patch = coarse_patch();
  const SteadyRollingInput in(kMu, kSpeed, {2e-3, 1e-3, 0.1});
  SteadyRollingSolver first(patch.influence);
  const TangentialSolution s0 = first.solve(patch.normal.pn, in);
  ASSERT_GT(first.factorisations(), 0)
      << "the case must need factors for the check to mean anything";
  ASSERT_TRUE(first.factors());
  GridField pn = patch.normal.pn;
  for (double& p : pn) p *= 1.03;
  SteadyRollingSolver seeded(patch.influence);
  seeded.precondition_with(first.factors());
  const TangentialSolution a = seeded.solve(pn, in, {}, &s0);
  const TangentialSolution b = solve_steady_rolling(patch.influence, pn, in, {}, &s0);
  double largest = 0.0, diff = 0.0;
  for (std::size_t k = 0; k < pn.size(); ++k) {
    largest = std::max({largest, std::abs(b.px[k]), std::abs(b.py[k])});
    diff = std::max({diff, std::abs(a.px[k] - b.px[k]), std::abs(a.py[k] - b.py[k])});
  }
  EXPECT_LE(diff, 1e-10 * largest);
  EXPECT_EQ(seeded.factorisations(), 0);
  // other elements: one contact element less
  GridField cut = pn;
  for (double& p : cut)
    if (p > 0.0) {
      p = 0.0;
      break;
    }
  SteadyRollingSolver other(patch.influence);
  other.precondition_with(first.factors());
  other.solve(cut, in, {}, &s0);
  EXPECT_GT(other.factorisations(), 0);
}
