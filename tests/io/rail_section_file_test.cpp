// The rail section outline file (io/rail_section_file.hpp, key track.rail_section): the shipped
// models/rail/uic60_outline.csv is the built-in UIC60 outline, so the waveguide built on it has the
// built-in's wavenumbers; a bad file names the file, line and field.
#include "io/rail_section_file.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <complex>
#include <filesystem>
#include <fstream>
#include <string>

#include "core/errors.hpp"
#include "dynamics/rail_section.hpp"
#include "dynamics/rail_waveguide.hpp"
#include "fem/mesh.hpp"
#include "support/test_helpers.hpp"

namespace {

using namespace rollnoise;
namespace fs = std::filesystem;

// A file in its own folder of this process's scratch folder (removed at exit;
// test_support::scratch_folder).
fs::path rail_section_temp_file(const std::string& name, const std::string& text) {
  const fs::path dir = test_support::scratch_folder("rollnoise_rail_section", name);
  std::ofstream(dir / name) << text;
  return dir / name;
}

// The InputError's key and message of reading `text` as a rail section file.
std::pair<std::string, std::string> error_of(const std::string& text) {
  const fs::path p = rail_section_temp_file("bad.csv", text);
  try {
    io::read_rail_section(p.string());
  } catch (const InputError& e) {
    return {e.key(), e.what()};
  }
  return {"", "no error"};
}

const std::string kSource = ROLLNOISE_SOURCE_DIR;

}  // namespace

// The shipped outline file holds the built-in outline's vertices exactly (mm with at most two
// decimals, scaled by 1e-3 in the same operation), so the mesh and the waveguide built on it are the
// built-in's: the free rail's wavenumbers at 1 kHz (all coordinates, 60 mm mesh) and the
// dispersion at k = 0 and 10 rad/m agree to round-off (1e-12 relative; they are identical).
TEST(RailSectionFile, ShippedUic60OutlineGivesTheBuiltInWavenumbers) {
  const auto read = io::read_rail_section(kSource + "/models/rail/uic60_outline.csv");
  const auto built_in = dynamics::uic60_outline();
  ASSERT_EQ(read.size(), built_in.size());
  for (std::size_t i = 0; i < read.size(); ++i) EXPECT_EQ(read[i], built_in[i]) << i;
  const dynamics::RailMaterial steel;
  const dynamics::RailWaveguide a(fem::mesh_polygon(read, 0.06), steel, std::nullopt),
      b(fem::mesh_polygon(built_in, 0.06), steel, std::nullopt);
  ASSERT_EQ(a.dofs(), b.dofs());
  for (double k : {0.0, 10.0}) {
    const Eigen::VectorXd fa = a.dispersion(k, 12), fb = b.dispersion(k, 12);
    for (int i = 4; i < 12; ++i) EXPECT_NEAR(fa(i), fb(i), 1e-12 * fb(i)) << k << " " << i;
  }
  auto sorted = [](const Eigen::VectorXcd& k) {
    std::vector<std::complex<double>> v(k.data(), k.data() + k.size());
    std::sort(v.begin(), v.end(), [](auto x, auto y) {
      return x.imag() != y.imag() ? x.imag() < y.imag() : x.real() < y.real();
    });
    return v;
  };
  const auto ka = sorted(a.waves(2.0 * M_PI * 1000.0).wavenumbers),
             kb = sorted(b.waves(2.0 * M_PI * 1000.0).wavenumbers);
  for (std::size_t i = 0; i < ka.size(); ++i)
    EXPECT_LE(std::abs(ka[i] - kb[i]), 1e-12 * std::abs(kb[i])) << i;
}

// A section given clockwise, closed (first point repeated) and lifted by 30 mm is read as the same
// counter-clockwise-equivalent polygon with its foot at z = 0: the same section properties.
TEST(RailSectionFile, OrientationClosingPointAndOffsetDoNotChangeTheSection) {
  const auto built_in = dynamics::uic60_outline();
  std::string text = "# clockwise, lifted\ny_mm,z_mm\n";
  for (int i = static_cast<int>(built_in.size()); i >= 0; --i) {
    const auto& p = built_in[i % built_in.size()];
    text += std::to_string(1e3 * p.x()) + "," + std::to_string(1e3 * p.y() + 30.0) + "\n";
  }
  const auto read = io::read_rail_section(rail_section_temp_file("cw.csv", text).string());
  ASSERT_EQ(read.size(), built_in.size());
  const auto sa = dynamics::section_properties(fem::mesh_polygon(read, 0.04));
  const auto sb = dynamics::section_properties(fem::mesh_polygon(built_in, 0.04));
  EXPECT_NEAR(sa.area, sb.area, 1e-9 * sb.area);
  EXPECT_NEAR(sa.centroid.y(), sb.centroid.y(), 1e-9);
  EXPECT_NEAR(sa.second_moment_yy, sb.second_moment_yy, 1e-9 * sb.second_moment_yy);
}

TEST(RailSectionFile, BadFileNamesTheLineAndField) {
  auto [key, what] = error_of("r_mm,z_mm\n0,0\n");
  EXPECT_NE(key.find("bad.csv:1"), std::string::npos) << key;
  std::tie(key, what) = error_of("y_mm,z_mm\n0,0\n75,0\n# note\n75,x\n");
  EXPECT_NE(key.find("bad.csv:5:z_mm"), std::string::npos) << key;
  EXPECT_NE(what.find("z_mm"), std::string::npos) << what;
  std::tie(key, what) = error_of("y_mm,z_mm\n0,0\n75,0,1\n");
  EXPECT_NE(key.find("bad.csv:3"), std::string::npos) << key;
  std::tie(key, what) = error_of("y_mm,z_mm\n0,0\n75,0\n");
  EXPECT_NE(what.find("at least 3 points"), std::string::npos) << what;
  std::tie(key, what) = error_of("y_mm,z_mm\n0,0\n75,10\n0,172\n");
  EXPECT_NE(what.find("flat bottom"), std::string::npos) << what;
  std::tie(key, what) = error_of("y_mm,z_mm\n0,0\n75,0\n150,0\n");
  EXPECT_NE(what.find("no area"), std::string::npos) << what;
  std::tie(key, what) = error_of("");
  EXPECT_NE(what.find("no header"), std::string::npos) << what;
  fs::remove_all(rail_section_temp_file("x", "").parent_path());
}
