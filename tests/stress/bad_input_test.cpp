// Bad inputs at library level give a clear error: rollnoise::InputError naming the key,
// NumericalError naming the solver, or the violated contract of a numerics function as
// std::invalid_argument / std::domain_error with a physical message (its case key is checked where
// it is read); never a silently non-finite result.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <stdexcept>

#include "core/errors.hpp"
#include "stress_support.hpp"

using namespace rollnoise;
using namespace rollnoise::stress;

namespace {

const double kNaN = std::numeric_limits<double>::quiet_NaN();
const double kInf = std::numeric_limits<double>::infinity();

const ContactPatch& small_patch() {
  static const ContactPatch p = hertz_patch(kPaperRatio, 16, 12);
  return p;
}

// Passes if `f` throws InputError, NumericalError or a stated contract (std::invalid_argument,
// std::domain_error); prints what happened otherwise.
::testing::AssertionResult clear_error(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    std::printf("  InputError [%s]: %s\n", e.key().c_str(), e.what());
    return ::testing::AssertionSuccess();
  } catch (const NumericalError& e) {
    std::printf("  NumericalError: %s\n", e.what());
    return ::testing::AssertionSuccess();
  } catch (const std::invalid_argument& e) {
    std::printf("  contract (invalid_argument): %s\n", e.what());
    return ::testing::AssertionSuccess();
  } catch (const std::domain_error& e) {
    std::printf("  contract (domain_error): %s\n", e.what());
    return ::testing::AssertionSuccess();
  } catch (const std::exception& e) {
    return ::testing::AssertionFailure() << "threw another exception: " << e.what();
  }
  return ::testing::AssertionFailure() << "returned without an error";
}

// Whether a steady solution is finite everywhere.
bool finite(const TangentialSolution& s) {
  for (const auto* v : {&s.px, &s.py, &s.sx, &s.sy})
    for (double x : *v)
      if (!std::isfinite(x)) return false;
  return true;
}

}  // namespace

TEST(BadInputStress, FrequenciesOutsideZeroToNyquistAreInputErrorsNamingTheKey) {
  const ContactPatch& p = small_patch();
  const auto s = solve_steady_rolling(p.influence, p.normal.pn, {0.3, kSpeed, {1e-3, 0, 0}, 0.0});
  const nss::LinearContactModel m(p, s, {0.3, kSpeed, 0.0});
  const double fn = m.nyquist_frequency();
  // Nyquist computed independently, V/(2 dx), and 0 are valid (the same formula up to the
  // rounding of dt = dx/V: 1e-12 relative is 4000 ulp, and check_frequency allows that much)
  EXPECT_NEAR(fn, 0.5 * kSpeed / p.grid.dx, 1e-12 * fn);
  EXPECT_NO_THROW(m.creep_coefficients({0.0, 0.5 * kSpeed / p.grid.dx}));
  EXPECT_NO_THROW(m.creep_coefficients_direct(0.5 * kSpeed / p.grid.dx));
  for (double bad : {fn * (1 + 1e-6), 2 * fn, -1.0, -1e-300, kNaN, kInf}) {
    SCOPED_TRACE("frequency " + std::to_string(bad));
    const std::vector<std::function<void()>> calls = {
        [&] {
          m.creep_coefficients({100.0, bad});
        },
        [&] { m.creep_coefficients_direct(bad); },
        [&] { m.creep_coefficients_markov({bad}); },
        [&] { m.creep_coefficients_hessenberg({bad}); },
    };
    for (const auto& call : calls) {
      try {
        call();
        ADD_FAILURE() << "no error";
      } catch (const InputError& e) {
        EXPECT_EQ(e.key(), "frequency");
        if (std::isfinite(bad) && bad > fn) {
          EXPECT_NE(std::string(e.what()).find("Nyquist"), std::string::npos) << e.what();
        }
      }
    }
  }
}

TEST(BadInputStress, NonPositiveOrNonFiniteHertzDataAndTooSmallGridsAreInputErrors) {
  for (double bad : {0.0, -1e-3, kNaN}) {
    EXPECT_TRUE(clear_error([&] { hertz_from_semi_axes(bad, 5e-3, kN, kSteel); }));
    EXPECT_TRUE(clear_error([&] { hertz_from_semi_axes(7e-3, bad, kN, kSteel); }));
    EXPECT_TRUE(clear_error([&] { hertz_from_semi_axes(7e-3, 5e-3, bad, kSteel); }));
    EXPECT_TRUE(clear_error([&] { hertz_from_curvatures(bad, 10.0, kN, kSteel); }));
  }
  // a potential contact area that cuts the ellipse: the contact reaches the border
  try {
    hertz_patch(kPaperRatio, 20, 16, kSteel, 0.9);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "grid");
  }
}

// The library checks these inputs itself (contact::check_rolling_input, keys friction.mu,
// rolling.speed, creepage.mean), not only the case reader: before, solve_steady_rolling returned NaN
// tractions flagged as converged (the residual's max-norm dropped the NaN, std::max(0, NaN) = 0),
// and the NSS model built on it NaN creep coefficients.
TEST(BadInputStress, NonFiniteCreepageIsAClearErrorNotANonFiniteSolution) {
  const ContactPatch& p = small_patch();
  for (const Creepage c : {Creepage{kNaN, 0, 0}, Creepage{0, kNaN, 0}, Creepage{0, 0, kNaN},
                           Creepage{kInf, 0, 0}, Creepage{1e-3, 0, -kInf}}) {
    SCOPED_TRACE(describe(c));
    EXPECT_TRUE(clear_error([&] {
      const auto s = solve_steady_rolling(p.influence, p.normal.pn, {0.3, kSpeed, c, 0.0});
      std::printf("  returned: finite %d, residual %g, %d iterations\n", finite(s), s.residual,
                  s.iterations);
    }));
  }
}

TEST(BadInputStress, NonPositiveSpeedOrNonFiniteFrictionIsAClearError) {
  const ContactPatch& p = small_patch();
  const Creepage c{1e-3, 0, 0};
  for (const auto& [mu, V] : std::vector<std::pair<double, double>>{
           {kNaN, kSpeed}, {-0.3, kSpeed}, {0.3, 0.0}, {0.3, -kSpeed}, {0.3, kNaN}}) {
    SCOPED_TRACE("mu = " + std::to_string(mu) + ", V = " + std::to_string(V));
    EXPECT_TRUE(clear_error([&] {
      const auto s = solve_steady_rolling(p.influence, p.normal.pn, {mu, V, c, 0.0});
      std::printf("  steady returned: finite %d, residual %g\n", finite(s), s.residual);
      const nss::LinearContactModel m(p, s, {mu, V, 0.0});
      const auto f = m.creep_coefficients({0.0});
      std::printf("  creep coefficients returned, finite %d\n", static_cast<int>(f[0].allFinite()));
    }));
  }
}
