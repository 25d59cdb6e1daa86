// The TSI Noise pass-by limits and the normalisation to 80 km/h, (T1) of tsi_noise.hpp.
#include "acoustics/tsi_noise.hpp"

#include <cmath>
#include <stdexcept>
#include <utility>

namespace rollnoise::acoustics {

namespace {

// Regulation (EU) No 1304/2014, Annex, clause 4.2.3, Table 4: L_pAeq,Tp(80 km/h) (dB).
const std::vector<std::pair<std::string, double>>& table4() {
  static const std::vector<std::pair<std::string, double>> t = {{"electric-locomotive", 84.0},
                                                                {"diesel-locomotive", 85.0},
                                                                {"emu", 80.0},
                                                                {"dmu", 81.0},
                                                                {"coach", 79.0},
                                                                {"wagon", 83.0}};
  return t;
}

}  // namespace

const std::vector<std::string>& tsi_categories() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> n;
    for (const auto& row : table4()) n.push_back(row.first);
    return n;
  }();
  return names;
}

double tsi_passby_limit(const std::string& category) {
  for (const auto& row : table4())
    if (row.first == category) return row.second;
  throw std::invalid_argument("tsi_passby_limit: no TSI category \"" + category + "\"");
}

double tsi_normalised_80(double level, double speed) {
  constexpr double kReference = 80.0 / 3.6;  // 80 km/h in m/s
  if (!(speed > 0.0)) throw std::invalid_argument("tsi_normalised_80: needs a speed > 0");
  return level - 30.0 * std::log10(speed / kReference);  // (T1)
}

}  // namespace rollnoise::acoustics
