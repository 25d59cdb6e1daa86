#include "io/bench_output.hpp"

#include "io/contact_output.hpp"

namespace rollnoise::io {

void write_bench(Hdf5Writer& w, const CaseReader& r, const std::vector<nss::GridMeasurement>& grids,
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

}  // namespace rollnoise::io
