// Mode shapes along the tread as a CSV table: the import of a user's FE modes (ANSYS, Abaqus,
// Code_Aster, CalculiX, ...) and the export of ours (`rollnoise modes --csv`), docs/interface.md
// "A user's FE modes" and docs/models.md Sec. 3.4.
//
// Format: '#' comment lines, the header
// `mode,n,frequency_Hz,damping_ratio,s_mm,r_mm,u_r,u_theta,u_z`, then one line per mode and tread
// point, the lines of a mode together and every mode on the same ascending list of s. s: lateral
// position on the running surface (mm, positive towards the field side, the profile coordinate); r:
// its radius (mm); (u_r, u_theta, u_z): the shape (m kg^-1/2) of the mass-normalised mode (phi^T M
// phi = 1 over the whole wheel: modal mass 1 kg) in the convention u_r = U_r cos n theta, u_theta =
// U_theta sin n theta, u_z = U_z cos n theta; damping_ratio 0: the case's by family
// (wheel.damping_*).
#pragma once

#include <string>

#include "dynamics/wheel_fe.hpp"
#include "io/output_files.hpp"

namespace rollnoise::io {

/// Reads a tread shapes file; InputError naming "path:line" and the field for a bad line, and the
/// file for an inconsistent table (modes on different s lists, s not ascending, no mode).
dynamics::WheelFeModes read_tread_shapes(const std::string& path);

/// Writes the modes' tread shapes (uncommitted, see write_text_file); damping_ratio as the modes
/// carry it (0 for ours: the case's by family). `option` names the output in messages.
TemporaryFile write_tread_shapes(const std::string& path, const std::string& option,
                                 const dynamics::WheelFeModes& w);

}  // namespace rollnoise::io
