#include "io/track_file.hpp"

#include <cmath>

#include "core/errors.hpp"
#include "io/parameter_table.hpp"

namespace rollnoise::io {
namespace {

dynamics::TrackParameters track_parameters_from(const ParameterTable& f) {
  dynamics::TrackParameters t;
  dynamics::BeamSection rail;
  rail.youngs_modulus = f.positive("rail.youngs_modulus");
  rail.shear_modulus = f.positive("rail.shear_modulus");
  rail.area = f.positive("rail.area");
  rail.mass_per_length = f.positive("rail.mass_per_length");
  rail.loss_factor = f.positive("rail.loss_factor", true);
  rail.timoshenko = f.flag_or("rail.timoshenko", true);
  t.vertical = rail;
  t.vertical.second_moment = f.positive("rail.vertical.second_moment");
  t.vertical.shear_coefficient = f.positive("rail.vertical.shear_coefficient");
  t.lateral = rail;
  t.lateral.second_moment = f.positive("rail.lateral.second_moment");
  t.lateral.shear_coefficient = f.positive("rail.lateral.shear_coefficient");
  auto support = [&](const std::string& p) {
    dynamics::Support s;
    s.pad_stiffness = f.positive(p + ".pad_stiffness");
    s.pad_loss_factor = f.positive(p + ".pad_loss_factor", true);
    s.sleeper_mass = f.positive(p + ".sleeper_mass", true);
    s.ballast_stiffness = f.positive(p + ".ballast_stiffness");
    s.ballast_loss_factor = f.positive(p + ".ballast_loss_factor", true);
    return s;
  };
  t.vertical_support = support("support.vertical");
  t.lateral_support = support("support.lateral");
  t.longitudinal_support = support("support.longitudinal");
  t.sleeper_spacing = f.positive("sleeper_spacing");
  t.head_height = f.positive("head_height", true);
  const double n = f.get_or("supports_each_side", 60.0);
  if (!(n >= 1.0) || n != std::floor(n) || n > 100000.0)
    throw InputError(f.origin() + ":supports_each_side",
                     f.origin() + ": supports_each_side must be a positive integer");
  t.supports_each_side = static_cast<int>(n);
  f.reject_unread_keys();
  t.validate();
  return t;
}

}  // namespace

dynamics::TrackParameters read_track_parameters(const std::string& path) {
  return track_parameters_from(ParameterTable::read(path));
}

dynamics::TrackParameters parse_track_parameters(const std::string& text,
                                                 const std::string& origin) {
  return track_parameters_from(ParameterTable::parse(text, origin));
}

}  // namespace rollnoise::io
