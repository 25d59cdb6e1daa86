// The vehicle data of the bogie's equilibrium in a curve ([vehicle] of a case;
// bogie_equilibrium.hpp, docs/noise_loop.md Sec. 7.4): masses, primary and secondary suspension,
// geometry. Plain values, SI units.
#pragma once

namespace rollnoise::noise {

/// The vehicle data of the equilibrium ([vehicle] of a case). The defaults are representative of
/// a passenger bogie of 2.5 m wheelbase (not one particular vehicle; docs/noise_loop.md Sec. 7.4).
struct VehicleParameters {
  /// m_c (kg) of the whole car body, half of it on the bogie; 0: the rest of the static load,
  /// 8 Q / g - 2 m_f - 4 m_w
  double carbody_mass = 0.0;
  double frame_mass = 2600.0;                    ///< m_f (kg) of one bogie frame
  double wheelset_mass = 1500.0;                 ///< m_w (kg) of one wheelset
  double primary_longitudinal_stiffness = 12e6;  ///< k_x (N/m) per axlebox
  double primary_lateral_stiffness = 4.5e6;      ///< k_y (N/m) per axlebox
  double axlebox_semi_spacing =
      1.0;  ///< b (m): lateral distance of an axlebox from the axle centre
  double secondary_yaw_stiffness = 3e5;  ///< K_s (N m/rad) between frame and body, per bogie
  double bogie_centre_distance = 19.0;   ///< 2L (m)
  bool rear_bogie = false;               ///< the rear bogie of the car (s = -1 in (B2))

  double primary_yaw_stiffness() const {  ///< K_psi = 2 k_x b^2 (N m/rad) per wheelset
    return 2.0 * primary_longitudinal_stiffness * axlebox_semi_spacing * axlebox_semi_spacing;
  }
  bool valid() const;
};

}  // namespace rollnoise::noise
