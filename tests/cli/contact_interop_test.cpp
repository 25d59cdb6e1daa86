// CONTACT interoperability (docs/contact_interop.md) on the raw CONTACT runs of
// tests/data/contact/raw:
//  - contact-input writes the numbers of the reference inputs (S2, S2facphi0, U1's first 40 steps;
//    numbers compared, not text: 1e-12 relative);
//  - round trip: the steady Hertzian case with --reference contact on S2 gives CONTACT's integrated
//    totals back and rollnoise's steady force agrees with them to 1e-5;
//  - validate --reference contact on U1: the unsteady solver equals CONTACT's 41 cases to the
//  printed
//    digits (4) and to the rounding of the .mat's 6-digit DX, DY (2.1e-6) where those files are
//    there;
//  - module 1 for a profile case: the numbers of the C1 u3 run that map, and the signs of its
//  forces
//    read back in rollnoise's conventions;
//  - a curve case: one module-1 input per wheel with the curve state's position, yaw, load;
//  - a cut CONTACT file: exit 2 naming file and line, no output.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>

#include "cli_support.hpp"
#include "io/case_reader.hpp"
#include "io/contact_results.hpp"
#include "io/hdf5_reader.hpp"
#include "io/noise_case.hpp"
#include "noise/wheel_contact.hpp"
#include "pipeline/curve_setup.hpp"
#include "vehicle/curve_state.hpp"

namespace rollnoise::cli_test {
namespace {

std::string raw(const std::string& rel) {
  return std::string(ROLLNOISE_TEST_DATA) + "/contact/raw/" + rel;
}
const char* kSixth = "0.16666666666666667";

/// Every number and string of every data line of two CONTACT inputs equal (relative `tol`).
void expect_same_numbers(const std::string& written, const std::string& reference, double tol) {
  const auto a = io::read_contact_inp(written), b = io::read_contact_inp(reference);
  ASSERT_EQ(a.size(), b.size()) << "cases";
  for (std::size_t c = 0; c < a.size(); ++c) {
    EXPECT_EQ(a[c].module, b[c].module);
    ASSERT_EQ(a[c].lines.size(), b[c].lines.size()) << "case " << c + 1;
    for (std::size_t l = 0; l < a[c].lines.size(); ++l) {
      const auto &x = a[c].lines[l], &y = b[c].lines[l];
      ASSERT_EQ(x.numbers.size(), y.numbers.size())
          << written << ":" << x.line << " vs " << reference << ":" << y.line;
      for (std::size_t k = 0; k < x.numbers.size(); ++k)
        EXPECT_NEAR(x.numbers[k], y.numbers[k], tol * std::abs(y.numbers[k]))
            << written << ":" << x.line << " value " << k + 1 << " vs " << reference << ":"
            << y.line;
      EXPECT_EQ(x.strings, y.strings);
    }
  }
}

std::vector<double> dataset(const std::string& file, const std::string& path) {
  io::Hdf5Reader r(file);
  EXPECT_TRUE(r.ok()) << file;
  return r.numbers(path).value_or(std::vector<double>{});
}

TEST(ContactInterop, SteadyInputReproducesTheReferenceInputsNumbers) {
  const auto dir = temp_dir() / "contact_input_s2";
  const Invocation r = run("contact-input " + paper_case() + " -o " + dir.string() +
                           " -q --set grid.spin_offset=" + kSixth);
  ASSERT_EQ(r.status, 0) << r.output;
  expect_same_numbers((dir / "hertz_paper.inp").string(), raw("S2/S2_coarse.inp"), 1e-12);
  // the case's own spin offset 0 is CONTACT's FACPHI = 0 (reference run S2facphi0)
  const Invocation r0 = run("contact-input " + paper_case() + " -o " + dir.string() + " -q");
  ASSERT_EQ(r0.status, 0) << r0.output;
  expect_same_numbers((dir / "hertz_paper.inp").string(), raw("S2/S2facphi0_coarse.inp"), 1e-12);
  EXPECT_NE(file_contents((dir / "hertz_paper.inp").string()).find("% written by rollnoise"),
            std::string::npos);
}

TEST(ContactInterop, TransientInputReproducesU1StepByStep) {
  const auto dir = temp_dir() / "contact_input_u1";
  const Invocation r = run(
      "contact-input " + source_file("cases/paper_s31_longitudinal.toml") + " -o " + dir.string() +
      " -q --set transient.duration=0.00137856 --set grid.spin_offset=" + kSixth);
  ASSERT_EQ(r.status, 0) << r.output;
  expect_same_numbers((dir / "paper_s31_longitudinal.inp").string(),
                      raw("U1/U1_coarse_40steps.inp"), 1e-12);
}

TEST(ContactInterop, WheelRailInputHasTheC1u3Numbers) {
  // module 1 for the state of C1 u3_vert_d2: every number that maps is that run's (1e-8: CONTACT's
  // input gives ROLL with 9 digits). Not compared: DX, DS (rollnoise chooses its grid around the
  // contact point), CURV (the C1 run was in a 300 m curve; a profile case has none), and VY, VPITCH
  // (C1 chose them for its curve; contact-input derives them from the case's creepage).
  const auto dir = temp_dir() / "contact_input_c1";
  const Invocation r = run("contact-input " + raw("C1_u3/u3.toml") + " -o " + dir.string() + " -q");
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_TRUE(std::filesystem::exists(dir / "MBench_S1002_v3.prw"));
  const auto a = io::read_contact_inp((dir / "u3.inp").string()),
             b = io::read_contact_inp(raw("C1_u3/u3_vert_d2.inp"));
  ASSERT_EQ(a.size(), 1u);
  ASSERT_EQ(a[0].module, 1);
  ASSERT_EQ(a[0].lines.size(), b[0].lines.size());
  for (std::size_t l = 0; l < b[0].lines.size(); ++l) {
    const auto &x = a[0].lines[l], &y = b[0].lines[l];
    ASSERT_EQ(x.numbers.size(), y.numbers.size()) << y.label;
    EXPECT_EQ(x.strings, y.strings) << y.label;
    for (std::size_t k = 0; k < y.numbers.size(); ++k) {
      const bool grid = y.label.rfind("DX, DS", 0) == 0 && k < 2;
      const bool curve = y.label.rfind("GAUGHT", 0) == 0 && k == 4;
      const bool speeds = y.label.rfind("VS", 0) == 0 && k > 0;
      if (grid || curve || speeds) continue;
      EXPECT_NEAR(x.numbers[k], y.numbers[k], 1e-8 * std::abs(y.numbers[k]))
          << y.label << " value " << k + 1;
    }
  }
}

TEST(ContactInterop, WheelRailReferenceSignsMatchRollnoisesWheelForces) {
  // CONTACT's module 1 puts body 1 on the rail: rollnoise's forces on the wheel are (-FX, -FS,
  // -MN), and the case's creepage is minus CONTACT's printed one. rollnoise's steady solution of
  // the u3 state on its own 24-element grid (its normal force 98.1 kN along the normal,
  // CONTACT's 96.4 kN) then has CONTACT's Fx and Fy to 5 % and Mz of the same sign (the two contact
  // points differ).
  const auto dir = temp_dir() / "c1_vert";
  std::filesystem::create_directories(dir);
  for (const char* ext : {".inp", ".out"})
    std::filesystem::copy_file(raw(std::string("C1_u3/u3_vert_d2") + ext),
                               dir / (std::string("u3_vert_d2") + ext),
                               std::filesystem::copy_options::overwrite_existing);
  const auto out = (temp_dir() / "c1_reference.h5").string();
  const Invocation r =
      run("steady " + raw("C1_u3/u3.toml") + " -o " + out + " --reference contact " + dir.string());
  ASSERT_EQ(r.status, 0) << r.output;
  const auto ref = dataset(out, "/reference/contact/force"), steady = dataset(out, "/steady/force");
  ASSERT_EQ(ref.size(), 3u);
  EXPECT_DOUBLE_EQ(ref[0], -1.235e4);  // -FX printed
  EXPECT_DOUBLE_EQ(ref[1], 2.240e4);   // -FS
  EXPECT_DOUBLE_EQ(ref[2], -4.529);    // -MN * 1e-3
  EXPECT_NEAR(steady[0], ref[0], 0.05 * std::abs(ref[0]));
  EXPECT_NEAR(steady[1], ref[1], 0.05 * std::abs(ref[1]));
  EXPECT_GT(steady[2] * ref[2], 0.0);
}

TEST(ContactInterop, SteadyRoundTripGivesTheReferenceForces) {
  const auto out = (temp_dir() / "s2_reference.h5").string();
  const Invocation r =
      run("steady " + paper_case() + " -o " + out + " --set grid.spin_offset=" + kSixth +
          " --reference contact " + raw("S2"));
  ASSERT_EQ(r.status, 0) << r.output;
  const auto ref = dataset(out, "/reference/contact/force");
  const auto steady = dataset(out, "/steady/force");
  ASSERT_EQ(ref.size(), 3u);
  // the integrated totals of S2_coarse.0001.mat (raw README: -11761.00 N, -8965.09 N, 22110.83 N
  // mm)
  EXPECT_NEAR(ref[0], -11761.00, 0.006);
  EXPECT_NEAR(ref[1], -8965.09, 0.006);
  EXPECT_NEAR(ref[2], 22.11083, 0.006e-3);
  EXPECT_NEAR(steady[0], ref[0], 1e-5 * std::abs(ref[0]));
  EXPECT_NEAR(steady[1], ref[1], 1e-5 * std::abs(ref[1]));
  EXPECT_EQ(dataset(out, "/reference/contact/pn").size(), 850u);
  const auto state = dataset(out, "/reference/contact/state");
  EXPECT_EQ(std::count(state.begin(), state.end(), 2.0), 177);
}

TEST(ContactInterop, TransientValidateAgreesToThePrintedDigits) {
  const auto out = (temp_dir() / "u1_reference.h5").string();
  const Invocation r =
      run("validate " + source_file("cases/paper_s31_longitudinal.toml") + " -o " + out +
          " --set transient.duration=0.00137856 --set transient.analysis_start=0.0005"
          " --reference contact " +
          raw("U1"));
  ASSERT_EQ(r.status, 0) << r.output;
  std::vector<std::size_t> dims;
  io::Hdf5Reader h(out);
  const auto contact = h.numbers("/validate/contact/force", &dims).value();
  ASSERT_EQ(dims.at(0), 41u);
  const auto diff = h.numbers("/validate/contact/unsteady_minus_contact").value();
  const auto integrated = h.numbers("/validate/contact/force_integrated").value();
  const auto unsteady = h.numbers("/validate/unsteady/force").value();
  int with_mat = 0;
  for (std::size_t k = 0; k < 41; ++k) {
    // Fx ~ -1.25e4 N printed with 4 digits: rounding up to 5 N
    EXPECT_LE(std::abs(diff[3 * k]), 5.0 + 1e-9) << "case " << k + 1;
    if (std::isfinite(integrated[3 * k])) {
      ++with_mat;
      // the .mat's DX = 0.478667, DY = 0.479627 mm carry 6 digits (relative rounding up to 1.05e-6
      // each), which scales the integrated totals by up to 2.1e-6 (0.026 N at 12500 N)
      EXPECT_NEAR(unsteady[3 * k], integrated[3 * k], 2.1e-6 * std::abs(integrated[3 * k]))
          << "case " << k + 1;
    }
  }
  EXPECT_EQ(with_mat, 4);  // cases 1, 2, 11, 41
  EXPECT_NE(r.output.find("max |unsteady - CONTACT|"), std::string::npos) << r.output;
}

TEST(ContactInterop, CutContactFileExitsTwoNamingFileAndLine) {
  const auto dir = temp_dir() / "cut_contact";
  std::filesystem::create_directories(dir);
  std::filesystem::copy_file(raw("S2/S2_coarse.inp"), dir / "S2_coarse.inp",
                             std::filesystem::copy_options::overwrite_existing);
  const std::string text = file_contents(raw("S2/S2_coarse.out"));
  std::ofstream(dir / "S2_coarse.out") << text.substr(0, text.find("Performance"));
  const auto out = (temp_dir() / "cut.h5").string();
  std::filesystem::remove(out);
  const Invocation r =
      run("steady " + paper_case() + " -o " + out + " --reference contact " + dir.string());
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find((dir / "S2_coarse.out").string() + ":"), std::string::npos) << r.output;
  EXPECT_FALSE(std::filesystem::exists(out));
  const Invocation bad =
      run("steady " + paper_case() + " -o " + out + " --reference abaqus " + dir.string());
  EXPECT_EQ(bad.status, 2) << bad.output;
}

TEST(ContactInterop, UnmappableKeysExitTwoNamingTheKeyWithoutOutput) {
  const auto dir = temp_dir() / "contact_input_unmappable";
  std::filesystem::remove_all(dir);
  const std::pair<std::string, std::string> cases[] = {
      {paper_case() + " --set 'friction.law=\"falling\"' --set friction.kinetic_ratio=0.5 --set "
                      "friction.decay=1",
       "friction.law"},
      {source_file("cases/paper_s31_longitudinal.toml") + " --set 'transient.start=\"zero\"'",
       "transient.start"}};
  for (const auto& [args, key] : cases) {
    const Invocation r = run("contact-input " + args + " -o " + dir.string());
    EXPECT_EQ(r.status, 2) << r.output;
    EXPECT_NE(r.output.find(key), std::string::npos) << r.output;
  }
  EXPECT_TRUE(!std::filesystem::exists(dir) || std::filesystem::is_empty(dir));
}

TEST(ContactInterop, CurveCaseWritesEachWheelsStateOfTheCurve) {
  // cases/curve_300m.toml: one module-1 input per wheel of the bogie, each with the state rollnoise
  // places that wheel in (pipeline::resolve_curve, noise::bogie_wheel_contacts; the noise
  // command's): the leading outer wheel's Y (axle lateral position), YAW and FZ (vertical load)
  // equal the library's to the 15 digits written (1e-12 relative), CURV is -1/R (CONTACT's sign for
  // the right wheel on the outer rail, its C1 run), and the inner wheels are mirrored (Y = -u).
  const std::string curve = source_file("cases/curve_300m.toml");
  const auto dir = fresh_dir("contact_input_curve");
  // the estimate's state (the equilibrium's is the same path, slower)
  const Invocation r =
      run("contact-input " + curve + " --set 'curve.creepage=\"estimate\"' -o " + dir.string());
  ASSERT_EQ(r.status, 0) << r.output;
  for (const char* w : {"leading_outer", "leading_inner", "trailing_outer", "trailing_inner"})
    EXPECT_TRUE(std::filesystem::exists(dir / (std::string("curve_300m_") + w + ".inp"))) << w;
  EXPECT_FALSE(std::filesystem::exists(dir / "curve_300m.inp"));
  EXPECT_TRUE(std::filesystem::exists(dir / "MBench_S1002_v3.prw"));

  const io::CaseReader reader = io::CaseReader::from_file(curve, {"curve.creepage=\"estimate\""});
  const io::NoiseInputs in = io::read_noise_inputs(reader);
  const pipeline::CurvePlacement p = pipeline::resolve_curve(in.contact, in.noise);
  ASSERT_TRUE(p.curve.state && p.curve.state_input);
  const std::vector<noise::WheelId> ids(noise::kAllWheels.begin(), noise::kAllWheels.end());
  const auto wheels = noise::bogie_wheel_contacts(*p.curve.state_input, *p.curve.state, ids);
  ASSERT_EQ(wheels.size(), 4u);
  for (const noise::WheelContact& w : wheels) {
    const auto inp = io::read_contact_inp(
        (dir / ("curve_300m_" + std::string(noise::wheel_name(w.wheel)) + ".inp")).string());
    ASSERT_EQ(inp.size(), 1u);
    ASSERT_EQ(inp[0].module, 1);
    const io::ContactInpLine* pos = inp[0].find("S, Y, FZ");
    const io::ContactInpLine* track = inp[0].find("GAUGHT");
    ASSERT_TRUE(pos && track);
    const double side = noise::is_outer(w.wheel) ? 1.0 : -1.0;  // the inner wheel mirrored
    EXPECT_NEAR(pos->numbers[1], side * 1e3 * w.lateral, 1e-12 * std::abs(1e3 * w.lateral))
        << noise::wheel_name(w.wheel);
    EXPECT_NEAR(pos->numbers[2], w.vertical_load, 1e-12 * w.vertical_load)
        << noise::wheel_name(w.wheel);
    EXPECT_NEAR(pos->numbers[4], side * w.yaw, 1e-12 * std::abs(w.yaw))
        << noise::wheel_name(w.wheel);
    EXPECT_NEAR(track->numbers[4], -side / (in.noise.curve_radius * 1e3),
                1e-12 / (in.noise.curve_radius * 1e3));
  }
  // the leading outer wheel: displaced, yawed and loaded above the static wheel load (the load
  // transfer), unlike a centred wheelset
  const noise::WheelContact& lo = wheels[0];
  ASSERT_EQ(lo.wheel, noise::WheelId::leading_outer);
  EXPECT_GT(lo.lateral, 1e-3);
  EXPECT_GT(lo.yaw, 1e-3);
  EXPECT_GT(lo.vertical_load, in.contact.normal_force);
  const std::string text = file_contents((dir / "curve_300m_leading_outer.inp").string());
  char y[32];
  std::snprintf(y, sizeof y, "%.3g", 1e3 * lo.lateral);  // e.g. "6.2" mm in the data line
  EXPECT_NE(text.find(std::string(" ") + y), std::string::npos) << y << "\n" << text;
}

TEST(ContactInterop, CurveCaseWithoutCurveStateExitsTwoNamingTheKey) {
  // curve.creepage = "case" has no curve contact state to write the wheels from
  const auto dir = fresh_dir("contact_input_curve_case");
  const Invocation r = run("contact-input " + source_file("cases/curve_300m.toml") +
                           " --set 'curve.creepage=\"case\"' -o " + dir.string());
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("curve.creepage"), std::string::npos) << r.output;
  EXPECT_TRUE(std::filesystem::is_empty(dir));
}

}  // namespace
}  // namespace rollnoise::cli_test
