// rollnoise corrugation: the growth rate of rail roughness per passage against wavelength, from the
// wear of the linearised contacts in the noise loop (docs/corrugation.md). Read the case as `noise`
// does plus [corrugation] and [wear], run pipeline::run_corrugation, write /corrugation/*
// (io/corrugation_output.hpp), print the growing wavelengths with the loop's nearest peak.
#include <algorithm>
#include <cstdio>

#include "cli/commands.hpp"
#include "io/corrugation_case.hpp"
#include "io/corrugation_output.hpp"
#include "io/noise_case.hpp"
#include "pipeline/corrugation.hpp"

namespace rollnoise::cli {

int run_corrugation(const CommonOptions& o) {
  const io::CaseReader reader = io::CaseReader::from_file(o.case_file, o.overrides);
  io::NoiseInputs in = io::read_noise_inputs(reader);
  const pipeline::CorrugationCase cc = io::read_corrugation_case(reader);
  const pipeline::NoiseCase& nc = in.noise;
  const pipeline::CorrugationResult r = io::within_case(
      reader, [&] { return pipeline::run_corrugation(std::move(in.contact), nc, cc); });
  const std::string out = output_path(o, reader.name());
  io::Hdf5Writer w(out);
  io::write_corrugation(w, reader, nc, cc, r);
  w.commit();

  const pipeline::ContactCase& c = r.noise.mean.contact();
  std::printf(
      "%s: V = %.3g m/s, %zu wavelengths %.3g-%.3g m (%.4g-%.4g Hz), %zu contacts; loop %.1f s, "
      "wear %.1f s, "
      "total %.1f s\n",
      reader.name().c_str(), c.speed, r.wavelength.size(), r.wavelength.back(),
      r.wavelength.front(), r.frequency.front(), r.frequency.back(), r.contacts.size(),
      r.seconds_loop, r.seconds_wear, r.seconds_total);
  for (const pipeline::ContactCorrugation& x : r.contacts) {
    const auto it = std::max_element(x.growth.begin(), x.growth.end());
    const std::size_t k = static_cast<std::size_t>(it - x.growth.begin());
    std::printf(
        "  %-14s %s rail, %4.2f m behind: largest growth %.3e /passage at %.1f mm (%.0f Hz); %d "
        "impulse "
        "steps, %.2f s\n",
        noise::wheel_name(x.wheel), io::rail_name(x.side), x.distance, *it, 1e3 * r.wavelength[k],
        r.frequency[k], x.steps, x.seconds);
  }
  for (const pipeline::RailCorrugation& rail : r.rails) {
    const auto it = std::max_element(rail.growth.begin(), rail.growth.end());
    const std::size_t k = static_cast<std::size_t>(it - rail.growth.begin());
    std::printf("  %s rail (bogie passage): largest growth %.3e /passage at %.1f mm (%.0f Hz)\n",
                io::rail_name(rail.side), *it, 1e3 * r.wavelength[k], r.frequency[k]);
  }
  std::printf("  wavelengths that grow (growth rate > 0), with the loop's nearest peak:\n");
  if (r.growing.empty()) std::printf("    none\n");
  for (const pipeline::GrowingBand& b : r.growing)
    std::printf(
        "    %s rail: %6.1f-%6.1f mm, largest %.3e /passage at %.1f mm (%.0f Hz); nearest: %s at "
        "%.0f Hz\n",
        io::rail_name(b.side), 1e3 * b.wavelength_min, 1e3 * b.wavelength_max, b.peak_growth,
        1e3 * b.peak_wavelength, b.peak_frequency,
        b.nearest.label.empty() ? "(no peak)" : b.nearest.label.c_str(), b.nearest.frequency);
  std::printf("wrote %s\n", out.c_str());
  return 0;
}

}  // namespace rollnoise::cli
