// rollnoise squeal (docs/squeal.md): the datasets users script against, and input faults (exit 2,
// the message names the key, no file left behind, the case file unchanged).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "cli_support.hpp"
#include "io/hdf5_reader.hpp"
#include "support/test_helpers.hpp"

using namespace rollnoise::cli_test;

namespace {

std::string hertz_curve() { return source_file("cases/curve_300m_hertz.toml"); }
const char* kCoarseSqueal = " --set grid.nx=12 --set grid.ny=10 --set grid.scale=1.3 --set 'track.support=\"continuous\"'";

using rollnoise::test_support::slurp;

}  // namespace

TEST(SquealCli, WritesTheSquealDatasetsAndASummaryLine) {
  const auto out = temp_dir() / "squeal_ok.h5";
  const auto r = run("squeal " + hertz_curve() + kCoarseSqueal + " --set noise.band_max=2500 -o " + out.string());
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("squeal: 0 unstable of"), std::string::npos) << r.output;
  const rollnoise::io::Hdf5Reader h(out.string());
  ASSERT_TRUE(h.ok());
  std::vector<std::size_t> dims;
  const auto f = h.numbers("/squeal/frequency", &dims);
  ASSERT_TRUE(f.has_value());
  EXPECT_GT(f->size(), 10u);  // the 920 mm wheel's modes up to 2.5 kHz
  for (const char* d : {"/squeal/damping_ratio", "/squeal/unstable", "/squeal/residual", "/squeal/natural_frequency"}) {
    const auto v = h.numbers(d);
    ASSERT_TRUE(v.has_value()) << d;
    EXPECT_EQ(v->size(), f->size()) << d;
  }
  EXPECT_TRUE(h.numbers("/squeal/contact/normal_stiffness").has_value());
  EXPECT_TRUE(h.attribute("/squeal", "route").has_value());
  const auto q = run("squeal " + hertz_curve() + kCoarseSqueal + " --set noise.band_max=2500 -q -o " + out.string());
  ASSERT_EQ(q.status, 0) << q.output;
  EXPECT_EQ(q.output.find("squeal:"), std::string::npos) << q.output;
}

TEST(SquealCli, NoModeInTheBandOrAboveNyquistIsAnInputErrorWithoutAFile) {
  const std::string before = slurp(hertz_curve());
  for (const std::string& set : {std::string(" --set noise.band_min=100 --set noise.band_max=200"),
                                 std::string(" --set rolling.speed=3")}) {  // modes above Nyquist
    const auto out = temp_dir() / "squeal_fault.h5";
    std::filesystem::remove(out);
    const auto r = run("squeal " + hertz_curve() + kCoarseSqueal + set + " -o " + out.string());
    EXPECT_EQ(r.status, 2) << r.output;
    EXPECT_NE(r.output.find("noise.band_max"), std::string::npos) << r.output;
    EXPECT_FALSE(std::filesystem::exists(out));
  }
  EXPECT_EQ(slurp(hertz_curve()), before);
}

// squeal_300m (issue 51: "5 unstable of 80 modes" was 4 distinct roots, one of them reported under
// two modes): every root once. No two converged rows share a root (frequency and damping ratio
// within 1e-7), the summary's count is the number of distinct unstable rows, and a row that is
// not converged names another mode's root (same_root_as) or its continuation failed. Route 2 only,
// the wheelsets off (their contacts are unstable alone as shipped).
TEST(SquealCli, EveryRootOfSqueal300mIsReportedOnce) {
  const auto out = temp_dir() / "squeal_300m_roots.h5";
  const auto r = run("squeal " + source_file("cases/squeal_300m.toml") +
                     " --route 2 --set 'noise.squeal_wheelsets=\"off\"' -o " + out.string());
  ASSERT_EQ(r.status, 0) << r.output;
  const rollnoise::io::Hdf5Reader h(out.string());
  ASSERT_TRUE(h.ok());
  const auto f = h.numbers("/squeal/frequency"), zeta = h.numbers("/squeal/damping_ratio");
  const auto converged = h.numbers("/squeal/converged"), unstable = h.numbers("/squeal/unstable");
  ASSERT_TRUE(f && zeta && converged && unstable);
  int distinct_unstable = 0;
  for (std::size_t i = 0; i < f->size(); ++i) {
    if ((*converged)[i] == 0) continue;
    distinct_unstable += (*unstable)[i] != 0 ? 1 : 0;
    for (std::size_t j = i + 1; j < f->size(); ++j) {
      if ((*converged)[j] == 0) continue;
      EXPECT_FALSE(std::abs((*f)[i] - (*f)[j]) <= 1e-7 * (*f)[i] &&
                   std::abs((*zeta)[i] - (*zeta)[j]) <= 1e-7)
          << "rows " << i << " and " << j << " report one root at " << (*f)[i] << " Hz";
    }
  }
  EXPECT_NE(r.output.find("squeal: " + std::to_string(distinct_unstable) + " unstable of " +
                          std::to_string(f->size()) + " modes"),
            std::string::npos)
      << r.output;
  std::printf("squeal_300m: %d distinct unstable roots of %zu modes\n", distinct_unstable,
              f->size());
}
