// RailModel's common part (rail_model.hpp): the track, checked, and the case's contact position.
#include "dynamics/rail_model.hpp"

#include <cmath>

#include "core/errors.hpp"

namespace rollnoise::dynamics {

namespace {
const TrackParameters& validated(const TrackParameters& t) {
  t.validate();
  return t;
}
}  // namespace

RailModel::RailModel(const TrackParameters& track, double contact_position)
    : track_(validated(track)), x_(contact_position) {
  if (!std::isfinite(x_)) throw InputError("track.position", "contact position must be finite");
}

}  // namespace rollnoise::dynamics
