// Writing CONTACT's input (.inp) for a rollnoise case (`rollnoise contact-input`,
// docs/contact_interop.md): the same problem for the stand-alone program of Vollebregt & Kalker.
//
//   module 3 (basic contact problems), Hertzian cases: IPOTCN = -3 (semi-axes a, b, the grid over
//     +-scale a by +-scale b), N = 1 (normal force prescribed), Coulomb friction (L = 0),
//     analytical half-space coefficients (C = 2), the spin offset as FACPHI;
//       steady: one case T = 3 at the mean creepage, `.mat` of every element (A = 2, O = 3);
//       transient: case 1 the steady state at the mean creepage, then one case per time step
//       (T = 2, DQ = DX: one element per step, dt = dx/V) with the creepage rollnoise uses in that
//       step (rolling.creepage_sampling) and the normal load at t_k, as CONTACT's reference runs;
//   module 1 (wheel-rail contact), profile cases: contact_input_wheelrail.hpp.
//
// Values in CONTACT's units (mm, N, N/mm^2, mm/s, rad/mm). What cannot be mapped (falling friction,
// an explicit grid, transient.start = "zero") is refused with an InputError naming the key.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "contact/creepage_history.hpp"
#include "pipeline/contact_case.hpp"

namespace rollnoise::io {

/// A transient run: the history, its number of steps and the step dt = dx/V (s).
struct ContactTransient {
  contact::CreepageHistory history;
  long steps = 0;
  double dt = 0.0;
};

/// CONTACT's solver tolerance EPS in every case written (that of the reference runs; CONTACT's
/// default is 1e-5). The iteration limits are MAXGS = 999, MAXIN = 500, MAXNR = 30, MAXOUT = 1.
constexpr double kContactSolverEps = 1e-8;

/// The comment lines that open every input written: program, version, case name and path.
std::vector<std::string> contact_input_comments(const std::string& case_name,
                                                const std::string& case_path,
                                                const std::string& what);

/// The module-3 input of a Hertzian case `c` (placed): steady without `transient`, else the
/// steady state followed by transient.steps step cases. `comments` open the file ('% ' added).
/// InputError naming the key that cannot be mapped.
std::string module3_input(const pipeline::ContactCase& c, const std::vector<std::string>& comments,
                          const std::optional<ContactTransient>& transient);

/// "%.15g": the digits CONTACT's reference inputs carry.
std::string contact_number(double v);

}  // namespace rollnoise::io
