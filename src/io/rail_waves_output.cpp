#include "io/rail_waves_output.hpp"

#include <vector>

#include "dynamics/rail_model.hpp"
#include "dynamics/waveguide_rail_model.hpp"

namespace rollnoise::io {

void write_rail_waves(Hdf5Writer& w, const dynamics::RailModel& rail) {
  const auto* waveguide = dynamic_cast<const dynamics::WaveguideRailModel*>(&rail);
  if (!waveguide) return;
  constexpr int kPoints = 81, kBranches = 12;
  constexpr double kMax = 40.0;  // rad/m: the bending waves' k at 5 kHz is ~20 rad/m
  std::vector<double> k(kPoints), f;
  f.reserve(kPoints * kBranches);
  for (int i = 0; i < kPoints; ++i) {
    k[i] = kMax * i / (kPoints - 1);
    const Eigen::VectorXd fi = waveguide->waveguide().dispersion(k[i], kBranches);
    for (int j = 0; j < kBranches; ++j) f.push_back(j < fi.size() ? fi(j) : 0.0);
  }
  w.write("/receptance/rail_waves/wavenumber", k, {kPoints}, "rad/m");
  w.write("/receptance/rail_waves/frequency", f, {kPoints, kBranches}, "Hz");
}

}  // namespace rollnoise::io
