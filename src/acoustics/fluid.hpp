// The acoustic medium and the time convention of the sound-radiation layer (docs/sound.md).
//
// Time convention: complex amplitudes X e^{+i omega t}, as in the rest of rollnoise (the
// receptances of dynamics/). The free-field Green's functions are then outgoing as
//   3D:  G(R) = e^{-i k R} / (4 pi R),
//   2D:  G(R) = -(i/4) H_0^(2)(k R),  H_0^(2) = J_0 - i Y_0,
// with k = omega / c. A time-averaged power of complex amplitudes is (1/2) Re(p v^*), so a
// velocity amplitude V has the mean square |V|^2 / 2.
//
// Radiation efficiency (Thompson, Railway Noise and Vibration, 2009, Sec. 6.1, Eq. 6.1):
//   sigma = W / (rho c S <v_n^2>),
// W the radiated power, S the radiating area and <v_n^2> the space- and time-averaged mean square
// of the normal velocity over it. Every sigma of this layer tends to 1 at high k a.
#pragma once

namespace rollnoise::acoustics {

/// Air at 20 degC and 101.325 kPa (ISO 9613-1 conditions): rho = 1.204 kg/m^3, c = 343.2 m/s.
struct Fluid {
  double density = 1.204;      ///< rho (kg/m^3)
  double sound_speed = 343.2;  ///< c (m/s)
  double impedance() const { return density * sound_speed; }  ///< rho c (Pa s/m)
};

}  // namespace rollnoise::acoustics
