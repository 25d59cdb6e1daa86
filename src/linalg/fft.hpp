// Real-to-complex discrete Fourier transforms: the project's one wrapper around FFTW (no other file
// includes <fftw3.h>; checked by tests/check_layering.cmake).
//
// RealFft owns the plans of one transform size (1-D n, or 2-D ny x nx, x fastest) and the
// SIMD-aligned arrays they were planned on (fftw_alloc_*), and frees both:
//   forward   X_k = sum_j x_j e^{-2 pi i jk/n}                (r2c; per dimension in 2-D)
//   backward  x_j = sum_k X_k e^{+2 pi i jk/n}, unnormalised   (c2r; overwrites its input)
// The complex side holds the non-redundant half, n/2 + 1 bins (2-D: ny rows of nx/2 + 1 bins).
// Further spectrum arrays (spectrum_array()) have the planning arrays' alignment, so the same
// plans execute on them (FFTW's new-array execute).
//
// Plans are made with FFTW_ESTIMATE: the plan, and so every result bit, is the same on every run.
// FFTW_MEASURE was measured 10-20 % faster on the transient benchmark (within the run-to-run noise
// of this machine) and would make results differ in the last bits between runs.
#pragma once

#include <complex>
#include <cstddef>
#include <memory>

namespace rollnoise::linalg {

namespace detail {
void* fft_allocate(std::size_t bytes);  // fftw_malloc (aligned for FFTW's SIMD kernels)
void fft_free(void* p);
struct FftFree {
  void operator()(void* p) const { fft_free(p); }
};
}  // namespace detail

/// An array of `size` values of T (double or std::complex<double>) allocated by FFTW, owned.
template <class T>
class FftArray {
 public:
  FftArray() = default;
  explicit FftArray(std::size_t size)
      : data_(static_cast<T*>(detail::fft_allocate(size * sizeof(T)))), size_(size) {}
  T* data() const { return data_.get(); }
  std::size_t size() const { return size_; }
  T& operator[](std::size_t k) const { return data_.get()[k]; }

 private:
  std::unique_ptr<T, detail::FftFree> data_;
  std::size_t size_ = 0;
};

class RealFft {
 public:
  /// 1-D: n real values, n/2 + 1 complex bins.
  explicit RealFft(int n);
  /// 2-D: ny rows of nx real values (x fastest), ny rows of nx/2 + 1 bins (r2c halves x).
  RealFft(int ny, int nx);
  /// 2-D with zero padding in y: forward() reads only the first `rows` rows of real() (the others
  /// are taken as zero and never read), backward() writes only the first `rows` rows of real() (the
  /// others are left as they were). The transform is computed by dimension: r2c along x on the
  /// `rows` rows that are not zero, c2c along y on the nx/2 + 1 columns; the inverse c2c along y,
  /// then c2r along x on the `rows` rows wanted. Same transform as RealFft(ny, nx) up to round-off,
  /// with ny - rows of the ny row transforms skipped each way (the circulant embedding of a Toeplitz
  /// operator, contact/halfspace_operator.cpp, has rows = ny / 2 about). 0 < rows <= ny.
  RealFft(int ny, int nx, int rows);
  ~RealFft();
  RealFft(RealFft&&) noexcept;
  RealFft& operator=(RealFft&&) noexcept;

  std::size_t real_size() const { return real_.size(); }
  std::size_t spectrum_size() const { return spectrum_.size(); }
  /// The real array: the input of forward(), the output of backward().
  double* real() const { return real_.data(); }
  /// The complex array the plans were made on.
  std::complex<double>* spectrum() const { return spectrum_.data(); }
  /// Another complex array of spectrum_size() bins on which the plans execute as well.
  FftArray<std::complex<double>> spectrum_array() const;

  /// real() -> spectrum (default: spectrum()).
  void forward() const { forward(spectrum()); }
  void forward(std::complex<double>* spectrum) const;
  /// spectrum -> real(), unnormalised; `spectrum` is overwritten (an array of this object's).
  void backward(std::complex<double>* spectrum) const;

  struct Plans;

 private:
  FftArray<double> real_;
  FftArray<std::complex<double>> spectrum_;
  std::unique_ptr<Plans> plans_;
};

}  // namespace rollnoise::linalg
