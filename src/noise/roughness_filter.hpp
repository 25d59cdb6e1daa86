// The contact filter: the contact patch averages the roughness over its area, so roughness of
// wavelengths comparable with or shorter than the patch excites the wheel and rail less
// (Remington, JASA 81, 1987; Remington & Webb, JSV 193, 1996; Thompson, Railway Noise and
// Vibration, 2009, section on the contact filter; Ford & Thompson, JSV 293, 2006).
//
// Model. The effective (excitation) roughness is a weighted mean of the roughness r(x, y) over the
// elliptic contact area (semi-axes a along the rolling direction x, b laterally),
//   r_eff = Int w(x, y) r(x, y) dA / Int w dA,
// with one of two weightings:
//
//  * kElasticHalfSpace (default): the linearised Hertz contact. The change of the normal force
//    caused by a small interference r(x, y) over the (frozen) contact area is, by Betti's
//    reciprocity with the uniform-approach solution, Int q r dA with q the pressure under a rigid
//    flat punch of the patch's shape, q ~ 1/sqrt(1 - x^2/a^2 - y^2/b^2). The punch pressure is
//    exactly d p_Hertz / d(approach), so a uniform r reproduces the Hertz contact stiffness
//    (Johnson, Contact Mechanics, 1985, Sec. 3.5 and 4.2). Fourier transform:
//      W(kx, ky) = sin(rho) / rho,   rho = sqrt((kx a)^2 + (ky b)^2).                        (1a)
//  * kUniform: the plain area average of Remington (JSV 46, 1976) and Thompson (2009):
//      W(kx, ky) = 2 J1(rho) / rho.                                                          (1b)
//
// A roughness component of wavenumber k = 2 pi / lambda along the rail is filtered by |H(k)|^2:
//
//  * kCorrelated: roughness fully correlated across the patch width (r = r(x), the "1D" model):
//      |H(k)|^2 = |W(k a, 0)|^2   ( [sin(ka)/ka]^2 or [2 J1(ka)/ka]^2 ).                     (2)
//  * kIsotropic: statistically isotropic roughness whose line spectrum along the rail is a power
//    law S1(k) ~ k^{-n} (the idea of Remington 1987). Its 2D spectrum is then ~ kappa^{-(n+1)}
//    and, with ky = u k,
//      |H(k)|^2 = Int (1 + u^2)^{-(n+1)/2} |W(k a, u k b)|^2 du / Int (1 + u^2)^{-(n+1)/2} du, (3)
//    integrated with GSL (QAGIU). The lateral averaging adds attenuation; b -> 0 gives Eq. (2).
//
// In 1/3-octave bands the filter is averaged over the band, weighting |H|^2 with the roughness
// spectrum k^{-n}; the zeros of W are then not seen in band levels.
#pragma once

namespace rollnoise::noise {

enum class ContactFilterModel { kNone, kCorrelated, kIsotropic };
enum class ContactWeighting { kElasticHalfSpace, kUniform };

struct ContactFilter {
  ContactFilterModel model = ContactFilterModel::kIsotropic;
  ContactWeighting weighting = ContactWeighting::kElasticHalfSpace;
  double a = 0.0;                  ///< contact semi-axis in the rolling direction (m)
  double b = 0.0;                  ///< lateral semi-axis (m); used by kIsotropic
  double spectral_exponent = 2.0;  ///< n of S1(k) ~ k^{-n}: isotropic model and band weighting

  /// The contract (a > 0, b >= 0 for the isotropic model, 0 < n < 10): std::invalid_argument
  /// naming the field; the pipeline sets the fields from the patch and roughness.filter.
  void validate() const;

  /// |H(k)|^2 at wavenumber k = 2 pi / lambda (rad/m).
  double squared(double wavenumber) const;

  /// 10 log10 of |H|^2 averaged over the 1/3-octave band centred at `centre_wavenumber`, weighted
  /// with k^{-n} (dB, <= 0).
  double band_db(double centre_wavenumber) const;
};

}  // namespace rollnoise::noise
