// The roughness spectrum files (src/io/roughness_file.hpp).
#include "io/roughness_file.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <string>
#include <utility>

#include "core/errors.hpp"

namespace rn = rollnoise::noise;

namespace {

std::string model_path(const std::string& rel) {
  return std::string(ROLLNOISE_SOURCE_DIR) + "/models/roughness/" + rel;
}

}  // namespace

TEST(RoughnessSpectra, CsvFilesEqualBuiltInTables) {
  const std::pair<const char*, rn::RoughnessSpectrum> files[] = {
      {"iso3095_2013_limit.csv", rn::iso3095_2013_rail_limit()},
      {"wheel_cast_iron_block.csv", rn::wheel_roughness_cast_iron_block()},
      {"wheel_disc_braked.csv", rn::wheel_roughness_disc_braked()},
      {"rail_cnossos_average_network.csv", rn::rail_roughness_cnossos_average()}};
  for (const auto& [name, builtin] : files) {
    const rn::RoughnessSpectrum s = rollnoise::io::read_roughness_csv(model_path(name));
    ASSERT_EQ(s.wavelength.size(), builtin.wavelength.size()) << name;
    for (std::size_t i = 0; i < s.wavelength.size(); ++i) {
      EXPECT_NEAR(s.wavelength[i], builtin.wavelength[i], 1e-15) << name;
      EXPECT_EQ(s.level[i], builtin.level[i]) << name << " band " << i;
    }
  }
  // Block-braked treads are rougher than disc-braked ones at 2-10 cm (what makes them noisier).
  const auto ci = rn::wheel_roughness_cast_iron_block(), disc = rn::wheel_roughness_disc_braked();
  for (double l : {0.05, 0.0315, 0.02}) EXPECT_GT(ci.level_at(l), disc.level_at(l) + 5.0) << l;
  // An average network's rail against the EN ISO 3095 limit (a test track's): rougher by more
  // than 5 dB at 1-2 m, and rougher at 2.5-4 cm, the wavelengths of 550-900 Hz at 80 km/h.
  const auto avg = rn::rail_roughness_cnossos_average(), iso = rn::iso3095_2013_rail_limit();
  for (double l : {2.0, 1.25, 1.0}) EXPECT_GT(avg.level_at(l), iso.level_at(l) + 5.0) << l;
  for (double l : {0.04, 0.0315, 0.025}) EXPECT_GT(avg.level_at(l), iso.level_at(l)) << l;
}

TEST(RoughnessSpectra, BadCsvNamesFileLineAndField) {
  using rollnoise::InputError;
  const struct {
    const char* text;
    const char* key;
  } cases[] = {
      {"wavelength_m,level_dB\n0.1,3\n0.05\n", ":3:level_dB"},
      {"wavelength_m,level_dB\n0.1,3\nabc,2\n", ":3:wavelength_m"},
      {"wavelength_m,level_dB\n-0.1,3\n0.05,2\n", ":2:wavelength_m"},
      {"# comment\nlambda,L\n0.1,3\n", ":2:header"},
      {"wavelength_m,level_dB\n0.1,3\n0.1,2\n", ".csv"},  // repeated band
  };
  int i = 0;
  for (const auto& c : cases) {
    const std::string path = ::testing::TempDir() + "rough" + std::to_string(::getpid()) + "_" +
                             std::to_string(i++) + ".csv";
    std::ofstream(path) << c.text;
    try {
      rollnoise::io::read_roughness_csv(path);
      ADD_FAILURE() << "no InputError for " << c.text;
    } catch (const InputError& e) {
      EXPECT_NE(e.key().find(path), std::string::npos) << e.key();
      EXPECT_NE(e.key().find(c.key), std::string::npos) << e.key();
    }
    std::remove(path.c_str());
  }
}
