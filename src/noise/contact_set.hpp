// The structures seen by several wheel-rail contacts at once (docs/noise_loop.md Sec. 5.2): the
// block receptance matrix between N contacts of a bogie, wheel part and rail part, in each
// contact's own frame.
//
// Frames. Each contact i keeps the frame of the single-contact loop (loop.hpp, docs/noise_loop.md
// Sec. 1): x forward, y towards *its* wheel (the field side), z up; its contact angle, wheel shift
// and rail offset are given in that local frame, so a contact state computed for the outer wheel
// and a mirrored one for the inner wheel enter unchanged, and f and g of its contact model keep
// their meaning. The common frame of the bogie is the one of side +1 (y towards the side +1
// wheel). A contact on side -1 sees the common frame reflected in y:
//
//   u_local = P u_common,   P = diag(1, -1, 1, -1, 1, -1)   (order x, y, z, rot x, rot y, rot z;
//   rotations are pseudovectors: a reflection in y keeps rot y and flips rot x, rot z),
//
// P = P^T = P^{-1}. A structure's 6x6 transfer receptance between two points a, b of the common
// frame, alpha_ab (displacement at a per force at b), becomes in the local frames
// P_a alpha_ab P_b, and in the contact frames (loop.hpp, columns T(gamma) of contact_frame)
//
//   A_ab = T_a^T P_a alpha_ab P_b T_b                                                       (M1)
//
// Reciprocity alpha_ba = alpha_ab^T gives A_ba = A_ab^T, so the assembled 4N x 4N matrix is
// symmetric when every structure is reciprocal; for a = b on side +1 (M1) is to_contact_frame.
//
// Lever arms between two points (the two-point form of loop.hpp's L2): with L(d) = [[I, -S(d)],
// [0, I]], the receptance between the points P_a + d_a and P_b + d_b rigidly attached to P_a, P_b
// is L(d_a) alpha_ab L(d_b)^T                                                              (M2)
//
// The structures (what each model provides for a cross term):
//  * rigid wheelset: the free body's centre receptance -(1/omega^2) diag(1/M, 1/M, 1/M, 1/I_xx,
//    1/I_yy, 1/I_zz) moved by (M2) to both contacts, d = (0, side (y_c + shift), -R) in the
//    common frame: exact for any two contacts of one wheelset (both wheels, several patches);
//    contacts on different wheelsets: zero (the bogie frame's suspension is far softer, its
//    coupling is not modelled);
//  * flexible wheel: the modal table gives each mode's shape at ONE point (the nominal running
//    circle) in the four contact directions. The cross receptance between two points of the same
//    wheel uses those same modal amplitudes at both points, moved by the lateral shift of each
//    (M2, modal rotations about x and y zero as in loop.hpp). LIMITATION of the mode table: the
//    change of the mode shapes across the tread and onto the flange is not modelled; a flange
//    patch then moves with the tread's modal amplitudes. The FE wheel (WheelModel::follows_contact)
//    gives each contact its own shapes, in the point and the cross terms
//    (WheelModel::modal_cross_receptance). The two wheels of a wheelset have independent modes (no modal cross term);
//  * rail: each rail its own model (the two rails are uncoupled: no sleeper bending, no track
//    cross-coupling); between two contacts on the same rail, the rail model's receptance between
//    the two contact points (RailModel::contact_transfers, dynamics/track.hpp): the beams'
//    transfer between x_a and x_b (Eq. 2 of track.hpp for discrete support, the infinite beam at
//    x_a - x_b for continuous support, the rod in x) moved by (M2) to each contact's lateral
//    offset on the head; the waveguide loaded at both contact points (docs/models.md Sec. 2.8).
//    Both contacts of one rail share its local frame, so the block is the rail model's 6x6.
#pragma once

#include <Eigen/Core>
#include <memory>
#include <utility>
#include <vector>

#include "dynamics/rail_model.hpp"
#include "dynamics/track.hpp"
#include "dynamics/wheel.hpp"
#include "noise/loop.hpp"

namespace rollnoise::noise {

/// One contact of the bogie: which wheel, where on it and on the rail.
struct ContactPoint {
  int wheelset = 0;          ///< index of the wheelset (0 leading, 1 trailing, ...)
  int side = 1;              ///< +1 or -1: the wheel and rail of this side (the local frame, above)
  ContactPosition position;  ///< shift on the wheel, offset on the rail head, angle (local frame)
  double rail_x = 0.3;       ///< position along the rail (m), measured from a sleeper (discrete
                             ///< support; the leading axle at x, the trailing at x + wheelbase)
};

/// Which cross terms between different contacts are kept.
struct CrossCoupling {
  bool wheelset = true;  ///< rigid-wheelset receptance between contacts of one wheelset
  bool wheel = true;     ///< flexible wheel between two patches of one wheel
  bool rail = true;      ///< rail transfer between contacts on one rail
  /// All off: every contact alone, each block equal to the single-contact loop's.
  static CrossCoupling none() { return {false, false, false}; }
};

/// InputError naming `contacts[i].side` etc. for an empty set or a contact out of range.
void validate_contacts(const std::vector<ContactPoint>& contacts);

/// P of the header for side +1 / -1 (the identity or diag(1, -1, 1, -1, 1, -1)).
Eigen::Matrix<double, 6, 6> side_reflection(int side);

/// (M2): L(d_a) alpha L(d_b)^T (dynamics/rail_contact.hpp).
using dynamics::move_points;

/// The rail pairs of a contact set, (a, b) with a <= b on one rail (a == b, or b != a when
/// `cross.rail`), and each as the rail's pair of contact points (RailModel::contact_transfers).
struct ContactSetRailPairs {
  std::vector<std::pair<Eigen::Index, Eigen::Index>> index;
  std::vector<dynamics::RailContactPair> points;
};
ContactSetRailPairs contact_set_rail_pairs(const std::vector<ContactPoint>& contacts,
                                           const CrossCoupling& cross);

/// The structures between N contacts at one frequency, for the loop with several contacts.
/// `wheel` and `rail` (6N x 4N): block (a, b) is the displacement of contact a's point in a's
/// LOCAL 6-dof frame per unit contact-frame force of contact b, P_a alpha_ab P_b T_b; the 4N x 4N
/// contact-frame matrices (M1) are their rows T_a^T. Both structures as seen by the force on the
/// wheel (the rail carries -F; see contact_set_loop.hpp).
struct ContactSetReceptance {
  Eigen::MatrixXcd wheel6, rail6;  ///< 6N x 4N
  Eigen::MatrixXcd wheel, rail;    ///< 4N x 4N, (M1)
};

/// The assembly at one frequency (Hz) from the wheel model (all wheelsets alike), a rail model per
/// side (both sides alike here: `rail`) and the contacts; `cross` selects the cross terms.
ContactSetReceptance contact_set_receptance(const dynamics::WheelModel& wheel,
                                            const dynamics::RailModel& rail,
                                            const std::vector<ContactPoint>& contacts,
                                            double frequency, const CrossCoupling& cross = {});
/// The wheel's mode table at each contact's position on the tread (WheelModel::modes_at of the
/// contact's wheel_shift_y; for the FE wheel the shapes interpolated there), one per contact: they
/// do not depend on the frequency, so a sweep builds them once (contact_set_structures).
using ContactModeTables = std::vector<std::vector<dynamics::WheelMode>>;
ContactModeTables contact_mode_tables(const dynamics::WheelModel& wheel,
                                      const std::vector<ContactPoint>& contacts);

/// The same assembly with the rail's 6x6 of each of contact_set_rail_pairs(contacts, cross) at
/// this frequency given (a grid's worth computed at once: contact_set_structures) and the
/// contacts' mode tables built beforehand (`tables[a]` for contact a, contact_mode_tables): the
/// same result to the bit.
ContactSetReceptance contact_set_receptance(const dynamics::WheelModel& wheel,
                                            const std::vector<Receptance6>& rail_pairs,
                                            const std::vector<ContactPoint>& contacts,
                                            const ContactModeTables& tables, double frequency,
                                            const CrossCoupling& cross = {});

/// The 4N x 4N contact-frame blocks (M1) from 6x6 common-frame pieces: `alpha(a, b)` gives the
/// 6x6 receptance between contacts a and b already in a's and b's LOCAL frames (zero blocks are
/// allowed); used by the Laplace-domain assembly of squeal as well.
template <class Pair>
Eigen::MatrixXcd contact_frame_blocks(const std::vector<ContactPoint>& contacts, Pair alpha) {
  const Eigen::Index n = static_cast<Eigen::Index>(contacts.size());
  Eigen::MatrixXcd A = Eigen::MatrixXcd::Zero(4 * n, 4 * n);
  for (Eigen::Index a = 0; a < n; ++a) {
    const Eigen::Matrix<cdouble, 6, 4> Ta =
        contact_frame(contacts[a].position.contact_angle).cast<cdouble>();
    for (Eigen::Index b = 0; b < n; ++b) {
      const Eigen::Matrix<cdouble, 6, 4> Tb =
          contact_frame(contacts[b].position.contact_angle).cast<cdouble>();
      A.block<4, 4>(4 * a, 4 * b) = Ta.transpose() * alpha(a, b) * Tb;
    }
  }
  return A;
}

/// The common-frame point of contact a on its wheelset relative to the wheelset's centre:
/// (0, side (y_c + shift), -R).
Eigen::Vector3d wheelset_arm(const dynamics::RigidWheelset& w, const ContactPoint& c);

/// Rigid wheelset between contacts a and b in their local frames, -(1/omega^2) C_ab with C_ab
/// returned here (real): P_a L(d_a) diag(1/M, .., 1/I_zz) L(d_b)^T P_b; zero for different
/// wheelsets.
Eigen::Matrix<double, 6, 6> rigid_flexibility6(const dynamics::RigidWheelset& w,
                                               const ContactPoint& a, const ContactPoint& b);

/// Flexible wheel (modal part) between contacts a and b of the same wheel in the local frame from
/// the modal receptance at the reference point (limitation above); zero for different wheels.
Receptance6 wheel_modal_cross(const Receptance4& modal_at_reference, const ContactPoint& a,
                              const ContactPoint& b);


}  // namespace rollnoise::noise
