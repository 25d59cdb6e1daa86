#include "io/input_problems.hpp"

namespace rollnoise::io {

void InputProblems::throw_if_any() const {
  if (problems_.empty()) return;
  if (problems_.size() == 1) throw problems_.front();
  std::string all = std::to_string(problems_.size()) + " problems in the case:";
  for (const InputError& e : problems_) all += std::string("\n  ") + e.what();
  throw InputError(problems_.front().key(), all);
}

}  // namespace rollnoise::io
