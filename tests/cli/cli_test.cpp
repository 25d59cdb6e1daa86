// The rollnoise program end to end: a steady run writes the docs/conventions.md Sec. 4 layout with units, and bad
// input gives exit status 2, a message naming the key, and no output file.
#include <gtest/gtest.h>
#include <hdf5.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "cli_support.hpp"

namespace fs = std::filesystem;
using namespace rollnoise::cli_test;

namespace {

std::string read_units(hid_t file, const char* path) {
  const hid_t set = H5Dopen2(file, path, H5P_DEFAULT);
  if (set < 0) return "(missing)";
  const hid_t attr = H5Aopen(set, "units", H5P_DEFAULT);
  const hid_t type = H5Aget_type(attr);
  std::string s(H5Tget_size(type), '\0');
  H5Aread(attr, type, s.data());
  H5Tclose(type);
  H5Aclose(attr);
  H5Dclose(set);
  return s.c_str();
}

// A fixed-width string dataset (io::Hdf5Writer's layout) as strings; empty when missing.
std::vector<std::string> read_strings(const std::string& file, const char* path) {
  std::vector<std::string> out;
  const hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  if (f < 0) return out;
  const hid_t set = H5Dopen2(f, path, H5P_DEFAULT);
  if (set >= 0) {
    const hid_t type = H5Dget_type(set), space = H5Dget_space(set);
    const std::size_t width = H5Tget_size(type);
    const auto count = static_cast<std::size_t>(H5Sget_simple_extent_npoints(space));
    std::vector<char> buf(width * count);
    H5Dread(set, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, buf.data());
    for (std::size_t i = 0; i < count; ++i)
      out.emplace_back(std::string(&buf[i * width], width).c_str());
    H5Sclose(space);
    H5Tclose(type);
    H5Dclose(set);
  }
  H5Fclose(f);
  return out;
}

}  // namespace

// rollnoise modes on the shipped wheel (cases/squeal_300m.toml: the 920 mm section, 8 mm): one
// label per mode in /modes/label, and the summary's cells (family, circles, n) are each one mode's
// (issue 51: two modes were "radial n=2 0 circles" at 1887 and 2135 Hz).
TEST(ModesCommand, EveryModeOfTheShippedWheelHasItsOwnLabel) {
  const auto out = (temp_dir() / "modes_labels.h5").string();
  const auto r = run("modes " + source_file("cases/squeal_300m.toml") + " -o " + out);
  ASSERT_EQ(r.status, 0) << r.output;
  const std::vector<std::string> labels = read_strings(out, "/modes/label");
  ASSERT_GT(labels.size(), 30u) << r.output;  // the 920 mm wheel's modes up to 6 kHz
  EXPECT_EQ(std::set<std::string>(labels.begin(), labels.end()).size(), labels.size()) << r.output;
  EXPECT_EQ(read_strings(out, "/modes/family").size(), labels.size());
  std::set<std::string> cells;  // "family, C nodal circles (Hz): n=N F n=N F ..." per line
  std::istringstream lines(r.output);
  for (std::string line; std::getline(lines, line);) {
    const auto colon = line.find("(Hz):");
    if (colon == std::string::npos) continue;
    std::istringstream words(line.substr(colon + 5));
    for (std::string n, f; words >> n >> f;)
      EXPECT_TRUE(cells.insert(line.substr(0, colon) + n).second) << line;
  }
  EXPECT_EQ(cells.size(), labels.size()) << r.output;
}

// rollnoise --version: the build's version (git describe at build time, as every result file's
// program_version attribute holds it) on one line, exit status 0, no command needed.
TEST(ProgramVersion, VersionFlagPrintsTheBuildsVersionAndExitsZero) {
  const Invocation r = run("--version");
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_EQ(r.output.rfind("rollnoise ", 0), 0u) << r.output;
  EXPECT_GT(r.output.size(), std::string("rollnoise \n").size()) << r.output;
  EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
}

TEST(SteadyCommand, WritesForcesTractionsAndUnitsInTheInterfaceLayout) {
  const fs::path out = temp_dir() / "steady.h5";
  const Invocation r = run("steady " + paper_case() + " -o " + out.string() + " --set grid.nx=20 --set grid.ny=15");
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("Fx ="), std::string::npos);
  EXPECT_NE(r.output.find("adhesion"), std::string::npos);
  ASSERT_TRUE(fs::exists(out));
  EXPECT_FALSE(fs::exists(out.string() + ".partial"));
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  const hid_t f = H5Fopen(out.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(f, 0);
  EXPECT_EQ(read_units(f, "/grid/x"), "m");
  EXPECT_EQ(read_units(f, "/normal/pn"), "Pa");
  EXPECT_EQ(read_units(f, "/steady/force"), "N, N, N m");
  EXPECT_EQ(read_units(f, "/steady/px"), "Pa");
  EXPECT_NE(read_units(f, "/steady/state"), "(missing)");
  // the case as run, with the override
  const hid_t g = H5Oopen(f, "/case", H5P_DEFAULT);
  const hid_t a = H5Aopen(g, "toml", H5P_DEFAULT);
  const hid_t t = H5Aget_type(a);
  std::string toml(H5Tget_size(t), '\0');
  H5Aread(a, t, toml.data());
  EXPECT_NE(toml.find("nx = 20"), std::string::npos) << toml;
  H5Tclose(t), H5Aclose(a), H5Oclose(g), H5Fclose(f);
}

TEST(SteadyCommand, SweepGivesAForceCreepageCurveInOneRun) {
  const fs::path out = temp_dir() / "sweep.h5";
  const Invocation r = run("steady " + paper_case() + " -o " + out.string() +
                    " --set grid.nx=20 --set grid.ny=15 --sweep 'creepage.mean[0]=0:0.01:5'");
  ASSERT_EQ(r.status, 0) << r.output;
  const hid_t f = H5Fopen(out.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(f, 0);
  const hid_t set = H5Dopen2(f, "/sweep/force", H5P_DEFAULT);
  ASSERT_GE(set, 0);
  std::array<double, 15> F;
  H5Dread(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, F.data());
  H5Dclose(set), H5Fclose(f);
  for (int i = 1; i < 5; ++i) EXPECT_LT(F[3 * i], F[3 * (i - 1)]) << "Fx falls with creepage";
  EXPECT_NEAR(F[12], -0.3 * 98100, 0.01 * 0.3 * 98100);  // saturates at mu N
}

struct BadInput {
  std::string name, toml_or_set, key;
};

class BadInputTest : public ::testing::TestWithParam<BadInput> {};

TEST_P(BadInputTest, ExitsWithStatus2NamingTheKeyAndWritesNoFile) {
  const BadInput& b = GetParam();
  const fs::path dir = temp_dir();
  const fs::path out = dir / (b.name + ".h5");
  std::string args;
  if (b.toml_or_set.rfind("--set", 0) == 0) {
    args = "steady " + paper_case() + " " + b.toml_or_set;
  } else {
    const fs::path file = dir / (b.name + ".toml");
    std::ofstream(file) << b.toml_or_set;
    args = "steady " + file.string();
  }
  const Invocation r = run(args + " -o " + out.string());
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find(b.key), std::string::npos) << "message must name '" << b.key << "': " << r.output;
  EXPECT_FALSE(fs::exists(out));
  EXPECT_FALSE(fs::exists(out.string() + ".partial"));
}

INSTANTIATE_TEST_SUITE_P(
    Cases, BadInputTest,
    ::testing::Values(
        BadInput{"malformed", "[contact\nnormal_force = 1", "malformed TOML"},
        BadInput{"unknown_key", "[contact]\nnormal_force = 98100\na = 7e-3\nb = 5e-3\nwidth = 3\n", "contact.width"},
        BadInput{"negative_load", "--set contact.normal_force=-98100", "contact.normal_force"},
        BadInput{"nan_creepage", "--set 'creepage.mean=[nan, 0.0, 0.0]'", "creepage.mean"},
        BadInput{"coarse_grid", "--set grid.nx=3", "grid.nx"},
        BadInput{"wrong_type", "--set grid.nx=2.5", "grid.nx"},
        BadInput{"bad_geometry", "--set contact.geometry=ellipse", "contact.geometry"},
        BadInput{"missing_load", "[contact]\na = 7e-3\nb = 5e-3\n", "contact.normal_force"},
        BadInput{"small_potential_area", "--set grid.scale=0.9", "grid.scale"}),
    [](const auto& info) { return info.param.name; });

TEST(TransientCommand, CsvHistoryWithSnapshotsWritesTimeCreepageAndForce) {
  const fs::path dir = temp_dir();
  {
    std::ofstream csv(dir / "history.csv");
    csv << "t,xi_x,xi_y,phi\n0,0.001,0,0\n0.001,0.0012,0,0\n0.002,0.001,0,0\n";
  }
  const fs::path case_file = dir / "tr.toml";
  std::ofstream(case_file) << "[contact]\nnormal_force = 98100\na = 7.18e-3\nb = 5.29e-3\n"
                              "[grid]\nnx = 20\nny = 15\n[creepage]\nmean = [0.001, 0.0, 0.0]\n"
                              "[excitation]\ntype = \"csv\"\nfile = \"history.csv\"\n"
                              "[transient]\nduration = 0.002\nsnapshots = [0.001]\n";
  const fs::path out = dir / "tr.h5";
  const Invocation r = run("transient " + case_file.string() + " -q -o " + out.string());
  ASSERT_EQ(r.status, 0) << r.output;
  const hid_t f = H5Fopen(out.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(f, 0);
  EXPECT_EQ(read_units(f, "/transient/time"), "s");
  EXPECT_EQ(read_units(f, "/transient/force"), "N, N, N m");
  EXPECT_EQ(read_units(f, "/transient/snapshots/0/px"), "Pa");
  const hid_t set = H5Dopen2(f, "/transient/creepage", H5P_DEFAULT);
  const hid_t space = H5Dget_space(set);
  hsize_t dims[2];
  H5Sget_simple_extent_dims(space, dims, nullptr);
  std::vector<double> c(dims[0] * dims[1]);
  H5Dread(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, c.data());
  H5Sclose(space), H5Dclose(set), H5Fclose(f);
  // dt = dx/V = (2 * 1.1333 * 7.18e-3 / 20) / 13.889: the creepage peaks mid-run at 0.0012
  double peak = 0;
  for (size_t k = 0; k < dims[0]; ++k) peak = std::max(peak, c[3 * k]);
  EXPECT_GT(peak, 0.00118);
  EXPECT_LE(peak, 0.0012 + 1e-15);
}

TEST(TransientCommand, DurationShorterThanOneStepIsAnInputError) {
  const Invocation r = run("transient " + paper_case() + " --set transient.duration=1e-6 -o " +
                           (temp_dir() / "short.h5").string());
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.output.find("transient.duration"), std::string::npos) << r.output;
}

TEST(CreepCommand, WritesComplexCoefficientsAndCsvAndRejectsFrequenciesAboveNyquist) {
  const fs::path dir = temp_dir();
  const fs::path out = dir / "creep.h5", csv = dir / "creep.csv";
  const Invocation r = run("creep " + paper_case() + " --set grid.nx=20 --set grid.ny=15 "
                           "--set 'frequency.list=[0.0, 500.0, 1000.0]' -o " + out.string() + " --csv " + csv.string());
  ASSERT_EQ(r.status, 0) << r.output;
  const hid_t f = H5Fopen(out.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(f, 0);
  EXPECT_EQ(read_units(f, "/creep/frequency"), "Hz");
  EXPECT_NE(read_units(f, "/creep/f").find("rows Fx"), std::string::npos);
  EXPECT_NE(read_units(f, "/creep/g").find("g3 = dMz/dN [m]"), std::string::npos);
  H5Fclose(f);
  std::ifstream in(csv);
  std::string line, header;
  int rows = 0;
  while (std::getline(in, line))
    if (!line.empty() && line[0] != '#') {
      if (rows++ == 0) header = line;
    }
  EXPECT_EQ(rows, 4);  // header + 3 frequencies
  EXPECT_NE(header.find(",re_g1,im_g1,re_g2,im_g2,re_g3,im_g3"), std::string::npos) << header;
  const Invocation bad = run("creep " + paper_case() + " --set grid.nx=20 --set grid.ny=15 "
                             "--set 'frequency.list=[1000.0, 40000.0]' -o " + (dir / "bad.h5").string());
  EXPECT_EQ(bad.status, 2);
  EXPECT_NE(bad.output.find("Nyquist"), std::string::npos) << bad.output;
  EXPECT_NE(bad.output.find("frequency.list"), std::string::npos) << bad.output;
  EXPECT_FALSE(fs::exists(dir / "bad.h5"));
}

TEST(ValidateCommand, LinearModelTracksTheUnsteadySolverAtTheMeanState) {
  const fs::path out = temp_dir() / "validate.h5";
  const Invocation r = run("validate " + paper_case() + " -q --set grid.nx=20 --set grid.ny=15 "
                           "--set 'excitation.amplitude=[5e-5, 5e-5, 0.0027]' --set transient.duration=0.004 -o " +
                           out.string());
  ASSERT_EQ(r.status, 0) << r.output;
  const hid_t f = H5Fopen(out.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(f, 0);
  std::array<double, 3> rms;
  const hid_t set = H5Dopen2(f, "/validate/errors/rms_relative", H5P_DEFAULT);
  H5Dread(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, rms.data());
  H5Dclose(set);
  EXPECT_NE(read_units(f, "/validate/spectrum/frequency"), "(missing)");
  H5Fclose(f);
  EXPECT_LT(rms[0], 0.02);
  EXPECT_LT(rms[1], 0.02);
}

namespace {

std::vector<double> read_doubles(hid_t f, const char* path) {
  const hid_t set = H5Dopen2(f, path, H5P_DEFAULT);
  if (set < 0) return {};
  const hid_t space = H5Dget_space(set);
  std::vector<double> v(H5Sget_simple_extent_npoints(space));
  H5Dread(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data());
  H5Sclose(space), H5Dclose(set);
  return v;
}

// The 300 m curve with the table wheel (the shipped curve_300m.toml has the FE wheel, whose modes would
// cost each of these runs 1-2 s, 20-30 s under the sanitizers; these checks are of the contact state,
// the outputs and the NSS-vs-Kalker forces of the table wheel's loop).
std::string curve_case() { return std::string(ROLLNOISE_SOURCE_DIR) + "/cases/curve_300m_table.toml"; }

}  // namespace

TEST(NoiseCommand, CurveCaseGivesBandLevelsAndTheNSSModelChangesTangentialNotVerticalForces) {
  const fs::path out = temp_dir() / "noise.h5";
  const Invocation r = run("noise " + curve_case() + " --set noise.points_per_band=12 --set noise.compare=kalker "
                           "--set track.support=continuous --set 'curve.wheels=[\"leading_outer\"]' --set noise.band_max=2000.0 -o " + out.string());
  ASSERT_EQ(r.status, 0) << r.output;
  const hid_t f = H5Fopen(out.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(f, 0);
  EXPECT_EQ(read_units(f, "/noise/frequency"), "Hz");
  EXPECT_NE(read_units(f, "/noise/force").find("per unit roughness"), std::string::npos);
  EXPECT_NE(read_units(f, "/noise/bands/velocity_level").find("1e-9 m/s"), std::string::npos);
  const auto centre = read_doubles(f, "/noise/bands/centre");
  const auto nss = read_doubles(f, "/noise/bands/force_level");
  const auto kalker = read_doubles(f, "/noise/kalker/bands/force_level");
  const auto creep = read_doubles(f, "/steady/creepage");
  H5Fclose(f);
  ASSERT_EQ(nss.size(), 4 * centre.size());
  ASSERT_EQ(kalker.size(), nss.size());
  EXPECT_LT(creep[1], 0.0) << "the leading outer wheel runs with negative lateral creepage in a curve";
  double dz = 0, dy = 0;
  for (size_t i = 0; i < centre.size(); ++i) {
    EXPECT_TRUE(std::isfinite(nss[4 * i]) && std::isfinite(nss[4 * i + 2]));
    if (centre[i] < 300) continue;
    dz = std::max(dz, std::abs(nss[4 * i] - kalker[4 * i]));
    dy = std::max(dy, std::abs(nss[4 * i + 2] - kalker[4 * i + 2]));
  }
  std::printf("above 300 Hz: Fz differs by at most %.2f dB, Fy by up to %.1f dB (NSS vs Kalker)\n", dz, dy);
  EXPECT_LT(dz, 3.0);
  EXPECT_GT(dy, 6.0);
}

// The default run (noise.normal_coupling = "on", noise.compare = "quasi-steady") also writes the
// loop without the coupling and the quasi-steady baseline; coupling_difference is the difference of
// the written levels. The 300 m curve's tread contact is fully sliding, so with the coupling Fy
// follows the mu-scaled normal force, L_Fy = 20 log10|Fy_mean/N| + L_Fz, and it raises Fy in every
// band, by far more on average than the quasi-steady baseline differs from the NSS result.
TEST(NoiseCommand, CoupledUncoupledAndQuasiSteadyOutputs) {
  const fs::path out = temp_dir() / "noise_coupling.h5";
  const Invocation r = run("noise " + curve_case() + " --set noise.points_per_band=12 "
                           "--set track.support=continuous --set 'curve.wheels=[\"leading_outer\"]' --set noise.band_max=2000.0 -o " + out.string());
  ASSERT_EQ(r.status, 0) << r.output;
  const hid_t f = H5Fopen(out.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(f, 0);
  const auto coupled = read_doubles(f, "/noise/bands/force_level");
  const auto uncoupled = read_doubles(f, "/noise/uncoupled/bands/force_level");
  const auto quasi = read_doubles(f, "/noise/quasi_steady/bands/force_level");
  const auto diff = read_doubles(f, "/noise/bands/coupling_difference");
  const auto centre = read_doubles(f, "/noise/bands/centre");
  const auto mean_force = read_doubles(f, "/steady/force");
  const auto normal = read_doubles(f, "/normal/force");
  EXPECT_EQ(read_units(f, "/noise/bands/coupling_difference").substr(0, 2), "dB");
  EXPECT_NE(read_units(f, "/noise/creep/g"), "(missing)");
  EXPECT_NE(read_units(f, "/noise/quasi_steady/g"), "(missing)");
  EXPECT_EQ(read_units(f, "/noise/kalker/force"), "(missing)");
  H5Fclose(f);
  ASSERT_EQ(uncoupled.size(), coupled.size());
  ASSERT_EQ(quasi.size(), coupled.size());
  ASSERT_EQ(diff.size(), coupled.size());
  ASSERT_EQ(4 * centre.size(), coupled.size());
  const double mu_level = 20 * std::log10(std::abs(mean_force[1] / normal[0]));
  double dy = 1e9, dy_mean = 0.0, dq = 0.0, follow = 0.0;
  for (size_t b = 0; b < centre.size(); ++b) {
    for (int j = 0; j < 4; ++j) EXPECT_NEAR(diff[4 * b + j], coupled[4 * b + j] - uncoupled[4 * b + j], 1e-12);
    dy = std::min(dy, diff[4 * b + 2]);
    dy_mean += diff[4 * b + 2] / centre.size();
    dq = std::max(dq, std::abs(coupled[4 * b + 2] - quasi[4 * b + 2]));
    if (centre[b] <= 1000.0) follow = std::max(follow, std::abs(coupled[4 * b + 2] - (mu_level + coupled[4 * b])));
  }
  std::printf("coupling raises Fy by %.1f dB at least, %.1f dB on average; Fy within %.2f dB of the mu-scaled Fz up "
              "to 1 kHz; NSS vs quasi-steady Fy within %.2f dB\n", dy, dy_mean, follow, dq);
  EXPECT_GT(dy, 0.0);
  EXPECT_GT(dy_mean, 6.0);
  EXPECT_LT(follow, 3.0);
  EXPECT_LT(dq, dy_mean);
}

TEST(NoiseCommand, DeprecatedCompareKalkerIsAnAliasAndMayNotContradict) {
  // the curve case without its noise.compare line (an older case file)
  const fs::path old_case = temp_dir() / "old_curve_300m.toml";
  {
    std::ifstream in(curve_case());
    std::ofstream o(old_case);
    for (std::string line; std::getline(in, line);)
      if (line.rfind("compare", 0) != 0) o << line << "\n";
  }
  const std::string base = "noise " + old_case.string() + " --set noise.points_per_band=4 --set track.support=continuous --set 'curve.wheels=[\"leading_outer\"]' "
                           "--set noise.band_max=500.0 ";
  const fs::path out = temp_dir() / "noise_alias.h5";
  const Invocation r = run(base + "--set noise.compare_kalker=yes -o " + out.string());
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("deprecated"), std::string::npos) << r.output;
  const hid_t f = H5Fopen(out.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(f, 0);
  EXPECT_NE(read_units(f, "/noise/kalker/force"), "(missing)");
  EXPECT_EQ(read_units(f, "/noise/quasi_steady/force"), "(missing)");
  H5Fclose(f);
  const Invocation bad = run(base + "--set noise.compare_kalker=yes --set noise.compare=none -o " +
                             (temp_dir() / "noise_bad.h5").string());
  EXPECT_EQ(bad.status, 2) << bad.output;
  EXPECT_NE(bad.output.find("noise.compare_kalker"), std::string::npos) << bad.output;
}

// The profile curve case: the contact state the loop ran on is written under /noise/contact with
// units (two_point an integer flag), the summary line names the contact and the two-point state,
// and [wheelset] keys outside the multibody input are an input error naming the key.
TEST(NoiseCommand, WritesTheCurveContactState) {
  const fs::path out = temp_dir() / "noise_contact.h5";
  const Invocation r = run("noise " + curve_case() + " --set noise.points_per_band=4 --set noise.band_max=1000.0 "
                           "--set track.support=continuous --set 'curve.wheels=[\"leading_outer\"]' --set noise.compare=\"none\" -o " + out.string());
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("two-point"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("on the wheel at"), std::string::npos) << r.output;
  const hid_t f = H5Fopen(out.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(f, 0);
  for (const char* name : {"/noise/contact/position_wheel", "/noise/contact/position_rail", "/noise/contact/rolling_radius"})
    EXPECT_EQ(read_units(f, name).substr(0, 1), "m") << name;
  EXPECT_EQ(read_units(f, "/noise/contact/angle"), "rad");
  EXPECT_EQ(read_units(f, "/noise/contact/normal_force"), "N");
  EXPECT_EQ(read_units(f, "/noise/contact/flange_normal_force"), "N");
  EXPECT_EQ(read_units(f, "/noise/contact/creepage"), "-, -, rad/m");
  EXPECT_EQ(read_units(f, "/noise/contact/two_point"), "-");
  const hid_t set = H5Dopen2(f, "/noise/contact/two_point", H5P_DEFAULT);
  ASSERT_GE(set, 0);
  const hid_t type = H5Dget_type(set);
  EXPECT_EQ(H5Tget_class(type), H5T_INTEGER);
  int two_point = -1;
  H5Dread(set, H5T_NATIVE_INT, H5S_ALL, H5S_ALL, H5P_DEFAULT, &two_point);
  H5Tclose(type), H5Dclose(set);
  const auto creepage = read_doubles(f, "/noise/contact/creepage");
  const auto steady = read_doubles(f, "/steady/creepage");
  const auto normal = read_doubles(f, "/noise/contact/normal_force");
  const auto force = read_doubles(f, "/normal/force");
  const auto flange = read_doubles(f, "/noise/contact/flange_normal_force");
  H5Fclose(f);
  EXPECT_EQ(two_point, 1);
  EXPECT_GT(flange[0], 0.0);
  ASSERT_EQ(creepage.size(), 3u);
  for (int i = 0; i < 3; ++i) EXPECT_EQ(creepage[i], steady[i]) << "the loop ran on the state's creepages";
  EXPECT_NEAR(force[0], normal[0], 1e-6 * normal[0]) << "the patch carries the state's normal force";

  const Invocation bad = run("noise " + curve_case() + " --set wheelset.yaw=0.002 -o " + (temp_dir() / "bad.h5").string());
  EXPECT_EQ(bad.status, 2) << bad.output;
  EXPECT_NE(bad.output.find("wheelset.yaw"), std::string::npos) << bad.output;
}

// curve.wheels (default: all four in a curve): each wheel's contact state and its loop's levels
// under /noise/wheels/<wheel>, with units; each patch carries its wheel's vertical load (the
// force in the track frame has up = vertical_load within 1e-5); the leading outer wheel is the
// top-level run (same normal force and band levels, bit for bit); the summary prints one line per
// wheel; each wheel's contact work gives its linear model's order r = 2 adhesion + slip elements,
// its sweep's block steps (> 0) and its wall time (> 0 s); a wrong wheel name or a
// [trailing_wheelset] key outside a multibody run names its key.
TEST(NoiseCommand, WritesEveryWheelsContactStateAndLevels) {
  const fs::path out = temp_dir() / "noise_wheels.h5";
  const Invocation r = run("noise " + curve_case() + " --set noise.points_per_band=4 --set noise.band_max=1000.0 "
                           "--set track.support=continuous --set noise.compare=\"none\" "
                           "--set noise.contact_coupling=\"none\" -o " + out.string());
  ASSERT_EQ(r.status, 0) << r.output;
  const hid_t f = H5Fopen(out.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(f, 0);
  const auto top_levels = read_doubles(f, "/noise/bands/force_level");
  const auto top_normal = read_doubles(f, "/noise/contact/normal_force");
  for (const std::string w : {"leading_outer", "leading_inner", "trailing_outer", "trailing_inner"}) {
    EXPECT_NE(r.output.find("  " + w + " "), std::string::npos) << w << r.output;
    const std::string g = "/noise/wheels/" + w;
    EXPECT_EQ(read_units(f, (g + "/contact/force_track").c_str()).substr(0, 1), "N") << w;
    EXPECT_EQ(read_units(f, (g + "/contact/creepage").c_str()).substr(0, 11), "-, -, rad/m") << w;
    EXPECT_EQ(read_units(f, (g + "/contact/position_wheel").c_str()).substr(0, 1), "m") << w;
    const auto force = read_doubles(f, (g + "/contact/force_track").c_str());
    const auto load = read_doubles(f, (g + "/contact/vertical_load").c_str());
    const auto levels = read_doubles(f, (g + "/bands/force_level").c_str());
    ASSERT_EQ(force.size(), 3u) << w;
    ASSERT_EQ(load.size(), 1u) << w;
    EXPECT_NEAR(force[2], load[0], 1e-5 * load[0]) << w;
    ASSERT_EQ(levels.size(), top_levels.size()) << w;
    for (double l : levels) EXPECT_TRUE(std::isfinite(l)) << w;
    if (w == "leading_outer") {
      EXPECT_EQ(levels, top_levels);
      EXPECT_EQ(read_doubles(f, (g + "/contact/normal_force").c_str()), top_normal);
    }
    const auto elements = read_doubles(f, (g + "/contact_work/elements").c_str());
    const auto unknowns = read_doubles(f, (g + "/contact_work/reduced_unknowns").c_str());
    const auto steps = read_doubles(f, (g + "/contact_work/block_steps").c_str());
    const auto seconds = read_doubles(f, (g + "/contact_work/seconds").c_str());
    ASSERT_EQ(elements.size(), 2u) << w;
    ASSERT_EQ(unknowns.size(), 1u) << w;
    EXPECT_EQ(unknowns[0], 2 * elements[0] + elements[1]) << w;
    EXPECT_GT(steps.at(0), 0.0) << w;
    EXPECT_GT(seconds.at(0), 0.0) << w;
    EXPECT_EQ(read_units(f, (g + "/contact_work/seconds").c_str()).substr(0, 2), "s ") << w;
  }
  H5Fclose(f);
  EXPECT_NE(r.output.find("in the loop alone"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("contact work (curve state"), std::string::npos) << r.output;

  const Invocation bad = run("noise " + curve_case() + " --set 'curve.wheels=[\"front_left\"]' -o " +
                             (temp_dir() / "bad_wheels.h5").string());
  EXPECT_EQ(bad.status, 2) << bad.output;
  EXPECT_NE(bad.output.find("curve.wheels"), std::string::npos) << bad.output;
  const Invocation trailing = run("noise " + curve_case() + " --set trailing_wheelset.yaw=0.001 -o " +
                                  (temp_dir() / "bad_trailing.h5").string());
  EXPECT_EQ(trailing.status, 2) << trailing.output;
  EXPECT_NE(trailing.output.find("trailing_wheelset.yaw"), std::string::npos) << trailing.output;
}

TEST(NoiseCommand, BandsAboveTheGridsNyquistLimitAreAnInputError) {
  const Invocation r = run("noise " + curve_case() + " --set noise.band_max=20000.0 --set noise.points_per_band=4 "
                           "--set track.support=continuous -o " + (temp_dir() / "nyq.h5").string());
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("noise.band_max"), std::string::npos) << r.output;
}

TEST(ReceptanceCommand, WritesReciprocalWheelAndRailAndTheContactReceptance) {
  const fs::path out = temp_dir() / "receptance.h5";
  const Invocation r = run("receptance " + curve_case() + " --set frequency.count=20 --set track.support=continuous -o " +
                           out.string());
  ASSERT_EQ(r.status, 0) << r.output;
  const hid_t f = H5Fopen(out.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(f, 0);
  for (const char* name : {"/receptance/wheel", "/receptance/rail", "/receptance/contact"})
    EXPECT_NE(read_units(f, name).find("m/N"), std::string::npos) << name;
  // complex {r, i} compound, [20][4][4]
  const hid_t set = H5Dopen2(f, "/receptance/wheel", H5P_DEFAULT);
  const hid_t type = H5Dget_type(set);
  std::vector<double> v(20 * 16 * 2);
  H5Dread(set, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data());
  H5Tclose(type), H5Dclose(set), H5Fclose(f);
  for (int k = 0; k < 20; ++k)
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < i; ++j) {
        const double* a = &v[2 * (16 * k + 4 * i + j)];
        const double* b = &v[2 * (16 * k + 4 * j + i)];
        EXPECT_NEAR(a[0], b[0], 1e-9 * (std::abs(a[0]) + 1e-30) + 1e-25);
        EXPECT_NEAR(a[1], b[1], 1e-9 * (std::abs(a[1]) + 1e-30) + 1e-25);
      }
}

namespace {

std::vector<std::complex<double>> read_complex(hid_t f, const std::string& path) {
  const hid_t set = H5Dopen2(f, path.c_str(), H5P_DEFAULT);
  if (set < 0) return {};
  const hid_t space = H5Dget_space(set), type = H5Dget_type(set);
  std::vector<std::complex<double>> v(H5Sget_simple_extent_npoints(space));
  H5Dread(set, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data());
  H5Tclose(type), H5Sclose(space), H5Dclose(set);
  return v;
}

}  // namespace

TEST(NonHertzianContact, LinearModelSpectraWithin1dBOfTheUnsteadySolverOnTheS1002Patch) {
  // Paper Sec. 3.5: S1002 on UIC60, centred, pseudo-random creepage in [100 Hz, 1 kHz]. Spectra
  // (Hann window after 2 ms) of the linear model and the unsteady solver, compared bin by bin over
  // 100 Hz - 1 kHz outside notches (bins where the unsteady amplitude is below 0.3 x its median).
  const fs::path out = temp_dir() / "nonhertz.h5";
  const Invocation r = run("validate " + std::string(ROLLNOISE_SOURCE_DIR) + "/cases/nonhertz_s1002_uic60.toml -q "
                           "--set transient.duration=0.03 -o " + out.string());
  ASSERT_EQ(r.status, 0) << r.output;
  const hid_t f = H5Fopen(out.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(f, 0);
  const auto freq = read_doubles(f, "/validate/spectrum/frequency");
  for (const std::string c : {"Fx", "Fy"}) {
    const auto u = read_complex(f, "/validate/spectrum/unsteady_" + c);
    const auto l = read_complex(f, "/validate/spectrum/linear_" + c);
    ASSERT_EQ(u.size(), freq.size());
    std::vector<double> band;
    for (size_t k = 0; k < freq.size(); ++k)
      if (freq[k] >= 100 && freq[k] <= 1000) band.push_back(std::abs(u[k]));
    ASSERT_GT(band.size(), 10u);
    std::nth_element(band.begin(), band.begin() + band.size() / 2, band.end());
    const double median = band[band.size() / 2];
    double worst = 0;
    int compared = 0;
    for (size_t k = 0; k < freq.size(); ++k)
      if (freq[k] >= 100 && freq[k] <= 1000 && std::abs(u[k]) >= 0.3 * median) {
        worst = std::max(worst, std::abs(20 * std::log10(std::abs(l[k]) / std::abs(u[k]))));
        ++compared;
      }
    std::printf("%s: %d bins compared, largest difference %.3f dB\n", c.c_str(), compared, worst);
    EXPECT_LT(worst, 1.0) << c;
  }
  H5Fclose(f);
}

TEST(BenchCommand, RefinementTableShowsTheErrorsFallingTowardsTheFinestGrid) {
  const fs::path csv = temp_dir() / "bench.csv", h5 = temp_dir() / "bench.h5";
  // CONTACT's creepage sampling: its first-order errors fall monotonically from 10x7 on (with midstep the
  // 100 Hz error of these coarse grids is the irregular spatial one, docs/accuracy.md)
  const Invocation r = run("bench " + paper_case() + " --nx 10,14,20,34 --csv " + csv.string() + " -o " +
                           h5.string() + " --set rolling.creepage_sampling='\"contact\"'");
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("postprocess/plot_bench.py"), std::string::npos) << r.output;
  std::ifstream in(csv);
  std::string line;
  std::vector<std::string> header;
  std::vector<std::vector<double>> rows;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::stringstream ss(line);
    std::string cell;
    std::vector<double> row;
    const bool is_header = header.empty();
    while (std::getline(ss, cell, ','))
      if (is_header)
        header.push_back(cell);
      else
        row.push_back(std::stod(cell));  // "nan" parses as NaN
    if (!is_header) rows.push_back(row);
  }
  ASSERT_EQ(rows.size(), 4u);
  auto col = [&](const std::string& name) {
    const auto it = std::find(header.begin(), header.end(), name);
    EXPECT_NE(it, header.end()) << name;
    std::vector<double> v;
    for (const auto& row : rows)
      v.push_back(it == header.end() ? NAN : row.at(it - header.begin()));
    return v;
  };
  // errors against the finest grid (34): falling on 10 -> 14 -> 20, zero on the reference
  for (const char* name : {"err_force_rel", "err_f_100Hz_rel", "err_f_1kHz_rel",
                           "err_transient_rel", "err_transient_pc_rel"}) {
    const auto e = col(name);
    for (int i = 0; i < 3; ++i) EXPECT_TRUE(std::isfinite(e[i])) << name << " " << i;
    EXPECT_GT(e[0], e[1]) << name;
    EXPECT_GT(e[1], e[2]) << name;
    EXPECT_EQ(e[3], 0.0) << name;
  }
  for (const char* name : {"t_transient_s", "transient_steps", "err_transient_vs_linear_rel"})
    for (double v : col(name)) EXPECT_TRUE(std::isfinite(v) && v >= 0) << name;
  // the unsteady solver agrees with the linear model on every grid (docs/conventions.md Sec. 3: 0.1 %)
  for (double v : col("err_transient_vs_linear_rel")) EXPECT_LT(v, 1e-3);
  // the same table in HDF5 (/bench/*), with units
  const hid_t f = H5Fopen(h5.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(f, 0) << "bench -o wrote no HDF5 file";
  for (const char* name : {"err_force_rel", "err_f_1kHz_rel", "err_transient_vs_linear_rel"}) {
    const std::string path = std::string("/bench/error/") + name;
    std::vector<double> v(4, NAN);
    const hid_t set = H5Dopen2(f, path.c_str(), H5P_DEFAULT);
    ASSERT_GE(set, 0) << path;
    H5Dread(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data());
    H5Dclose(set);
    const auto c = col(name);
    for (int i = 0; i < 4; ++i) EXPECT_NEAR(v[i], c[i], 1e-7 * std::abs(c[i]) + 1e-300) << path << " " << i;
  }
  EXPECT_EQ(read_units(f, "/bench/time_creep").rfind("s", 0), 0u);
  EXPECT_EQ(read_units(f, "/bench/dx"), "m");
  H5Fclose(f);
}

TEST(Program, KeysListsTheSchemaWithDefaults) {
  const Invocation r = run("keys");
  EXPECT_EQ(r.status, 0);
  EXPECT_NE(r.output.find("spin_offset"), std::string::npos);
  EXPECT_NE(r.output.find("[creepage]"), std::string::npos);
}

TEST(TransientCommand, NormalAmplitudeIsWrittenAsTheHarmonicNormalForceHistory) {
  const fs::path out = temp_dir() / "tr_normal.h5";
  const Invocation r = run("transient " + paper_case() + " -q --set grid.nx=20 --set grid.ny=15 "
                           "--set excitation.normal_amplitude=981 --set excitation.normal_phase=0.5235987755982988 "
                           "--set excitation.frequency=1000 --set transient.duration=0.002 -o " + out.string());
  ASSERT_EQ(r.status, 0) << r.output;
  const hid_t f = H5Fopen(out.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(f, 0);
  EXPECT_EQ(read_units(f, "/transient/normal_force"), "N");
  EXPECT_EQ(read_units(f, "/transient/excitation/normal_amplitude"), "N");
  const auto t = read_doubles(f, "/transient/time"), N = read_doubles(f, "/transient/normal_force");
  const auto force = read_doubles(f, "/transient/force");
  H5Fclose(f);
  ASSERT_EQ(N.size(), t.size());
  ASSERT_GT(t.size(), 20u);
  for (size_t k = 0; k < t.size(); ++k)
    EXPECT_NEAR(N[k], 98100 + 981 * std::cos(2 * M_PI * 1000 * t[k] + M_PI / 6), 1e-9) << "t = " << t[k];
  // the load reaches the tractions: Fx differs from a run at constant load
  const fs::path out0 = temp_dir() / "tr_constant.h5";
  ASSERT_EQ(run("transient " + paper_case() + " -q --set grid.nx=20 --set grid.ny=15 "
                "--set transient.duration=0.002 -o " + out0.string()).status, 0);
  const hid_t f0 = H5Fopen(out0.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  const auto N0 = read_doubles(f0, "/transient/normal_force"), force0 = read_doubles(f0, "/transient/force");
  H5Fclose(f0);
  for (double v : N0) EXPECT_EQ(v, 98100.0) << "written, constant, without a variation";
  double d = 0;
  for (size_t i = 0; i < force.size(); i += 3) d = std::max(d, std::abs(force[i] - force0[i]));
  EXPECT_GT(d, 1.0);
}

namespace {

struct BadLoad {
  std::string name, args, csv, key;
};

class BadNormalLoadTest : public ::testing::TestWithParam<BadLoad> {};

}  // namespace

TEST_P(BadNormalLoadTest, ExitsWithStatus2NamingTheKey) {
  const BadLoad& b = GetParam();
  const fs::path dir = temp_dir();
  std::string args = b.args;
  if (!b.csv.empty()) {
    std::ofstream(dir / (b.name + ".csv")) << b.csv;
    args += " --set excitation.type=csv --set excitation.file=" + (dir / (b.name + ".csv")).string();
  }
  const fs::path out = dir / (b.name + ".h5");
  const Invocation r = run("transient " + paper_case() + " --set grid.nx=20 --set grid.ny=15 " + args + " -o " +
                           out.string());
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find(b.key), std::string::npos) << "message must name '" << b.key << "': " << r.output;
  EXPECT_FALSE(fs::exists(out));
}

INSTANTIATE_TEST_SUITE_P(
    Cases, BadNormalLoadTest,
    ::testing::Values(
        BadLoad{"amplitude_above_mean", "--set excitation.normal_amplitude=-98100", "", "excitation.normal_amplitude"},
        BadLoad{"nan_amplitude", "--set excitation.normal_amplitude=nan", "", "excitation.normal_amplitude"},
        BadLoad{"infinite_phase", "--set excitation.normal_amplitude=10 --set excitation.normal_phase=inf", "",
                "excitation.normal_phase"},
        // 1000 frequencies of 500 N with random phases: the sum reaches -98.1 kN within 2 ms
        BadLoad{"multiharmonic_negative",
                "--set excitation.type=multiharmonic --set excitation.normal_amplitude=5000 "
                "--set transient.duration=0.002",
                "", "excitation.normal_amplitude"},
        BadLoad{"csv_negative_total", "", "t,xi_x,xi_y,phi,dN\n0,0.001,0,0,0\n0.001,0.001,0,0,-99000\n",
                "excitation.file"},
        BadLoad{"csv_nan", "", "0,0.001,0,0,0\n0.001,0.001,0,0,nan\n", "excitation.file"},
        BadLoad{"csv_mixed_columns", "", "0,0.001,0,0,0\n0.001,0.001,0,0\n", "excitation.file"},
        // checked by io (io/excitation.cpp) before contact::CreepageHistory::samples takes the series
        BadLoad{"csv_times_not_increasing", "", "0,0.001,0,0\n0,0.001,0,0\n", "excitation.file"},
        BadLoad{"csv_one_sample", "", "0,0.001,0,0\n", "excitation.file"},
        BadLoad{"grid_too_small", "--set excitation.normal_amplitude=90000", "", "excitation.normal_amplitude"}),
    [](const auto& info) { return info.param.name; });

TEST(ValidateCommand, NormalLoadVariationIsComparedWithTheLinearModelsLoadInput) {
  // Full sliding, N = N_bar + 981 cos(2 pi 1000 t): both the unsteady solver (normal problem per
  // step) and the linear model (g) carry the load; Fx follows mu N at once in both.
  const fs::path out = temp_dir() / "v_normal.h5";
  const Invocation r = run("validate " + paper_case() + " -q --set grid.nx=20 --set grid.ny=15 "
                           "--set 'creepage.mean=[0.006, 0.0, 0.0]' --set 'excitation.amplitude=[0.0, 0.0, 0.0]' "
                           "--set excitation.normal_amplitude=981 --set transient.duration=0.008 "
                           "--set transient.analysis_start=0.002 -o " + out.string());
  ASSERT_EQ(r.status, 0) << r.output;
  const hid_t f = H5Fopen(out.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(f, 0);
  EXPECT_EQ(read_units(f, "/validate/linear/normal_force"), "N");
  const auto rms = read_doubles(f, "/validate/errors/rms_relative");
  const auto normal = read_doubles(f, "/validate/linear/normal_force");
  const auto force = read_doubles(f, "/validate/unsteady/force");
  H5Fclose(f);
  double lo = 1e300, hi = -1e300, flo = 1e300, fhi = -1e300;
  for (size_t k = 0; k < normal.size(); ++k) {
    lo = std::min(lo, normal[k]), hi = std::max(hi, normal[k]);
    flo = std::min(flo, force[3 * k]), fhi = std::max(fhi, force[3 * k]);
  }
  EXPECT_NEAR(hi - lo, 2 * 981.0, 20.0);
  EXPECT_NEAR(fhi - flo, 0.3 * 2 * 981.0, 0.03 * 0.3 * 2 * 981.0) << "Fx follows mu N";
  EXPECT_LT(rms[0], 1e-3) << "linear model vs unsteady solver, Fx";
}

namespace {

// A string attribute of a group ("(missing)" without it).
std::string read_group_attribute(hid_t file, const char* group, const char* name) {
  if (H5Aexists_by_name(file, group, name, H5P_DEFAULT) <= 0) return "(missing)";
  const hid_t attr = H5Aopen_by_name(file, group, name, H5P_DEFAULT, H5P_DEFAULT);
  const hid_t type = H5Aget_type(attr);
  std::string s(H5Tget_size(type), '\0');
  H5Aread(attr, type, s.data());
  H5Tclose(type);
  H5Aclose(attr);
  return s.c_str();
}

}  // namespace

// One answer per wheel: the top-level bands of `noise` are the answer of
// the loop the case asks for (the four wheels coupled by default) for the leading outer wheel,
// the same numbers as its group /noise/wheels/leading_outer (exactly), named in /noise's
// attributes and in the printed table; with curve.wheels naming another wheel alone, the top
// level is that wheel's.
TEST(NoiseCommand, TopLevelBandsAreTheReportedWheelsAnswerInTheCasesLoop) {
  auto check = [](const std::string& wheels, const std::string& reported) {
    const fs::path out = temp_dir() / ("noise_one_answer_" + reported + ".h5");
    std::string set = " --set noise.band_max=630.0 --set noise.points_per_band=12";
    if (!wheels.empty()) set += " --set 'curve.wheels=" + wheels + "'";
    const Invocation r = run("noise " + curve_case() + set + " -o " + out.string());
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("  " + reported + ", "), std::string::npos) << r.output;
    const hid_t f = H5Fopen(out.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    ASSERT_GE(f, 0);
    const std::string g = "/noise/wheels/" + reported;
    for (const char* d : {"/bands/force_level", "/bands/velocity_level"}) {
      const auto top = read_doubles(f, (std::string("/noise") + d).c_str());
      const auto own = read_doubles(f, (g + d).c_str());
      ASSERT_FALSE(top.empty()) << d;
      EXPECT_EQ(top, own) << d;
    }
    EXPECT_EQ(read_group_attribute(f, "/noise", "wheel"), reported);
    EXPECT_NE(read_group_attribute(f, "/noise", "loop").find(reported), std::string::npos);
    H5Fclose(f);
  };
  check("", "leading_outer");
  check("[\"trailing_inner\"]", "trailing_inner");
}
