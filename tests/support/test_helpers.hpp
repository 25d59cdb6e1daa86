// Helpers that several test files share, defined once: each test program (one per folder of
// tests/) may be compiled as a unity build (CMakeLists.txt, ROLLNOISE_UNITY_BUILD), where the files
// of a folder become one translation unit and file-local copies of one name would clash
// (`bash scripts/check_unity_names.sh --tests` finds such clashes).
#pragma once

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace rollnoise::test_support {

/// The whole content of file `p`, byte for byte (empty if it cannot be read).
inline std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

/// A fresh folder `name` under this test process's scratch root `<temp>/<root>_<pid>` (emptied if
/// it exists; the whole root removed when the process ends).
inline std::filesystem::path scratch_folder(const std::string& root, const std::string& name) {
  namespace fs = std::filesystem;
  static struct Roots {
    std::vector<fs::path> made;
    ~Roots() {
      std::error_code ec;
      for (const auto& d : made) fs::remove_all(d, ec);
    }
  } roots;
  const fs::path dir = fs::temp_directory_path() / (root + "_" + std::to_string(::getpid()));
  if (std::find(roots.made.begin(), roots.made.end(), dir) == roots.made.end())
    roots.made.push_back(dir);
  const fs::path d = dir / name;
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
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
