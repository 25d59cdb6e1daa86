// The product u = A p of the half-space influence matrix with a traction field, behind one `apply`.
//
// A is block-Toeplitz (InfluenceTable), so A p is a discrete convolution. Two backends compute it:
//   Fft    zero-pad the nx by ny grid to 2nx by 2ny, embed the kernel as a circulant and multiply
//          in Fourier space (FFTW, real-to-complex): O(N log N) per product, exact to round-off.
//   Dense  assemble the full matrix once (Eigen) and multiply: O(N^2), faster for small grids.
// Auto picks Dense up to a size measured with bench/ (see docs/accuracy.md, "Benchmarks").
//
// `column_shift` = 1 gives the matrix A0 of the rolling step (Kalker 1990, Sec. 5.3;
// docs/conventions.md Secs. 1-2): the influence at x_I + dx of the previous position, A0(I,J) = A(di + 1, dj).
#pragma once

#include <functional>
#include <memory>

#include "contact/influence.hpp"

namespace rollnoise::contact {

enum class Backend { Auto, Fft, Dense };

/// Normal: u_z = A_zz p_z, one component. Tangential: (u_x, u_y) = [A_xx A_xy; A_xy A_yy](p_x, p_y).
enum class Problem { Normal, Tangential };

/// A block-Toeplitz kernel: the coefficient of component c for the element offset (di, dj),
/// di in [-(nx-1), nx-1], dj in [-(ny-1), ny-1].
using ToeplitzKernel = std::function<double(Component c, int di, int dj)>;

class HalfSpaceOperator {
 public:
  HalfSpaceOperator(const InfluenceTable& table, Problem problem, int column_shift = 0,
                    Backend backend = Backend::Auto);
  /// Any block-Toeplitz operator on the grid with the structure of `problem` (e.g. the slip
  /// operator S of slip_operator.hpp): the same backends, the same `apply`.
  HalfSpaceOperator(const Grid& grid, Problem problem, const ToeplitzKernel& kernel,
                    Backend backend = Backend::Auto);
  ~HalfSpaceOperator();
  HalfSpaceOperator(HalfSpaceOperator&&) noexcept;
  HalfSpaceOperator& operator=(HalfSpaceOperator&&) noexcept;

  /// Number of values in p and u: components x elements, component-major ([c][iy][ix]).
  int size() const;
  Backend backend() const;
  /// u = A p. p and u hold size() values; they may not alias.
  void apply(const double* p, double* u) const;

  /// The backend Auto chooses for this many unknowns (components x elements).
  static Backend auto_backend(int unknowns);

  /// The inverse of the FFT backend's circulant embedding of the tangential kernel of `table`
  /// (shift 0): per bin of the zero-padded periodic grid the 2 x 2 symbol [xx xy; xy yy] (real
  /// symmetric: the kernels are even under (di, dj) -> (-di, -dj)) is inverted, its eigenvalues
  /// floored at `floor` times the self-compliance min(A_xx, A_yy)(0, 0): the truncated, zero-padded
  /// kernel is not positive definite at every bin (measured on 68 x 50: 17 of 6800 bins slightly
  /// negative), while the smallest true eigenvalues are of the order of the self-compliance.
  /// Restricted to part of the grid it approximates the inverse of A restricted there (the
  /// preconditioner of nss/reduced_form.cpp). With `diagonal` > 0 the symbol inverted is that of
  /// A + diagonal I (the eigenvalues floored first, then shifted).
  static HalfSpaceOperator inverse_circulant(const InfluenceTable& table, double floor, double diagonal = 0.0);

  class Impl;

 private:
  explicit HalfSpaceOperator(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace rollnoise::contact
