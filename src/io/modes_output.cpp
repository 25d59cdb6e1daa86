#include "io/modes_output.hpp"

#include "dynamics/wheel_mode_family.hpp"

namespace rollnoise::io {

void write_wheel_modes(Hdf5Writer& w, const dynamics::WheelFeModes& m,
                       const dynamics::WheelModalDamping& damping) {
  const std::size_t count = m.modes.size(), samples = m.tread_s.size(), nodes = m.mesh.nodes.size();
  std::vector<double> frequency, modal_mass, zeta, tread, section;
  std::vector<int> n, circles, triangles;
  std::vector<std::string> family;
  for (const auto& mode : m.modes) {
    frequency.push_back(mode.frequency);
    n.push_back(mode.n);
    family.push_back(dynamics::family_name(mode.family));
    circles.push_back(mode.nodal_circles);
    modal_mass.push_back(1.0);  // mass-normalised shapes
    zeta.push_back(damping.ratio(mode));
    for (std::size_t i = 0; i < samples; ++i)
      for (int c = 0; c < 3; ++c) tread.push_back(mode.tread_shape(i, c));
    section.insert(section.end(), mode.dofs.data(), mode.dofs.data() + mode.dofs.size());
  }
  w.write("/modes/frequency", frequency, {count}, "Hz");
  w.write("/modes/n", n, {count}, "-");
  w.write("/modes/family", family, "-");
  w.write("/modes/label", dynamics::mode_labels(m.modes),
          "- (family n=N C circles, unique: ' #k' in ascending frequency where modes share it)");
  w.write("/modes/nodal_circles", circles, {count}, "-");
  w.write("/modes/modal_mass", modal_mass, {count}, "kg");
  w.write("/modes/damping", zeta, {count}, "-");
  w.attribute("/modes", "convention",
              "u_r = U_r cos n theta, u_theta = U_theta sin n theta, u_z = U_z cos n theta; shapes "
              "normalised to "
              "phi^T M phi = 1 over the whole wheel (modal mass 1 kg); z lateral from the taping "
              "line, positive "
              "towards the field side (the profile coordinate s); docs/models.md Sec. 3.4");
  w.write("/modes/tread/s", m.tread_s, {samples}, "m");
  w.write("/modes/tread/r", m.tread_r, {samples}, "m");
  w.write("/modes/tread/shape", tread, {count, samples, 3}, "m kg^-1/2 (U_r, U_theta, U_z)");
  std::vector<double> xy;
  for (const auto& p : m.mesh.nodes) xy.push_back(p.x()), xy.push_back(p.y());
  for (const auto& t : m.mesh.triangles) triangles.insert(triangles.end(), t.begin(), t.end());
  w.write("/modes/mesh/nodes", xy, {nodes, 2}, "m (r, z)");
  w.write("/modes/mesh/triangles", triangles, {m.mesh.triangles.size(), 6},
          "- (node indices: corners, then mid-sides)");
  w.write("/modes/mesh/shape", section, {count, nodes, 3}, "m kg^-1/2 (U_r, U_theta, U_z)");
  w.write("/modes/mass", m.mass, "kg");
}

}  // namespace rollnoise::io
