#include "io/wheel_file.hpp"

#include "core/errors.hpp"
#include "io/parameter_table.hpp"
#include "io/text_file.hpp"

namespace rollnoise::io {

using dynamics::kWheelModeFields;

namespace {

dynamics::RigidWheelset wheelset_from(const ParameterTable& f) {
  dynamics::RigidWheelset w;
  w.mass = f.positive("mass");
  w.roll_inertia = f.positive("roll_inertia");
  w.spin_inertia = f.positive("spin_inertia");
  w.yaw_inertia = f.positive("yaw_inertia");
  w.contact_offset_y = f.get("contact_offset_y");
  w.wheel_radius = f.positive("wheel_radius");
  f.reject_unread_keys();
  w.validate(f.origin());
  return w;
}

}  // namespace

dynamics::RigidWheelset read_wheelset(const std::string& path) {
  return wheelset_from(ParameterTable::read(path));
}

dynamics::RigidWheelset parse_wheelset(const std::string& text, const std::string& origin) {
  return wheelset_from(ParameterTable::parse(text, origin));
}

std::vector<dynamics::WheelMode> read_wheel_modes(const std::string& path) {
  std::vector<dynamics::WheelMode> modes;
  bool header = false;
  for_each_data_line(path, "wheel mode file", [&](const std::string& where, const std::string& t) {
    const auto cells = split_csv(t);
    if (!header) {  // the header must name the columns in order
      for (int c = 0; c < 7; ++c)
        if (static_cast<int>(cells.size()) <= c || cells[c] != kWheelModeFields[c])
          throw InputError(where + ":" + kWheelModeFields[c],
                           where + ": header must be '" +
                               std::string("frequency_Hz,damping_ratio,"
                                           "modal_mass_kg,phi_z,phi_x,"
                                           "phi_y,phi_rz[,label]") +
                               "'; column " + std::to_string(c + 1) + " should be '" +
                               kWheelModeFields[c] + "'");
      header = true;
      return;
    }
    double v[7];
    for (int c = 0; c < 7; ++c) {
      if (static_cast<int>(cells.size()) <= c || cells[c].empty())
        throw InputError(where + ":" + kWheelModeFields[c],
                         where + ": missing field '" + kWheelModeFields[c] + "'");
      if (!parse_finite(cells[c], v[c]))
        throw InputError(where + ":" + kWheelModeFields[c],
                         where + ": field '" + kWheelModeFields[c] + "' is not a finite number: '" +
                             cells[c] + "'");
    }
    if (cells.size() > 8)
      throw InputError(where, where + ": too many fields (" + std::to_string(cells.size()) +
                                  "), expected 7 or 8");
    dynamics::WheelMode m;
    m.frequency = v[0];
    m.damping_ratio = v[1];
    m.modal_mass = v[2];
    m.shape << v[3], v[4], v[5], v[6];
    if (cells.size() == 8) m.label = cells[7];
    dynamics::validate_mode(m, where);
    modes.push_back(m);
  });
  if (!header) throw InputError(path, path + ": no header line (empty wheel mode file)");
  return modes;
}

}  // namespace rollnoise::io
