// CONTACT module-3 input for Hertzian cases (contact_input.hpp). The digit lines and the order of
// the data lines follow CONTACT's user guide (Vollebregt, "User guide for CONTACT", module 3,
// Sec. 4) as the reference runs were written (tests/data/contact/raw).
#include "io/contact_input.hpp"

#include <cmath>
#include <cstdio>
#include <sstream>

#include "core/constants.hpp"
#include "core/errors.hpp"
#include "io/output_files.hpp"

namespace rollnoise::io {
namespace {

constexpr double kMpa = 1e-6;  // Pa -> N/mm^2

std::string solver_line() {
  return "   999   500    30    1   " + contact_number(kContactSolverEps) +
         "     MAXGS, MAXIN, MAXNR, MAXOUT, EPS\n";
}

std::string load_line(double force, const contact::Creepage& xi) {
  // CONTACT's CPHI is in rad/mm
  return "  " + contact_number(force) + "  " + contact_number(xi.xi_x) + "  " +
         contact_number(xi.xi_y) + "  " + contact_number(xi.phi / kMm) +
         "     FN, CKSI, CETA, CPHI\n";
}

/// SCALE of IPOTCN = -3: the grid must span +-scale a by +-scale b; InputError otherwise.
double hertz_scale(const pipeline::ContactCase& c) {
  const contact::Grid& g = c.grid;
  const double sx = -g.x_min / c.a, sy = -g.y_min / c.b;
  const bool centred = std::abs(g.x_min + 0.5 * g.nx * g.dx) <= 1e-9 * g.nx * g.dx &&
                       std::abs(g.y_min + 0.5 * g.ny * g.dy) <= 1e-9 * g.ny * g.dy;
  if (!centred || std::abs(sx - sy) > 1e-9 * sx)
    throw InputError(
        "grid.x_min",
        "contact-input: CONTACT's Hertzian grid (IPOTCN = -3) spans +-SCALE a by +-SCALE b; "
        "an explicit grid (grid.x_min ...) cannot be mapped");
  return sx;
}

/// The first case: new grid, material, geometry; steady rolling (T = 3) at the mean creepage.
/// `tractions_of_all_elements`: A = 2, O = 3 (a steady run); else A = 1, O = 2 (the start of a
/// transient run, as the reference run U1).
std::string steady_case(const pipeline::ContactCase& c, bool tractions_of_all_elements) {
  std::ostringstream s;
  const double facphi = c.spin_offset;
  s << " 3 MODULE\n";
  s << "  203100     P-B-T-N-F-S   PVTIME, BOUND, TANG, NORM, FORCE, STRESS\n";
  s << "  022020     L-D-C-M-Z-E   FRCLAW, DISCNS, INFLCF, MATER, RZNORM, EXRHS\n";
  s << (tractions_of_all_elements ? " 0002311" : " 0001211")
    << "   H-G-I-A-O-W-R HEAT, GAUSEI, IESTIM, MATFIL, OUTPUT, FLOW, RETURN\n";
  s << solver_line();
  s << load_line(c.normal_force, c.creepage);
  s << "  " << contact_number(c.mu) << "  " << contact_number(c.mu)
    << "                       FSTAT, FKIN\n";
  // FACPHI (the spin offset of the rigid slip, in DQ) is CONTACT's default 1/6 when left out
  const bool default_facphi = std::abs(facphi - 1.0 / 6.0) < 1e-12;
  s << "  0.0  " << contact_number(c.grid.dx * kMm) << "  " << contact_number(c.speed * kMm)
    << (default_facphi ? "" : "  " + contact_number(facphi))
    << (default_facphi ? "         CHI, DQ, VELOC\n" : "   CHI, DQ, VELOC, FACPHI\n");
  const double nu = c.material.nu, G = c.material.shear_modulus() * kMpa;
  s << "  " << contact_number(nu) << "  " << contact_number(nu) << "  " << contact_number(G) << "  "
    << contact_number(G) << "   POISS 1,2, GG 1,2\n";
  s << "   -3                                   IPOTCN\n";
  s << "  " << c.grid.nx << "  " << c.grid.ny << "  " << contact_number(c.a * kMm) << "  "
    << contact_number(c.b * kMm) << "  " << contact_number(hertz_scale(c))
    << "       MX, MY, AA, BB, SCALE\n";
  return s.str();
}

/// Step k of a transient run: continue from the previous case (P = 0), transient rolling (T = 2)
/// over DQ, friction, grid, material and geometry kept (L = 1, D = C = M = Z = 0).
std::string step_case(double force, const contact::Creepage& xi) {
  std::string s = " 3 MODULE\n";
  s += "  002100     P-B-T-N-F-S   PVTIME, BOUND, TANG, NORM, FORCE, STRESS\n";
  s += "  100000     L-D-C-M-Z-E   FRCLAW, DISCNS, INFLCF, MATER, RZNORM, EXRHS\n";
  s += " 0011111   H-G-I-A-O-W-R HEAT, GAUSEI, IESTIM, MATFIL, OUTPUT, FLOW, RETURN\n";
  return s + solver_line() + load_line(force, xi);
}

}  // namespace

std::string contact_number(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.15g", v);
  return buf;
}

std::vector<std::string> contact_input_comments(const std::string& case_name,
                                                const std::string& case_path,
                                                const std::string& what) {
  return {"written by rollnoise " + provenance().program_version +
              " (rollnoise contact-input) from case " + case_name + " (" + case_path + ")",
          what};
}

std::string module3_input(const pipeline::ContactCase& c, const std::vector<std::string>& comments,
                          const std::optional<ContactTransient>& transient) {
  if (c.geometry != "hertz")
    throw InputError("contact.geometry",
                     "contact-input: module 3 is written for contact.geometry = \"hertz\"");
  if (c.falling.active())
    throw InputError(
        "friction.law",
        "contact-input: friction.law = \"falling\" cannot be mapped to CONTACT (its falling laws "
        "L = 2..4 have other forms); use \"constant\"");
  std::ostringstream s;
  for (const auto& line : comments) s << "% " << line << "\n";
  char buf[256];
  std::snprintf(buf, sizeof buf,
                "E = %.6g Pa, nu = %.6g (G = %.10g N/mm2) both bodies; mu = %.6g Coulomb; V = %s "
                "mm/s; N = %s N; "
                "Hertz a = %.6g mm, b = %.6g mm; EPS = %g",
                c.material.E, c.material.nu, c.material.shear_modulus() * kMpa, c.mu,
                contact_number(c.speed * kMm).c_str(), contact_number(c.normal_force).c_str(),
                c.a * kMm, c.b * kMm, kContactSolverEps);
  s << "% " << buf << "\n";
  std::snprintf(
      buf, sizeof buf,
      "grid MX = %d, MY = %d, DX = DQ = %s mm, DY = %s mm, dt = DQ/V = %.6g s; FACPHI = %.6g",
      c.grid.nx, c.grid.ny, contact_number(c.grid.dx * kMm).c_str(),
      contact_number(c.grid.dy * kMm).c_str(), c.grid.dx / c.speed, c.spin_offset);
  s << "% " << buf << "\n\n";
  if (!transient) {
    std::snprintf(buf, sizeof buf,
                  "%% case 1: steady rolling, cksi = %.6g, ceta = %.6g, cphi = %.6g rad/m\n",
                  c.creepage.xi_x, c.creepage.xi_y, c.creepage.phi);
    s << buf << steady_case(c, true) << "\n 0 MODULE\n";
    return s.str();
  }
  s << "% case 1: steady state rolling at the mean creepage, t = 0\n" << steady_case(c, false);
  const auto& h = transient->history;
  for (long k = 1; k <= transient->steps; ++k) {
    const double t = double(k) * transient->dt;
    // the creepage rollnoise uses in step k (rolling.creepage_sampling); the load at t_k
    const contact::Creepage xi = h.step_creepage(c.sampling, k, transient->dt);
    std::snprintf(buf, sizeof buf, "\n%% case %ld: step %ld, t = %.6g s\n", k + 1, k, t);
    s << buf << step_case(c.normal_force + h.normal_variation(t), xi);
  }
  s << "\n 0 MODULE\n";
  return s.str();
}

}  // namespace rollnoise::io
