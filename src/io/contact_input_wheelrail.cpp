// CONTACT module-1 input for profile cases (contact_input_wheelrail.hpp). Layout of the data
// lines as in CONTACT's user guide, module 1, and the reference run C1 u3 (tests/data/contact/raw).
#include "io/contact_input_wheelrail.hpp"

#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>

#include "core/constants.hpp"
#include "core/errors.hpp"
#include "io/contact_input.hpp"
#include "noise/wheel_contact.hpp"

namespace rollnoise::io {
namespace {

std::string numbers(const std::vector<double>& v) {
  std::string s = " ";
  for (double x : v) s += " " + contact_number(x);
  return s;
}

}  // namespace

namespace {

// What module 1 is given for one wheel, in that wheel's own frame (CONTACT's right wheel, C = 1).
struct Module1State {
  double lateral = 0.0, roll = 0.0, yaw = 0.0;  // Y (m), ROLL, YAW (rad)
  double vertical_load = 0.0;                   // FZ (N)
  double curvature = 0.0;                       // CURV (1/m)
  double lateral_velocity = 0.0;                // VY (m/s)
  double pitch_velocity = 0.0;                  // VPITCH (rad/s)
  std::string note;                             // the comment line of rollnoise's state
};

void check_mappable(const pipeline::ContactCase& c) {
  if (c.geometry != "profiles" || !c.profiles || !c.placed)
    throw InputError("contact.geometry", "contact-input: module 1 needs a placed profile case");
  if (c.falling.active())
    throw InputError("friction.law",
                     "contact-input: friction.law = \"falling\" cannot be mapped to CONTACT");
}

std::string module1_text(const pipeline::ContactCase& c, const std::vector<std::string>& comments,
                         const std::string& rail_file, const std::string& wheel_file,
                         const Module1State& m) {
  const auto& track = c.profiles->track();
  const auto& ws = c.profiles->wheelset();
  const double V = c.speed * kMm;  // mm/s
  const double G = c.material.shear_modulus() * 1e-6;
  std::ostringstream s;
  for (const auto& line : comments) s << "% " << line << "\n";
  s << "% " << m.note << "\n";
  s << "  1 MODULE\n";
  s << " 1203100    C-P-B-T-N-F-S   CONFIG, PVTIME, BOUND,  TANG,   NORM,   FORCE,  STRESS\n";
  s << " 0022033    V-L-D-C-M-Z-E   VARFRC, FRCLAW, DISCNS, INFLCF, MATER,  ZTRACK, EWHEEL\n";
  s << " 0002321    H-G-I-A-O-W-R     HEAT, GAUSEI, IESTIM, MATFIL, OUTPUT, FLOW,   RETURN\n";
  s << "    999     500    30    1     " << contact_number(kContactSolverEps)
    << "         MAXGS , MAXIN , MAXNR , MAXOUT, EPS\n";
  s << numbers({c.mu, c.mu}) << "                                 FSTAT, FKIN\n";
  s << numbers({c.material.nu, c.material.nu, G, G}) << "            POISS 1,2,  GG 1,2\n";
  // patch separation as the reference run: A_SEP = pi/2, D_SEP = 8 mm, D_COMB = 4 mm
  s << numbers({c.grid.dx * kMm, c.grid.dy * kMm, 1.0, kPi / 2, 8.0, 4.0})
    << "       DX, DS, DQREL, A_SEP, D_SEP, D_COMB\n";
  s << numbers({track.gauge_point_depth * kMm, 0.0, track.gauge * kMm, 0.0, m.curvature / kMm})
    << "      GAUGHT, GAUGSQ, GAUGWD, CANT, CURV\n";
  s << "  '" << rail_file << "'   0     1.0   0.0       RFNAME, MIRRORY, SCALE, SMOOTH\n";
  s << "     0.0    0.0   0.000   0.0   0.0   0.000     DY, DZ, ROLL, VY, VZ, VROLL\n";
  s << numbers({ws.back_to_back * kMm, -ws.taping_line_offset * kMm, ws.nominal_radius * kMm})
    << "                         FBDIST, FBPOS, NOMRAD\n";
  s << "  '" << wheel_file << "'   0     1.0   0.0       WFNAME, MIRRORY, SCALE, SMOOTH\n";
  s << numbers({0.0, m.lateral * kMm, m.vertical_load, m.roll, m.yaw, 0.0})
    << "      S, Y, FZ, ROLL, YAW, PITCH\n";
  s << numbers({V, m.lateral_velocity * kMm, 0.0, 0.0, 0.0, m.pitch_velocity})
    << "   VS,VY,VZ, VROLL,VYAW,VPITCH\n";
  s << " 0 MODULE\n";
  return s.str();
}

}  // namespace

std::string module1_input(const pipeline::ContactCase& c, const std::vector<std::string>& comments,
                          const std::string& rail_file, const std::string& wheel_file) {
  check_mappable(c);
  const geometry::ContactGeometry& p = c.contact_point;
  Module1State m;
  m.lateral = c.wheelset.lateral;
  m.yaw = c.wheelset.yaw;
  m.roll = p.pose.roll;  // rollnoise's equilibrium pose (both wheels touching), as the C1 run
  m.vertical_load = c.normal_force;
  m.pitch_velocity = -c.speed * (1.0 - c.creepage.xi_x) / p.rolling_radius;
  m.lateral_velocity = c.speed * (c.wheelset.yaw + c.creepage.xi_y / std::cos(p.contact_angle));
  char buf[320];
  std::snprintf(
      buf, sizeof buf,
      "rollnoise contact point: y = %.6g mm, s_wheel = %.6g mm, delta = %.6g rad, r = %.6g mm; "
      "mean "
      "creepage (%.6g, %.6g, %.6g rad/m): xi_x by VPITCH, xi_y by VY, spin from CONTACT's geometry",
      p.y * kMm, p.wheel_s * kMm, p.contact_angle, p.rolling_radius * kMm, c.creepage.xi_x,
      c.creepage.xi_y, c.creepage.phi);
  m.note = buf;
  return module1_text(c, comments, rail_file, wheel_file, m);
}

std::string module1_wheel_input(const pipeline::ContactCase& c, const noise::WheelContact& w,
                                double inverse_radius, const std::vector<std::string>& comments,
                                const std::string& rail_file, const std::string& wheel_file) {
  check_mappable(c);
  const geometry::ContactGeometry& p = w.contact;  // this side's frame
  const double kappa = noise::is_outer(w.wheel) ? inverse_radius : -inverse_radius;
  const double V = c.speed;
  const Eigen::Vector3d& xi = w.creepage;
  for (double v :
       {w.lateral, w.yaw, w.vertical_load, p.rolling_radius, p.contact_angle, xi(0), xi(1)})
    if (!std::isfinite(v))
      throw InputError("curve.radius", std::string("contact-input: the ") +
                                           noise::wheel_name(w.wheel) +
                                           " wheel's state is not finite");
  if (!(w.vertical_load > 0.0))
    throw InputError(w.creepage_given ? "wheelset.wheel_load" : "contact.normal_force",
                     std::string("contact-input: the ") + noise::wheel_name(w.wheel) +
                         " wheel's vertical load is not positive (CONTACT's FZ)");
  if (!(std::cos(p.contact_angle) > 0.0))
    throw InputError("curve.radius", std::string("contact-input: the ") +
                                         noise::wheel_name(w.wheel) +
                                         " wheel's contact angle cannot be given to CONTACT");
  Module1State m;
  m.lateral = p.local_pose.lateral;  // +u (outer), -u (inner, mirrored)
  m.yaw = p.local_pose.yaw;          // +psi (outer), -psi (inner)
  m.roll = p.local_pose.roll;
  m.vertical_load = w.vertical_load;
  // CONTACT's CURV is negative for a curve away from its right wheel's rail (the C1 u3 reference
  // run, tests/data/contact/raw: the right wheel on the outer rail of a 300 m curve, CURV =
  // -1/300000 1/mm), i.e. -kappa in this side's frame
  m.curvature = -kappa;
  // the axle's pitch rate: with (K2') the rolling of the axle on both wheels' radii, 2 V/(r_c +
  // r_other) (the C1 run's VPITCH); with given creepages the rate that gives the wheel's xi_x when
  // the rail moves at V (1 + kappa y_c) at the contact, V (1 + kappa y_c - xi_x)/r_c (kappa = 0:
  // the tangent case's). (K2') is the first-order form of either. VY as the tangent case.
  m.pitch_velocity = w.creepage_given ? -V * (1.0 + kappa * p.y - xi(0)) / p.rolling_radius
                                      : -2.0 * V / (p.rolling_radius + w.other_rolling_radius);
  m.lateral_velocity = V * (m.yaw + xi(1) / std::cos(p.contact_angle));
  char buf[480];
  std::snprintf(
      buf, sizeof buf,
      "rollnoise %s wheel (%s): axle u = %.6g mm, psi = %.6g mrad; Q = %.6g N, N = %.6g N; "
      "contact y = %.6g mm, s_wheel = %.6g mm, delta = %.6g rad, r = %.6g mm, r_other = %.6g mm; "
      "kappa = %.6g 1/m; creepage (%.6g, %.6g, %.6g rad/m)%s: xi_x by VPITCH with CURV, xi_y "
      "by VY, spin from CONTACT's geometry",
      noise::wheel_name(w.wheel),
      noise::is_outer(w.wheel) ? "outer rail, as CONTACT's right wheel"
                               : "inner rail, mirrored y -> -y, as CONTACT's right wheel",
      w.lateral * kMm, w.yaw * 1e3, w.vertical_load, w.normal_force(), p.y * kMm, p.wheel_s * kMm,
      p.contact_angle, p.rolling_radius * kMm, w.other_rolling_radius * kMm, kappa, xi(0), xi(1),
      xi(2), w.creepage_given ? " (multibody)" : " (K2')");
  m.note = buf;
  return module1_text(c, comments, rail_file, wheel_file, m);
}

}  // namespace rollnoise::io
