// Error types shared by every layer.
//
//   InputError      bad user input (case file, profile file, option): exit status 2.
//   NumericalError  a solver did not converge or a result is not finite: exit status 1.
#pragma once

#include <stdexcept>
#include <string>

namespace rollnoise {

/// Bad input. `key` is the dotted case key (or file/field) the message is about.
class InputError : public std::runtime_error {
 public:
  InputError(std::string key, const std::string& what)
      : std::runtime_error(what), key_(std::move(key)) {}
  const std::string& key() const { return key_; }

 private:
  std::string key_;
};

/// A numerical failure: which solver, its residual and iteration count are in the message.
class NumericalError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace rollnoise
