// Mode shapes along the tread as CSV (io/tread_shapes_file.hpp): our FE modes exported and imported
// give the same contact receptance, and a bad file names the line and field.
#include "io/tread_shapes_file.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "core/errors.hpp"
#include "dynamics/wheel_fe.hpp"
#include "io/wheel_section_file.hpp"

namespace {

using namespace rollnoise;
namespace fs = std::filesystem;

fs::path tread_shapes_temp_path(const std::string& name) {
  const fs::path dir =
      fs::temp_directory_path() / ("rollnoise_tread_shapes_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  return dir / name;
}

}  // namespace

// Round trip: the FE modes of a coarse 920 mm wheel (n <= 4, <= 3 kHz) written with 17 digits and
// read back give the same point and cross receptance (tread contact and a flange-root contact at
// 0.6 rad, rotation split on) at 0.4 .. 3 kHz to 1e-12 (the case's damping by family is the same
// for all families here), and the families the tread gives: the file has no section, so an
// imported mode's family is its tread's dominant direction (tread_family), not the whole section's
// of the FE wheel (docs/models.md Sec. 3.4: the one-nodal-circle axial modes come back radial).
TEST(TreadShapesFile, ExportedFeModesImportToTheSameReceptance) {
  dynamics::WheelFeOptions o;
  o.n_max = 4;
  o.f_max = 3000.0;
  o.mesh_size = 0.02;
  const auto fe =
      dynamics::wheel_fe_modes(io::read_wheel_section(std::string(ROLLNOISE_SOURCE_DIR) +
                                                      "/models/wheel/wheel_920mm_section.csv"),
                               o);
  const fs::path path = tread_shapes_temp_path("shapes.csv");
  io::write_tread_shapes(path.string(), "--csv", fe).commit();
  const auto back = io::read_tread_shapes(path.string());
  ASSERT_EQ(back.modes.size(), fe.modes.size());
  for (std::size_t k = 0; k < fe.modes.size(); ++k)
    EXPECT_EQ(back.modes[k].family, dynamics::tread_family(fe.modes[k].tread_shape)) << k;
  dynamics::WheelFeContactOptions co;
  co.spin_speed = 42.0;
  const dynamics::TreadContact a{0.0, 0.02}, b{-0.03, 0.6};
  for (double f : {400.0, 1200.0, 3000.0}) {
    const auto h0 = dynamics::fe_cross_receptance(fe, co, a, b, f),
               h1 = dynamics::fe_cross_receptance(back, co, a, b, f);
    EXPECT_LT((h1 - h0).norm(), 1e-12 * h0.norm()) << f << " Hz";
    const auto p0 = dynamics::fe_cross_receptance(fe, co, b, b, f),
               p1 = dynamics::fe_cross_receptance(back, co, b, b, f);
    EXPECT_LT((p1 - p0).norm(), 1e-12 * p0.norm()) << f << " Hz";
  }
  fs::remove_all(path.parent_path());
}

// A bad line names the file, line and field; an inconsistent table names the file.
TEST(TreadShapesFile, BadFilesNameLineAndField) {
  const std::string header = "mode,n,frequency_Hz,damping_ratio,s_mm,r_mm,u_r,u_theta,u_z\n";
  const std::vector<std::pair<std::string, std::string>> cases = {
      // the header is line 1
      {header + "0,2,abc,0,0,460,1,0,0\n0,2,360,0,1,460,1,0,0\n", ":2: field 'frequency_Hz'"},
      {header + "0,2,360,1.5,0,460,1,0,0\n", ":2: field 'damping_ratio'"},
      {header + "0,2.5,360,0,0,460,1,0,0\n", ":2: field 'n'"},
      {header + "0,2,360,0,0,460,1,0,0\n0,2,360,0,-1,460,1,0,0\n", ":3: s_mm"},
      {header + "0,2,360,0,0,460,1,0,0\n0,2,360,0,1,460,1,0,0\n1,3,900,0,0,460,1,0,0\n",
       "is not given on the s_mm"},
      {header + "1,2,360,0,0,460,1,0,0\n", ":2: modes must be numbered"},
      {"s,u\n", ":1: expected the header"},
  };
  for (const auto& [text, expected] : cases) {
    const fs::path path = tread_shapes_temp_path("bad.csv");
    std::ofstream(path) << text;
    try {
      io::read_tread_shapes(path.string());
      ADD_FAILURE() << "no error for: " << text;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
    }
    fs::remove_all(path.parent_path());
  }
}
