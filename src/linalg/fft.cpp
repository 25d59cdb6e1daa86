#include "linalg/fft.hpp"

#include <fftw3.h>

#include <algorithm>
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

// One transform: `forward`/`backward` (the whole 1-D or 2-D transform), or, for the zero-padded 2-D
// transform, the rows' r2c/c2r along x and the columns' in-place c2c along y.
struct RealFft::Plans {
  fftw_plan forward = nullptr, backward = nullptr;
  fftw_plan rows_forward = nullptr, rows_backward = nullptr;
  fftw_plan columns_forward = nullptr, columns_backward = nullptr;
  int rows = 0, ny = 0, bins = 0;  // zero-padded 2-D: rows read/written, all rows, bins per row
  ~Plans() {
    const std::lock_guard<std::mutex> lock(planner_mutex());
    for (fftw_plan p : {forward, backward, rows_forward, rows_backward, columns_forward, columns_backward})
      if (p) fftw_destroy_plan(p);
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

RealFft::RealFft(int ny, int nx, int rows)
    : real_(static_cast<std::size_t>(nx) * ny),
      spectrum_(static_cast<std::size_t>(nx / 2 + 1) * ny),
      plans_(std::make_unique<Plans>()) {
  Plans& p = *plans_;
  p.rows = rows;
  p.ny = ny;
  p.bins = nx / 2 + 1;
  const std::lock_guard<std::mutex> lock(planner_mutex());
  // Rows: `rows` transforms of length nx, one row apart (real rows nx apart, spectrum rows `bins`).
  p.rows_forward = fftw_plan_many_dft_r2c(1, &nx, rows, real(), nullptr, 1, nx, as_fftw(spectrum()),
                                          nullptr, 1, p.bins, FFTW_ESTIMATE);
  p.rows_backward = fftw_plan_many_dft_c2r(1, &nx, rows, as_fftw(spectrum()), nullptr, 1, p.bins,
                                           real(), nullptr, 1, nx, FFTW_ESTIMATE);
  // Columns: `bins` transforms of length ny, stride `bins`, in place.
  p.columns_forward = fftw_plan_many_dft(1, &ny, p.bins, as_fftw(spectrum()), nullptr, p.bins, 1,
                                         as_fftw(spectrum()), nullptr, p.bins, 1, FFTW_FORWARD,
                                         FFTW_ESTIMATE);
  p.columns_backward = fftw_plan_many_dft(1, &ny, p.bins, as_fftw(spectrum()), nullptr, p.bins, 1,
                                          as_fftw(spectrum()), nullptr, p.bins, 1, FFTW_BACKWARD,
                                          FFTW_ESTIMATE);
}

RealFft::~RealFft() = default;
RealFft::RealFft(RealFft&&) noexcept = default;
RealFft& RealFft::operator=(RealFft&&) noexcept = default;

FftArray<std::complex<double>> RealFft::spectrum_array() const {
  return FftArray<std::complex<double>>(spectrum_size());
}

void RealFft::forward(std::complex<double>* spectrum) const {
  const Plans& p = *plans_;
  if (p.forward) {
    fftw_execute_dft_r2c(p.forward, real(), as_fftw(spectrum));
    return;
  }
  fftw_execute_dft_r2c(p.rows_forward, real(), as_fftw(spectrum));
  const std::size_t filled = static_cast<std::size_t>(p.rows) * p.bins;
  std::fill(spectrum + filled, spectrum + static_cast<std::size_t>(p.ny) * p.bins, 0.0);
  fftw_execute_dft(p.columns_forward, as_fftw(spectrum), as_fftw(spectrum));
}

void RealFft::backward(std::complex<double>* spectrum) const {
  const Plans& p = *plans_;
  if (p.backward) {
    fftw_execute_dft_c2r(p.backward, as_fftw(spectrum), real());
    return;
  }
  fftw_execute_dft(p.columns_backward, as_fftw(spectrum), as_fftw(spectrum));
  fftw_execute_dft_c2r(p.rows_backward, as_fftw(spectrum), real());
}

}  // namespace rollnoise::linalg
