// What a wheel mode is called: its family from the whole section's motion, its nodal circles, and
// a label that no other mode of the wheel shares (docs/models.md Sec. 3.4, "Classification").
//
// The families of the wheel-noise literature (Thompson, Railway Noise and Vibration, 2009,
// Sec. 5.2; Thompson, J. Sound Vib. 161 (1993) 401-419): axial (out-of-plane: the web bends,
// with 0, 1, 2 ... nodal circles), radial and circumferential (in-plane: the rim and web move in
// their own plane, radially or tangentially). A family is a property of the whole wheel, not of
// the tread: the one-nodal-circle axial modes rock the rim, and the rocking moves the tread more
// radially than axially, so a classification by the tread's dominant direction names them radial
// (it did: each n >= 2 had two "radial, 0 circles" modes on the 920 mm wheel).
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

namespace rollnoise::dynamics {

enum class ModeFamily;
struct WheelFeMode;

/// The family from the kinetic energy shares (U_r, U_theta, U_z) of the whole section
/// (fem::kinetic_energy_shares, summing to 1): axial when the out-of-plane share U_z exceeds the
/// in-plane share U_r + U_theta; otherwise radial or circumferential, whichever in-plane share is
/// larger.
ModeFamily section_family(const Eigen::Vector3d& kinetic_shares);

/// The displacement component (0: U_r, 1: U_theta, 2: U_z) whose sign changes along the section's
/// mid-line (hub to rim) are the family's nodal circles: the out-of-plane U_z for axial modes (the
/// web's nodal circles), the dominant in-plane one for the others.
int nodal_circle_component(ModeFamily family);

/// "FAMILY n=N C circles" (C = -1: not known, an imported mode).
std::string mode_label(const WheelFeMode& mode);

/// One label per mode, in the modes' order, no two alike: mode_label, and where several modes
/// share it (e.g. imported modes, whose nodal circles are unknown) " #1", " #2", ... in ascending
/// frequency (ties: in the modes' order).
std::vector<std::string> mode_labels(const std::vector<WheelFeMode>& modes);

}  // namespace rollnoise::dynamics
