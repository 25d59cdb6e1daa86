// The state-space export (pipeline/statespace.hpp) on a coarse Hertzian patch with adhesion and
// slip: the continuous fit reproduces f and g over the band, the recursion's realisation reproduces
// the sweep exactly, the discrete model of the creepage samples (recursion and sampling filter) has
// the transfer f and g itself, the bilinear map keeps the transfer, and the fitted model's step
// response equals the linear model's time response.
#include "pipeline/statespace.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "io/case_reader.hpp"
#include "io/contact_case.hpp"
#include "linalg/state_space.hpp"

namespace {

using namespace rollnoise;

struct Fixture {
  pipeline::StateSpaceResult r;
  std::vector<double> band;
};

// The paper's Hertzian case on 20 x 15 elements at 25 m/s and 80 kN, combined creepage with spin
// (adhesion and slip, so g is not 0); the band 10 Hz .. Nyquist/2 on a log axis of 120 points.
const Fixture& fixture() {
  static const Fixture fx = [] {
    const io::CaseReader reader = io::CaseReader::from_file(
        std::string(ROLLNOISE_SOURCE_DIR) + "/cases/hertz_paper.toml",
        {"grid.nx=20", "grid.ny=15", "rolling.speed=25.0", "contact.normal_force=80e3",
         "creepage.mean=[0.0012, -0.0008, -0.1]"});
    io::InputProblems problems;
    pipeline::ContactCase c = io::read_contact_case(reader, problems);
    problems.throw_if_any();
    const double fn = pipeline::nyquist_frequency(c);
    Fixture f;
    for (int i = 0; i < 120; ++i) f.band.push_back(10.0 * std::pow(0.5 * fn / 10.0, i / 119.0));
    f.r = pipeline::run_statespace(c, f.band, pipeline::StateSpaceOptions{}, "frequency.f_max");
    return f;
  }();
  return fx;
}

TEST(StateSpaceExport, TheFittedModelReproducesFAndGOverTheBand) {
  const pipeline::StateSpaceResult& r = fixture().r;
  const nss::LinearContactModel& model = *r.creep.state.model();
  ASSERT_GT(model.slip_elements(), 0);
  ASSERT_GT(model.adhesion_elements(), 0);
  EXPECT_EQ(r.frequency.front(), 0.0);  // the static gain is a fitted sample
  EXPECT_LT(r.fit.error, 1e-3);
  for (const auto& a : r.fit.poles) EXPECT_LT(a.real(), 0.0);
  // independently: each entry against the direct LU (the reference), between the fitted samples
  double worst = 0.0;
  std::vector<double> check = {0.0};
  for (size_t k = 1; k < r.frequency.size(); k += 7)
    check.push_back(std::sqrt(r.frequency[k - 1] * r.frequency[k]) + 0.0);
  std::vector<nss::CreepMatrix> f;
  std::vector<nss::LoadVector> g;
  for (double fr : check)
    f.push_back(model.creep_coefficients_direct(fr)),
        g.push_back(model.normal_load_coefficients_direct(fr));
  const auto H = pipeline::contact_transfer(f, g);
  Eigen::MatrixXd peak = Eigen::MatrixXd::Zero(3, 4);
  for (const auto& h : pipeline::contact_transfer(r.creep.f, r.creep.g))
    peak = peak.cwiseMax(h.cwiseAbs());
  for (size_t k = 0; k < check.size(); ++k) {
    const Eigen::MatrixXcd d = r.fit.model.frequency_response(check[k]) - H[k];
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 4; ++j) worst = std::max(worst, std::abs(d(i, j)) / peak(i, j));
  }
  std::printf(
      "fit: order %d, %zu poles, error %.3g (entries %.3g); between samples against the direct LU "
      "%.3g\n",
      r.fit.model.order(), r.fit.poles.size(), r.fit.error, r.fit.element_error, worst);
  EXPECT_LT(worst, 1e-3);
}

TEST(StateSpaceExport, TheRecursionsRealisationReproducesTheSweepExactly) {
  const pipeline::StateSpaceResult& r = fixture().r;
  const nss::LinearContactModel& model = *r.creep.state.model();
  EXPECT_LT(r.recursion.markov_error, 1e-8);
  EXPECT_LT(r.recursion_error, 1e-8);
  EXPECT_EQ(r.input_sampling, model.sampling());  // the case's (the default, average)
  // at frequencies that were not in the realisation's check: against the sweep, entry by entry
  const std::vector<double> fr = {3.3, 123.0, 0.31 * model.nyquist_frequency(),
                                  0.97 * model.nyquist_frequency()};
  const auto H =
      pipeline::contact_transfer(model.creep_coefficients(fr), model.normal_load_coefficients(fr));
  for (size_t k = 0; k < fr.size(); ++k) {
    Eigen::MatrixXcd Hd = r.recursion.model.discrete_frequency_response(fr[k], r.dt);
    Hd.leftCols(3) *= contact::step_sampling_factor(r.input_sampling, fr[k], r.dt);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 4; ++j)
        EXPECT_LT(std::abs(Hd(i, j) - H[k](i, j)),
                  1e-8 * H[k].col(j).cwiseAbs().maxCoeff() + 1e-300)
            << fr[k] << " " << i << j;
  }
}

// The exported discrete model, fed with the samples xi~(t_k), N~(t_k), has the transfer [-f | g]
// itself (docs/statespace.md Sec. 3: D + C (zI - A)^-1 B at z = e^{2 pi i f dt}, no factor): at the
// fitted frequencies to the fit's tolerance (1e-5, the filter's tenth of it plus the recursion's
// 1e-8), and between the samples, inside the band, entry by entry against the sweep to 1e-4 of
// each column's largest entry (the filter is fitted on the samples; measured 3.3e-6).
TEST(StateSpaceExport, TheDiscreteModelOfTheCreepageSamplesHasTheTransferFAndG) {
  const pipeline::StateSpaceResult& r = fixture().r;
  const nss::LinearContactModel& model = *r.creep.state.model();
  ASSERT_EQ(r.input_sampling, contact::CreepageSampling::average);
  EXPECT_GT(r.sampling_filter.order(), 0);
  EXPECT_LT(r.sampling_filter_error, 1e-5);
  EXPECT_LT(r.discrete_error, 1e-5);
  EXPECT_EQ(r.discrete.order(), r.recursion.model.order() + 3 * r.sampling_filter.order());
  // stable: every pole of the series connection inside the unit circle
  EXPECT_LT(r.discrete.A.eigenvalues().cwiseAbs().maxCoeff(), 1.0);
  std::vector<double> fr;
  for (size_t k = 1; k < r.frequency.size(); k += 9)
    fr.push_back(std::sqrt(std::max(r.frequency[k - 1], 1.0) * r.frequency[k]));
  const auto H =
      pipeline::contact_transfer(model.creep_coefficients(fr), model.normal_load_coefficients(fr));
  double worst = 0.0;
  for (size_t k = 0; k < fr.size(); ++k) {
    const Eigen::MatrixXcd Hd = r.discrete.discrete_frequency_response(fr[k], r.dt);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 4; ++j)
        worst =
            std::max(worst, std::abs(Hd(i, j) - H[k](i, j)) / H[k].col(j).cwiseAbs().maxCoeff());
  }
  std::printf("discrete model of the samples: order %d (filter %d), between samples %.3g\n",
              r.discrete.order(), r.sampling_filter.order(), worst);
  EXPECT_LT(worst, 1e-4);
}

// A step in each input with a raised-cosine onset over T = 16 dt (its spectrum is 1e-3 of the
// step's by f = 3/T, within the band, so the band-limited fit sees all of it): the continuous
// model simulated exactly (first-order hold on dt/8) against the linear model's time response
// (nss::LinearContactModel::time_response: the discrete recursion), compared at every t_k over 1.5
// times the Markov length, relative to the final value, outputs in the fit's scaling.
TEST(StateSpaceExport, TheStepResponseEqualsTheLinearModelsTimeResponse) {
  const pipeline::StateSpaceResult& r = fixture().r;
  const nss::LinearContactModel& model = *r.creep.state.model();
  const double dt = r.dt, T = 16 * dt;
  const int steps = r.markov_count * 3 / 2, sub = 8;
  auto onset = [&](double t) {
    return t <= 0 ? 0.0 : t >= T ? 1.0 : 0.5 * (1.0 - std::cos(M_PI * t / T));
  };
  // its integral from 0, for the step mean (1/dt) int_{t_k - dt}^{t_k} onset (average sampling)
  auto integral = [&](double t) {
    return t <= 0 ? 0.0 : t >= T ? t - 0.5 * T : 0.5 * (t - T / M_PI * std::sin(M_PI * t / T));
  };
  // the discrete model's creepage input of step k in the sweep's sampling
  auto creepage_input = [&](double t) {
    switch (r.input_sampling) {
      case contact::CreepageSampling::contact:
        return onset(t);
      case contact::CreepageSampling::midstep:
        return onset(t - 0.5 * dt);
      case contact::CreepageSampling::average:
        return (integral(t) - integral(t - dt)) / dt;
    }
    return onset(t);
  };
  const Eigen::VectorXd so = r.fit.scaling.output;
  double worst = 0.0;
  for (int j = 0; j < 4; ++j) {
    const double size = 1.0 / r.fit.scaling.input(j);  // a unit step in the fit's scaling
    std::vector<Eigen::VectorXd> u;
    for (int k = 0; k < steps * sub; ++k) {
      u.push_back(Eigen::VectorXd::Zero(4));
      u.back()(j) = size * onset(k * dt / sub);
    }
    const std::vector<Eigen::VectorXd> yc =
        linalg::simulate_first_order_hold(r.fit.model, dt / sub, u);
    std::vector<Eigen::Vector3d> xi(steps, Eigen::Vector3d::Zero());
    std::vector<double> dN(steps, 0.0);
    for (int k = 0; k < steps; ++k) {
      const double t = k * dt;
      if (j < 3)
        xi[k](j) = size * creepage_input(t);  // the sweep's creepage sampling
      else
        dN[k] = size * onset(t);
    }
    const std::vector<Eigen::Vector3d> yd = model.time_response(xi, dN);
    const double final_value = so.cwiseInverse().cwiseProduct(yd.back()).norm();
    ASSERT_GT(final_value, 0.0);
    for (int k = 0; k < steps; ++k)
      worst =
          std::max(worst, so.cwiseInverse().cwiseProduct(yc[k * sub] - yd[k]).norm() / final_value);
  }
  std::printf("step responses: max |y_fit - y_linear| / |y_final| = %.3g over %d steps\n", worst,
              steps);
  EXPECT_LT(worst, 1e-3);
}

}  // namespace

TEST(StateSpaceExport, TheDiscreteModelHasTheTransferFAndGInEverySampling) {
  // the Markov parameters are those of the creepage of step k, whatever the sampling (the
  // recursion times the sampling's factor is f exactly); the sampling filter turns the samples at
  // t_k into that creepage, so that the discrete model is f itself within the band (the fit's
  // tolerance 1e-5); contact needs no filter
  for (const contact::CreepageSampling s :
       {contact::CreepageSampling::contact, contact::CreepageSampling::midstep,
        contact::CreepageSampling::average}) {
    const io::CaseReader reader = io::CaseReader::from_file(
        std::string(ROLLNOISE_SOURCE_DIR) + "/cases/hertz_paper.toml",
        {"grid.nx=14", "grid.ny=11", "contact.normal_force=80e3",
         "creepage.mean=[0.0012, -0.0008, -0.1]",
         "rolling.creepage_sampling=\"" + std::string(contact::sampling_name(s)) + "\""});
    io::InputProblems problems;
    pipeline::ContactCase c = io::read_contact_case(reader, problems);
    problems.throw_if_any();
    EXPECT_EQ(c.sampling, s);
    const double fn = pipeline::nyquist_frequency(c);
    std::vector<double> band;
    // the band to Nyquist/2, as the fixture's: near the Nyquist limit no rational filter has the
    // half-step delay (docs/statespace.md Sec. 3; to 0.9 Nyquist midstep's reaches 1.4e-5)
    for (int i = 0; i < 30; ++i) band.push_back(10.0 * std::pow(0.5 * fn / 10.0, i / 29.0));
    const auto r =
        pipeline::run_statespace(c, band, pipeline::StateSpaceOptions{}, "frequency.f_max");
    EXPECT_EQ(r.input_sampling, s) << contact::sampling_name(s);
    EXPECT_LT(r.recursion_error, 1e-8) << contact::sampling_name(s);
    EXPECT_EQ(r.sampling_filter.order() == 0, s == contact::CreepageSampling::contact);
    EXPECT_LT(r.discrete_error, 1e-5) << contact::sampling_name(s);
  }
}

// The bilinear map is an identity of transfer functions: G_d(z) = G_c((2/dt)(z - 1)/(z + 1)) at
// any z (here on and off the unit circle), to rounding (1e-12 relative).
TEST(StateSpaceExport, TheBilinearMapKeepsTheTransferAtTheWarpedFrequency) {
  linalg::StateSpace c;
  c.A.resize(3, 3);
  c.A << -50.0, 800.0, 0.0, -800.0, -50.0, 0.0, 0.0, 0.0, -3000.0;
  c.B.resize(3, 2);
  c.B << 1.0, 0.5, -0.3, 2.0, 1.5, 0.0;
  c.C.resize(1, 3);
  c.C << 0.7, -1.1, 2.0;
  c.D.resize(1, 2);
  c.D << 0.1, -0.2;
  const double dt = 1e-4;
  const linalg::StateSpace d = linalg::bilinear_discretisation(c, dt);
  for (const std::complex<double> z :
       {std::polar(1.0, 0.3), std::polar(1.0, 2.9), std::complex<double>(0.4, -1.7)}) {
    const Eigen::MatrixXcd gd = d.response(z), gc = c.response(2.0 / dt * (z - 1.0) / (z + 1.0));
    EXPECT_LT((gd - gc).norm(), 1e-12 * gc.norm()) << z;
  }
}
