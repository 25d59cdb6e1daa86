// `rollnoise cnossos`: the case's rolling noise as the CNOSSOS-EU railway source model has it
// (Commission Directive (EU) 2015/996, Annex II, Sec. 2.3.2, as amended by Commission Delegated
// Directive (EU) 2021/1226): transfer functions from the total effective roughness to the sound
// power per axle, of the track (rail and sleepers) and of the vehicle (the wheels), per
// 1/3-octave band i of the 24 from 50 Hz to 10 kHz:
//   L_H,TR,i  = L_W,TR,axle,i  - L_R,TOT,i,   L_H,VEH,i = L_W,VEH,axle,i - L_R,TOT,i        (C1)
// with L_W,.,axle the bogie's powers per axle (dB re 1 pW: the four wheels of the bogie, each
// with the powers passby.hpp's bogie_sources gives it, halved) and L_R,TOT,i the effective
// roughness of the reported contact (dB re 1 um: rail and wheel roughness and the contact filter,
// which is (2.3.7)'s L_R,TOT = 10 lg(10^{L_r,TR/10} + 10^{L_r,VEH/10}) + A_3).
// The Directive's equations then give the source power of a vehicle with N_a axles and of a flow:
//   L_W,0,TR,i  = L_R,TOT,i + L_H,TR,i  + 10 lg N_a                                         (2.3.8)
//   L_W,0,VEH,i = L_R,TOT,i + L_H,VEH,i + 10 lg N_a                                         (2.3.9)
//   L_W,0,i = 10 lg(10^{L_W,0,TR,i/10} + 10^{L_W,0,VEH,i/10})                              (2.3.10)
//   L_W',eq,line,i = L_W,0,i + 10 lg(Q / (1000 v))                                          (2.3.2)
// Q vehicles per hour, v in km/h: dB re 1 pW per metre of track.
//
// Bands outside the case's (noise.band_min .. noise.band_max) are not computed: they take the
// value of the nearest computed band, and are listed as filled (CnossosTransfer::computed).
#pragma once

#include <array>
#include <vector>

#include "noise/wheel_contact.hpp"
#include "pipeline/sound_power.hpp"

namespace rollnoise::pipeline {

constexpr std::size_t kCnossosBands = 24;
using CnossosSpectrum = std::array<double, kCnossosBands>;

/// The nominal 1/3-octave centres 50 Hz ... 10 kHz (Hz).
const CnossosSpectrum& cnossos_centres();

struct CnossosTransfer {
  CnossosSpectrum track{}, vehicle{};          ///< L_H,TR,i and L_H,VEH,i (dB)
  CnossosSpectrum roughness{};                 ///< L_R,TOT,i (dB re 1 um)
  std::array<bool, kCnossosBands> computed{};  ///< false: filled from the nearest computed band
};

/// (C1) from the bogie's powers (`sound`, `wheels` the computed wheels as for run_passby) and the
/// effective roughness `roughness` in the same bands (dB re 1 um). std::invalid_argument when no
/// band of `sound` is one of the 24.
CnossosTransfer cnossos_transfer(const SoundResult& sound,
                                 const std::vector<noise::WheelId>& wheels,
                                 const std::vector<double>& roughness);

struct CnossosLinePower {
  CnossosSpectrum band{};  ///< L_W',eq,line,i (dB re 1 pW per metre)
  double total_a = 0.0;    ///< its A-weighted sum (dB(A) re 1 pW per metre)
};

/// (2.3.8)-(2.3.10), (2.3.2) for `axles` N_a per vehicle, `flow` Q (vehicles per hour) and
/// `speed` v (km/h).
CnossosLinePower cnossos_line_power(const CnossosTransfer& t, double axles, double flow,
                                    double speed);

}  // namespace rollnoise::pipeline
