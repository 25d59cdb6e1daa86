// The readers of CONTACT's files (io/contact_results.hpp) on the raw CONTACT runs of
// tests/data/contact/raw (S2 steady, U1 transient first 40 steps, C1 u3 module 1; README there):
// CONTACT's printed totals read back exactly, the totals integrated over the .mat rows equal the
// ones documented with the files (to their 2 printed decimals), and bad or cut files give an
// InputError that names the file and the line.
#include "io/contact_results.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/errors.hpp"
#include "support/test_helpers.hpp"

namespace rollnoise::io {
namespace {

std::string raw(const std::string& rel) {
  return std::string(ROLLNOISE_TEST_DATA) + "/contact/raw/" + rel;
}

std::string slurp(const std::string& path) {
  std::ifstream in(path);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// A file in its own folder of this process's scratch folder (removed at exit).
std::string scratch(const std::string& name, const std::string& text) {
  const auto dir = rollnoise::test_support::scratch_folder("rollnoise_contact_results_test", name);
  const std::string p = (dir / name).string();
  std::ofstream(p) << text;
  return p;
}

/// The InputError message of reading `path` with `read` (empty if none was thrown).
template <class Read>
std::string error_of(Read&& read, const std::string& path) {
  try {
    read(path);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(ContactResults, FortranNumbersIncludingThreeDigitExponentWithoutE) {
  double v = 0;
  ASSERT_TRUE(parse_fortran_number("0.228751-310", v));
  EXPECT_NEAR(v / 0.228751e-310, 1.0, 1e-9);
  ASSERT_TRUE(parse_fortran_number("0.5+300", v));
  EXPECT_DOUBLE_EQ(v, 0.5e300);
  ASSERT_TRUE(parse_fortran_number("-0.521237E-02", v));
  EXPECT_DOUBLE_EQ(v, -0.521237e-2);
  ASSERT_TRUE(parse_fortran_number("-8965.", v));
  EXPECT_DOUBLE_EQ(v, -8965.0);
  ASSERT_TRUE(parse_fortran_number("9.810E+04", v));
  EXPECT_DOUBLE_EQ(v, 98100.0);
  EXPECT_FALSE(parse_fortran_number("FN", v));
  EXPECT_FALSE(parse_fortran_number("1.2.3", v));
  EXPECT_FALSE(parse_fortran_number("P-B-T-N-F-S", v));
}

TEST(ContactResults, SteadyS2PrintedTotalsReadBack) {
  const ContactOut out = read_contact_out(raw("S2/S2_coarse.out"));
  EXPECT_EQ(out.revision, "2707");
  ASSERT_EQ(out.cases.size(), 1u);
  const auto& p = out.cases[0].patches.at(0).values;
  EXPECT_EQ(out.cases[0].module, 3);
  EXPECT_DOUBLE_EQ(p.at("FN"), 9.810e4);
  EXPECT_DOUBLE_EQ(p.at("FX"), -1.176e4);
  EXPECT_DOUBLE_EQ(p.at("FY"), -8965.0);
  EXPECT_DOUBLE_EQ(p.at("MZ"), 2.211e4);
  EXPECT_DOUBLE_EQ(p.at("ELAST.EN."), 4.207);
  EXPECT_DOUBLE_EQ(p.at("FRIC.POWER"), -266.1);
  EXPECT_DOUBLE_EQ(p.at("FN/G"), 1.196);
  EXPECT_DOUBLE_EQ(p.at("APPROACH"), 0.104158);
  EXPECT_DOUBLE_EQ(p.at("PMAX"), 1233.0);
  EXPECT_DOUBLE_EQ(p.at("CPHI"), -5.3e-5);
  EXPECT_EQ(p.at("NPOT"), 850);
  EXPECT_EQ(p.at("NCON"), 538);
  EXPECT_EQ(p.at("NADH"), 361);
  EXPECT_EQ(p.at("NSLIP"), 177);
}

TEST(ContactResults, SteadyS2IntegratedTractionsReproduceTheDocumentedTotals) {
  const ContactMat m = read_contact_mat(raw("S2/S2_coarse.0001.mat"));
  EXPECT_EQ(m.rows(), 850u);  // A = 2: every element of the potential contact area
  EXPECT_EQ(m.mx(), 34);
  EXPECT_DOUBLE_EQ(m.header_value("XL"), -8.13733);
  EXPECT_DOUBLE_EQ(m.header_value("DY"), 0.479627);
  EXPECT_DOUBLE_EQ(m.header_value("VELOC"), 13888.9);
  EXPECT_EQ(m.header_value("T"), 3);
  const ContactMatTotals t = integrate(m);
  // README of the raw files: 98100.16, -11761.00, -8965.09 N, 22110.83 N mm (2 decimals)
  EXPECT_NEAR(t.Fn, 98100.16, 0.006);
  EXPECT_NEAR(t.Fx, -11761.00, 0.006);
  EXPECT_NEAR(t.Fy, -8965.09, 0.006);
  EXPECT_NEAR(t.Mz, 22110.83, 0.006);
  EXPECT_NEAR(t.max_pn, 1232.98, 0.006);
  EXPECT_EQ(t.n_exterior, 312);
  EXPECT_EQ(t.n_adhesion, 361);
  EXPECT_EQ(t.n_slip, 177);
  // integrated and printed totals agree to CONTACT's 4 printed digits
  const ContactOut out = read_contact_out(raw("S2/S2_coarse.out"));
  const auto& p = out.cases[0].patches[0].values;
  EXPECT_NEAR(t.Fx, p.at("FX"), 0.5e-3 * std::abs(p.at("FX")));
  EXPECT_NEAR(t.Mz, p.at("MZ"), 0.5e-3 * std::abs(p.at("MZ")));
}

TEST(ContactResults, TransientU1EveryCasePrintedAndIntegrated) {
  const ContactOut out = read_contact_out(raw("U1/U1_coarse_40steps.out"));
  ASSERT_EQ(out.cases.size(), 41u);  // steady + 40 steps, O = 1 prints only the force block
  EXPECT_DOUBLE_EQ(out.cases[0].patches[0].values.at("FX"), -1.250e4);
  EXPECT_DOUBLE_EQ(out.cases[1].patches[0].values.at("FX"), -1.252e4);
  EXPECT_DOUBLE_EQ(out.cases[40].patches[0].values.at("FX"), -1.256e4);
  EXPECT_EQ(out.cases[40].number, 41);
  const std::pair<const char*, double> documented[] = {
      {"0001", -12496.37}, {"0002", -12520.02}, {"0011", -12551.27}, {"0041", -12556.23}};
  for (const auto& [n, fx] : documented) {
    const ContactMat m = read_contact_mat(raw(std::string("U1/U1_coarse_40steps.") + n + ".mat"));
    EXPECT_EQ(m.rows(), 538u) << n;  // A = 1: the contact elements only
    const ContactMatTotals t = integrate(m);
    EXPECT_NEAR(t.Fx, fx, 0.006) << n;
    EXPECT_NEAR(t.Fn, 98100.16, 0.006) << n;
    EXPECT_LT(std::abs(t.Fy), 1e-4) << n;
    EXPECT_EQ(t.n_adhesion, 396) << n;
    EXPECT_EQ(t.n_slip, 142) << n;
  }
  const auto cases = read_contact_inp(raw("U1/U1_coarse_40steps.inp"));
  ASSERT_EQ(cases.size(), 41u);
  const ContactInpLine* l = cases[1].find("FN, CKSI");
  ASSERT_NE(l, nullptr);
  EXPECT_DOUBLE_EQ(l->numbers.at(1), 0.00104883229430894);
}

TEST(ContactResults, WheelRailC1CaseAndPatchTotals) {
  const ContactOut out = read_contact_out(raw("C1_u3/u3_norm_d2.out"));
  ASSERT_EQ(out.cases.size(), 1u);
  const ContactOutCase& c = out.cases[0];
  EXPECT_EQ(c.module, 1);
  EXPECT_DOUBLE_EQ(c.values.at("FX(TR)"), 1.236e4);
  EXPECT_DOUBLE_EQ(c.values.at("FY(TR)"), -1.348e4);
  EXPECT_DOUBLE_EQ(c.values.at("FZ(TR)"), 9.863e4);
  EXPECT_DOUBLE_EQ(c.values.at("Y_WS"), 3.010);
  ASSERT_EQ(c.patches.size(), 1u);
  const auto& p = c.patches[0].values;
  EXPECT_DOUBLE_EQ(p.at("FN"), 9.696e4);
  EXPECT_DOUBLE_EQ(p.at("FS"), -2.253e4);
  EXPECT_DOUBLE_EQ(p.at("MN"), 4560.0);
  EXPECT_DOUBLE_EQ(p.at("CKSI"), -1.461e-3);
  EXPECT_DOUBLE_EQ(p.at("CPHI"), 2.031e-4);
  EXPECT_DOUBLE_EQ(p.at("XCP(TR)"), -1.3887);
  EXPECT_DOUBLE_EQ(p.at("YCP(W)"), -12.9593);
  EXPECT_DOUBLE_EQ(p.at("APPROACH"), 0.111733);
  EXPECT_EQ(p.at("NCON"), 1128);
  const ContactOut vert = read_contact_out(raw("C1_u3/u3_vert_d2.out"));
  EXPECT_DOUBLE_EQ(vert.cases[0].values.at("Z_WS"), 0.2024);
  EXPECT_DOUBLE_EQ(vert.cases[0].values.at("FZ(TR)"), 9.810e4);
  EXPECT_DOUBLE_EQ(vert.cases[0].patches.at(0).values.at("MN"), 4529.0);
}

TEST(ContactResults, TruncatedOutNamesFileAndLine) {
  const std::string text = slurp(raw("S2/S2_coarse.out"));
  const std::size_t cut = text.find("TOTAL FORCES");
  const std::string p =
      scratch("cut.out", text.substr(0, text.find('\n', text.find("FN  ", cut)) + 1));
  const std::string msg = error_of(read_contact_out, p);
  EXPECT_NE(msg.find(p + ":"), std::string::npos) << msg;
  EXPECT_NE(msg.find("FN"), std::string::npos) << msg;
  // cut after the last case: the end line is missing
  const std::string q = scratch("noend.out", text.substr(0, text.find("Performance timers")));
  EXPECT_NE(error_of(read_contact_out, q).find("truncated"), std::string::npos);
  EXPECT_NE(error_of(read_contact_out, scratch("empty.out", "")).find("no ' Case n'"),
            std::string::npos);
}

TEST(ContactResults, TruncatedOrBadMatNamesFileAndLine) {
  const std::string text = slurp(raw("S2/S2_coarse.0001.mat"));
  const std::string cut =
      scratch("cut.mat", text.substr(0, text.size() - 40));  // last row cut short
  const std::string m1 = error_of(read_contact_mat, cut);
  EXPECT_NE(m1.find(cut + ":863:"), std::string::npos)
      << m1;  // 12 header lines, the column line, 850 rows: the last one cut
  std::string bad = text;
  bad.replace(bad.find("0.958938E-01"), 12, "0.958938X-01");
  const std::string b = scratch("bad.mat", bad);
  EXPECT_NE(error_of(read_contact_mat, b).find(b + ":18:"), std::string::npos)
      << error_of(read_contact_mat, b);
  std::string fmt = text;
  fmt.replace(fmt.find("2410"), 4, "2310");
  EXPECT_NE(error_of(read_contact_mat, scratch("fmt.mat", fmt)).find("2410"), std::string::npos);
  // a 3-digit exponent without E in a row is read
  std::string small = text;
  small.replace(small.find("0.958938E-01"), 12, "0.958938-301");
  const ContactMat m = read_contact_mat(scratch("small.mat", small));
  EXPECT_NEAR(m.column("H")[4] / 0.958938e-301, 1.0, 1e-9);
}

TEST(ContactResults, InputWithoutEndNamesFileAndLine) {
  const std::string text = slurp(raw("S2/S2_coarse.inp"));
  const std::string p = scratch("cut.inp", text.substr(0, text.find(" 0 MODULE")));
  EXPECT_NE(error_of(read_contact_inp, p).find(p + ":"), std::string::npos);
}

}  // namespace
}  // namespace rollnoise::io
