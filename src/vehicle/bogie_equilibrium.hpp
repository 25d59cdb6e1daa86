// The quasi-static curving of a two-axle bogie in equilibrium on the exact contacts
// (docs/noise_loop.md Sec. 7.4): where the wheelsets and the bogie frame sit in a steady curve
// when every wheel's contact forces come from the same contact the noise loop runs on (profiles,
// the wheel lowered under its vertical load on the curved surface of the rail profile, Kalker's
// steady rolling solution at its kinematic creepages, noise/wheel_contact.hpp).
//
// Frame (as curving.hpp and the geometry layer): x forward, y lateral towards the OUTER rail,
// yaw positive turning the forward direction towards the outer rail; every body's lateral
// displacement and yaw are taken from the track centre line and the track tangent at its own
// station (the curve turns towards -y: the track heading at a station x ahead of the bogie centre
// is -x kappa, its centre line lies x^2 kappa / 2 inwards of the centre's tangent).
//
// Unknowns q = (y1, psi1, eps1, y2, psi2, eps2, yb, psib): lateral displacement, yaw (angle of
// attack) and rolling-speed excess (the axle turns at (1 + eps) V / r0) of the leading (axle at
// x1 = +a) and the trailing wheelset (x2 = -a), and the bogie frame's lateral displacement and yaw.
// Per axle i, the primary suspension's lateral deflection and yaw deflection relative to the
// frame (small angles; Wickens, Fundamentals of Rail Vehicle Dynamics, 2003, Sec. 2.3 and the
// chapter on curving; Iwnicki (ed.), Handbook of Railway Vehicle Dynamics, 2006, chapter on
// curving, the "bogie with flexible primary yaw" model):
//
//   d_i = y_i - yb - x_i psib - x_i^2 kappa / 2,    e_i = psi_i - psib - x_i kappa          (B1)
//
// with K_y = 2 k_y (the two axleboxes' lateral stiffness) and K_psi = 2 k_x b^2 (their
// longitudinal stiffness k_x at the lateral semi-spacing b) per wheelset. The equilibrium:
//
//   wheelset i, lateral:  F_i(y_i, psi_i, eps_i) - K_y d_i + m_w a_u                = 0
//   wheelset i, yaw:      M_i(y_i, psi_i, eps_i) - K_psi e_i                        = 0
//   wheelset i, spin:     T_i(y_i, psi_i, eps_i)                                    = 0
//   frame, lateral:       sum_i K_y d_i + (m_f + m_c / 2) a_u                       = 0
//   frame, yaw:           sum_i (K_psi e_i + x_i K_y d_i) - K_s (psib - s L kappa)  = 0      (B2)
//
// F_i, M_i: the lateral force (towards the outer rail) and the yaw moment about the axle's centre
// of the contact forces on the wheelset's two wheels,
//
//   F_i = sum_w F_lat,w,   M_i = sum_w (x_w F_lat,w - y_w F_x,w + s_w M_z,w cos(delta_w)),
//   T_i = sum_w r_w F_x,w                                                                   (B3)
//
// (T_i: the torque of the longitudinal creep forces about the axle, r_w the rolling radius; a
// free-rolling axle, no traction or braking, turns at the speed that makes it vanish).
// (track-frame forces on the wheel, WheelContact::force_track; x_w, y_w the contact point, y_w =
// +y_c outer, -y_c inner; M_z the spin moment of the patch about its normal, s_w = +1 outer, -1
// inner for the mirrored frame of the inner wheel). a_u = g h_d / s the unbalanced lateral
// acceleration of the cant deficiency h_d (s = 1.5 m, vehicle/cant.hpp); the car body carries
// half its mass on the bogie, its lateral share reaches the frame through the secondary
// suspension (the body in lateral equilibrium, its displacement not needed), and its yaw is held
// on the chord between the bogie centres, 2L apart: relative to the tangent at the bogie it is
// s L kappa (s = +1 the front bogie, -1 the rear one), against the secondary yaw stiffness K_s.
// The wheel loads are Q +- dQ (the load transfer (K4) of curving.hpp); roll and the vertical
// suspension are not solved.
//
// Solution: Newton's method on (B2) from a guess at the curve (BogieEquilibriumInput::guess: the
// quasi-static estimate's state, estimated_guess) to 1e-2 Q; where that does not lead there, a
// continuation from tangent track (t = 0, q = 0: the symmetric wheelset has no lateral force or yaw
// moment) to the curve (t = 1) in the curvature kappa = t / R, the cant deficiency t h_d and the
// load transfer t dQ. Both on the way (AxleQuery::coarse): the contacts solved on a third of the
// elements each way and settled to 1e-6, each continuation step to 1e-2 Q (1e-3 Q at t = 1); where
// they cannot lead it (a step below 1/64), the full contacts take over. The last digits at t = 1 on
// the full grid, settled to 1e-9, every contact started from the last iterate's with its grid kept
// where it lies on the rail (VerticalLoadInput::start), so that the residual varies smoothly; where
// that stalls (the onset of a two-point contact), on each contact's own grid. Jacobian: the
// suspension's part analytic, the contacts' 3 x 3 blocks d(F_i, M_i, T_i) / d(y_i, psi_i, eps_i) by
// forward differences (three more contact pairs per axle), then Broyden's rank-one updates. Steps:
// damped (at most 2 mm, 4 mrad and 1e-3, a backtracking line search on the residual norm, every
// iterate within |y| <= 10 mm); a continuation step whose Newton iteration fails is halved (down to
// 1/64). How a flange contact that comes or goes along the path is passed: the contacts are taken
// as two-point contacts where the gap has two minima (VerticalLoadInput::gap_regions) and with the
// axle's own rolling speed (axle_spin), so their forces stay continuous where the contact point
// jumps across the profile; where they turn steeply (the flange root) the line search and the
// smaller continuation steps keep the iterate on the branch. Converged when every equation of (B2)
// is within tolerance x Q (N, N m). docs/noise_loop.md Sec. 7.4 has the measurements behind each
// choice.
#pragma once

#include <array>
#include <functional>
#include <optional>
#include <vector>

#include "noise/wheel_contact.hpp"
#include "vehicle/curve_state.hpp"
#include "vehicle/vehicle_parameters.hpp"

namespace rollnoise::noise {

/// The forces of the contacts on one wheelset, (B3), with its two wheels' contact states.
struct AxleContactForces {
  double lateral = 0.0;                ///< F_i (N), towards the outer rail
  double yaw = 0.0;                    ///< M_i (N m), turning towards the outer rail
  double torque = 0.0;                 ///< T_i (N m) about the axle
  std::array<WheelContact, 2> wheels;  ///< outer, inner
};

/// One evaluation of an axle's contact forces: which axle at which state of the continuation,
/// and how its contacts are solved.
struct AxleQuery {
  int axle = 0;                          ///< 0 leading, 1 trailing
  double y = 0.0, psi = 0.0, eps = 0.0;  ///< m, rad, -
  double t = 1.0;  ///< continuation in [0, 1]: curvature t / R, load transfer t dQ
  /// On the way (the continuation): the contacts on a grid of half the elements each way and
  /// settled to 1e-7 (they only lead the way to the curve's state); false: the full grid,
  /// settled to 1e-9.
  bool coarse = false;
  /// The same axle at a nearby state to start from, its wheels' grids kept
  /// (VerticalLoadInput::start); null: each wheel's grid chosen for its state.
  const AxleContactForces* near = nullptr;
};

/// The contact forces of an axle. A function so that the solver can be checked on a model
/// contact; bogie_equilibrium uses contact_forces below.
using AxleForceFunction = std::function<AxleContactForces(const AxleQuery&)>;

/// A guess of the bogie's state in the curve, e.g. the quasi-static estimate (curving.hpp).
struct BogieGuess {
  std::array<double, 2> lateral{};  ///< y1, y2 (m)
  std::array<double, 2> yaw{};      ///< psi1, psi2 (rad)
  double bogie_lateral = 0.0;       ///< yb (m)
  double bogie_yaw = 0.0;           ///< psib (rad)
};

struct BogieEquilibriumInput {
  CurveStateInput curve;  ///< the profiles, material, grid, curve, friction, wheel load Q, h_cg
  VehicleParameters vehicle;
  /// Where Newton starts at the curve itself; where it does not lead there (or none is given),
  /// the continuation from tangent track.
  std::optional<BogieGuess> guess;
  double tolerance = 1e-6;     ///< on every equation of (B2), x Q (N, N m)
  int max_newton = 40;         ///< iterations per continuation step
  double lateral_step = 1e-7;  ///< forward-difference step in y (m)
  double yaw_step = 1e-7;      ///< forward-difference step in psi (rad)
  double spin_step = 1e-8;     ///< forward-difference step in eps (-)
};

struct BogieEquilibrium {
  std::array<double, 2> lateral{};  ///< y1, y2 (m), towards the outer rail
  std::array<double, 2> yaw{};      ///< psi1, psi2 (rad)
  std::array<double, 2> spin{};     ///< eps1, eps2 (-): rolling-speed excess
  double bogie_lateral = 0.0;       ///< yb (m)
  double bogie_yaw = 0.0;           ///< psib (rad)
  /// (B2) at the solution, in the order: leading lateral (N), yaw (N m), spin (N m); trailing
  /// lateral, yaw, spin; frame lateral (N), yaw (N m).
  std::array<double, 8> residual{};
  /// Every equation within the tolerance; false: the last digits stalled (the residual above says
  /// how far), their best iterate kept rather than failing the run.
  bool converged = true;
  int iterations = 0;                    ///< Newton iterations, all continuation steps
  int continuation_steps = 0;            ///< accepted steps in t
  int contact_evaluations = 0;           ///< axle contact-force evaluations (two wheels each)
  double unbalanced_acceleration = 0.0;  ///< a_u (m/s^2)
  double load_transfer = 0.0;            ///< dQ (N)
  /// The four wheels' contact states at the solution, in the order of kAllWheels.
  std::vector<WheelContact> wheels;
  double max_residual() const;
};

/// The contact forces (B3) of one axle from the wheels' contacts (wheel_contact) at loads
/// Q + t dQ (outer), Q - t dQ (inner), curvature t / R, as the solver needs them: every small-gap
/// region in the patch (a contact jump is a two-point contact, VerticalLoadInput::gap_regions),
/// the axle's own rolling speed (WheelContactInput::axle_spin), the grid and the lowering's
/// settling as AxleQuery::coarse says, started from AxleQuery::near.
AxleContactForces contact_forces(const CurveStateInput& in, double load_transfer,
                                 const AxleQuery& query);

/// The quasi-static estimate's state (curving.hpp, a rigid bogie: the frame where the axles put
/// it, no primary deflection) as a guess; none where the estimate has no answer (a profile pair
/// outside it, the flange friction at Nadal's limit).
std::optional<BogieGuess> estimated_guess(const CurveStateInput& in);

/// Solves (B2) for the input (the curve, the vehicle, Q); `forces` replaces the contacts (tests).
/// On tangent track (1/R = 0 and no cant deficiency) y, psi and the frame's q are 0 by symmetry
/// and only the axles' rolling speed is solved for (Newton from q = 0, no continuation).
/// NumericalError when the continuation step falls below 1/64; where the last digits stall, their
/// best iterate is kept (BogieEquilibrium::converged false, the residual says how far).
BogieEquilibrium solve_bogie_equilibrium(const BogieEquilibriumInput& in,
                                         const AxleForceFunction& forces = {});

}  // namespace rollnoise::noise
