// rollnoise squeal --route 1|2|both (docs/squeal.md Sec. 4, docs/interface.md): the route-1 datasets
// and the route agreement, route 1 alone in /squeal/*, and a bad --route (exit status, the message
// names the option, no file left, the case unchanged).
#include <gtest/gtest.h>

#include <filesystem>

#include "cli_support.hpp"
#include "io/hdf5_reader.hpp"

using namespace rollnoise::cli_test;

namespace {

std::string curve() { return source_file("cases/curve_300m_hertz.toml"); }
const char* kCoarseRoutes =
    " --set grid.nx=12 --set grid.ny=10 --set grid.scale=1.3 --set 'track.support=\"continuous\"' --set noise.band_max=2000";

}  // namespace

TEST(SquealRouteCli, BothRoutesWriteRouteOneBesideRouteTwoAndTheirAgreement) {
  const auto out = temp_dir() / "squeal_routes.h5";
  const auto r = run("squeal " + curve() + kCoarseRoutes + " -o " + out.string());
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("route agreement:"), std::string::npos) << r.output;
  const rollnoise::io::Hdf5Reader h(out.string());
  ASSERT_TRUE(h.ok());
  const auto f = h.numbers("/squeal/frequency");
  ASSERT_TRUE(f.has_value());
  for (const char* d : {"/squeal/route1/frequency", "/squeal/route1/damping_ratio", "/squeal/route1/unstable"}) {
    const auto v = h.numbers(d);
    ASSERT_TRUE(v.has_value()) << d;
    EXPECT_EQ(v->size(), f->size()) << d;
  }
  for (const char* d : {"/squeal/route1/fit_error_rail", "/squeal/route1/fit_error_contact"})
    EXPECT_TRUE(h.numbers(d).has_value()) << d;
  const auto a = h.numbers("/squeal/route_agreement");
  ASSERT_TRUE(a.has_value());
  EXPECT_EQ(a->size(), 3u);
  EXPECT_NE(h.attribute("/squeal", "route").value_or("").rfind("2:", 0), std::string::npos);
}

TEST(SquealRouteCli, RouteOneAloneFillsTheSquealDatasets) {
  const auto out = temp_dir() / "squeal_route1.h5";
  const auto r = run("squeal " + curve() + kCoarseRoutes + " --route 1 -q -o " + out.string());
  ASSERT_EQ(r.status, 0) << r.output;
  const rollnoise::io::Hdf5Reader h(out.string());
  ASSERT_TRUE(h.ok());
  const auto f = h.numbers("/squeal/frequency"), f1 = h.numbers("/squeal/route1/frequency");
  ASSERT_TRUE(f.has_value() && f1.has_value());
  EXPECT_EQ(*f, *f1);
  EXPECT_FALSE(h.numbers("/squeal/route_agreement").has_value());
  EXPECT_EQ(h.attribute("/squeal", "route").value_or("").rfind("1:", 0), 0u);
}

TEST(SquealRouteCli, AnUnknownRouteIsAnErrorWithoutAFile) {
  const std::string before = file_contents(curve());
  const auto out = temp_dir() / "squeal_route_fault.h5";
  std::filesystem::remove(out);
  const auto r = run("squeal " + curve() + kCoarseRoutes + " --route 3 -o " + out.string());
  EXPECT_NE(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("--route"), std::string::npos) << r.output;
  EXPECT_FALSE(std::filesystem::exists(out));
  EXPECT_EQ(file_contents(curve()), before);
}
