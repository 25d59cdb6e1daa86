#include "contact/halfspace_operator.hpp"

#include <fftw3.h>

#include <Eigen/Dense>
#include <algorithm>
#include <complex>
#include <vector>

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
  FftImpl(const Grid& g, Problem problem, const ToeplitzKernel& t) : g_(g) {
    n = g_.size();
    ncomp = problem == Problem::Normal ? 1 : 2;
    backend = Backend::Fft;
    Nx_ = smooth_size(2 * g_.nx - 1);
    Ny_ = smooth_size(2 * g_.ny - 1);
    Nc_ = Nx_ / 2 + 1;  // r2c halves the last (x) dimension
    const size_t nreal = static_cast<size_t>(Nx_) * Ny_, ncplx = static_cast<size_t>(Nc_) * Ny_;
    real_ = fftw_alloc_real(nreal);
    spec_.resize(ncomp);
    for (auto& s : spec_) s = fftw_alloc_complex(ncplx);
    out_ = fftw_alloc_complex(ncplx);
    // FFTW_ESTIMATE: the plan, and so every result bit, is the same on every run. FFTW_MEASURE
    // was measured 10-20 % faster on the transient benchmark (within the run-to-run noise of this
    // machine) and would make results differ in the last bits between runs.
    fwd_ = fftw_plan_dft_r2c_2d(Ny_, Nx_, real_, spec_[0], FFTW_ESTIMATE);
    bwd_ = fftw_plan_dft_c2r_2d(Ny_, Nx_, spec_[0], real_, FFTW_ESTIMATE);

    // Kernel spectra, scaled by 1/(Nx Ny) so that the unnormalised inverse transform is exact.
    const auto comps = blocks(problem);
    kernel_.assign(comps.size(), std::vector<std::complex<double>>(ncplx));
    for (size_t b = 0; b < comps.size(); ++b) {
      std::fill(real_, real_ + nreal, 0.0);
      for (int m = 0; m < Ny_; ++m) {
        const int dj = m < g_.ny ? m : m - Ny_;
        if (dj <= -g_.ny) continue;  // the padding between the offsets +(ny-1) and -(ny-1)
        for (int l = 0; l < Nx_; ++l) {
          const int di = l < g_.nx ? l : l - Nx_;
          if (di <= -g_.nx) continue;
          real_[static_cast<size_t>(m) * Nx_ + l] = t(comps[b], di, dj) / nreal;
        }
      }
      fftw_execute_dft_r2c(fwd_, real_, spec_[0]);
      for (size_t k = 0; k < ncplx; ++k)
        kernel_[b][k] = {spec_[0][k][0], spec_[0][k][1]};
    }
  }
  ~FftImpl() override {
    fftw_destroy_plan(fwd_);
    fftw_destroy_plan(bwd_);
    fftw_free(real_);
    for (auto* s : spec_) fftw_free(s);
    fftw_free(out_);
  }
  void apply(const double* p, double* u) const override {
    const size_t ncplx = static_cast<size_t>(Nc_) * Ny_;
    for (int c = 0; c < ncomp; ++c) {  // forward transforms of each traction component
      std::fill(real_, real_ + static_cast<size_t>(Nx_) * Ny_, 0.0);
      for (int j = 0; j < g_.ny; ++j)
        for (int i = 0; i < g_.nx; ++i)
          real_[static_cast<size_t>(j) * Nx_ + i] = p[c * n + g_.index(i, j)];
      fftw_execute_dft_r2c(fwd_, real_, spec_[c]);
    }
    auto* out = reinterpret_cast<std::complex<double>*>(out_);
    for (int a = 0; a < ncomp; ++a) {
      std::fill(out, out + ncplx, 0.0);
      for (int b = 0; b < ncomp; ++b) {
        const auto& K = kernel_[a * ncomp + b];
        const auto* P = reinterpret_cast<const std::complex<double>*>(spec_[b]);
        for (size_t k = 0; k < ncplx; ++k) out[k] += K[k] * P[k];
      }
      fftw_execute_dft_c2r(bwd_, out_, real_);
      for (int j = 0; j < g_.ny; ++j)
        for (int i = 0; i < g_.nx; ++i)
          u[a * n + g_.index(i, j)] = real_[static_cast<size_t>(j) * Nx_ + i];
    }
  }

 private:
  Grid g_;
  int Nx_ = 0, Ny_ = 0, Nc_ = 0;
  double* real_ = nullptr;
  std::vector<fftw_complex*> spec_;
  fftw_complex* out_ = nullptr;  // product spectrum (aligned like the planning arrays)
  fftw_plan fwd_ = nullptr, bwd_ = nullptr;
  std::vector<std::vector<std::complex<double>>> kernel_;
};

}  // namespace

Backend HalfSpaceOperator::auto_backend(int unknowns) {
  // Crossover measured with `rollnoise_bench --benchmark_filter=HalfSpace` (README, Benchmarks).
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

HalfSpaceOperator::~HalfSpaceOperator() = default;
HalfSpaceOperator::HalfSpaceOperator(HalfSpaceOperator&&) noexcept = default;
HalfSpaceOperator& HalfSpaceOperator::operator=(HalfSpaceOperator&&) noexcept = default;

int HalfSpaceOperator::size() const { return impl_->ncomp * impl_->n; }
Backend HalfSpaceOperator::backend() const { return impl_->backend; }
void HalfSpaceOperator::apply(const double* p, double* u) const { impl_->apply(p, u); }

}  // namespace rollnoise::contact
