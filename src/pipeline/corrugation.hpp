// `rollnoise corrugation` (docs/corrugation.md): which wavelengths a rail's roughness grows at,
// from the linearised contacts of the noise loop at the curve's mean state.
//
//   1. the wavelengths lambda (corrugation.wavelength_min .. _max, log-spaced) and f = V / lambda;
//   2. the noise loop on these frequencies (noise_pipeline.hpp run_noise_loop: curve state, every
//      contact's mean contact and linear model, the one loop of the contacts);
//   3. per contact a, its wear transfer T_a (nss/wear_transfer.hpp), on its own thread;
//   4. per rail R (outer +1, inner -1), a rail roughness r e^{ikX} met by contact b at distance
//      d_b behind the leading axle with the phase e^{-ik d_b} and seen by its frozen patch as
//      H_b(k) r (nss/wear_transfer.hpp W6): the sources of the loop combined
//      coherently, the inputs u_a = (xi~_a, Fz_a) of each contact a from its forces,
//      xi~ = -f^{-1} (F~t - g Fz) (noise/contact_receptance.hpp C3), and its wear per passage
//      relative to the roughness, G_a = e^{ik d_a} T_a u_a (the depth deepens the depression r:
//      loop.hpp's sign, so Re G_a > 0 grows the roughness);
//   5. the growth rate per passage, Re G: per contact, and per rail the sum over its contacts
//      (one bogie passage).
#pragma once

#include <complex>
#include <string>
#include <vector>

#include "nss/wear_transfer.hpp"
#include "pipeline/noise_pipeline.hpp"

namespace rollnoise::pipeline {

/// [corrugation] and [wear] of a case.
struct CorrugationCase {
  double wavelength_min = 0.01;  ///< corrugation.wavelength_min (m)
  double wavelength_max = 0.5;   ///< corrugation.wavelength_max (m)
  int points = 160;              ///< corrugation.points
  nss::WearLaw law;              ///< wear.law, wear.coefficient, wear.hardness
};

struct ContactCorrugation {
  noise::WheelId wheel = noise::WheelId::leading_outer;
  int side = 1;           ///< the rail it runs on: +1 outer, -1 inner
  double distance = 0.0;  ///< behind the leading axle (m)
  std::vector<nss::WearRow>
      transfer;  ///< T_a: depth per passage (m) per unit xi_x, xi_y, phi (rad/m), N~ (N)
  /// H_a(k) of (W6): the roughness its frozen patch sees per unit rail roughness (-)
  std::vector<std::complex<double>> filter;
  /// T_r,a(k) of (W8): depth per passage (m) per unit roughness from the roughness's own pressure
  /// within its patch at a given load
  std::vector<std::complex<double>> roughness_transfer;
  std::vector<Eigen::Vector4cd>
      input;  ///< u_a = (xi_x, xi_y, phi, Fz) per m of its rail's roughness
  std::vector<std::complex<double>> depth;  ///< G_a: depth per passage / roughness amplitude (-)
  std::vector<double> growth;               ///< Re G_a (1/passage)
  int steps = 0;                            ///< steps of the element fields' impulse response
  double seconds = 0.0;
};

struct RailCorrugation {
  int side = 1;                             ///< +1 outer, -1 inner
  std::vector<std::complex<double>> depth;  ///< sum of its contacts' G_a (-)
  std::vector<double> growth;               ///< Re of it: per bogie passage (1/passage)
};

/// A peak of what the loop responds to, to name the resonance behind a growing wavelength.
struct LoopPeak {
  double frequency = 0.0;  ///< Hz
  std::string label;
};

/// A range of wavelengths with positive growth on a rail, its largest growth and the loop's peak
/// nearest to it in frequency.
struct GrowingBand {
  int side = 1;
  double wavelength_min = 0.0, wavelength_max = 0.0, peak_wavelength = 0.0, peak_frequency = 0.0,
         peak_growth = 0.0;
  LoopPeak nearest;
};

struct CorrugationResult {
  NoiseResult noise;                          ///< the loop as run on `frequency` (no bands)
  std::vector<double> wavelength, frequency;  ///< m, Hz (f = V / lambda), wavelength decreasing
  std::vector<ContactCorrugation> contacts;   ///< the wheels of the loop, in its order
  std::vector<RailCorrugation> rails;         ///< outer then inner, each with at least one contact
  std::vector<LoopPeak> peaks;  ///< of the loop's forces and the structures, by frequency
  std::vector<GrowingBand> growing;
  double seconds_loop = 0.0, seconds_wear = 0.0, seconds_total = 0.0;
};

/// A contact's inputs and wear from its loop forces at one wavenumber (stage 4 of the header).
struct ContactWear {
  Eigen::Vector4cd input;          ///< u = (xi~x, xi~y, phi~, Fz) per m of roughness
  std::complex<double> depth = 0;  ///< G = e^{ik d} T u (W5): depth per passage / roughness
};

/// u and G of a contact from its loop force F = (Fz, Fx, Fy, Mz) (noise/loop.hpp L1, per unit
/// roughness), its creep coefficients f and, when not null, its normal-load coefficients g
/// (xi~ = -f^{-1} (F~t - g Fz), noise/contact_receptance.hpp C3), its wear transfer T (W4) at the
/// same frequency, the wear T_r of the roughness's own pressure in its patch (W8), the wavenumber
/// k (rad/m) and its distance d behind the leading axle (m): the contact meets the roughness
/// r^ e^{-ik d}, so G = e^{ik d} (T u + T_r e^{-ik d}) = e^{ik d} T u + T_r (W5).
ContactWear contact_wear(const Eigen::Vector4cd& force, const Eigen::Matrix3cd& creep,
                         const Eigen::Vector3cd* load, const nss::WearRow& transfer,
                         std::complex<double> roughness_transfer, double wavenumber,
                         double distance);

/// The whole command. InputError naming noise.contact_model with the Kalker contact (no patch
/// fields), corrugation.wavelength_min when the grid cannot resolve the shortest wavelength.
CorrugationResult run_corrugation(ContactCase c, const NoiseCase& nc, const CorrugationCase& cc);

/// The wavelengths of a case: `points` log-spaced from wavelength_max down to wavelength_min.
std::vector<double> corrugation_wavelengths(const CorrugationCase& cc);

/// The local maxima (over their neighbours) of |values| on the frequency axis, each with `label`.
std::vector<LoopPeak> local_peaks(const std::vector<double>& frequency,
                                  const std::vector<double>& values, const std::string& label);

/// The ranges of positive growth of a rail, each with the peak of `peaks` nearest its largest
/// growth in frequency.
std::vector<GrowingBand> growing_bands(const CorrugationResult& r, const RailCorrugation& rail);

}  // namespace rollnoise::pipeline
