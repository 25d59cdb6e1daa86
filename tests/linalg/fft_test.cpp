// linalg::RealFft: the 2-D transform of an array zero-padded in y, computed by dimension on the
// rows that are not zero (RealFft(ny, nx, rows)), equals the whole 2-D transform, and its inverse
// returns the wanted rows.
#include "linalg/fft.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <complex>
#include <random>

using rollnoise::linalg::RealFft;

namespace {

// Sizes of the half-space products: the padded array of an nx x ny grid is at least (2nx-1) x
// (2ny-1) (contact/halfspace_operator.cpp); an odd and an even row count, a 7-smooth odd size.
struct Sizes {
  int ny, nx, rows;
};

class ZeroPaddedFft : public ::testing::TestWithParam<Sizes> {};

TEST_P(ZeroPaddedFft, EqualsTheWhole2dTransformAndItsInverseToRoundOff) {
  const auto [ny, nx, rows] = GetParam();
  const RealFft whole(ny, nx), padded(ny, nx, rows);
  std::mt19937_64 rng(38);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::fill(whole.real(), whole.real() + whole.real_size(), 0.0);
  std::fill(padded.real(), padded.real() + padded.real_size(), -7.0);  // rows >= `rows`: not read
  for (int j = 0; j < rows; ++j)
    for (int i = 0; i < nx; ++i) whole.real()[j * nx + i] = padded.real()[j * nx + i] = u(rng);

  whole.forward();
  padded.forward();
  double scale = 0.0, difference = 0.0;
  for (std::size_t k = 0; k < whole.spectrum_size(); ++k) {
    scale = std::max(scale, std::abs(whole.spectrum()[k]));
    difference = std::max(difference, std::abs(whole.spectrum()[k] - padded.spectrum()[k]));
  }
  EXPECT_LE(difference, 1e-14 * scale) << "spectrum, largest bin " << scale;

  // The inverse (unnormalised): the wanted rows are ny nx times the input; the rest untouched.
  std::vector<double> input(padded.real(), padded.real() + static_cast<std::size_t>(rows) * nx);
  std::fill(padded.real() + static_cast<std::size_t>(rows) * nx, padded.real() + padded.real_size(),
            5.0);
  padded.backward(padded.spectrum());
  double worst = 0.0;
  for (std::size_t k = 0; k < input.size(); ++k)
    worst = std::max(worst, std::abs(padded.real()[k] / (double(nx) * ny) - input[k]));
  EXPECT_LE(worst, 1e-14);
  for (std::size_t k = input.size(); k < padded.real_size(); ++k) ASSERT_EQ(padded.real()[k], 5.0);
}

INSTANTIATE_TEST_SUITE_P(HalfSpaceSizes, ZeroPaddedFft,
                         ::testing::Values(Sizes{112, 128, 55}, Sizes{64, 64, 32},
                                           Sizes{35, 27, 18}, Sizes{1, 8, 1}));

}  // namespace
