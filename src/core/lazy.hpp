// A value built on its first use, exactly once (std::call_once: threads that ask together wait
// for the one that builds), and shared by copies of its holder. A build that throws builds
// nothing: the exception reaches the caller and the next use tries again.
#pragma once

#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <utility>

namespace rollnoise {

template <class T>
class Lazy {
 public:
  explicit Lazy(std::function<T()> make) : state_(std::make_shared<State>(std::move(make))) {}

  const T& get() const {
    State& s = *state_;
    std::call_once(s.once, [&s] {
      s.value.emplace(s.make());
      s.make = nullptr;  // what it captured is no longer needed
    });
    return *s.value;
  }

 private:
  struct State {
    explicit State(std::function<T()> m) : make(std::move(m)) {}
    std::once_flag once;
    std::function<T()> make;
    std::optional<T> value;
  };
  std::shared_ptr<State> state_;
};

}  // namespace rollnoise
