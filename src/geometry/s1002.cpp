// S1002 coefficients: EN 13715 (UIC 510-2) as used in the SIMPACK / Manchester contact benchmark
// definition (S. Iwnicki, The Manchester benchmarks for rail vehicle simulation, Veh. Syst. Dyn. 30
// (1998) and P. Shackleton, S. Iwnicki, Veh. Syst. Dyn. 46 (2008) 129-149) and widely reproduced,
// e.g. in the DLR S1002 routine by H. Netter distributed with the Assimulo wheelset example.
// Units in the formulas: s and F in mm. Sections (s from the flange back to the field side):
//
//   H  [-70,         -62.764705882]  F = AH + sqrt(BH^2 - (s + CH)^2)     flange back arc R20.5
//   G  [-62.764705882, -49.662510381] F = AG + sqrt(BG^2 - (s + CG)^2)     flange tip arc R12
//   F  [-49.662510381, -39.764473993] F = AF + sqrt(BF^2 - (s + CF)^2)     flange flank arc R20
//   E  [-39.764473993, -38.426669071] F = -AE - BE s                       flange flank, straight
//   D  [-38.426669071, -35]           F = AD - sqrt(BD^2 - (s + CD)^2)     flange root arc R13
//   C  [-35, -26]                     F = -AC - BC s - CC s^2 - ... - HC s^7
//   B  [-26, 32.15796]                F = AB - BB s + CB s^2 - DB s^3 + EB s^4 - FB s^5 + GB s^6
//                                         - HB s^7 + IB s^8                  tread
//   A  [32.15796, 60]                 F = AA - BA s                        outer chamfer 1:15
//
// (The point file agrees with these to 2e-6 mm: tests/geometry/test_profile.cpp.)
#include "geometry/s1002.hpp"

#include <array>
#include <cmath>
#include <sstream>

#include "core/errors.hpp"

namespace rollnoise::geometry {
namespace {

// Section boundaries (mm), from the flange back to the field side.
constexpr double kSH = -70.0, kHG = -62.764705882, kGF = -49.662510381, kFE = -39.764473993,
                 kED = -38.426669071, kDC = -35.0, kCB = -26.0, kBA = 32.15796, kSA = 60.0;

double arc(double a, double sign, double r, double c, double s) {
  return a + sign * std::sqrt(std::max(0.0, r * r - (s + c) * (s + c)));
}

// F(s) in mm for s in mm.
double s1002_mm(double s) {
  if (s >= kBA) return 1.364323640 - 0.066666667 * s;  // A
  if (s >= kCB) {                                      // B (Horner, alternating signs)
    constexpr std::array<double, 9> c = {0.0,
                                         -3.358537058e-02,
                                         1.565681624e-03,
                                         -2.810427944e-05,
                                         5.844240864e-08,
                                         -1.562379023e-08,
                                         5.309217349e-15,
                                         -5.957839843e-12,
                                         2.646656573e-13};
    double f = 0.0;
    for (int k = 8; k >= 0; --k) f = f * s + c[k];
    return f;
  }
  if (s >= kDC) {  // C
    constexpr std::array<double, 8> c = {4.320221063e+03, 1.038384026e+03, 1.065501873e+02,
                                         6.051367875,     2.054332446e-01, 4.169739389e-03,
                                         4.687195829e-05, 2.252755540e-07};
    double f = 0.0;
    for (int k = 7; k >= 0; --k) f = f * s + c[k];
    return -f;
  }
  if (s >= kED) return arc(16.446, -1.0, 13.0, 26.210665, s);         // D
  if (s >= kFE) return -93.576667419 - 2.747477419 * s;               // E
  if (s >= kGF) return arc(8.834924130, 1.0, 20.0, 58.558326413, s);  // F
  if (s >= kHG) return arc(16.0, 1.0, 12.0, 55.0, s);                 // G
  return arc(9.519259302, 1.0, 20.5, 49.5, s);                        // H
}

}  // namespace

double s1002_height(double s) {
  if (!(s >= s1002_s_min - 1e-12 && s <= s1002_s_max + 1e-12)) {
    std::ostringstream m;
    m << "S1002 is defined for s in [-70, 60] mm, not s = " << s * 1e3 << " mm";
    throw std::domain_error(m.str());
  }
  return 1e-3 * s1002_mm(1e3 * s);
}

Profile s1002_profile(double spacing) {
  if (!(spacing > 0.0 && spacing < 5e-3))
    throw std::invalid_argument("the S1002 sample spacing must be in (0, 5 mm)");
  std::vector<double> y, z;
  const double s0 = -69.9e-3;
  const std::array<double, 8> knots = {kHG, kGF, kFE, kED, kDC, kCB, kBA, kSA};
  std::size_t next = 0;
  for (double s = s0;; s += spacing) {
    // Insert the section boundaries so that the kinks (none in S1002, it is C1) sit on knots.
    while (next < knots.size() && knots[next] * 1e-3 <= s + 1e-12) {
      const double k = knots[next++] * 1e-3;
      if (y.empty() || k > y.back() + 1e-9) {
        y.push_back(k);
        z.push_back(s1002_height(k));
      }
    }
    if (s > s1002_s_max + 1e-12) break;
    if (y.empty() || s > y.back() + 1e-9) {
      y.push_back(s);
      z.push_back(s1002_height(std::min(s, s1002_s_max)));
    }
  }
  return Profile(std::move(y), std::move(z), ProfileKind::Wheel, "S1002 (EN 13715, analytic)");
}

}  // namespace rollnoise::geometry
