// First-run experience: `rollnoise keys` lists each table once and says for every key its default
// or whether it is required or optional; the excitation phases are in radians on input and output.
#include <gtest/gtest.h>
#include <hdf5.h>

#include <cmath>
#include <filesystem>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "cli_support.hpp"
#include "io/case_schema.hpp"

namespace fs = std::filesystem;
using namespace rollnoise::cli_test;

namespace {

std::vector<double> read_doubles_and_units(hid_t file, const char* path, std::string* units) {
  const hid_t set = H5Dopen2(file, path, H5P_DEFAULT);
  if (set < 0) return {};
  const hid_t space = H5Dget_space(set);
  std::vector<double> v(static_cast<std::size_t>(H5Sget_simple_extent_npoints(space)));
  H5Dread(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data());
  const hid_t attr = H5Aopen(set, "units", H5P_DEFAULT);
  const hid_t type = H5Aget_type(attr);
  std::string s(H5Tget_size(type), '\0');
  H5Aread(attr, type, s.data());
  *units = s.c_str();
  H5Tclose(type), H5Aclose(attr), H5Sclose(space), H5Dclose(set);
  return v;
}

}  // namespace

TEST(KeysCommand, ListsEachTableOnceAndEveryKeysDefaultOrWhetherItIsRequired) {
  const Invocation r = run("keys");
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_EQ(r.output.find("required where used"), std::string::npos);
  std::set<std::string> tables;
  for (const auto& k : rollnoise::io::case_schema()) {
    const std::string table = k.key.substr(0, k.key.find('.'));
    tables.insert(table);
    // the table's block, then the key's line in it: "  name = DEFAULT" or "  name = (required
    // ...)" / "(optional ...)"
    const auto start = r.output.find("\n[" + table + "]\n");
    ASSERT_NE(start, std::string::npos) << table;
    const auto end = r.output.find("\n[", start + 1);
    const std::string block = r.output.substr(start, end == std::string::npos ? end : end - start);
    const std::string name = k.key.substr(table.size() + 1);
    const std::regex line("\n  " + name + " = ([^\n]*)");
    std::smatch m;
    ASSERT_TRUE(std::regex_search(block, m, line)) << k.key;
    const std::string value = m[1];
    if (k.default_value.empty())
      EXPECT_TRUE(value.rfind("(required", 0) == 0 || value.rfind("(optional", 0) == 0)
          << k.key << ": " << value;
    else
      EXPECT_EQ(value.rfind(k.default_value, 0), 0u) << k.key << ": " << value;
  }
  for (const auto& t : tables) {
    const std::string header = "\n[" + t + "]\n";
    const auto first = r.output.find(header);
    ASSERT_NE(first, std::string::npos) << t;
    EXPECT_EQ(r.output.find(header, first + 1), std::string::npos) << "[" << t << "] listed twice";
  }
  EXPECT_NE(r.output.find("normal_force = (required)"), std::string::npos);
}

// ξy(t) = mean + amplitude cos(2π f t + phase) with the phase in radians (paper Eq. 31), and the
// phases written back under the units "rad".
TEST(TransientCommand, ExcitationPhaseIsReadAndWrittenInRadians) {
  const fs::path out = temp_dir() / "phase.h5";
  const double f = 1000.0, amp = 2e-4, phase = 1.0;
  const Invocation r = run("transient " + paper_case() + " -q -o " + out.string() +
                           " --set grid.nx=20 --set grid.ny=15 --set transient.duration=4e-4"
                           " --set excitation.type='\"harmonic\"' --set excitation.frequency=1000"
                           " --set 'excitation.amplitude=[0.0, 2e-4, 0.0]'"
                           " --set 'excitation.phase=[0.0, 1.0, 0.0]'");
  ASSERT_EQ(r.status, 0) << r.output;
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  const hid_t file = H5Fopen(out.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(file, 0);
  std::string units;
  const auto ph = read_doubles_and_units(file, "/transient/excitation/phase", &units);
  EXPECT_EQ(units, "rad");
  ASSERT_EQ(ph.size(), 3u);
  EXPECT_EQ(ph[1], phase);
  const auto mean = read_doubles_and_units(file, "/transient/excitation/mean", &units);
  const auto t = read_doubles_and_units(file, "/transient/time", &units);
  EXPECT_EQ(units, "s");
  const auto xi = read_doubles_and_units(file, "/transient/creepage", &units);
  H5Fclose(file);
  ASSERT_EQ(mean.size(), 3u);
  ASSERT_GT(t.size(), 3u);
  ASSERT_EQ(xi.size(), 3 * t.size());
  // the creepage of step k as the step took it: its mean over [t_k - dt, t_k]
  // (rolling.creepage_sampling = "average", the default), amp cos(w (t_k - dt/2) + phase) sinc(w dt/2)
  const double half_step = 0.5 * (t[1] - t[0]), x = 2.0 * M_PI * f * half_step;
  for (std::size_t k = 0; k < t.size(); ++k)
    EXPECT_NEAR(xi[3 * k + 1],
                mean[1] + amp * std::sin(x) / x * std::cos(2.0 * M_PI * f * (t[k] - half_step) + phase), 1e-15)
        << "t = " << t[k];
  fs::remove(out);
}

TEST(TransientCommand, PhaseBeyondTwoPiIsRefusedAsProbablyDegrees) {
  for (const std::string set :
       {"'excitation.phase=[0.0, 90.0, 0.0]'", "excitation.normal_phase=180"}) {
    const fs::path out = temp_dir() / "phase_deg.h5";
    const Invocation r = run("transient " + paper_case() + " -q -o " + out.string() +
                             " --set excitation.type='\"harmonic\"' --set " + set);
    EXPECT_EQ(r.status, 2) << r.output;
    EXPECT_NE(r.output.find(set.find("normal") != std::string::npos ? "excitation.normal_phase"
                                                                    : "excitation.phase"),
              std::string::npos)
        << r.output;
    EXPECT_NE(r.output.find("radians"), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(out));
  }
}
