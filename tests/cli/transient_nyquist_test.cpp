// `transient` refuses an excitation its grid cannot resolve (above the Nyquist
// limit V/(2 dx) it would alias onto a lower frequency), as `validate` and `response` do.
#include <gtest/gtest.h>

#include <filesystem>

#include "cli_support.hpp"

using namespace rollnoise::cli_test;

TEST(TransientCommand, ExcitationAboveTheGridsNyquistLimitIsRefusedNamingTheKey) {
  // paper case: V = 13.9 m/s, 34 x 25 grid over 2 x 1.133 a: dx = 0.48 mm, Nyquist V/(2 dx) = 14.5 kHz
  for (const std::string& set : {std::string("--set excitation.frequency=60000 --set 'excitation.amplitude=[1e-4,0,0]'"),
                                 std::string("--set 'excitation.type=\"multiharmonic\"' --set excitation.f_max=60000 "
                                             "--set excitation.count=5 --set 'excitation.amplitude=[1e-4,0,0]'")}) {
    for (const char* command : {"transient", "validate"}) {
      const auto out = temp_dir() / (std::string(command) + "_nyquist.h5");
      const auto r = run(std::string(command) + " " + paper_case() + " " + set + " -o " + out.string());
      EXPECT_EQ(r.status, 2) << r.output;
      const bool multi = set.find("multiharmonic") != std::string::npos;
      EXPECT_NE(r.output.find(multi ? "excitation.f_max" : "excitation.frequency"), std::string::npos) << r.output;
      EXPECT_NE(r.output.find("Nyquist"), std::string::npos) << r.output;
      EXPECT_FALSE(std::filesystem::exists(out));
    }
  }
}
