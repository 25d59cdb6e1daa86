// The JSON of `rollnoise cnossos` (io/cnossos_output.hpp) in NoiseModelling's railway layout: a
// made-up transfer function written, read back from the text and put through the Directive's
// equations by hand gives the sound power per metre that the command prints
// (pipeline::cnossos_line_power).
#include "io/cnossos_output.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

#include "acoustics/a_weighting.hpp"

namespace pl = rollnoise::pipeline;

namespace {

// The numbers of the JSON array that follows `name` after `from` in `text`.
std::vector<double> json_numbers(const std::string& text, const std::string& from,
                                 const std::string& name) {
  const std::size_t at = text.find("\"" + name + "\": [", text.find(from));
  std::vector<double> v;
  if (at == std::string::npos) return v;
  const char* p = text.c_str() + text.find('[', at) + 1;
  while (*p != ']') {
    char* end = nullptr;
    v.push_back(std::strtod(p, &end));
    p = end;
    while (*p == ',' || *p == ' ') ++p;
  }
  return v;
}

}  // namespace

// A made-up transfer (L_H,TR_i = 90 + i, L_H,VEH_i = 100 - i dB, L_R,TOT_i = 5 - 0.5 i dB re 1 um):
// the JSON's Vehicle/Transfer and Track/TrackTransfer Spectre hold 24 values each; through
// (2.3.8)-(2.3.10) and (2.3.2) of Directive (EU) 2015/996 Annex II by hand (N_a = 4, Q = 20
// vehicles/h, v = 100 km/h) they give the per-metre power of cnossos_line_power within 1e-9 dB.
TEST(CnossosJson, MadeUpTransferThroughTheDirectiveByHand) {
  pl::CnossosTransfer t;
  for (std::size_t i = 0; i < pl::kCnossosBands; ++i)
    t.track[i] = 90.0 + i, t.vehicle[i] = 100.0 - i, t.roughness[i] = 5.0 - 0.5 * i,
    t.computed[i] = i > 2;
  const std::string json = rollnoise::io::cnossos_json(t, {"made_up", 100.0, 920.0});
  const std::vector<double> veh = json_numbers(json, "\"Transfer\"", "Spectre");
  const std::vector<double> tr = json_numbers(json, "\"TrackTransfer\"", "Spectre");
  const std::vector<double> lr = json_numbers(json, "\"rollnoise\"", "roughness_total");
  ASSERT_EQ(veh.size(), 24u);
  ASSERT_EQ(tr.size(), 24u);
  ASSERT_EQ(lr.size(), 24u);
  double a = 0.0;
  for (std::size_t i = 0; i < 24; ++i) {
    const double w_tr = lr[i] + tr[i] + 10.0 * std::log10(4.0);    // (2.3.8)
    const double w_veh = lr[i] + veh[i] + 10.0 * std::log10(4.0);  // (2.3.9)
    const double w0 =
        10.0 * std::log10(std::pow(10.0, w_tr / 10.0) + std::pow(10.0, w_veh / 10.0));  // (2.3.10)
    const double line = w0 + 10.0 * std::log10(20.0 / (1000.0 * 100.0));                // (2.3.2)
    a +=
        std::pow(10.0, (line + rollnoise::acoustics::a_weighting(pl::cnossos_centres()[i])) / 10.0);
  }
  EXPECT_NEAR(10.0 * std::log10(a), pl::cnossos_line_power(t, 4.0, 20.0, 100.0).total_a, 1e-9);
  EXPECT_NE(json.find("\"filled\": \"50, 63, 80 Hz"), std::string::npos);
}
