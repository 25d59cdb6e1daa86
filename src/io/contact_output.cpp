#include "io/contact_output.hpp"

namespace rollnoise::io {

void write_case(Hdf5Writer& w, const CaseReader& r) {
  w.attribute("/case", "toml", r.toml_text());
  w.attribute("/case", "source", r.source());
}

void write_patch(Hdf5Writer& w, const contact::ContactPatch& patch) {
  const contact::Grid& g = patch.grid;
  std::vector<double> x(g.nx), y(g.ny);
  for (int i = 0; i < g.nx; ++i) x[i] = g.x(i);
  for (int j = 0; j < g.ny; ++j) y[j] = g.y(j);
  const std::vector<std::size_t> field = {std::size_t(g.ny), std::size_t(g.nx)};
  w.write("/grid/x", x, {x.size()}, "m");
  w.write("/grid/y", y, {y.size()}, "m");
  w.write("/grid/dx", g.dx, "m");
  w.write("/grid/dy", g.dy, "m");
  w.write("/normal/pn", patch.normal.pn, field, "Pa");
  w.write("/normal/force", patch.normal.force, "N");
  w.write("/normal/approach", patch.normal.approach, "m");
  w.write("/normal/undeformed_distance", patch.undeformed_distance, field, "m");
}

void write_tangential(Hdf5Writer& w, const std::string& group, const contact::Grid& g,
                      const contact::Creepage& c, const contact::TangentialSolution& s) {
  const std::vector<std::size_t> field = {std::size_t(g.ny), std::size_t(g.nx)};
  const contact::TangentialForces f = contact::total_forces(g, s.px, s.py);
  w.write(group + "/creepage", std::vector<double>{c.xi_x, c.xi_y, c.phi}, {3}, "-, -, rad/m");
  w.write(group + "/force", std::vector<double>{f.Fx, f.Fy, f.Mz}, {3}, "N, N, N m");
  w.write(group + "/px", s.px, field, "Pa");
  w.write(group + "/py", s.py, field, "Pa");
  w.write(group + "/sx", s.sx, field, "m/s");
  w.write(group + "/sy", s.sy, field, "m/s");
  w.write(group + "/state", s.state, field, "0 exterior, 1 adhesion, 2 slip");
}

void write_mean_state(Hdf5Writer& w, const CaseReader& r, const contact::ContactPatch& patch,
                      const contact::Creepage& mean, const contact::TangentialSolution& steady) {
  write_case(w, r);
  write_patch(w, patch);
  write_tangential(w, "/steady", patch.grid, mean, steady);
}

}  // namespace rollnoise::io
