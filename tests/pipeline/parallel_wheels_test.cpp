// The further wheels of a noise run on a pool of threads (pipeline::run_noise, solver.threads):
// every wheel's output is bit-identical with 1 and 2 threads, with the bogie loop and with each
// wheel's loop alone; and the pool (core/task_pool.hpp) runs every task once and hands the
// caller the exception a serial loop would have thrown first.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "core/errors.hpp"
#include "core/task_pool.hpp"
#include "io/case_reader.hpp"
#include "io/noise_case.hpp"
#include "pipeline/noise_pipeline.hpp"

namespace {

using namespace rollnoise;

// cases/curve_300m.toml, four wheels, on a small grid (nx = 16), 4 points per band up to 800 Hz,
// the FE wheel on a coarse mesh (20 mm, modes to 2 kHz).
pipeline::NoiseResult run_curve(int threads, const std::string& coupling) {
  const std::vector<std::string> o = {"grid.nx=16",
                                      "curve.creepage=\"estimate\"",
                                      "noise.points_per_band=4",
                                      "noise.band_max=800.0",
                                      "noise.compare=\"none\"",
                                      "wheel.mesh_size=0.02",
                                      "wheel.f_max=2000",
                                      "noise.contact_coupling=\"" + coupling + "\"",
                                      "solver.threads=" + std::to_string(threads)};
  const io::NoiseInputs in = io::read_noise_inputs(
      io::CaseReader::from_file(std::string(ROLLNOISE_SOURCE_DIR) + "/cases/curve_300m.toml", o));
  return pipeline::run_noise(in.contact, in.noise);
}

void expect_same_loop(const noise::LoopResult& a, const noise::LoopResult& b,
                      const std::string& what) {
  ASSERT_EQ(a.frequency.size(), b.frequency.size()) << what;
  for (std::size_t k = 0; k < a.frequency.size(); ++k) {
    EXPECT_TRUE(a.force[k] == b.force[k]) << what << " force, line " << k;
    EXPECT_TRUE(a.wheel_velocity[k] == b.wheel_velocity[k])
        << what << " wheel velocity, line " << k;
    EXPECT_TRUE(a.rail_velocity[k] == b.rail_velocity[k]) << what << " rail velocity, line " << k;
  }
}

void expect_same_bands(const noise::BandLevels& a, const noise::BandLevels& b,
                       const std::string& what) {
  ASSERT_EQ(a.centre.size(), b.centre.size()) << what;
  for (std::size_t j = 0; j < a.centre.size(); ++j) {
    EXPECT_EQ(a.force_level[j], b.force_level[j]) << what << " force level, band " << j;
    EXPECT_EQ(a.velocity_level[j], b.velocity_level[j]) << what << " velocity level, band " << j;
  }
}

// Each wheel's contact state, elements in adhesion, contact receptance, loop and band levels with
// 2 threads equal those with 1 exactly (tolerance 0: the wheels are independent tasks, each
// model's products do not depend on its threads).
void expect_wheels_independent_of_threads(const std::string& coupling) {
  const pipeline::NoiseResult one = run_curve(1, coupling), two = run_curve(2, coupling);
  ASSERT_EQ(one.wheels.size(), 4u);
  ASSERT_EQ(two.wheels.size(), 4u);
  for (std::size_t i = 0; i < one.wheels.size(); ++i) {
    const pipeline::WheelNoise &a = one.wheels[i], &b = two.wheels[i];
    const std::string what = coupling + ", wheel " + std::to_string(i);
    EXPECT_EQ(a.wheel, b.wheel) << what;
    EXPECT_EQ(a.adhesion_elements, b.adhesion_elements) << what;
    EXPECT_EQ(a.mean_force.Fx, b.mean_force.Fx) << what;
    EXPECT_EQ(a.mean_force.Fy, b.mean_force.Fy) << what;
    ASSERT_EQ(a.receptance.main.size(), b.receptance.main.size()) << what;
    for (std::size_t k = 0; k < a.receptance.main.size(); ++k)
      EXPECT_TRUE(a.receptance.main[k] == b.receptance.main[k]) << what << ", line " << k;
    expect_same_bands(a.bands, b.bands, what);
  }
  ASSERT_EQ(one.coupled_contacts, two.coupled_contacts);
  for (int a = 0; a < 4; ++a)
    expect_same_loop(noise::contact_response(one.loops.main, a, a),
                     noise::contact_response(two.loops.main, a, a), "loop " + std::to_string(a));
}

}  // namespace

TEST(ParallelWheels, BogieLoopBitIdenticalOnOneAndTwoThreads) {
  expect_wheels_independent_of_threads("bogie");
}

TEST(ParallelWheels, LoopsAloneBitIdenticalOnOneAndTwoThreads) {
  expect_wheels_independent_of_threads("none");
}

// Every index runs exactly once on 1, 2 and 3 threads; two failing tasks: the caller gets the
// lower index's exception (its type and message), as from a serial loop.
TEST(ParallelWheels, TaskPoolRunsEachTaskOnceAndRethrowsTheFirst) {
  for (int workers : {1, 2, 3}) {
    std::vector<std::atomic<int>> runs(7);
    parallel_for(runs.size(), workers, [&](std::size_t i, int worker) {
      EXPECT_GE(worker, 0);
      EXPECT_LT(worker, workers);
      ++runs[i];
    });
    for (const auto& r : runs) EXPECT_EQ(r.load(), 1) << workers << " workers";
    try {
      parallel_for(5, workers, [](std::size_t i, int) {
        if (i == 1) throw InputError("noise.band_max", "wheel 1");
        if (i == 3) throw std::runtime_error("wheel 3");
      });
      ADD_FAILURE() << "no exception";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("wheel 1"), std::string::npos) << e.what();
    }
  }
}

// A caller with work of its own before finish() (the main wheel: TaskPool::Caller::busy) does not
// hold the further wheels back: one task on two workers starts on a background thread (worker 1)
// while the caller has not called finish() yet (the caller waits up to 60 s for it); a ready
// caller's single task waits for finish() and runs on the caller (worker 0); with busy, no more
// background threads than tasks (each task once, workers < 3).
TEST(ParallelWheels, TaskPoolStartsAFurtherWheelBesideABusyCaller) {
  std::atomic<bool> ran{false};
  std::atomic<int> on{-1};
  TaskPool busy(
      1, 2, [&](std::size_t, int worker) { on = worker, ran = true; }, TaskPool::Caller::busy);
  for (int ms = 0; ms < 60000 && !ran; ++ms)
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  EXPECT_TRUE(ran.load());
  busy.finish();
  EXPECT_EQ(on.load(), 1);

  std::atomic<int> ready_on{-1};
  TaskPool ready(1, 2, [&](std::size_t, int worker) { ready_on = worker; });
  std::this_thread::sleep_for(std::chrono::milliseconds(20));
  EXPECT_EQ(ready_on.load(), -1);  // not started: no background thread for one task
  ready.finish();
  EXPECT_EQ(ready_on.load(), 0);

  std::vector<std::atomic<int>> runs(3);
  TaskPool three(
      runs.size(), 8,
      [&](std::size_t i, int worker) {
        EXPECT_LE(worker, 3);
        ++runs[i];
      },
      TaskPool::Caller::busy);
  three.finish();
  for (const auto& r : runs) EXPECT_EQ(r.load(), 1);
}
