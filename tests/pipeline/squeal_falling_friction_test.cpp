// `squeal` with falling friction (docs/squeal.md): the shipped 150 m case squeals in wheel axial
// modes, and a contact that is unstable by itself is refused with an error naming friction.decay.
#include <gtest/gtest.h>

#include <string>

#include "core/errors.hpp"
#include "io/case_reader.hpp"
#include "io/noise_case.hpp"
#include "pipeline/squeal.hpp"

namespace {

using namespace rollnoise;

pipeline::SquealResult squeal(const std::vector<std::string>& set) {
  const io::CaseReader reader =
      io::CaseReader::from_file(std::string(ROLLNOISE_SOURCE_DIR) + "/cases/squeal_150m.toml", set);
  io::NoiseInputs in = io::read_noise_inputs(reader);
  return pipeline::run_squeal(std::move(in.contact), in.noise);
}

TEST(SquealFallingFriction, TightCurveCaseSquealsInAxialModesOnly) {
  const pipeline::SquealResult r = squeal({});
  ASSERT_GE(r.contact_spectral_radius, 0.0);  // checked (falling friction)
  EXPECT_LT(r.contact_spectral_radius, 1.0);
  int unstable = 0;
  for (const auto& root : r.roots) {
    EXPECT_TRUE(root.converged) << root.label;
    EXPECT_LT(root.singular_ratio, 1e-8) << root.label;  // a true zero of (S1)
    if (!root.unstable) continue;
    ++unstable;
    EXPECT_EQ(root.label.rfind("axial", 0), 0u) << root.label;  // squeal in the axial modes
    EXPECT_GT(root.frequency, 300.0);
  }
  EXPECT_GE(unstable, 1);
}

TEST(SquealFallingFriction, UnstableContactIsRefusedNamingTheDecay) {
  // docs/falling_friction.md Sec. 3: B = 4 s/m at this state makes the contact's recursion grow.
  try {
    squeal({"friction.decay=4.0"});
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "friction.decay");
    EXPECT_NE(std::string(e.what()).find("contact alone is unstable"), std::string::npos)
        << e.what();
  }
}

}  // namespace
