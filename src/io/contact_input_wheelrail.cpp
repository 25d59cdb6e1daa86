// CONTACT module-1 input for profile cases (contact_input_wheelrail.hpp). Layout of the data
// lines as in CONTACT's user guide, module 1, and the reference run C1 u3 (tests/data/contact/raw).
#include "io/contact_input_wheelrail.hpp"

#include <cmath>
#include <cstdio>
#include <sstream>

#include "core/constants.hpp"
#include "core/errors.hpp"
#include "io/contact_input.hpp"

namespace rollnoise::io {
namespace {


std::string numbers(const std::vector<double>& v) {
  std::string s = " ";
  for (double x : v) s += " " + contact_number(x);
  return s;
}

}  // namespace

std::string module1_input(const pipeline::ContactCase& c, const std::vector<std::string>& comments,
                          const std::string& rail_file, const std::string& wheel_file) {
  if (c.geometry != "profiles" || !c.profiles || !c.placed)
    throw InputError("contact.geometry", "contact-input: module 1 needs a placed profile case");
  if (c.falling.active())
    throw InputError("friction.law",
                     "contact-input: friction.law = \"falling\" cannot be mapped to CONTACT");
  const geometry::ContactGeometry& p = c.contact_point;
  const auto& track = c.profiles->track();
  const auto& ws = c.profiles->wheelset();
  const double V = c.speed * kMm;  // mm/s
  const double vpitch = -V * (1.0 - c.creepage.xi_x) / (p.rolling_radius * kMm);
  const double vy = V * (c.wheelset.yaw + c.creepage.xi_y / std::cos(p.contact_angle));
  const double G = c.material.shear_modulus() * 1e-6;
  std::ostringstream s;
  for (const auto& line : comments) s << "% " << line << "\n";
  char buf[320];
  std::snprintf(
      buf, sizeof buf,
      "rollnoise contact point: y = %.6g mm, s_wheel = %.6g mm, delta = %.6g rad, r = %.6g mm; "
      "mean "
      "creepage (%.6g, %.6g, %.6g rad/m): xi_x by VPITCH, xi_y by VY, spin from CONTACT's geometry",
      p.y * kMm, p.wheel_s * kMm, p.contact_angle, p.rolling_radius * kMm, c.creepage.xi_x,
      c.creepage.xi_y, c.creepage.phi);
  s << "% " << buf << "\n";
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
  s << numbers({track.gauge_point_depth * kMm, 0.0, track.gauge * kMm, 0.0, 0.0})
    << "      GAUGHT, GAUGSQ, GAUGWD, CANT, CURV\n";
  s << "  '" << rail_file << "'   0     1.0   0.0       RFNAME, MIRRORY, SCALE, SMOOTH\n";
  s << "     0.0    0.0   0.000   0.0   0.0   0.000     DY, DZ, ROLL, VY, VZ, VROLL\n";
  s << numbers({ws.back_to_back * kMm, -ws.taping_line_offset * kMm, ws.nominal_radius * kMm})
    << "                         FBDIST, FBPOS, NOMRAD\n";
  s << "  '" << wheel_file << "'   0     1.0   0.0       WFNAME, MIRRORY, SCALE, SMOOTH\n";
  // the roll of rollnoise's equilibrium pose (both wheels touching), as the C1 reference run
  s << numbers({0.0, c.wheelset.lateral * kMm, c.normal_force, p.pose.roll, c.wheelset.yaw, 0.0})
    << "      S, Y, FZ, ROLL, YAW, PITCH\n";
  s << numbers({V, vy, 0.0, 0.0, 0.0, vpitch}) << "   VS,VY,VZ, VROLL,VYAW,VPITCH\n";
  s << " 0 MODULE\n";
  return s.str();
}

}  // namespace rollnoise::io
