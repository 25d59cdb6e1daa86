// Internal contract checks (deal.II's Assert, MFEM's MFEM_ASSERT): a violated ROLLNOISE_ASSERT is a
// programming error inside rollnoise, not bad input, so it names no case key. In builds without
// NDEBUG (Debug, and the sanitizer build) it throws std::logic_error naming the condition, file and
// line; in Release (NDEBUG) it compiles to nothing and the condition is not evaluated. Bad input
// is checked where it is read and reported as InputError (core/errors.hpp).
#pragma once

#include <stdexcept>
#include <string>

namespace rollnoise::detail {

[[noreturn]] inline void assertion_failed(const char* condition, const std::string& message, const char* file,
                                          int line) {
  throw std::logic_error(std::string(file) + ":" + std::to_string(line) + ": internal error: " + message +
                         " (violated: " + condition + ")");
}

}  // namespace rollnoise::detail

#ifdef NDEBUG
#define ROLLNOISE_ASSERT(condition, message) ((void)sizeof((condition) ? 1 : 0))
#else
#define ROLLNOISE_ASSERT(condition, message) \
  ((condition) ? (void)0 : ::rollnoise::detail::assertion_failed(#condition, (message), __FILE__, __LINE__))
#endif
