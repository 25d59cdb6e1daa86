// rollnoise statespace: the files users script against (/statespace/*, /creep/* at the fitted
// frequencies, the CSV matrices), and bad bands refused before anything is written.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "cli_support.hpp"
#include "io/hdf5_reader.hpp"

using namespace rollnoise::cli_test;

namespace {

// The paper's Hertzian case copied to the scratch folder (to check that it stays unchanged).
std::string case_copy() {
  const auto c = temp_dir() / "statespace_case.toml";
  std::filesystem::copy_file(paper_case(), c, std::filesystem::copy_options::overwrite_existing);
  return c.string();
}

}  // namespace

TEST(StatespaceCommand, WritesTheModelTheCreepCoefficientsAndOneCsvPerMatrix) {
  const std::string c = case_copy();
  const auto out = temp_dir() / "ss.h5";
  const auto prefix = (temp_dir() / "ss").string();
  const auto r =
      run("statespace " + c + " --set frequency.count=60 --set frequency.f_max=5000 -q -o " +
          out.string() + " --csv " + prefix);
  ASSERT_EQ(r.status, 0) << r.output;
  rollnoise::io::Hdf5Reader h(out.string());
  std::vector<std::size_t> dA, dB, dC, dD, dF;
  ASSERT_TRUE(h.numbers("/statespace/A", &dA));
  ASSERT_TRUE(h.numbers("/statespace/B", &dB));
  ASSERT_TRUE(h.numbers("/statespace/C", &dC));
  ASSERT_TRUE(h.numbers("/statespace/D", &dD));
  const std::size_t n = dA[0];
  EXPECT_EQ(dA, (std::vector<std::size_t>{n, n}));
  EXPECT_EQ(dB, (std::vector<std::size_t>{n, 4}));
  EXPECT_EQ(dC, (std::vector<std::size_t>{3, n}));
  EXPECT_EQ(dD, (std::vector<std::size_t>{3, 4}));
  EXPECT_LT((*h.numbers("/statespace/fit_error"))[0], 1e-3);
  EXPECT_EQ(*h.numbers("/statespace/band"), (std::vector<double>{10.0, 5000.0}));
  const auto freq = *h.numbers("/creep/frequency", &dF);
  EXPECT_EQ(dF[0], 61u);  // 0 Hz and the case's 60
  EXPECT_EQ(freq[0], 0.0);
  for (const char* d :
       {"/statespace/discrete/A", "/statespace/discrete/B", "/statespace/discrete/C",
        "/statespace/discrete/D", "/statespace/discrete/dt", "/statespace/discrete/response_error",
        "/statespace/discrete/sampling_filter_error",
        "/statespace/discrete/sampling_filter_peak_gain", "/statespace/discrete/recursion/A",
        "/statespace/discrete/recursion/markov_error"})
    EXPECT_TRUE(h.numbers(d)) << d;
  // one CSV per matrix, rows as lines
  for (const char* m : {"A", "B", "C", "D", "Ad", "Bd", "Cd", "Dd"}) {
    const std::string text = file_contents(prefix + "_" + m + ".csv");
    const auto lines = std::count(text.begin(), text.end(), '\n');
    const std::string name = m;
    if (name == "A" || name == "B") {
      EXPECT_EQ(std::size_t(lines), n) << m;
    } else if (name == "C" || name == "D") {
      EXPECT_EQ(lines, 3) << m;
    }
  }
  EXPECT_EQ(file_contents(c), file_contents(paper_case()));
}

TEST(StatespaceCommand, BadBandsAndTolerancesAreRefusedNamingTheKeyAndLeaveNoFile) {
  const std::string c = case_copy();
  const std::vector<std::pair<std::string, std::string>> faults = {
      {"--set frequency.f_max=60000", "frequency.f_max"},  // above the Nyquist limit
      {"--set frequency.f_min=6000 --set frequency.f_max=5000",
       "frequency.f_max"},  // an empty band
      {"--set 'frequency.list=[100, 60000]'", "frequency.list"},
      {"--set statespace.tolerance=1.5", "statespace.tolerance"},
  };
  for (const auto& [set, key] : faults) {
    const auto out = temp_dir() / "ss_fault.h5";
    const auto prefix = (temp_dir() / "ss_fault").string();
    const auto r = run("statespace " + c + " " + set + " -o " + out.string() + " --csv " + prefix);
    EXPECT_EQ(r.status, 2) << set << "\n" << r.output;
    EXPECT_NE(r.output.find(key), std::string::npos) << r.output;
    EXPECT_FALSE(std::filesystem::exists(out)) << set;
    EXPECT_FALSE(std::filesystem::exists(prefix + "_A.csv")) << set;
    EXPECT_EQ(file_contents(c), file_contents(paper_case()));
  }
}
