#include "dynamics/wheel_fe_contact.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/errors.hpp"
#include "dynamics/wheel_fe.hpp"
#include "dynamics/wheel_mode_family.hpp"

namespace rollnoise::dynamics {
namespace {

constexpr double kTwoPi = 2.0 * 3.14159265358979323846;

// The contact frame of noise/loop.hpp applied to a local (x, y, z, rot z) motion.
Eigen::Vector4d to_contact_frame(double ux, double uy, double uz, double rot_z, double gamma) {
  const double s = std::sin(gamma), c = std::cos(gamma);
  return {-s * uy + c * uz, ux, c * uy + s * uz, c * rot_z};
}

// R(omega) of a mode of unit modal mass (split by +-n Omega, see the header).
cdouble modal_response(double omega_k, double zeta, int n, double spin, double omega) {
  const auto r = [&](double wk) {
    return 1.0 / cdouble(wk * wk - omega * omega, 2 * zeta * wk * omega);
  };
  if (n == 0 || spin == 0.0) return r(omega_k);
  return 0.5 * (r(omega_k + n * spin) + r(omega_k - n * spin));
}

void check_spin(const WheelFeModes& w, const WheelFeContactOptions& o) {
  if (!(o.spin_speed >= 0.0))
    throw InputError("wheel.rotation", "the spin speed must be >= 0 rad/s");
  for (const auto& m : w.modes)
    if (m.n >= std::max(o.n_min, 1) && kTwoPi * m.frequency - m.n * o.spin_speed <= 0.0)
      throw InputError("wheel.rotation",
                       "n Omega exceeds the natural frequency of mode n = " + std::to_string(m.n) +
                           " (" + std::to_string(m.frequency) + " Hz)");
}

}  // namespace

double WheelModalDamping::ratio(int n, ModeFamily family) const {
  if (n == 0) return n0;
  if (n == 1) return n1;
  return family == ModeFamily::kAxial ? axial
                                      : (family == ModeFamily::kRadial ? radial : circumferential);
}

double WheelModalDamping::ratio(const WheelFeMode& m) const {
  return m.damping_ratio > 0.0 ? m.damping_ratio : ratio(m.n, m.family);
}

double tread_radius_at(const WheelFeModes& w, double s) {
  const auto& t = w.tread_s;
  if (t.size() < 2 || s < t.front() - 1e-9 || s > t.back() + 1e-9)
    throw InputError("tread_position", "contact position s = " + std::to_string(s) +
                                           " m is outside the wheel's running surface");
  const auto it = std::upper_bound(t.begin(), t.end(), s);
  const std::size_t i1 =
      std::min<std::size_t>(std::max<std::ptrdiff_t>(it - t.begin(), 1), t.size() - 1);
  const double x = std::clamp((s - t[i1 - 1]) / (t[i1] - t[i1 - 1]), 0.0, 1.0);
  return (1 - x) * w.tread_r[i1 - 1] + x * w.tread_r[i1];
}

ContactShapes contact_shapes(const WheelFeModes& w, const WheelFeMode& mode,
                             const TreadContact& c) {
  const Eigen::Vector3d u =
      tread_shape_at(w, mode, c.s);  // (U_r, U_theta, U_z); throws off the tread
  const double r = tread_radius_at(w, c.s), g = c.contact_angle;
  ContactShapes out;
  if (mode.n == 0) {
    out.cos_set = to_contact_frame(-u(1), u(2), -u(0), 0.0, g);
    return out;
  }
  out.cos_set = to_contact_frame(0.0, u(2), -u(0), 0.0, g);
  out.sin_set = to_contact_frame(u(1), 0.0, 0.0, -mode.n * u(2) / r, g);
  return out;
}

Receptance4 fe_cross_receptance(const WheelFeModes& w, const WheelFeContactOptions& o,
                                const TreadContact& a, const TreadContact& b, double frequency) {
  check_spin(w, o);
  const double omega = kTwoPi * frequency;
  Receptance4 h = Receptance4::Zero();
  for (const auto& m : w.modes) {
    if (m.n < o.n_min) continue;
    const ContactShapes sa = contact_shapes(w, m, a), sb = contact_shapes(w, m, b);
    const Eigen::Matrix4d participation =
        sa.cos_set * sb.cos_set.transpose() + sa.sin_set * sb.sin_set.transpose();
    h += participation.cast<cdouble>() *
         modal_response(kTwoPi * m.frequency, o.damping.ratio(m), m.n, o.spin_speed, omega);
  }
  return h;
}

std::vector<WheelMode> contact_mode_table(const WheelFeModes& w, double s,
                                          const WheelFeContactOptions& o) {
  check_spin(w, o);
  std::vector<WheelMode> table;
  const std::vector<std::string> labels = mode_labels(w.modes);  // no two modes alike
  for (std::size_t k = 0; k < w.modes.size(); ++k) {
    const WheelFeMode& m = w.modes[k];
    if (m.n < o.n_min) continue;
    const ContactShapes c = contact_shapes(w, m, {s, 0.0});
    WheelMode entry;
    entry.damping_ratio = o.damping.ratio(m);
    entry.modal_mass = 1.0;
    const std::string& label = labels[k];
    const bool split = m.n >= 1 && o.spin_speed > 0.0;
    const double df = split ? m.n * o.spin_speed / kTwoPi : 0.0;
    const double scale = split ? std::sqrt(0.5) : 1.0;
    for (int set = 0; set < (m.n == 0 ? 1 : 2); ++set) {
      const Eigen::Vector4d psi =
          set == 0 ? c.cos_set : c.sin_set;  // (z, x, y, rot z) at gamma = 0
      const std::string name = label + (set == 0 ? "" : " sin");
      for (int wave = 0; wave < (split ? 2 : 1); ++wave) {
        entry.frequency = m.frequency + (split ? (wave == 0 ? -df : df) : 0.0);
        entry.shape = scale * psi;
        entry.label = name + (split ? (wave == 0 ? " backward" : " forward") : "");
        table.push_back(entry);
      }
    }
  }
  return table;
}

ModalParticipation modal_participation(const WheelFeModes& w, const WheelFeContactOptions& o,
                                       const std::vector<TreadContact>& contacts) {
  check_spin(w, o);
  ModalParticipation p;
  p.spin_speed = o.spin_speed;
  for (std::size_t k = 0; k < w.modes.size(); ++k)
    if (w.modes[k].n >= o.n_min) p.modes.push_back(static_cast<int>(k));
  const Eigen::Index m = static_cast<Eigen::Index>(p.modes.size());
  const Eigen::Index cols = 4 * static_cast<Eigen::Index>(contacts.size());
  p.cos_set = Eigen::MatrixXd::Zero(m, cols);
  p.sin_set = Eigen::MatrixXd::Zero(m, cols);
  for (Eigen::Index i = 0; i < m; ++i) {
    const WheelFeMode& mode = w.modes[static_cast<std::size_t>(p.modes[static_cast<std::size_t>(i)])];
    p.omega.push_back(kTwoPi * mode.frequency);
    p.zeta.push_back(o.damping.ratio(mode));
    p.n.push_back(mode.n);
    for (std::size_t a = 0; a < contacts.size(); ++a) {
      const ContactShapes c = contact_shapes(w, mode, contacts[a]);
      p.cos_set.block<1, 4>(i, 4 * static_cast<Eigen::Index>(a)) = c.cos_set.transpose();
      p.sin_set.block<1, 4>(i, 4 * static_cast<Eigen::Index>(a)) = c.sin_set.transpose();
    }
  }
  return p;
}

Eigen::VectorXcd modal_responses(const ModalParticipation& p, double frequency) {
  const double omega = kTwoPi * frequency;
  Eigen::VectorXcd r(static_cast<Eigen::Index>(p.omega.size()));
  for (std::size_t k = 0; k < p.omega.size(); ++k)
    r(static_cast<Eigen::Index>(k)) = modal_response(p.omega[k], p.zeta[k], p.n[k], p.spin_speed, omega);
  return r;
}

}  // namespace rollnoise::dynamics
