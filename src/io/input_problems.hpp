// Every problem of a case at once: the readers run their checks through one InputProblems, which
// records each InputError instead of stopping at the first, and throws them together at the end.
// A check is a group of reads that depend on each other (a grid and its coverage of the patch):
// its first problem ends that group only.
#pragma once

#include <algorithm>
#include <string>
#include <vector>

#include "core/errors.hpp"

namespace rollnoise::io {

class InputProblems {
 public:
  /// Run `check`; an InputError it throws is recorded, once (two readers of one key find the
  /// same problem: it is listed once). True when it passed.
  template <class Check>
  bool check(Check&& check) {
    try {
      check();
      return true;
    } catch (const InputError& e) {
      const bool known = std::any_of(problems_.begin(), problems_.end(), [&](const InputError& p) {
        return std::string(p.what()) == e.what();
      });
      if (!known) problems_.push_back(e);
      return false;
    }
  }
  bool empty() const { return problems_.empty(); }
  /// One InputError for all problems: the key of the first, every message on its own line.
  void throw_if_any() const;

 private:
  std::vector<InputError> problems_;
};

}  // namespace rollnoise::io
