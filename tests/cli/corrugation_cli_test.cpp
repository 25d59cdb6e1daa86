// rollnoise corrugation (docs/corrugation.md): the datasets the acceptance scripts read, with their
// units, and input faults (exit 2, the message names the key, no file left behind).
#include <gtest/gtest.h>

#include <filesystem>

#include "cli_support.hpp"
#include "io/hdf5_reader.hpp"

using namespace rollnoise::cli_test;

TEST(CorrugationCli, WritesWavelengthsAndGrowthRatesWithUnits) {
  const auto out = temp_dir() / "corrugation_ok.h5";
  const auto r =
      run("corrugation " + paper_case() + " --set corrugation.points=8 -o " + out.string());
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("wavelengths that grow"), std::string::npos) << r.output;
  const rollnoise::io::Hdf5Reader h(out.string());
  ASSERT_TRUE(h.ok());
  for (const char* d :
       {"/corrugation/wavelength", "/corrugation/frequency", "/corrugation/outer/growth_rate",
        "/corrugation/contacts/leading_outer/growth_rate"}) {
    const auto v = h.numbers(d);
    ASSERT_TRUE(v.has_value()) << d;
    EXPECT_EQ(v->size(), 8u) << d;
    const auto units = h.attribute(d, "units");
    ASSERT_TRUE(units.has_value()) << d;
    EXPECT_FALSE(units->empty()) << d;
  }
  EXPECT_EQ(*h.attribute("/corrugation/wavelength", "units"), "m");
  EXPECT_EQ(h.attribute("/corrugation/outer/growth_rate", "units")->rfind("1/passage", 0), 0u);
}

TEST(CorrugationCli, BadWearAndWavelengthKeysAreRefusedNamingTheKey) {
  const struct {
    const char* set;
    const char* key;
  } cases[] = {{"wear.coefficient=-1.0", "wear.coefficient"},
               {"wear.hardness=0.0", "wear.hardness"},
               {"'wear.law=\"linear\"'", "wear.law"},
               {"corrugation.wavelength_max=0.005", "corrugation.wavelength_max"},
               {"corrugation.wavelength_min=1e-4", "corrugation.wavelength_min"},
               {"'noise.contact_model=\"kalker\"'", "noise.contact_model"}};
  for (const auto& c : cases) {
    const auto out = temp_dir() / "corrugation_bad.h5";
    const auto r = run("corrugation " + paper_case() + " --set corrugation.points=4 --set " +
                       c.set + " -o " + out.string());
    EXPECT_EQ(r.status, 2) << c.set << ": " << r.output;
    EXPECT_NE(r.output.find(c.key), std::string::npos) << c.set << ": " << r.output;
    EXPECT_FALSE(std::filesystem::exists(out)) << c.set;
  }
}
