// A rail model's sampling archive in memory (the role io::RailSamplingCache plays with files),
// counting its reads and writes: for the tests of what a model keeps and shares.
#pragma once

#include <map>
#include <mutex>
#include <optional>
#include <string>

#include "dynamics/waveguide_frequency_sampling.hpp"

namespace rollnoise_test {

class MemoryArchive : public rollnoise::dynamics::SamplingArchive {
 public:
  std::optional<rollnoise::dynamics::KeptSampling> read(const std::string& key) const override {
    const std::lock_guard<std::mutex> lock(mutex_);
    const auto it = kept_.find(key);
    if (it == kept_.end()) return std::nullopt;
    ++reads;
    return it->second;
  }
  void write(const std::string& key, const rollnoise::dynamics::KeptSampling& kept) const override {
    const std::lock_guard<std::mutex> lock(mutex_);
    kept_[key] = kept;
    ++writes;
  }
  std::optional<rollnoise::dynamics::KeptLaplace> read_laplace(const std::string&) const override {
    return std::nullopt;
  }
  void write_laplace(const std::string&, const rollnoise::dynamics::KeptLaplace&) const override {}
  mutable int reads = 0, writes = 0;
  mutable std::map<std::string, rollnoise::dynamics::KeptSampling> kept_;

 private:
  mutable std::mutex mutex_;
};

}  // namespace rollnoise_test
