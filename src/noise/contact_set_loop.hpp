// The rolling-noise loop with several contacts (docs/noise_loop.md Sec. 5.2): the contacts of a
// wheelset (both wheels, and each patch of a multi-patch contact) or of a bogie, coupled through
// the wheelset and through each rail.
//
// Unknowns: F_a = (Fz, Fx, Fy, Mz)_a, the force variation on the wheel at contact a in a's
// contact frame (loop.hpp, contact_set.hpp), a = 1..N. The wheel's contact point a moves by
// u_w,a = sum_b W_ab F_b, the rail's by u_r,a = sum_b R_ab (-F_b) (the rail carries -F_b at b),
// W and R the 4N x 4N block receptances of contact_set.hpp (M1). Each contact is the spring
// element (C1) of contact_receptance.hpp with its own receptance alpha_c,a (its normal stiffness,
// its creep coefficients f_a and normal-load coefficients g_a, C2-C3) and its own roughness r_a:
// e_a = u_w,a - u_r,a = -alpha_c,a F_a - r_a e_z. Hence
//
//   sum_b (W_ab + R_ab) F_b + alpha_c,a F_a = -r_a e_z,   a = 1..N,
//   (W + R + blockdiag(alpha_c,a)) F = -r (x) e_z                                            (M3)
//
// (N = 1: loop.hpp's L1). Without the cross terms (W_ab = R_ab = 0 for a != b) (M3) splits into N
// single-contact loops (L1), each with its contact's point receptances.
//
// Excitation (docs/noise_loop.md Sec. 5.2). The roughness is a set of E mutually uncorrelated
// sources: source e drives contact a with the amplitude rho_ae per unit of its roughness (an
// N x E matrix rho). Each tread contact has its own source (its wheel's and its rail's
// roughness): the two sides' roughnesses are independent, and so are two wheels' on one rail (the
// rail roughness the trailing wheel meets is the leading wheel's delayed by the wheelbase, but
// the delay's phase turns every V/l Hz (7.8 Hz at 70 km/h, l = 2.5 m), so its cross-spectrum
// averages out of 1/3-octave bands above some tens of Hz). A second patch of a wheel has no
// source of its own (rho = 0) unless one is given: it is excited through the coupling only.
// The response to source e is H_e = -(W + R + alpha_c)^{-1} (rho_e (x) e_z), and the power
// spectra add over the sources (Bendat & Piersol, Random Data, 2010, Ch. 7: the output spectrum
// of a linear system under uncorrelated inputs is the sum of |H_e|^2 S_e):
//
//   S_X(f) = sum_e |H_X,e(f)|^2 S_e(f),   L_X(b) = 10 log10 sum_e 10^{L_X,e(b)/10} (M4)
//
// with L_X,e the band level (B1) of bands.hpp of X under source e alone.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "dynamics/rail_model.hpp"
#include "noise/bands.hpp"
#include "noise/contact_set.hpp"
#include "noise/loop.hpp"

namespace rollnoise::noise {

/// The structures of a set of contacts at a list of frequencies (compute once, then solve for as
/// many contact models and roughness sources as needed).
struct ContactSetStructures {
  std::vector<double> frequency;  ///< Hz
  std::vector<ContactPoint> contacts;
  CrossCoupling cross;
  std::vector<ContactSetReceptance> receptance;  ///< one per frequency
};

/// The rail's transfers on the whole grid at once (a rail model may sample the grid); the wheel's
/// receptances and the assembly per frequency, the frequencies shared out in contiguous slices on
/// `threads` threads (each frequency computed alone: the same result for any count).
ContactSetStructures contact_set_structures(const dynamics::WheelModel& wheel,
                                            const dynamics::RailModel& rail,
                                            const std::vector<ContactPoint>& contacts,
                                            const std::vector<double>& frequencies,
                                            const CrossCoupling& cross = {}, int threads = 1);

/// rho of (M4) with one unit source per contact flagged `excited` (the others: zero rows).
Eigen::MatrixXd independent_sources(const std::vector<bool>& excited);

/// The loop's solution: per frequency, the forces and velocities of every contact (rows 4a .. 4a +
/// 3 for contact a) under each source (columns), per unit roughness of the source.
struct ContactSetLoopResult {
  std::vector<double> frequency;        ///< Hz
  std::vector<Eigen::MatrixXcd> force;  ///< 4N x E: (Fz, Fx, Fy, Mz) of each contact, contact frame
  std::vector<Eigen::MatrixXcd>
      wheel_velocity;  ///< 4N x E: (z, x, y, rot z), each contact's local frame
  std::vector<Eigen::MatrixXcd> rail_velocity;  ///< 4N x E
  Eigen::MatrixXd rho;                          ///< the sources' amplitudes at the contacts (N x E)
  int contacts() const { return force.empty() ? 0 : static_cast<int>(force.front().rows() / 4); }
  int sources() const { return force.empty() ? 0 : static_cast<int>(force.front().cols()); }
};

/// Solves (M3) at every frequency: `contact[a][k]` is contact a's alpha_c at frequency k (contact
/// frame, e.g. from contact_receptances(...) with its f, g and k_H); `sources` is rho (N x E). The
/// frequencies in contiguous slices on `threads` threads (the same result for any count).
ContactSetLoopResult solve_contact_set_loop(const ContactSetStructures& structures,
                                            const std::vector<std::vector<Receptance4>>& contact,
                                            const Eigen::MatrixXd& sources, bool velocities = true,
                                            int threads = 1);

/// (M3) at one frequency: F (4N x E) from the assembled total receptance and rho.
Eigen::MatrixXcd solve_contact_set_forces(const Eigen::MatrixXcd& total,
                                          const Eigen::MatrixXd& sources);

/// Contact a under source e as a single-contact LoopResult (for bands.hpp).
LoopResult contact_response(const ContactSetLoopResult& result, int contact, int source);

/// Band levels (M4) of contact a: the power sum over the sources of (B1) with each source's own
/// effective roughness levels (`roughness_levels[e]`, dB re 1 um in the bands `centres`). Its
/// roughness_level is the power sum of the sources that drive contact a directly (rho_ae != 0).
BandLevels contact_band_levels(const ContactSetLoopResult& result, int contact,
                               const std::vector<double>& centres,
                               const std::vector<std::vector<double>>& roughness_levels);

}  // namespace rollnoise::noise
