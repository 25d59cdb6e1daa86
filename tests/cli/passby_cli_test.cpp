// rollnoise passby and cnossos: the datasets users script against (/passby/* with units), the
// pass-by's L_pAeq,Tp against its own spectrum, the JSON's 24 bands, and bad trains and categories
// refused naming their key (exit 2) before any computation. The runs use the shipped tangent case
// on a coarse sampling (a coarse FE wheel, 4 lines per band, 500 Hz - 2 kHz, two coaches).
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "acoustics/a_weighting.hpp"
#include "cli_support.hpp"
#include "io/hdf5_reader.hpp"

using namespace rollnoise::cli_test;

namespace {

// The FE wheel's coarse mesh (its modes are read with the case).
const std::string kCoarseWheel =
    " --set wheel.mesh_size=0.03 --set wheel.n_max=3 --set wheel.f_max=2500";
const std::string kCoarse =
    kCoarseWheel +
    " --set noise.points_per_band=4 --set noise.band_refinement=0"
    " --set noise.band_min=500 --set noise.band_max=2000 --set noise.compare=\\\"none\\\""
    " --set train.vehicles=2 -q";

std::string tangent() {
  return source_file("cases/passby_tangent.toml");
}

}  // namespace

// Every /passby dataset is written with a units attribute; L_pAeq,Tp equals the A-weighted power
// sum of the spectrum's total column within 0.2 dB (measured: 1e-12 dB, both over T_p);
// L_pAFmax >= L_pAeq,Tp; the TSI limit of the case's category (coach: 79 dB) with its category.
TEST(PassbyCommand, WritesEveryDatasetWithUnitsAndLeqIsTheSpectrumsATotal) {
  const auto out = temp_dir() / "passby.h5";
  const Invocation r = run("passby " + tangent() + " -o " + out.string() + kCoarse);
  ASSERT_EQ(r.status, 0) << r.output;
  rollnoise::io::Hdf5Reader h(out.string());
  for (const char* d :
       {"time", "level_a", "leq_a", "tel", "lmax_a", "band_centre", "spectrum", "leq_a_80",
        "limit_a", "passage_time", "speed", "receiver", "train/axle_position"}) {
    const std::string path = std::string("/passby/") + d;
    EXPECT_TRUE(h.numbers(path)) << path;
    const auto units = h.attribute(path, "units");
    EXPECT_TRUE(units && !units->empty()) << path;
  }
  EXPECT_EQ(h.attribute("/passby/limit_a", "category").value_or(""), "coach");
  std::vector<std::size_t> dims;
  const std::vector<double> fc = *h.numbers("/passby/band_centre");
  const std::vector<double> s = *h.numbers("/passby/spectrum", &dims);
  ASSERT_EQ(dims, (std::vector<std::size_t>{fc.size(), 4}));
  double sum = 0.0;
  for (std::size_t b = 0; b < fc.size(); ++b)
    sum += std::pow(10.0, 0.1 * (s[4 * b + 3] + rollnoise::acoustics::a_weighting(fc[b])));
  const double leq = h.numbers("/passby/leq_a")->front(),
               lmax = h.numbers("/passby/lmax_a")->front();
  EXPECT_NEAR(10.0 * std::log10(sum), leq, 0.2);
  EXPECT_GE(lmax, leq);
  EXPECT_EQ(h.numbers("/passby/limit_a")->front(), 79.0);
  EXPECT_EQ(h.numbers("/passby/train/axle_position")->size(), 8u);
}

// cnossos on the same coarse case: a JSON whose Vehicle/Transfer and Track/TrackTransfer entries
// hold 24 values each, the bands outside 500 Hz - 2 kHz marked filled, and the printed per-metre
// power.
TEST(CnossosCommand, WritesTwentyFourBandsAndSaysWhichAreFilled) {
  const auto out = temp_dir() / "cn.json";
  const Invocation r = run("cnossos " + tangent() + " -o " + out.string() + kCoarse);
  ASSERT_EQ(r.status, 0) << r.output;
  const std::string json = file_contents(out.string());
  for (const char* entry : {"\"Transfer\"", "\"TrackTransfer\""}) {
    const std::size_t at = json.find("\"Spectre\": [", json.find(entry));
    ASSERT_NE(at, std::string::npos) << entry;
    const std::string values = json.substr(at, json.find(']', at) - at);
    EXPECT_EQ(std::count(values.begin(), values.end(), ','), 23) << entry;
  }
  EXPECT_NE(json.find("\"filled\": \"50, 63, 80, 100, 125, 160, 200, 250, 315, 400, 2500"),
            std::string::npos)
      << json;
  EXPECT_NE(r.output.find("bands outside"), std::string::npos) << r.output;
}

// A negative vehicle length, a wheelbase not shorter than the bogie distance, a bad vehicle entry
// and an unknown category: exit 2, the message naming the key, before any computation.
TEST(PassbyCommand, BadTrainsAndCategoriesAreRefusedNamingTheKey) {
  const auto out = (temp_dir() / "bad.h5").string();
  const std::pair<std::string, std::string> cases[] = {
      {"--set train.vehicle_length=-3", "train.vehicle_length"},
      {"--set train.wheelbase=19.5", "train.wheelbase"},
      {"--set train.bogie_distance=30", "train.bogie_distance"},
      {"--set 'train.vehicle=[{count = 2, wheelbase = 25.0}]' --set train.vehicles=1",
       "train.vehicle"},
      {"--set passby.category=\\\"tram\\\"", "passby.category"},
      {"--set passby.height=-1", "passby.height"},
  };
  for (const auto& [set, key] : cases) {
    const Invocation r = run("passby " + tangent() + " -o " + out + kCoarseWheel + " " + set);
    EXPECT_EQ(r.status, 2) << set << ": " << r.output;
    EXPECT_NE(r.output.find(key), std::string::npos) << set << ": " << r.output;
  }
  EXPECT_TRUE(listing(temp_dir(), "bad").empty());
}
