// Internal to the linear model's source files (linear_model.cpp, paper_form.cpp, reduced_form.cpp,
// markov_sweep.cpp, transfer.cpp): the parts LinearContactModel builds on first use.
#pragma once

#include <Eigen/Dense>
#include <memory>
#include <mutex>

#include "nss/linear_model.hpp"
#include "nss/step_solver.hpp"

namespace rollnoise::nss {

// The Krylov sweep's Y = K0 V is kept beside the basis V (as on the dense path) while it takes at
// most this many bytes (at the largest basis the sweep allocates, 1.5 times its first capacity);
// above, the matrix-free path recomputes K0 X instead (three more FFT products per column and
// step, against memory r d): 68 x 50 keeps it (~20 MB), 200 x 200 drops it (~0.7 GB).
constexpr double kKrylovYBudget = 256e6;

inline bool lean_krylov_basis(int r, int capacity) { return 8.0 * r * 1.5 * capacity > kKrylovYBudget; }

/// The paper's formulation, dense: M(z) = M0 - z M1 (for the reference solve and the Hessenberg
/// sweep).
struct LinearContactModel::Dense {
  Eigen::MatrixXd M0, M1;
};

/// M0^{-1} M1 = Q H Q' (real Hessenberg form) with Rhat = Q' M0^{-1} [W, wN0, wN1], Lhat = Q' L.
struct LinearContactModel::HessenbergForm {
  Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> H;
  Eigen::MatrixXd Rhat, Lhat;
};

/// Each part is built once, by the first caller (std::call_once: concurrent callers wait for it;
/// a build that throws leaves the part unbuilt).
struct LinearContactModel::Built {
  std::once_flag step_once;
  std::unique_ptr<StepSolver> step;
  std::once_flag dense_once;
  std::unique_ptr<Dense> dense;
  std::once_flag hessenberg_once;
  std::unique_ptr<HessenbergForm> hessenberg;
  std::once_flag radius_once;
  double spectral_radius = -1.0;
  std::once_flag series_once;
  std::unique_ptr<MarkovSeries> series;
};

}  // namespace rollnoise::nss
