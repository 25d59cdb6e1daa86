// Shared inputs of the curve-state tests: S1002 on UIC60 1:40 (the profiles of models/), their
// profile curving table, the 10 t static wheel load and 70 km/h of cases/curve_300m.toml.
#pragma once

#include <memory>

#include "geometry/wheel_rail.hpp"
#include "io/profile_file.hpp"
#include "vehicle/curve_state.hpp"
#include "vehicle/curving.hpp"
#include "noise_fixture.hpp"

namespace noise_test {

inline constexpr double kCurveQ = 98.1e3;    // static wheel load (N)
inline constexpr double kCurveV = 70 / 3.6;  // m/s

inline const std::shared_ptr<const rollnoise::geometry::WheelRailPair>& s1002_uic60() {
  static const auto p = std::make_shared<const rollnoise::geometry::WheelRailPair>(
      rollnoise::io::read_profile(model_path("profiles/MBench_S1002_v3.prw")),
      rollnoise::io::read_profile(model_path("profiles/MBench_UIC60_v3.prr")));
  return p;
}

inline const std::shared_ptr<const rn::ProfileCurvingTable>& s1002_uic60_table() {
  static const auto t =
      std::make_shared<const rn::ProfileCurvingTable>(rn::profile_curving_table(*s1002_uic60()));
  return t;
}

// The names the curve-state tests use for them.
inline constexpr double kQ = kCurveQ;  // static wheel load (N)
inline constexpr double kV = kCurveV;  // m/s
inline const std::shared_ptr<const rollnoise::geometry::WheelRailPair>& pair() {
  return s1002_uic60();
}
inline const std::shared_ptr<const rn::ProfileCurvingTable>& table() {
  return s1002_uic60_table();
}

/// The curve state's input on the fixture's profiles (no curving table): 16 elements in x, the
/// fixture's speed and wheel load, friction mu.
inline rn::CurveStateInput curve_input(double radius, double cant_deficiency, double mu = 0.3) {
  rn::CurveStateInput in;
  in.pair = pair();
  in.material = material();
  in.grid.nx = 16;
  in.radius = radius;
  in.speed = kV;
  in.cant_deficiency = cant_deficiency;
  in.wheel_load = kQ;
  in.friction = mu;
  return in;
}

}  // namespace noise_test
