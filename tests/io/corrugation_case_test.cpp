// [corrugation] and [wear] (io/corrugation_case.hpp): a case without them reads the schema's
// defaults, which are pipeline::CorrugationCase's initialisers (docs/architecture.md "Defaults"),
// and Archard's law without a coefficient takes its own default.
#include "io/corrugation_case.hpp"

#include <gtest/gtest.h>

#include "io/case_reader.hpp"

namespace {

using namespace rollnoise;

const char* kCorrugationMinimalCase = R"(
[contact]
normal_force = 98100.0
a = 7.18e-3
b = 5.29e-3
)";

pipeline::CorrugationCase read_corrugation(const std::vector<std::string>& overrides) {
  return io::read_corrugation_case(
      io::CaseReader::from_string(kCorrugationMinimalCase, "minimal.toml", overrides));
}

}  // namespace

TEST(CorrugationCase, WithoutTheKeysTheStructsInitialisersAreTheSchemaDefaults) {
  const pipeline::CorrugationCase read = read_corrugation({}), init;
  EXPECT_EQ(read.wavelength_min, init.wavelength_min) << "corrugation.wavelength_min";
  EXPECT_EQ(read.wavelength_max, init.wavelength_max) << "corrugation.wavelength_max";
  EXPECT_EQ(read.points, init.points) << "corrugation.points";
  EXPECT_EQ(read.law.kind, init.law.kind) << "wear.law";
  EXPECT_EQ(read.law.coefficient, init.law.coefficient) << "wear.coefficient";
  EXPECT_EQ(read.law.hardness, init.law.hardness) << "wear.hardness";
}

TEST(CorrugationCase, ArchardWithoutACoefficientTakesTheMildRegimes1e4) {
  const pipeline::CorrugationCase a = read_corrugation({"wear.law=\"archard\""});
  EXPECT_EQ(a.law.kind, nss::WearLaw::Kind::archard);
  EXPECT_EQ(a.law.coefficient, 1e-4);
  const pipeline::CorrugationCase b =
      read_corrugation({"wear.law=\"archard\"", "wear.coefficient=3e-3"});
  EXPECT_EQ(b.law.coefficient, 3e-3);
}
