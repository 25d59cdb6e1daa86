// The wheel's mode cache (io/wheel_modes_cache.hpp): what is read back is what was computed, to
// the bit; another key, a damaged or truncated file, or a directory that cannot take the file give
// nothing (the modes are then computed); every input of the modes changes the key.
#include "io/wheel_modes_cache.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>

#include "io/case_reader.hpp"
#include "io/input_problems.hpp"
#include "io/wheel_section_file.hpp"
#include "support/test_helpers.hpp"

namespace {

using namespace rollnoise;
namespace fs = std::filesystem;

fs::path scratch(const std::string& name) {
  return test_support::scratch_folder("rollnoise_modes_cache", name);
}

// The default FE wheel case with a coarse mesh and a short range (n <= 3, 2.5 kHz: a few modes).
io::WheelFeCase coarse_case(const std::vector<std::string>& more = {}) {
  std::vector<std::string> overrides = {"wheel.model=\"fe\"", "wheel.mesh_size=0.03",
                                        "wheel.n_max=3", "wheel.f_max=2500.0"};
  overrides.insert(overrides.end(), more.begin(), more.end());
  io::InputProblems problems;
  const auto c = io::read_wheel_fe_case(
      io::CaseReader::from_string("", std::string(ROLLNOISE_SOURCE_DIR) + "/cases/w.toml",
                                  overrides),
      problems);
  problems.throw_if_any();
  return *c;
}

const dynamics::WheelFeModes& computed() {
  static const dynamics::WheelFeModes w = *io::wheel_fe_modes_once(coarse_case());
  return w;
}

bool same_bits(double a, double b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

void expect_bit_identical(const dynamics::WheelFeModes& a, const dynamics::WheelFeModes& b) {
  ASSERT_EQ(a.tread_s.size(), b.tread_s.size());
  ASSERT_EQ(a.modes.size(), b.modes.size());
  EXPECT_TRUE(same_bits(a.mass, b.mass));
  for (std::size_t i = 0; i < a.tread_s.size(); ++i) {
    EXPECT_TRUE(same_bits(a.tread_s[i], b.tread_s[i]));
    EXPECT_TRUE(same_bits(a.tread_r[i], b.tread_r[i]));
  }
  for (std::size_t k = 0; k < a.modes.size(); ++k) {
    const auto &x = a.modes[k], &y = b.modes[k];
    EXPECT_TRUE(same_bits(x.frequency, y.frequency)) << k;
    EXPECT_EQ(x.n, y.n);
    EXPECT_EQ(x.family, y.family);
    EXPECT_EQ(x.nodal_circles, y.nodal_circles);
    EXPECT_TRUE(same_bits(x.damping_ratio, y.damping_ratio));
    ASSERT_EQ(x.tread_shape.rows(), y.tread_shape.rows());
    for (Eigen::Index i = 0; i < x.tread_shape.size(); ++i)
      EXPECT_TRUE(same_bits(x.tread_shape.data()[i], y.tread_shape.data()[i])) << k << " " << i;
  }
}

}  // namespace

// Written, then read back: every number the contact path uses has the same bits.
TEST(WheelModesCache, ModesReadBackAreBitIdenticalToTheComputedOnes) {
  const fs::path dir = scratch("roundtrip");
  const std::string key = io::mode_cache_key(coarse_case());
  ASSERT_FALSE(key.empty());
  EXPECT_FALSE(io::read_cached_modes(dir.string(), key));  // nothing stored yet
  ASSERT_TRUE(io::write_cached_modes(dir.string(), key, computed()));
  ASSERT_GT(computed().modes.size(), 3u);
  const std::optional<dynamics::WheelFeModes> read = io::read_cached_modes(dir.string(), key);
  ASSERT_TRUE(read);
  expect_bit_identical(computed(), *read);
  EXPECT_TRUE(read->mesh.nodes.empty());  // along the tread only
  int files = 0;
  for (const auto& e : fs::directory_iterator(dir)) files += e.is_regular_file() ? 1 : 0;
  EXPECT_EQ(files, 1);  // no temporary left beside it
}

// Another key reads nothing from the same folder; a file whose payload lost a byte (checksum),
// lost its tail (truncated) or had one byte changed reads nothing; a folder that is a file takes
// nothing and no error escapes.
TEST(WheelModesCache, AnotherKeyADamagedOrTruncatedFileReadsNothing) {
  const fs::path dir = scratch("damaged");
  const std::string key = io::mode_cache_key(coarse_case());
  ASSERT_TRUE(io::write_cached_modes(dir.string(), key, computed()));
  EXPECT_FALSE(
      io::read_cached_modes(dir.string(), io::mode_cache_key(coarse_case({"wheel.n_max=2"}))));
  const std::string file = io::mode_cache_file(dir.string(), key);
  std::string bytes;
  {
    std::ifstream in(file, std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), {});
  }
  auto rewrite = [&](const std::string& b) {
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    out << b;
  };
  std::string flipped = bytes;
  flipped[bytes.size() / 2] ^= 0x10;
  rewrite(flipped);
  EXPECT_FALSE(io::read_cached_modes(dir.string(), key));
  rewrite(bytes.substr(0, bytes.size() - 100));
  EXPECT_FALSE(io::read_cached_modes(dir.string(), key));
  rewrite(bytes.substr(0, 20));
  EXPECT_FALSE(io::read_cached_modes(dir.string(), key));
  rewrite(bytes);
  EXPECT_TRUE(io::read_cached_modes(dir.string(), key));

  const fs::path not_a_folder = dir / "plain_file";
  std::ofstream(not_a_folder) << "x";
  EXPECT_FALSE(io::write_cached_modes(not_a_folder.string(), key, computed()));
}

// Each input of the modes changes the key (material, mesh, range, the section file's bytes);
// what does not enter the modes (damping, rotation) leaves it.
TEST(WheelModesCache, EveryInputOfTheModesChangesTheKey) {
  const std::string base = io::mode_cache_key(coarse_case());
  for (const char* o :
       {"wheel.youngs_modulus=2.0e11", "wheel.poisson_ratio=0.29", "wheel.density=7800.0",
        "wheel.mesh_size=0.031", "wheel.n_max=4", "wheel.f_max=2600.0"})
    EXPECT_NE(io::mode_cache_key(coarse_case({o})), base) << o;
  for (const char* o : {"wheel.damping_radial=1e-3", "wheel.rotation=\"none\""})
    EXPECT_EQ(io::mode_cache_key(coarse_case({o})), base) << o;

  // the same outline in another file reads the same key; one changed point does not
  const fs::path dir = scratch("section");
  const std::string shipped =
      std::string(ROLLNOISE_SOURCE_DIR) + "/models/wheel/wheel_920mm_section.csv";
  fs::copy_file(shipped, dir / "copy.csv");
  EXPECT_EQ(
      io::mode_cache_key(coarse_case({"wheel.section=\"" + (dir / "copy.csv").string() + "\""})),
      base);
  std::string text;
  {
    std::ifstream in(shipped);
    text.assign(std::istreambuf_iterator<char>(in), {});
  }
  const std::size_t digit = text.find_last_of("123456789");
  text[digit] = text[digit] == '9' ? '8' : char(text[digit] + 1);
  std::ofstream(dir / "changed.csv") << text;
  EXPECT_NE(
      io::mode_cache_key(coarse_case({"wheel.section=\"" + (dir / "changed.csv").string() + "\""})),
      base);
}

// The folder: ROLLNOISE_CACHE_DIR ("off": none), else $XDG_CACHE_HOME/rollnoise, else
// $HOME/.cache/rollnoise.
TEST(WheelModesCache, FolderFromTheEnvironment) {
  struct Saved {
    const char* name;
    std::optional<std::string> value;
  };
  std::vector<Saved> saved;
  for (const char* name : {"ROLLNOISE_CACHE_DIR", "XDG_CACHE_HOME", "HOME"}) {
    const char* v = std::getenv(name);
    saved.push_back({name, v ? std::optional<std::string>(v) : std::nullopt});
  }
  ::setenv("HOME", "/home/someone", 1);
  ::unsetenv("XDG_CACHE_HOME");
  ::unsetenv("ROLLNOISE_CACHE_DIR");
  EXPECT_EQ(io::mode_cache_directory(),
            std::optional<std::string>("/home/someone/.cache/rollnoise"));
  ::setenv("XDG_CACHE_HOME", "/var/cache/u", 1);
  EXPECT_EQ(io::mode_cache_directory(), std::optional<std::string>("/var/cache/u/rollnoise"));
  ::setenv("ROLLNOISE_CACHE_DIR", "/scratch/modes", 1);
  EXPECT_EQ(io::mode_cache_directory(), std::optional<std::string>("/scratch/modes"));
  ::setenv("ROLLNOISE_CACHE_DIR", "off", 1);
  EXPECT_FALSE(io::mode_cache_directory());
  for (const Saved& s : saved)
    if (s.value)
      ::setenv(s.name, s.value->c_str(), 1);
    else
      ::unsetenv(s.name);
}
