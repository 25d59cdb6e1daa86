// The files of a study (docs/study.md): each case's HDF5 (the `rollnoise noise` layout, plus the
// root attributes `study_case`, the case's parameters, and `run_time`), a case_NNNN.error text
// file for a case that failed, and the merged table study.h5 / study.csv that `collect` writes.
#pragma once

#include "core/constants.hpp"

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "io/case_reader.hpp"
#include "pipeline/noise_pipeline.hpp"
#include "pipeline/study_plan.hpp"

namespace rollnoise::io {

/// A case's results file: /noise/* as `rollnoise noise` writes it, then the study's attributes.
void write_study_case(const std::string& path, const CaseReader& reader, const pipeline::NoiseCase& nc,
                      const pipeline::NoiseResult& r, const std::string& stamp, double seconds);
/// The stamp of a complete case file (its `study_case` attribute); nullopt when the file is missing,
/// unreadable or not a study case.
std::optional<std::string> read_case_stamp(const std::string& path);

/// The error file of a failed case: its message (written whole or not at all).
void write_case_error(const std::string& path, const std::string& message);
std::optional<std::string> read_case_error(const std::string& path);

/// One wheel of curve.wheels in a case file (/noise/wheels/<name>): its contact state and bands.
struct WheelRecord {
  std::string name;                      ///< leading_outer, leading_inner, trailing_outer, trailing_inner
  std::array<double, 3> creepage{};      ///< xi_x, xi_y (-), phi (rad/m), the wheel's own contact frame
  double contact_angle = 0.0;            ///< rad
  double normal_force = 0.0;             ///< N
  double wheelset_lateral = kNaN;        ///< m, the wheel's axle towards the outer rail (NaN: not in the file)
  double wheelset_yaw = kNaN;            ///< rad, the wheel's axle
  double two_point = kNaN;               ///< 1: flange contact on this wheel's side, 0: none (NaN: not in the file)
  std::vector<double> force_level;       ///< nb x 4, as CaseRecord::force_level (on its band_centre)
  std::vector<double> velocity_level;    ///< nb x 2 x 4, as CaseRecord::velocity_level
};

/// What `collect` takes from a case file.
struct CaseRecord {
  double run_time = 0.0;                 ///< s
  std::array<double, 3> creepage{};      ///< xi_x, xi_y (-), phi (rad/m)
  double contact_angle = 0.0;            ///< rad
  double normal_force = 0.0;             ///< N
  long adhesion_elements = 0, slip_elements = 0;
  std::vector<double> band_centre;       ///< Hz
  std::vector<double> force_level;       ///< nb x 4, dB (Fz, Fx, Fy re 1 N; Mz re 1 N m)
  std::vector<double> velocity_level;    ///< nb x 2 x 4, dB re 1e-9 m/s, rad/s ([wheel, rail] x (z, x, y, rot z))
  std::vector<WheelRecord> wheels;       ///< /noise/wheels/*, in the order leading_outer ... trailing_inner
  /// /noise/sound/power_a: A-weighted sound power of wheel, rail, sleepers, total (dB(A) re 1 pW;
  /// NaN for a case run with noise.sound = "off")
  std::array<double, 4> sound_power_a{kNaN, kNaN, kNaN, kNaN};
};
/// nullopt when the file lacks what a noise case writes.
std::optional<CaseRecord> read_case_record(const std::string& path);

enum class CaseStatus { kComplete = 0, kFailed = 1, kMissing = 2, kStale = 3 };

/// One row per case of the study.
struct StudyRow {
  pipeline::StudyCase parameters;
  CaseStatus status = CaseStatus::kMissing;
  std::string message;  ///< the error of a failed case
  CaseRecord record;    ///< complete cases
};

/// study.h5 (/study/*) and study.csv: parameters, status, run time, mean state and band levels
/// (on the band centres of the first complete case; a case with other bands gets NaN there).
void write_study_table(const std::string& h5_path, const std::string& csv_path, const pipeline::StudyPlan& plan,
                       const std::vector<StudyRow>& rows);

}  // namespace rollnoise::io
