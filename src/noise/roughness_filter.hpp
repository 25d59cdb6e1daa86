// The contact filter: the contact patch averages the roughness over its area, so roughness of
// wavelengths comparable with or shorter than the patch excites the wheel and rail less
// (Remington, JASA 81, 1987; Remington & Webb, JSV 193, 1996; Thompson 2009, Sec. 5.5;
// Ford & Thompson, JSV 293, 2006).
//
// Model: the effective (excitation) roughness is the average of the roughness r(x, y) over the
// elliptic contact area (semi-axes a along the rolling direction x and b laterally) with uniform
// weight. The averaging operator has the 2D Fourier transform
//
//   W(kx, ky) = 2 J1(rho) / rho,   rho = sqrt((kx a)^2 + (ky b)^2),                           (1)
//
// so a roughness component of wavenumber k = 2 pi / lambda along the rail is filtered with
// |H(k)|^2:
//
//  * kCorrelated: roughness fully correlated across the patch width (r = r(x), the "1D" model):
//      |H(k)|^2 = [2 J1(k a) / (k a)]^2,                                                     (2)
//    which falls off as 8/(pi (ka)^3) for ka >> 1 (Thompson 2009 Sec. 5.5.2 for the circle).
//
//  * kIsotropic: statistically isotropic roughness whose line spectrum along the rail is a power
//  law
//    S1(k) ~ k^{-n} (Remington 1987 uses this idea). Its 2D spectrum is then ~ kappa^{-(n+1)} and,
//    with ky = u k,
//      |H(k)|^2 = Int (1 + u^2)^{-(n+1)/2} |W(k a, u k b)|^2 du / Int (1 + u^2)^{-(n+1)/2} du, (3)
//    integrated with GSL (QAGIU). The lateral averaging adds attenuation; b -> 0 gives Eq. (2).
//
// In 1/3-octave bands the filter is averaged over the band, weighting |H|^2 with the roughness
// spectrum k^{-n} (the zeros of J1 are not seen in band levels).
#pragma once

namespace rollnoise::noise {

enum class ContactFilterModel { kNone, kCorrelated, kIsotropic };

struct ContactFilter {
  ContactFilterModel model = ContactFilterModel::kIsotropic;
  double a = 0.0;                  ///< contact semi-axis in the rolling direction (m)
  double b = 0.0;                  ///< lateral semi-axis (m); used by kIsotropic
  double spectral_exponent = 2.0;  ///< n of S1(k) ~ k^{-n}: isotropic model and band weighting

  /// Throws InputError naming the field.
  void validate() const;

  /// |H(k)|^2 at wavenumber k = 2 pi / lambda (rad/m).
  double squared(double wavenumber) const;

  /// 10 log10 of |H|^2 averaged over the 1/3-octave band centred at `centre_wavenumber`, weighted
  /// with k^{-n} (dB, <= 0).
  double band_db(double centre_wavenumber) const;
};

}  // namespace rollnoise::noise
