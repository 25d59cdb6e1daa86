// The rail's surface in the wavenumber domain: what the sound radiation of a waveguide rail needs
// (pipeline/rail_section_sound.hpp; docs/sound.md Sec. 3.3).
//
// A waveguide rail's displacement per unit force of loads on its head, u(x; y, z), has along the
// rail the Fourier transform
//
//   U(kappa; y, z) = Int u(x; y, z) e^{i kappa x} dx,   u(x) = (1/2 pi) Int U(kappa) e^{-i kappa x}
//   dkappa
//
// (the waves e^{-i k x} of rail_waveguide.hpp). On the free or the continuously supported rail,
// Eq. (W4) transforms term by term: with Int_0^inf e^{-i k_j x} e^{i kappa x} dx = i / (kappa -
// k_j) and Int_-inf^0 e^{i k_j x} e^{i kappa x} dx = -i / (kappa + k_j) (Im k_j < 0),
//
//   G~(kappa) = A_+(r)^T diag(1 / (d_j (kappa - k_j))) A_-(f)
//             - A_-(r)^T diag(1 / (d_j (kappa + k_j))) A_+(f),                             (W7)
//
// the partial fractions of Q(kappa)^{-1} (A_s the waves' amplitudes of the response and load
// distributions, RailWaveguide::wave_amplitudes); a load at x_l multiplies its column by
// e^{i kappa x_l}. On discrete supports, Eq. (D3) of waveguide_discrete_support.hpp transforms the
// same way, each seat's force -K v_n a load of the foot at x_n:
//
//   U(kappa) = G~_rf(kappa) e^{i kappa x_l} - G~_r,foot(kappa) Sum_n K v_n e^{i kappa x_n}, (D4)
//
// v_n the seats' resultants of Eq. (D2) under the load at x_l (the 2N + 1 seats nearest it).
//
// The response distributions are the mean normal displacement over each piece of the outline,
// (1/l) Int_piece u . n ds, the piece's constant normal velocity in a boundary element model of the
// section's sound (u by the mesh's quadratic boundary edges, Gauss points along the piece).
#pragma once

#include <Eigen/Core>
#include <functional>
#include <vector>

#include "dynamics/receptance.hpp"
#include "fem/mesh.hpp"

namespace rollnoise::dynamics {

class RailWaveguide;
struct RailWaves;

/// A straight piece of the section's outline, (y, z) in m, with its outward unit normal.
struct OutlinePiece {
  Eigen::Vector2d start, end, normal;
};

/// A load on the rail's head: a contact at (offset_y, contact_angle) (as RailContactPoint) at x
/// (m along the rail, from a sleeper), four columns in its frame (Receptance4 order).
struct RailLoadPoint {
  double offset_y = 0.0;
  double contact_angle = 0.0;
  double x = 0.0;
};

/// Loads at RailLoadPoints as combinations of a model's load distributions (RailModel::load_basis):
/// the points' columns (4 a point, its frame) = the distributions at the distinct positions `x`
/// (per_position columns each, side by side) times `combination`.
struct RailLoadBasis {
  std::vector<double> x;        ///< the points' distinct positions, ascending (m along the rail)
  int per_position = 0;         ///< distributions a position
  Eigen::MatrixXd combination;  ///< (per_position x.size()) x (4 points)
};

/// The rail's surface spectrum at one frequency: U at the pieces per unit force of each load
/// column (m^2/N: m of displacement times m of rail, per N).
struct SurfaceSpectrum {
  /// U at each of `kappas` (rad/m), side by side: pieces x (columns x kappas.size()), the block
  /// of kappas[q] in columns [c q, c (q + 1)), c = 4 x points.
  std::function<Eigen::MatrixXcd(const std::vector<double>& kappas)> at;
  int columns = 0;
  /// The wavenumbers k_j (rad/m, Im k_j <= 0) of the waves behind it (the poles of U at +-k_j):
  /// where U varies fastest along the real kappa axis.
  Eigen::VectorXcd wavenumbers;
};

/// A rail's surface spectra for fixed loads and pieces, per frequency (Hz).
using SurfaceSpectra = std::function<SurfaceSpectrum(double frequency)>;

/// The response distributions of the pieces on the section `mesh` (3 x nodes rows, one column per
/// piece): the mean normal displacement over each piece. A piece off the mesh's boundary (by more
/// than 1e-6 m) is an error.
Eigen::MatrixXd outline_normal_distributions(const fem::QuadraticTriangleMesh& mesh,
                                             const std::vector<OutlinePiece>& pieces);

/// The waves' amplitudes of one frequency's distributions for both signs of x.
struct WaveAmplitudes {
  Eigen::MatrixXcd plus, minus;  ///< A_+(d), A_-(d): waves x columns
};
WaveAmplitudes wave_amplitudes(const RailWaveguide& rail, const RailWaves& w,
                               const Eigen::MatrixXd& d);

/// What Eq. (W7) / (D4) needs at one frequency; spectrum_of() evaluates it.
struct SpectrumTerms {
  Eigen::VectorXcd wavenumbers, norms;  ///< k_j, d_j
  WaveAmplitudes response, load;        ///< the pieces' and the loads' amplitudes
  std::vector<double> load_x;           ///< per load column (m)
  // Discrete supports (empty on the continuous one): the foot's amplitudes (4 columns), and per
  // load column the seats' forces K v_n (4 (2N + 1) rows) and the first seat's position.
  WaveAmplitudes foot;
  Eigen::MatrixXcd seat_forces;
  std::vector<double> first_seat_x;
  double spacing = 0.0;
  double seat_length = 0.0;  ///< each seat's force spread evenly over it (m): S times sinc
};
SurfaceSpectrum spectrum_of(SpectrumTerms terms);

/// The spectrum of loads made of `basis`'s columns: U_points(kappa) = U_basis(kappa) C at every
/// kappa (U linear in the loads), C = `combination` (basis.columns rows).
SurfaceSpectrum combined(SurfaceSpectrum basis, Eigen::MatrixXd combination);

/// The same per frequency: spectra of loads made of `basis`'s columns.
SurfaceSpectra combined(SurfaceSpectra basis, Eigen::MatrixXd combination);

/// Load columns `distributions` (dofs x c) placed at each of `x` (m along the rail), side by
/// side, with each column's position: the loads of a load basis (RailLoadBasis).
struct PlacedLoads {
  Eigen::MatrixXd load;   ///< dofs x (c x.size())
  std::vector<double> x;  ///< per column (m)
};
PlacedLoads placed_at(const Eigen::MatrixXd& distributions, const std::vector<double>& x);

/// Eq. (W7) on the free or continuously supported `rail` at angular frequency omega: the
/// spectrum of `response` (dofs() x pieces) per loads `load` (dofs() x c) at `load_x` (per column).
SurfaceSpectrum surface_spectrum(const RailWaveguide& rail, double omega,
                                 const Eigen::MatrixXd& response, const Eigen::MatrixXd& load,
                                 const std::vector<double>& load_x);

}  // namespace rollnoise::dynamics
