#include "contact/halfspace_operator.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <complex>
#include <vector>

#include "linalg/fft.hpp"

namespace rollnoise::contact {
namespace {

// Kernel blocks of the problem: for Normal {zz}; for Tangential {xx, xy; xy, yy} row-major.
std::vector<Component> blocks(Problem problem) {
  if (problem == Problem::Normal) return {Component::zz};
  return {Component::xx, Component::xy, Component::xy, Component::yy};
}

}  // namespace

class HalfSpaceOperator::Impl {
 public:
  virtual ~Impl() = default;
  virtual void apply(const double* p, double* u) const = 0;
  int ncomp = 1;
  int n = 0;
  Backend backend = Backend::Dense;
};

namespace {

class DenseImpl final : public HalfSpaceOperator::Impl {
 public:
  DenseImpl(const Grid& g, Problem problem, const ToeplitzKernel& t) {
    n = g.size();
    ncomp = problem == Problem::Normal ? 1 : 2;
    backend = Backend::Dense;
    const auto comps = blocks(problem);
    M_.resize(ncomp * n, ncomp * n);
    for (int a = 0; a < ncomp; ++a)
      for (int b = 0; b < ncomp; ++b) {
        const Component c = comps[a * ncomp + b];
        for (int jI = 0; jI < g.ny; ++jI)
          for (int iI = 0; iI < g.nx; ++iI)
            for (int jJ = 0; jJ < g.ny; ++jJ)
              for (int iJ = 0; iJ < g.nx; ++iJ)
                M_(a * n + g.index(iI, jI), b * n + g.index(iJ, jJ)) =
                    t(c, iI - iJ, jI - jJ);
      }
  }
  void apply(const double* p, double* u) const override {
    Eigen::Map<Eigen::VectorXd>(u, ncomp * n).noalias() =
        M_ * Eigen::Map<const Eigen::VectorXd>(p, ncomp * n);
  }

 private:
  Eigen::MatrixXd M_;
};

// The smallest N >= n whose prime factors are 2, 3, 5, 7 (FFTW is fastest on these; 2 nx itself can
// carry a large prime factor, e.g. 136 = 8 x 17 on the paper's fine grid).
int smooth_size(int n) {
  for (int N = std::max(n, 1);; ++N) {
    int r = N;
    for (int f : {2, 3, 5, 7})
      while (r % f == 0) r /= f;
    if (r == 1) return N;
  }
}

// Circulant embedding on the zero-padded Nx by Ny array, Nx >= 2nx - 1, Ny >= 2ny - 1:
// u(i) = sum_k c(i-k mod N) p(k) for i, k < n has no wrap-around because the offsets
// -(n-1) <= i - k <= n-1 map to distinct residues mod N.
class FftImpl final : public HalfSpaceOperator::Impl {
 public:
  FftImpl(const Grid& g, Problem problem, const ToeplitzKernel& t)
      : g_(g), Nx_(smooth_size(2 * g.nx - 1)), Ny_(smooth_size(2 * g.ny - 1)), fft_(Ny_, Nx_, g.ny) {
    n = g_.size();
    ncomp = problem == Problem::Normal ? 1 : 2;
    backend = Backend::Fft;
    spec_.resize(ncomp);  // spec_[0] is the planning array, the others have its alignment
    for (int c = 1; c < ncomp; ++c) spec_[c] = fft_.spectrum_array();
    out_ = fft_.spectrum_array();

    // Kernel spectra, scaled by 1/(Nx Ny) so that the unnormalised inverse transform is exact. The
    // kernel fills rows of both ends of the padded array (offsets -(ny-1)..ny-1): the whole 2-D
    // transform, once; the products in apply() transform only the ny rows that hold tractions.
    const linalg::RealFft whole(Ny_, Nx_);
    const size_t nreal = whole.real_size(), ncplx = whole.spectrum_size();
    double* real = whole.real();
    const auto comps = blocks(problem);
    kernel_.assign(comps.size(), std::vector<std::complex<double>>(ncplx));
    for (size_t b = 0; b < comps.size(); ++b) {
      std::fill(real, real + nreal, 0.0);
      for (int m = 0; m < Ny_; ++m) {
        const int dj = m < g_.ny ? m : m - Ny_;
        if (dj <= -g_.ny) continue;  // the padding between the offsets +(ny-1) and -(ny-1)
        for (int l = 0; l < Nx_; ++l) {
          const int di = l < g_.nx ? l : l - Nx_;
          if (di <= -g_.nx) continue;
          real[static_cast<size_t>(m) * Nx_ + l] = t(comps[b], di, dj) / nreal;
        }
      }
      whole.forward();
      std::copy(whole.spectrum(), whole.spectrum() + ncplx, kernel_[b].begin());
    }
  }
  /// Replace the tangential kernel spectra by the inverse of the 2 x 2 symbol in every bin, its
  /// eigenvalues floored at floor * self, plus `diagonal` (HalfSpaceOperator::inverse_circulant).
  void invert_symbol(double floor, double self, double diagonal) {
    const size_t ncplx = fft_.spectrum_size(), nreal = fft_.real_size();
    // kernel_ holds sigma / nreal; the inverse multiplier is sigma^{-1} / nreal.
    std::vector<Eigen::Matrix2d> sym(ncplx);
    for (size_t k = 0; k < ncplx; ++k) {
      Eigen::Matrix2d s;
      s << kernel_[0][k].real(), 0.5 * (kernel_[1][k].real() + kernel_[2][k].real()), 0.0, kernel_[3][k].real();
      s(1, 0) = s(0, 1);
      sym[k] = s * double(nreal);
    }
    for (size_t k = 0; k < ncplx; ++k) {
      const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> es(sym[k]);
      const Eigen::Vector2d inv =
          (es.eigenvalues().cwiseMax(floor * self) + Eigen::Vector2d::Constant(diagonal)).cwiseInverse();
      const Eigen::Matrix2d si = es.eigenvectors() * inv.asDiagonal() * es.eigenvectors().transpose() / nreal;
      kernel_[0][k] = si(0, 0);
      kernel_[1][k] = si(0, 1);
      kernel_[2][k] = si(1, 0);
      kernel_[3][k] = si(1, 1);
    }
  }
  void apply(const double* p, double* u) const override {
    const size_t ncplx = fft_.spectrum_size();
    double* real = fft_.real();
    for (int c = 0; c < ncomp; ++c) {  // forward transforms of each traction component
      // Rows j >= ny are zero padding, which the zero-padded transform neither reads nor needs.
      std::fill(real, real + static_cast<size_t>(g_.ny) * Nx_, 0.0);
      for (int j = 0; j < g_.ny; ++j)
        for (int i = 0; i < g_.nx; ++i)
          real[static_cast<size_t>(j) * Nx_ + i] = p[c * n + g_.index(i, j)];
      fft_.forward(spectrum(c));
    }
    std::complex<double>* out = out_.data();
    for (int a = 0; a < ncomp; ++a) {
      std::fill(out, out + ncplx, 0.0);
      for (int b = 0; b < ncomp; ++b)
        multiply_add(kernel_[a * ncomp + b].data(), spectrum(b), out, ncplx);
      fft_.backward(out);
      for (int j = 0; j < g_.ny; ++j)
        for (int i = 0; i < g_.nx; ++i)
          u[a * n + g_.index(i, j)] = real[static_cast<size_t>(j) * Nx_ + i];
    }
  }

 private:
  std::complex<double>* spectrum(int c) const { return c == 0 ? fft_.spectrum() : spec_[c].data(); }

  // out_k += K_k P_k on n bins, the complex product written out in real arithmetic: std::complex's
  // operator* also checks for NaN (C99 Annex G) on every product, which keeps the loop from
  // vectorising; the kernel and the tractions are finite here.
  static void multiply_add(const std::complex<double>* K, const std::complex<double>* P,
                           std::complex<double>* out, size_t n) {
    const double* k = reinterpret_cast<const double*>(K);
    const double* p = reinterpret_cast<const double*>(P);
    double* o = reinterpret_cast<double*>(out);
    for (size_t i = 0; i < 2 * n; i += 2) {
      o[i] += k[i] * p[i] - k[i + 1] * p[i + 1];
      o[i + 1] += k[i] * p[i + 1] + k[i + 1] * p[i];
    }
  }

  Grid g_;
  int Nx_ = 0, Ny_ = 0;
  linalg::RealFft fft_;  // zero-padded in y (ny of Ny rows); r2c halves x: Ny rows of Nx/2 + 1 bins
  std::vector<linalg::FftArray<std::complex<double>>> spec_;  // per traction component (c > 0)
  linalg::FftArray<std::complex<double>> out_;  // product spectrum
  std::vector<std::vector<std::complex<double>>> kernel_;
};

}  // namespace

Backend HalfSpaceOperator::auto_backend(int unknowns) {
  // Crossover measured with `rollnoise_bench --benchmark_filter=HalfSpace` (docs/accuracy.md, Benchmarks).
  // Measured (tangential, 2 x n^2 unknowns): dense 1.6 us vs FFT 2.6 us at 128 unknowns, dense
  // 37 us vs FFT 11 us at 512.
  return unknowns <= 256 ? Backend::Dense : Backend::Fft;
}

HalfSpaceOperator::HalfSpaceOperator(const InfluenceTable& table, Problem problem,
                                     int column_shift, Backend backend)
    : HalfSpaceOperator(
          table.grid(), problem,
          [&table, column_shift](Component c, int di, int dj) {
            return table(c, di + column_shift, dj);
          },
          backend) {}

HalfSpaceOperator::HalfSpaceOperator(const Grid& grid, Problem problem,
                                     const ToeplitzKernel& kernel, Backend backend) {
  const int unknowns = grid.size() * (problem == Problem::Normal ? 1 : 2);
  if (backend == Backend::Auto) backend = auto_backend(unknowns);
  if (backend == Backend::Dense)
    impl_ = std::make_unique<DenseImpl>(grid, problem, kernel);
  else
    impl_ = std::make_unique<FftImpl>(grid, problem, kernel);
}

HalfSpaceOperator::HalfSpaceOperator(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}

HalfSpaceOperator HalfSpaceOperator::inverse_circulant(const InfluenceTable& table, double floor, double diagonal) {
  auto impl = std::make_unique<FftImpl>(
      table.grid(), Problem::Tangential, [&table](Component c, int di, int dj) { return table(c, di, dj); });
  impl->invert_symbol(floor, std::min(table(Component::xx, 0, 0), table(Component::yy, 0, 0)), diagonal);
  return HalfSpaceOperator(std::move(impl));
}

HalfSpaceOperator::~HalfSpaceOperator() = default;
HalfSpaceOperator::HalfSpaceOperator(HalfSpaceOperator&&) noexcept = default;
HalfSpaceOperator& HalfSpaceOperator::operator=(HalfSpaceOperator&&) noexcept = default;

int HalfSpaceOperator::size() const { return impl_->ncomp * impl_->n; }
Backend HalfSpaceOperator::backend() const { return impl_->backend; }
void HalfSpaceOperator::apply(const double* p, double* u) const { impl_->apply(p, u); }

}  // namespace rollnoise::contact
