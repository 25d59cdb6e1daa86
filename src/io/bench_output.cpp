#include "io/bench_output.hpp"

#include "io/contact_output.hpp"

namespace rollnoise::io {

void write_bench(Hdf5Writer& w, const CaseReader& r, const std::vector<pipeline::GridMeasurement>& grids,
                 const std::vector<BenchColumn>& errors, double c11_table) {
  write_case(w, r);
  const std::size_t n = grids.size();
  auto column = [&](auto field) {
    std::vector<double> v;
    for (const auto& g : grids) v.push_back(double(field(g)));
    return v;
  };
  w.write("/bench/nx", column([](const auto& g) { return g.nx; }), {n}, "-");
  w.write("/bench/ny", column([](const auto& g) { return g.ny; }), {n}, "-");
  w.write("/bench/elements", column([](const auto& g) { return g.nx * g.ny; }), {n}, "-");
  w.write("/bench/contact_elements", column([](const auto& g) { return g.contact; }), {n}, "-");
  w.write("/bench/dx", column([](const auto& g) { return g.dx; }), {n}, "m");
  w.write("/bench/time_steady", column([](const auto& g) { return g.t_steady; }), {n}, "s (normal + steady problem)");
  w.write("/bench/time_creep", column([](const auto& g) { return g.t_creep; }), {n},
          "s (linear model set-up + f at the study frequencies)");
  w.write("/bench/time_transient", column([](const auto& g) { return g.t_transient; }), {n}, "s");
  w.write("/bench/transient_steps", column([](const auto& g) { return g.steps; }), {n}, "-");
  std::vector<double> force;
  for (const auto& g : grids) force.insert(force.end(), {g.force(0), g.force(1), g.force(2)});
  w.write("/bench/steady_force", force, {n, 3}, "N, N, N m (Fx, Fy, Mz)");
  w.write("/bench/C11", column([](const auto& g) { return g.c11; }), {n}, "-");
  w.write("/bench/C11_kalker_table", c11_table, "-");
  for (const auto& e : errors) {
    w.write("/bench/error/" + e.column, *e.err, {n}, "- (relative)");
    w.attribute("/bench/error/" + e.column, "description", e.name);
  }
  w.attribute("/bench", "reference", "errors relative to the finest grid (the last), C11 also against Kalker's table");
}

void write_bench_sampling(Hdf5Writer& w, const std::vector<pipeline::GridMeasurement>& grids,
                          const pipeline::SamplingAccuracy& a, const std::vector<double>& frequencies) {
  const std::size_t n = grids.size(), nf = frequencies.size();
  for (size_t sm = 0; sm < pipeline::kStudySamplings.size(); ++sm) {
    const std::string name = contact::sampling_name(pipeline::kStudySamplings[sm]);
    std::vector<double> t;
    for (const auto& g : grids) t.push_back(g.sampling[sm].seconds);
    w.write("/bench/time_sweep_" + name, t, {n},
            "s (linear model set-up + sweep of 1000 frequencies, rolling.creepage_sampling = " + name + ")");
  }
  std::vector<std::complex<double>> f;
  std::vector<double> err, order;
  for (std::size_t i = 0; i < nf; ++i) {
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) f.push_back(a.converged[i](j, k)), err.push_back(a.converged_error[i](j, k));
    for (int q = 0; q < 3; ++q) order.push_back(a.order[i](q));
  }
  w.write("/bench/sampling/frequency", frequencies, {nf}, "Hz");
  w.write("/bench/sampling/converged_f", f, {nf, 3, 3},
          "f_jk as /creep/f: f11..f22 in N, f13, f23, f31, f32 in N m, f33 in N m^2 (Richardson on the three "
          "finest grids of the sampling named by reference_sampling)");
  std::vector<std::string> ref;
  for (int r : a.reference) ref.push_back(contact::sampling_name(pipeline::kStudySamplings[r]));
  std::string refs;
  for (size_t i = 0; i < ref.size(); ++i) refs += (i ? "," : "") + ref[i];
  w.attribute("/bench/sampling/converged_f", "reference_sampling", refs);
  w.write("/bench/sampling/converged_f_error", err, {nf, 3, 3}, "units of converged_f (Roache's grid convergence index)");
  w.write("/bench/sampling/order", order, {nf, 3}, "- (order of f11, f22, f23 used by the extrapolation)");
}

}  // namespace rollnoise::io
