// What passby and cnossos share: the case read with its noise and pass-by keys, its noise run with
// the sound powers, and the wheels the run computed.
#pragma once

#include <vector>

#include "cli/commands.hpp"
#include "io/case_reader.hpp"
#include "io/noise_case.hpp"
#include "noise/wheel_contact.hpp"
#include "pipeline/noise_pipeline.hpp"
#include "pipeline/passby.hpp"

namespace rollnoise::cli {

struct TrainNoise {
  io::CaseReader reader;
  io::NoiseInputs in;  ///< in.noise: the noise case (in.contact went into the run)
  pipeline::PassbyCase train;
  pipeline::NoiseResult noise;
  std::vector<noise::WheelId> wheels;  ///< noise.wheels' ids: contact_power[i] is wheels[i]'s
};

/// Read the case of `o` (InputError naming noise.sound for a case without sound, `command` in the
/// message) and run its noise pipeline.
TrainNoise run_train_noise(const CommonOptions& o, const char* command);

}  // namespace rollnoise::cli
