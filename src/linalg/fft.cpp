#include "linalg/fft.hpp"

#include <fftw3.h>

#include <mutex>
#include <new>

namespace rollnoise::linalg {

namespace detail {

void* fft_allocate(std::size_t bytes) {
  void* p = fftw_malloc(bytes);
  if (!p && bytes > 0) throw std::bad_alloc();
  return p;
}

void fft_free(void* p) { fftw_free(p); }

}  // namespace detail

namespace {

fftw_complex* as_fftw(std::complex<double>* z) { return reinterpret_cast<fftw_complex*>(z); }

// FFTW's planner (plan creation and destruction) is not thread-safe; fftw_execute_* is. The
// further wheels of a noise run build their models on several threads (pipeline/noise_pipeline.cpp).
std::mutex& planner_mutex() {
  static std::mutex m;
  return m;
}

}  // namespace

struct RealFft::Plans {
  fftw_plan forward = nullptr, backward = nullptr;
  ~Plans() {
    const std::lock_guard<std::mutex> lock(planner_mutex());
    if (forward) fftw_destroy_plan(forward);
    if (backward) fftw_destroy_plan(backward);
  }
};

RealFft::RealFft(int n)
    : real_(static_cast<std::size_t>(n)),
      spectrum_(static_cast<std::size_t>(n / 2 + 1)),
      plans_(std::make_unique<Plans>()) {
  const std::lock_guard<std::mutex> lock(planner_mutex());
  plans_->forward = fftw_plan_dft_r2c_1d(n, real(), as_fftw(spectrum()), FFTW_ESTIMATE);
  plans_->backward = fftw_plan_dft_c2r_1d(n, as_fftw(spectrum()), real(), FFTW_ESTIMATE);
}

RealFft::RealFft(int ny, int nx)
    : real_(static_cast<std::size_t>(nx) * ny),
      spectrum_(static_cast<std::size_t>(nx / 2 + 1) * ny),
      plans_(std::make_unique<Plans>()) {
  const std::lock_guard<std::mutex> lock(planner_mutex());
  plans_->forward = fftw_plan_dft_r2c_2d(ny, nx, real(), as_fftw(spectrum()), FFTW_ESTIMATE);
  plans_->backward = fftw_plan_dft_c2r_2d(ny, nx, as_fftw(spectrum()), real(), FFTW_ESTIMATE);
}

RealFft::~RealFft() = default;
RealFft::RealFft(RealFft&&) noexcept = default;
RealFft& RealFft::operator=(RealFft&&) noexcept = default;

FftArray<std::complex<double>> RealFft::spectrum_array() const {
  return FftArray<std::complex<double>>(spectrum_size());
}

void RealFft::forward(std::complex<double>* spectrum) const {
  fftw_execute_dft_r2c(plans_->forward, real(), as_fftw(spectrum));
}

void RealFft::backward(std::complex<double>* spectrum) const {
  fftw_execute_dft_c2r(plans_->backward, as_fftw(spectrum), real());
}

}  // namespace rollnoise::linalg
