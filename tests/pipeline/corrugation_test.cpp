// `rollnoise corrugation`'s pipeline (pipeline/corrugation.hpp, docs/corrugation.md Sec. 4): the
// rail's growth is the sum of its contacts'; without the coupling of the contacts each contact's
// growth is its own loop's under its own filtered roughness (the wheelbase phase cancels:
// e^{ik d} (T H_loop H_filter + T_r) e^{-ik d}); in pure rolling nothing grows.
#include "pipeline/corrugation.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "io/case_reader.hpp"
#include "io/corrugation_case.hpp"
#include "io/noise_case.hpp"

namespace {

using namespace rollnoise;

struct CorrugationInputs {
  io::NoiseInputs in;
  pipeline::CorrugationCase cc;
};

CorrugationInputs corrugation_case(const std::string& name, std::vector<std::string> overrides) {
  overrides.push_back("corrugation.points=12");
  overrides.push_back("noise.compare=\"none\"");
  const io::CaseReader r =
      io::CaseReader::from_file(std::string(ROLLNOISE_SOURCE_DIR) + "/cases/" + name, overrides);
  return {io::read_noise_inputs(r), io::read_corrugation_case(r)};
}

}  // namespace

TEST(Corrugation, EachRailIsTheSumOfItsContactsAndUncoupledContactsNeedNoWheelbasePhase) {
  CorrugationInputs x = corrugation_case(
      "curve_300m.toml",
      {"curve.creepage=\"estimate\"", "grid.nx=24", "noise.contact_coupling=\"none\"",
       "wheel.mesh_size=0.02", "wheel.f_max=3000", "corrugation.wavelength_min=0.02"});
  const pipeline::CorrugationResult r = pipeline::run_corrugation(x.in.contact, x.in.noise, x.cc);
  ASSERT_EQ(r.contacts.size(), 4u);
  ASSERT_EQ(r.rails.size(), 2u);
  for (const pipeline::RailCorrugation& rail : r.rails)
    for (std::size_t k = 0; k < r.frequency.size(); ++k) {
      std::complex<double> sum = 0.0;
      for (const auto& c : r.contacts)
        if (c.side == rail.side) sum += c.depth[k];
      EXPECT_LE(std::abs(rail.depth[k] - sum), 1e-12 * std::abs(sum));
      EXPECT_EQ(rail.growth[k], rail.depth[k].real());
    }
  // each contact alone: its own source's response, no phase (relative 1e-10)
  const noise::ContactSetLoopResult& loop = r.noise.loops.main;
  for (std::size_t a = 0; a < r.contacts.size(); ++a) {
    const auto& c = r.contacts[a];
    const auto& fg = r.noise.wheels[a].coefficients;
    for (std::size_t k = 0; k < r.frequency.size(); ++k) {
      const Eigen::VectorXcd F = loop.force[k].col(static_cast<Eigen::Index>(a)) * c.filter[k];
      Eigen::Vector3cd Ft = F.segment<3>(4 * a + 1);
      if (r.noise.coupled) Ft -= fg.load[k] * F(4 * a);
      Eigen::Vector4cd u;
      u << -fg.creep[k].partialPivLu().solve(Ft), F(4 * a);
      // (W5) with the roughness's own pressure in the patch (W8), met without phase here too
      const std::complex<double> own = (c.transfer[k] * u)(0) + c.roughness_transfer[k];
      EXPECT_LE(std::abs(c.depth[k] - own), 1e-10 * std::abs(own)) << a << " " << k;
    }
  }
}

TEST(Corrugation, PureRollingWithoutSpinGrowsNothing) {
  CorrugationInputs x = corrugation_case("hertz_paper.toml", {"creepage.mean=[0.0, 0.0, 0.0]"});
  const pipeline::CorrugationResult r = pipeline::run_corrugation(x.in.contact, x.in.noise, x.cc);
  ASSERT_FALSE(r.rails.empty());
  for (const auto& rail : r.rails)
    for (double g : rail.growth) EXPECT_EQ(g, 0.0);
}
