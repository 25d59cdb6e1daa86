// rollnoise squeal: the linear stability of the wheel-rail-contact loop at the curve's mean state
// (docs/squeal.md). Read the case as `noise` does, run pipeline::run_squeal (route 2) and/or
// pipeline::squeal_route1 (route 1), write /squeal/* (io/squeal_output.hpp); a one-line summary on
// stderr (none with -q), the table on stdout. With both routes /squeal/* are route 2's and route 1's
// go to /squeal/route1/*, with /squeal/route_agreement.
#include <cstdio>
#include <string>

#include "cli/commands.hpp"
#include "io/noise_case.hpp"
#include "io/squeal_output.hpp"
#include "io/squeal_wheels_output.hpp"
#include "pipeline/squeal.hpp"
#include "pipeline/squeal_wheels.hpp"

namespace rollnoise::cli {

namespace {

// Per wheelset of curve.wheels: its unstable roots, each with the wheel it belongs to.
void print_wheelsets(const std::vector<pipeline::WheelsetSqueal>& s) {
  for (const pipeline::WheelsetSqueal& ws : s) {
    int unstable = 0, unconverged = 0;
    for (const auto& x : ws.roots) {
      unstable += x.root.unstable ? 1 : 0;
      unconverged += x.root.converged ? 0 : 1;
    }
    std::printf("  wheelset %s (%zu contacts, %zu roots, %d unstable, %d not converged, %.1f s, %ld evaluations)\n",
                noise::is_leading(ws.wheels.front()) ? "leading" : "trailing", ws.wheels.size() + ws.second_patches, ws.roots.size(),
                unstable, unconverged, ws.seconds, ws.evaluations);
    if (!ws.skipped.empty()) std::printf("    left out: %s\n", ws.skipped.c_str());
    for (const auto& x : ws.roots)
      if (x.root.unstable || !x.root.converged)
        std::printf("    %-14s %-32s %10.3f Hz zeta %12.4e share %.2f%s%s\n",
                    noise::wheel_name(x.wheel), x.root.label.c_str(), x.root.frequency,
                    x.root.damping_ratio, x.share, x.root.unstable ? " UNSTABLE" : "",
                    x.root.converged ? "" : " (continuation failed)");
  }
}

// The routes' agreement and, beyond its tolerance, a warning naming the worst mode and the likely
// cause (pipeline::route_warning; docs/squeal.md Sec. 4.2).
void print_route_agreement(const pipeline::RouteAgreement& agreement, const std::string& warning) {
  std::printf("route agreement: frequency %.2e, damping ratio %.2e relative / %.2e absolute over %d modes%s\n",
              agreement.frequency, agreement.damping_relative, agreement.damping_absolute, agreement.compared,
              agreement.distinct ? "" : " (two roots matched one route-1 eigenvalue)");
  if (!warning.empty()) std::printf("warning: %s\n", warning.c_str());
}

// The table's last column for a root: UNSTABLE, and how its continuation ended (docs/squeal.md
// Sec. 4.2: each root once).
std::string root_status(const noise::ModeRoot& x, const std::vector<noise::ModeRoot>& roots) {
  if (x.same_root_as >= 0) {
    std::string owner = "mode " + std::to_string(x.same_root_as);
    for (const auto& y : roots)
      if (static_cast<long>(y.mode) == x.same_root_as) owner = y.label;
    return "(continuation reached the root of " + owner + ": counted there)";
  }
  return std::string(x.unstable ? "UNSTABLE" : "") + (x.converged ? "" : " (continuation failed)") +
         (x.refined ? " (own root found again: the continuation had reached another's)" : "");
}

// The summary line on stderr. A root whose continuation failed (converged = false) has no decided
// stability: counted apart, so that "0 unstable" is not read as a verdict on it; routes that
// disagree beyond their target: where and why in the table's warning.
void print_summary(const pipeline::SquealResult& r, const std::string& warning) {
  int unconverged = 0;
  for (const auto& x : r.roots) unconverged += x.converged ? 0 : 1;
  std::fprintf(stderr, "squeal: %d unstable of %zu modes%s", r.unstable_count(), r.roots.size(),
               r.unstable_count() ? " (see /squeal/unstable)" : "");
  if (unconverged > 0)
    std::fprintf(stderr, "; %d not converged, their stability not decided (/squeal/converged)",
                 unconverged);
  if (!warning.empty())
    std::fprintf(
        stderr,
        "; warning: routes 1 and 2 disagree beyond their tolerance (/squeal route_warning)");
  std::fprintf(stderr, "\n");
}

}  // namespace

int run_squeal(const CommonOptions& o, const std::string& route) {
  const bool route1 = route != "2", route2 = route != "1";
  const io::CaseReader reader = io::CaseReader::from_file(o.case_file, o.overrides);
  io::NoiseInputs in = io::read_noise_inputs(reader);
  const pipeline::NoiseCase& nc = in.noise;
  pipeline::SquealResult r = io::within_case(reader, [&] { return pipeline::run_squeal(std::move(in.contact), nc, {}, route2); });
  pipeline::Route1Result r1;
  std::vector<noise::ModeRoot> roots1;
  pipeline::RouteAgreement agreement;
  if (route1) {
    r1 = io::within_case(reader, [&] { return pipeline::squeal_route1(r, nc); });
    roots1 = pipeline::match_route1(r1, route2 ? r.roots : pipeline::uncoupled_roots(nc));
    if (route2) agreement = pipeline::route_agreement(roots1, r.roots);
  }
  pipeline::Route1Deviation dev;
  if (route1 && route2) {
    std::vector<dynamics::cdouble> s;
    for (const auto& x : r.roots) s.push_back(x.s);
    dev = pipeline::route1_deviation(r1, r, nc, s);
  }
  const std::string warning =
      route1 && route2 ? pipeline::route_warning(agreement, r.roots, roots1, dev) : "";
  std::vector<pipeline::WheelsetSqueal> wheelsets;  // curve.wheels, per wheelset (route 2)
  if (route2) wheelsets = io::within_case(reader, [&] { return pipeline::squeal_wheelsets(r, nc); });
  if (!route2) r.roots = roots1, r.route = 1;
  const std::string out = output_path(o, reader.name());
  io::Hdf5Writer w(out);
  io::write_squeal(w, reader, nc, r);
  if (route1) io::write_squeal_route1(w, r1, roots1, route2 ? &agreement : nullptr, warning);
  io::write_squeal_wheels(w, wheelsets);
  w.commit();

  if (!o.quiet) {
    std::printf("%s: %zu wheel modes in %g-%g Hz, normal coupling %s; contact %.2f s", reader.name().c_str(),
                r.roots.size(), nc.band_min, nc.band_max, r.coupled ? "on" : "off", r.seconds_contact);
    if (route2) std::printf(", route 2 %.2f s (%ld loop evaluations)", r.seconds_roots, r.evaluations);
    if (route1)
      std::printf(", route 1 %.2f s fits (rail %.3g s, %g-%g Hz: %zu poles, error %.1e at %.0f Hz, %.1e at the modes; "
                  "contact %zu poles, error %.1e) + %.2f s eigenvalues",
                  r1.seconds_fit, r1.seconds_rail, r1.fit_min, r1.fit_max, r1.rail.poles.size(), r1.rail.error,
                  r1.rail.worst_frequency, r1.rail_error_at_modes, r1.contact.poles.size(), r1.contact.error,
                  r1.seconds_eigen);
    std::printf("\n  %-32s %9s %10s %12s %12s %9s", "mode", "f_n (Hz)", "f (Hz)", "Re s (1/s)",
                "zeta", route2 ? "residual" : "");
    if (route1 && route2) std::printf(" %10s %12s %8s %8s", "f1 (Hz)", "zeta1", "dev rail", "dev cont");
    std::printf("\n");
    for (std::size_t k = 0; k < r.roots.size(); ++k) {
      const auto& x = r.roots[k];
      std::printf("  %-32s %9.1f %10.3f %12.5g %12.4e", x.label.c_str(), x.natural_frequency,
                  x.frequency, x.s.real(), x.damping_ratio);
      if (route2)
        std::printf(" %9.1e", x.residual);
      else
        std::printf(" %9s", "");
      if (route1 && route2)
        std::printf(" %10.3f %12.4e %8.1e %8.1e", roots1[k].frequency, roots1[k].damping_ratio, dev.rail[k], dev.contact[k]);
      std::printf(" %s\n", root_status(x, r.roots).c_str());
    }
    if (route1 && route2) print_route_agreement(agreement, warning);
    print_wheelsets(wheelsets);
    std::printf("wrote %s\n", out.c_str());
    print_summary(r, warning);
  }
  return 0;
}

}  // namespace rollnoise::cli
