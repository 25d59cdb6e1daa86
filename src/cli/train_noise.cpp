#include "cli/train_noise.hpp"

#include <string>
#include <utility>

#include "io/passby_case.hpp"

namespace rollnoise::cli {

TrainNoise run_train_noise(const CommonOptions& o, const char* command) {
  const io::CaseReader reader = io::CaseReader::from_file(o.case_file, o.overrides);
  io::NoiseInputs in = io::read_noise_inputs(reader);
  pipeline::PassbyCase train = io::read_passby_case(reader, in.noise);
  if (!in.noise.sound.on)
    reader.fail("noise.sound", std::string(command) + " needs the sound powers: noise.sound = \"on\"");
  pipeline::NoiseResult r =
      io::within_case(reader, [&] { return pipeline::run_noise(std::move(in.contact), in.noise); });
  std::vector<noise::WheelId> wheels;
  for (const pipeline::WheelNoise& wn : r.wheels) wheels.push_back(wn.wheel);
  return TrainNoise{reader, std::move(in), std::move(train), std::move(r), std::move(wheels)};
}

}  // namespace rollnoise::cli
