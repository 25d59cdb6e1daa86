// A CONTACT run in a folder as a reference for rollnoise (`validate --reference contact DIR`,
// `steady --reference contact DIR`; docs/contact_interop.md Sec. 3): its forces per case in
// rollnoise's conventions and SI, the case times, and the traction field of its first case.
//
// Conventions (CONTACT -> rollnoise):
//   module 3: body 1 is the body rollnoise calls the wheel, so (FX, FY, MZ) map as they are:
//             Fx = FX, Fy = FY (N), Mz = MZ * 1e-3 (N mm -> N m), tractions on body 1;
//   module 1: body 1 is the rail, forces act on the rail in the patch frame (x, s, n):
//             Fx = -FX, Fy = -FS, Mz = -MN * 1e-3, tractions negated.
//   Time: case 1 is the steady state at t = 0, case n > 1 the step k = n - 1 at t_k = k DQ/VELOC
//   (DQ, VELOC from the .inp, which must lie beside the .out).
//   Forces: the 4 printed digits of the .out; where the case's .mat file is present, also its
//   6-digit integrated totals (force_integrated, NaN where absent).
#pragma once

#include <Eigen/Dense>
#include <optional>
#include <string>
#include <vector>

#include "io/contact_results.hpp"

namespace rollnoise::io {

struct ContactReference {
  std::string folder, out_path, inp_path;
  int module = 3;
  double dt = 0.0;                                ///< DQ/VELOC (s)
  std::vector<double> time;                       ///< s, one per case
  std::vector<Eigen::Vector3d> force;             ///< printed (Fx, Fy, Mz) in N, N, N m
  std::vector<Eigen::Vector3d> force_integrated;  ///< from the .mat files, NaN where absent
  std::vector<double> normal_force;               ///< printed FN (N)
  std::optional<ContactMat> first_tractions;      ///< the .mat of case 1, if present
};

/// Reads the CONTACT run in `folder`: exactly one `.out`, the `.inp` of the same name, and the
/// `.mat` files NAME.NNNN.mat (module 3) or NAME.NNNNa.mat (module 1, first patch) that are there.
/// InputError naming the folder or file (and line) when the folder does not hold one run, a file is
/// bad or cut short, or the .inp and .out disagree on the number of cases. Module 1: one patch per
/// case is required.
ContactReference read_contact_reference(const std::string& folder);

/// A traction field of CONTACT on rollnoise's grid layout [iy][ix] (SI: Pa, m): pn, px, py in
/// rollnoise's conventions (module 1 negated), state = IGS (0 exterior, 1 adhesion, 2 slip), and
/// the element centres x, y (m).
struct ContactTractionField {
  int nx = 0, ny = 0;
  std::vector<double> x, y, pn, px, py;
  std::vector<int> state;
};
ContactTractionField traction_field(const ContactMat& m, int module);

}  // namespace rollnoise::io
