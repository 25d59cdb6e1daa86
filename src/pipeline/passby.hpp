// `rollnoise passby`: a train of bogie vehicles passing the EN ISO 3095 receiver, each of its
// wheels, rails and sleepers a moving source with the sound powers the noise pipeline computed
// for the bogie (pipeline/sound_power.hpp), the levels by the acoustics core
// (acoustics/passby.hpp, formulas there; docs/sound.md Sec. 6).
//
// The train: vehicles one behind the other, each of length L (over buffers), two two-axle bogies
// whose centres lie b apart, symmetric about the vehicle's middle, with the wheelbase w:
//   bogie centres at s_k + (L - b)/2 and s_k + (L + b)/2,  axles at a bogie centre -+ w/2,  (A1)
// s_k the vehicle's start behind the train's front (the sum of the lengths in front of it). The
// train length is l = Sum L; it moves at V in +x, its front passing the receiver at t = 0, so an
// axle d behind the front is at x(t) = -d + V t, and the pass-by time is T_p = l / V
// (EN ISO 3095:2013 3.5).
//
// Sources per axle (each of its two wheels; y > 0 is the receiver's side, which is the OUTER rail
// of a curve: the project's track y points towards the outer rail):
//   - the wheel: a point at its centre, (x, -+g, r0), g = 0.75 m half the distance between the
//     rail heads' centres (1435 mm gauge + 65 mm), r0 the nominal rolling radius (curve.
//     wheel_radius). Its power per band is split by the wheel's mode families
//     (SoundResult::contact_family): the axial family's share radiates as a dipole along the axle
//     (y: the wheel's web moving along the axle radiates like a piston, strongest on the axis),
//     the radial and circumferential share as a monopole (the tread's radial motion radiates
//     round the axle); without the families (no FE wheel) the whole power is a monopole;
//   - the rail: a line of exponentially decaying vibration centred on the contact, (x, -+g,
//     -0.08 m: mid-height of the 172 mm UIC60), with the decay rate of its vertical vibration
//     (SoundResult::decay_vertical; the vertical motion carries most of the rail's power under
//     rolling) and a monopole directivity: the rail's column holds its vertical and lateral
//     radiation together, so neither dipole alone describes it;
//   - the sleepers: a line at the ground plane (x, -+g, ground_level) with the same decay and a
//     monopole directivity; the sleeper's power is that of a baffled piston radiating into the
//     half space above the ballast (sound_power.hpp (S3)), which the monopole with its image
//     (Q = 1) at the plane is, whatever passby.ground says of the ground further out.
//
// Each wheel of the bogie (leading/trailing axle x outer/inner side) takes the powers of its own
// wheel from the noise run (contact_power, with its rail and sleepers under that wheel's contact);
// a wheel the run did not compute (curve.wheels) takes those of the same axle's other wheel, else
// of the other axle's wheel on its side, else of the first computed wheel (tangent track: the two
// sides are one model; the run computes the leading outer wheel alone by default). Every bogie of
// the train is that bogie.
//
// Levels (acoustics/passby.hpp (E1)-(E3)): L_pAeq,Tp over [0, T_p), TEL over the whole history,
// L_pAFmax; per band and source the unweighted L_eq over the same [0, T_p), so that the
// A-weighted power sum of the total column is L_pAeq,Tp. The history spans the passage with a
// lead and a tail of max(10 d, 50 m) / V each (d the receiver's distance): beyond that the nearest
// axle is 10 d away and adds less than 0.05 dB to TEL.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "acoustics/passby.hpp"
#include "noise/wheel_contact.hpp"
#include "pipeline/sound_power.hpp"

namespace rollnoise::pipeline {

/// One vehicle of the train (m).
struct Vehicle {
  double length = 26.4;          ///< over buffers
  double bogie_distance = 19.0;  ///< between the bogie centres
  double wheelbase = 2.5;        ///< of each bogie
};

/// An axle of the train.
struct Axle {
  double from_front = 0.0;  ///< distance behind the train's front (m)
  bool leading = true;      ///< the leading axle of its bogie
};

/// (A1): every axle of `train` (front to rear), four per vehicle.
std::vector<Axle> train_axles(const std::vector<Vehicle>& train);
/// l = Sum L (m).
double train_length(const std::vector<Vehicle>& train);

/// For each wheel of the bogie (noise::WheelId order) the index into `wheels` (the computed wheels)
/// whose powers it takes: itself, the same axle's other wheel, the other axle's wheel on its side,
/// else the first (the rule above). `wheels` not empty.
std::array<std::size_t, 4> bogie_sources(const std::vector<noise::WheelId>& wheels);

/// What a pass-by needs besides the noise run (read by io from [train] and [passby]).
struct PassbyCase {
  std::vector<Vehicle> train;
  acoustics::PassbyGeometry geometry;  ///< passby.distance, passby.height, passby.ground
  double wheel_radius = 0.46;          ///< r0: the wheel centre's height above the rail (m)
  double time_step = 0.01;             ///< of the history (s), passby.time_step
  /// the rails' line sources (passby.rail_directivity): the monopole of the header, or a dipole
  /// along z or y (the rail's vertical or lateral motion alone)
  acoustics::Directivity rail_directivity = acoustics::Directivity::kMonopole;
  std::string category;                ///< passby.category; empty: none
  int threads =
      1;  ///< for the lines' bands (solver.threads resolved; the result does not depend on it)
};

/// The sources' places across the track and in height (m), named once.
constexpr double kRailHalfDistance = 0.75;   ///< g: rail head centre from the track centre
constexpr double kRailCentreHeight = -0.08;  ///< the rail's centre below its top

struct PassbyResult {
  double speed = 0.0;         ///< V (m/s)
  double passage_time = 0.0;  ///< T_p = l / V (s)
  double length = 0.0;        ///< l (m)
  std::vector<Axle> axles;
  std::vector<double> time;                     ///< s
  std::vector<double> level_a;                  ///< L_pAF(t), dB(A) re 20 uPa
  double leq_a = 0.0, tel = 0.0, lmax_a = 0.0;  ///< dB(A) re 20 uPa
  std::vector<double> centre;                   ///< band centres (Hz)
  /// L_eq over [0, T_p) per band: [wheel, rail, sleepers, total], dB re 20 uPa
  std::vector<std::array<double, 4>> spectrum;
  std::array<double, 4> spectrum_a{};  ///< the columns' A-weighted sums, dB(A)
  double leq_a_80 = 0.0;               ///< (T1) of acoustics/tsi_noise.hpp
  double limit_a = 0.0;                ///< TSI limit of the category; NaN without one
  /// For each wheel of the bogie (noise::WheelId order) the computed wheel whose powers it took.
  std::array<noise::WheelId, 4> source_wheel{};
  bool wheel_split = false;  ///< the wheel's power split by its mode families (else monopole)
  double seconds = 0.0;
};

/// The pass-by of `pc.train` at `speed` (m/s) with the powers `sound` of the computed wheels
/// `wheels` (contact_power[i] is wheels[i]'s). std::invalid_argument for a train without
/// vehicles or sound without powers.
PassbyResult run_passby(const PassbyCase& pc, const SoundResult& sound,
                        const std::vector<noise::WheelId>& wheels, double speed);

}  // namespace rollnoise::pipeline
