// rollnoise squeal: the linear stability of the wheel-rail-contact loop at the curve's mean state
// (docs/squeal.md). Read the case as `noise` does, run pipeline::run_squeal, write /squeal/*
// (io/squeal_output.hpp); a one-line summary on stderr (none with -q), the table on stdout.
#include <cstdio>

#include "cli/commands.hpp"
#include "io/noise_case.hpp"
#include "io/squeal_output.hpp"
#include "pipeline/squeal.hpp"

namespace rollnoise::cli {

int run_squeal(const CommonOptions& o) {
  const io::CaseReader reader = io::CaseReader::from_file(o.case_file, o.overrides);
  io::NoiseInputs in = io::read_noise_inputs(reader);
  const pipeline::NoiseCase& nc = in.noise;
  const pipeline::SquealResult r =
      io::within_case(reader, [&] { return pipeline::run_squeal(std::move(in.contact), nc); });
  const std::string out = output_path(o, reader.name());
  io::Hdf5Writer w(out);
  io::write_squeal(w, reader, nc, r);
  w.commit();

  if (!o.quiet) {
    std::printf("%s: %zu wheel modes in %g-%g Hz, normal coupling %s; contact %.2f s, roots %.2f s (%ld loop "
                "evaluations)\n",
                reader.name().c_str(), r.roots.size(), nc.band_min, nc.band_max, r.coupled ? "on" : "off",
                r.seconds_contact, r.seconds_roots, r.evaluations);
    std::printf("  %-24s %9s %10s %12s %12s %9s %s\n", "mode", "f_n (Hz)", "f (Hz)", "Re s (1/s)", "zeta", "residual",
                "");
    for (const auto& x : r.roots)
      std::printf("  %-24s %9.1f %10.3f %12.5g %12.4e %9.1e %s%s\n", x.label.c_str(), x.natural_frequency, x.frequency,
                  x.s.real(), x.damping_ratio, x.residual, x.unstable ? "UNSTABLE" : "",
                  x.converged ? "" : " (continuation failed)");
    std::printf("wrote %s\n", out.c_str());
    std::fprintf(stderr, "squeal: %d unstable of %zu modes%s\n", r.unstable_count(), r.roots.size(),
                 r.unstable_count() ? " (see /squeal/unstable)" : "");
  }
  return 0;
}

}  // namespace rollnoise::cli
