#include "contact/friction_law.hpp"

#include <sstream>

#include "core/errors.hpp"

namespace rollnoise::contact {

void check_falling_friction(const FallingFriction& f) {
  auto text = [](double v) {
    std::ostringstream s;
    s << v;
    return s.str();
  };
  if (!(std::isfinite(f.kinetic_ratio) && f.kinetic_ratio > 0.0 && f.kinetic_ratio <= 1.0))
    throw InputError("friction.kinetic_ratio",
                     "must lie in (0, 1] (mu(inf)/mu_s of the falling law), got " + text(f.kinetic_ratio));
  if (!(std::isfinite(f.decay) && f.decay >= 0.0))
    throw InputError("friction.decay", "must be a finite decay >= 0 (s/m), got " + text(f.decay));
}

}  // namespace rollnoise::contact
