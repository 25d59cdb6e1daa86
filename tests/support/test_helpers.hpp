// Helpers that several test files share, defined once: each test program (one per folder of
// tests/) may be compiled as a unity build (CMakeLists.txt, ROLLNOISE_UNITY_BUILD), where the files
// of a folder become one translation unit and file-local copies of one name would clash
// (`bash scripts/check_unity_names.sh --tests` finds such clashes).
#pragma once

#include <cmath>
#include <complex>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace rollnoise::test_support {

/// The whole content of file `p`, byte for byte (empty if it cannot be read).
inline std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

/// A level in dB of a complex amplitude: 20 log10 |z| (z in its own units, re 1 of them).
inline double db(std::complex<double> z) { return 20.0 * std::log10(std::abs(z)); }

/// ||a - b|| / ||b||: the difference of `a` from the reference `b` relative to it (Eigen
/// matrices or vectors, Frobenius / Euclidean norms).
template <class A, class B>
double relative(const A& a, const B& b) {
  return (a - b).norm() / b.norm();
}

}  // namespace rollnoise::test_support
