// The radiation of the structures, independent of the case's contact (docs/sound.md Sec. 2-4):
// what the sound power needs of the wheel's surface and of the rail's section, tabulated on a
// frequency grid once, so that a run from the cache (io/radiation_cache.hpp) repeats none of it.
//
// Wheel (docs/sound.md Sec. 2). The FE wheel's section boundary (its mesh's boundary edges, each
// split at its mid-side node into two straight boundary elements) is the generator of an
// axisymmetric surface; each mode k of order n moves it with the normal velocity amplitude
// v_k(s) = i omega q_k (U_r n_r + U_z n_z)(s) cos(n theta) (wheel_fe.hpp: U_theta is tangential to
// the surface and does not radiate). For the modes of one order n and one set (cos or sin; the two
// sets radiate alike and without cross power, their patterns being orthogonal in theta) the
// axisymmetric BEM (acoustics/axisymmetric_bem.hpp) gives the Hermitian matrix P_n(f) with
//
//   W_n = vdot^H P_n(f) vdot,   vdot = i omega q (the modal velocity amplitudes)             (W3)
//
// the time-averaged power, modal cross terms included. The bore, clamped, has zero velocity; the
// axle, the other wheel and the bogie are not in the model (docs/sound.md Sec. 6).
//
// Rail (docs/sound.md Sec. 3). The 2D BEM of the section (acoustics/bem2d.hpp) gives the power per
// unit length of the section moving as a rigid body, vertically and laterally, per unit velocity
// amplitude squared: W' = P_v |V_z|^2 + P_l |V_y|^2 (the symmetric section radiates no cross power
// between the two, its patterns being even and odd in y). Optionally over a rigid ground plane at
// the foot (sound.rail_ground = "rigid").
//
// The grids: radiation_grid(centres, per_band), log-spaced over the bands' edges; values between
// them are interpolated linearly in log f (grid_place): the radiation has no resonance (the BEM's
// irregular frequencies are removed by CHIEF), so a few points a band hold the band levels
// (docs/sound.md Sec. 5, measured against twice as many).
#pragma once

#include <Eigen/Core>
#include <vector>

#include "acoustics/bem2d.hpp"
#include "acoustics/fluid.hpp"
#include "dynamics/wheel_fe.hpp"

namespace rollnoise::pipeline {

/// `per_band` log-spaced frequencies per 1/3 octave from the lower edge of the first band to the
/// upper edge of the last (Hz, ascending): kRailGridPerBand for the rail's tables,
/// kWheelGridPerBand for the wheel's (docs/sound.md Sec. 5: the wheel's modal efficiencies vary by
/// a factor 2 within a sixth of an octave at 1-3 kHz; 6 a band hold its band levels within 0.2 dB
/// of 12 a band).
std::vector<double> radiation_grid(const std::vector<double>& centres, int per_band);
constexpr int kRailGridPerBand = 6;
constexpr int kWheelGridPerBand = 6;

/// Position of f on `grid` for linear interpolation in log f: the lower index i and the weight w of
/// grid[i + 1] (clamped to the grid's ends).
struct GridPlace {
  std::size_t i = 0;
  double w = 0.0;
};
GridPlace grid_place(const std::vector<double>& grid, double f);

/// The wheel's radiation by order (W3).
struct WheelRadiation {
  std::vector<double> frequency;  ///< the grid (Hz)
  struct Order {
    int n = 0;
    std::vector<int> modes;  ///< index into WheelFeModes::modes, ascending
    /// P_n at each grid frequency (modes x modes, W per (m/s sqrt(kg))^2 of modal velocity)
    std::vector<Eigen::MatrixXcd> power;
  };
  std::vector<Order> orders;
  /// Each mode's radiation efficiency sigma_k(f) = P_kk / (rho c S <v_n^2>) on the grid, in the
  /// order of `orders` and their modes.
  std::vector<std::vector<double>> efficiency;
  /// Each efficiency column's mode: its family (dynamics::ModeFamily as int: 0 axial, 1 radial,
  /// 2 circumferential) and nodal circles, as the FE wheel classifies it.
  std::vector<int> family, nodal_circles;
  double surface = 0.0;  ///< the radiating surface (m^2): the section boundary swept around
  int elements = 0;      ///< boundary elements of the generator
};

/// The radiation of the modes of `w` with n >= n_min (w from wheel_fe_modes: with its mesh and
/// section shapes) on `grid`. std::invalid_argument for modes without section shapes.
/// The grid's frequencies on `threads` threads (the same result for any number). `per_edge`:
/// boundary elements a quadratic edge of the FE mesh (1: the mesh's 8 mm edges, 8.6 elements a
/// wavelength at 5 kHz; 2: each edge split at its mid-side node; docs/sound.md Sec. 2 compares
/// them).
WheelRadiation wheel_radiation(const dynamics::WheelFeModes& w, int n_min,
                               const std::vector<double>& grid, const acoustics::Fluid& fluid,
                               int threads = 1, int per_edge = 1);

/// The rail section's radiation per unit length.
struct RailRadiation {
  std::vector<double> frequency;       ///< the grid (Hz)
  std::vector<double> vertical;        ///< P_v (W/m per (m/s)^2 velocity amplitude)
  std::vector<double> lateral;         ///< P_l
  std::vector<double> sigma_vertical;  ///< P_v / (rho c (1/2) Int n_z^2 ds)
  std::vector<double> sigma_lateral;   ///< P_l / (rho c (1/2) Int n_y^2 ds)
  bool ground = false;                 ///< over a rigid plane at the foot
};

/// The rail section's BEM options at wavenumber k (1/m): 10 elements a wavelength over the
/// outline's perimeter (within 0.5 % of 4 times as many, bem2d_test), at least 40 and at most 400;
/// `ground`: a rigid plane at the foot's lowest z.
acoustics::Bem2dOptions rail_bem_options(const std::vector<Eigen::Vector2d>& outline, bool ground,
                                         double k);

/// `outline`: the section (y, z) in m, closed polygon (dynamics::uic60_outline() or
/// track.rail_section); `ground`: a rigid plane at the foot's lowest z.
/// 10 boundary elements a wavelength (at least 40); the grid on `threads` threads.
RailRadiation rail_radiation(const std::vector<Eigen::Vector2d>& outline, bool ground,
                             const std::vector<double>& grid, const acoustics::Fluid& fluid,
                             int threads = 1);

}  // namespace rollnoise::pipeline
