// `validate` reports components that do not vary as "not excited" (their
// variation is solver round-off) instead of meaningless relative errors, in the printout and in
// /validate/errors (excited = 0, errors NaN).
#include <gtest/gtest.h>
#include <hdf5.h>

#include <cmath>
#include <vector>

#include "cli_support.hpp"

using namespace rollnoise::cli_test;

namespace {

std::vector<double> read(const std::string& file, const char* path, std::size_t n) {
  std::vector<double> v(n, -1.0);
  const hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  const hid_t set = H5Dopen2(f, path, H5P_DEFAULT);
  if (set >= 0) H5Dread(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data()), H5Dclose(set);
  H5Fclose(f);
  return v;
}

}  // namespace

TEST(ValidateCommand, ComponentsThatDoNotVaryAreReportedAsNotExcited) {
  const std::string base = "validate " + paper_case() +
                           " --set grid.nx=16 --set grid.ny=12 --set transient.duration=0.004 "
                           "--set transient.analysis_start=0.001 --set 'creepage.mean=[0.001,0,0]'";  // the summary is checked: no -q
  // a pure xi_x variation about a pure xi_x state: Fy and Mz stay zero by symmetry
  const auto out = (temp_dir() / "validate_xi_x.h5").string();
  auto r = run(base + " --set 'excitation.amplitude=[1e-4,0,0]' -o " + out);
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("Fy not excited"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("Mz not excited"), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("Fx not excited"), std::string::npos) << r.output;
  EXPECT_EQ(read(out, "/validate/errors/excited", 3), (std::vector<double>{1, 0, 0}));
  const auto rms = read(out, "/validate/errors/rms_relative", 3);
  EXPECT_TRUE(std::isfinite(rms[0]) && rms[0] < 0.1) << rms[0];
  EXPECT_TRUE(std::isnan(rms[1]) && std::isnan(rms[2]));
  const auto amplitude = read(out, "/validate/errors/amplitude", 3);  // one frequency: Fx, Fy, Mz
  EXPECT_TRUE(std::isfinite(amplitude[0]));
  EXPECT_TRUE(std::isnan(amplitude[1]) && std::isnan(amplitude[2]));
  // zero amplitude: nothing is excited
  const auto zero = (temp_dir() / "validate_zero.h5").string();
  r = run(base + " --set 'excitation.amplitude=[0,0,0]' -o " + zero);
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("Fx not excited, Fy not excited, Mz not excited"), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find('%'), std::string::npos) << "no percentage of round-off: " << r.output;
  EXPECT_EQ(read(zero, "/validate/errors/excited", 3), (std::vector<double>{0, 0, 0}));
}
