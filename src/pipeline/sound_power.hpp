// How loud: the sound power of the wheels, the rails and the sleepers under the loop's contact
// forces, per 1/3-octave band (docs/sound.md). The stage after the band levels of run_noise.
//
// Per roughness source e and narrow-band line f, with F the loop's contact forces per unit
// roughness amplitude (noise/contact_set_loop.hpp, contact frames, on the wheels):
//
//  wheel (each wheel alone; its contacts' forces, W2 of dynamics/wheel_fe_contact.hpp, W3 of
//  sound_radiation.hpp):
//    W_wheel = omega^2 sum_n sum_{set} q_set,n^H P_n(f) q_set,n                              (S1)
//
//  rail (each rail: the response at its centre line u(x) = sum_b alpha(x, b) T_b (-F_b) of the
//  contacts b on it, RailModel::contact_transfers; where the section deforms, the waveguide, the
//  wavenumber integral (R2) of rail_section_sound.hpp instead):
//    W_rail = omega^2 Int [ P_v(f) |u_z(x)|^2 + P_l(f) |u_y(x)|^2 ] dx
//           = omega^2 [ P_v F^H G_z F + P_l F^H G_y F ],   G_c = Int A_c(x)^H A_c(x) dx (S2)
//  with A_c(x) the row c of alpha(x, b) T_b over the contacts b. The integral: Gauss-Legendre
//  points in each sleeper span over a window around the contacts, the tails beyond it closed as
//  the geometric series of the last spans' ratio (the slowest Floquet wave's decay; docs/sound.md
//  Sec. 3.2);
//
//  sleepers (a baffled rigid piston of the sleeper's area per rail seat, acoustics/piston.hpp;
//  the seat's sleeper displacement tau u_z(x_j), tau = k_p* / (k_p* + k_b* - m_s omega^2) of
//  Eq. (1) of dynamics/track.hpp):
//    W_sleepers = omega^2 |tau|^2 (rho c / 2) sigma_p(k) A_s F^H G_s F,  G_s = sum_j A_z(x_j)^H
//    A_z(x_j)  (S3)
//
// The G matrices vary smoothly with frequency; they are computed on the radiation grid
// (sound_radiation.hpp) and interpolated to the lines. Band levels as (B1) of noise/bands.hpp with
// each source's own roughness levels, the power per unit mean-square roughness being 2 W:
//
//    L_W(b) = 10 log10( sum_e r_e,b^2 <2 W_e>_b / W0 ),   W0 = 1 pW (S4)
//
// The bogie's wheel column sums the wheels, the rail column both rails (each coherently over its
// contacts), the sleeper column both rails' sleepers; total = wheel + rail + sleepers. A wheel's
// own group: its wheel's power, and its rail's and sleepers' power under its contact's forces
// alone (without the other contacts on that rail: a wheel's rail columns do not add up to the
// bogie's, whose coherent sum also holds the cross terms).
//
// The bound (S5): the mechanical power the contact forces put into the structures,
//   P_in = (1/2) Re sum_a F_a^H (v_wheel,a - v_rail,a)   (contact frames),
// of which the radiated power can only be a part (the rest is dissipated in the pads, the ballast,
// the wheel's and the rail's damping).
//
// Decay rates (EN 15461, acoustics/decay_rate.hpp): the transfer receptances along the rail from a
// vertical (lateral) force at the centre line at track.position, band means of |A(x)|^2 on the
// grid.
#pragma once

#include <array>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "dynamics/rail_model.hpp"
#include "dynamics/wheel_fe_contact.hpp"
#include "noise/contact_set_loop.hpp"
#include "pipeline/rail_section_sound.hpp"
#include "pipeline/sound_radiation.hpp"

namespace rollnoise::pipeline {

/// (S2), (S3) for loads on the rail's centre line: at each frequency of `grid`, with a_c(x) the
/// row c of the rail's 6x6 transfer (RailModel::contact_transfers, centre line to centre line) from
/// the loads at each of `positions` (6 per position: x, y, z, rot x, rot y, rot z),
///   G_z = Int a_z^H a_z dx,  G_y = Int a_y^H a_y dx,  G_s = sum_j a_z(x_j)^H a_z(x_j)  (sleepers
///   x_j = j L);
/// m^2/N^2 m and m^2/N^2 (6 p x 6 p). `gauss`: Gauss-Legendre points a sleeper span; 0: the
/// sleepers alone (G_z = G_y = 0), for a rail whose own radiation comes from its section's loads
/// (Eq. R2, RailModel::section_deforms) and which needs the line for its sleepers only. The same
/// for both rails (one track model); it depends on the track, the positions and the grid alone, so
/// io keeps it in the cache (io/radiation_cache.hpp).
struct RailLineGram {
  std::vector<double> positions;                 ///< m along the rail, from a sleeper
  std::vector<Eigen::MatrixXcd> z, y, sleepers;  ///< per grid frequency
};
RailLineGram rail_line_gram(const dynamics::RailModel& rail, const std::vector<double>& positions,
                            const std::vector<double>& grid, int gauss, int threads = 1);

/// What the sound power needs besides the loop (read by io from the [sound] keys).
struct SoundCase {
  bool on = true;  ///< noise.sound
  acoustics::Fluid fluid;
  bool rail_ground = false;                   ///< sound.rail_ground = "rigid"
  double sleeper_length = 1.3;                ///< sound.sleeper_length: per rail seat (m)
  double sleeper_width = 0.25;                ///< sound.sleeper_width (m)
  std::vector<Eigen::Vector2d> rail_section;  ///< (y, z) m; empty: dynamics::uic60_outline()
  /// The FE wheel along the tread and its contact options (null: the table wheel, no surface)
  std::function<std::shared_ptr<const dynamics::WheelFeModes>()> wheel_tread;
  dynamics::WheelFeContactOptions wheel_options;
  /// The radiation tables on a grid: computed here, or read from the cache (io). Null: computed
  /// directly (wheel_radiation needs the FE modes with their mesh: wheel_modes).
  std::function<std::shared_ptr<const WheelRadiation>(const std::vector<double>& grid)> wheel_table;
  std::function<std::shared_ptr<const RailRadiation>(const std::vector<double>& grid)> rail_table;
  /// The rail's line Gram matrices (rail_line_gram below), from the cache where io gives one; null:
  /// computed here.
  std::function<std::shared_ptr<const RailLineGram>(
      const dynamics::RailModel& rail, const std::vector<double>& positions,
      const std::vector<double>& grid, int gauss, int threads)>
      rail_line_table;
  /// The section's 2D power table up to k_r = max_k (rail_section_sound.hpp), from the cache where
  /// io gives one; null: computed here. Used where the rail's section deforms (the waveguide).
  std::function<std::shared_ptr<const SectionRadiationTable>(double max_k)> section_table;
  /// The section Gram matrices (R2) of one rail's loads on the grid, from the cache where io gives
  /// one; null: computed here (section_grams).
  std::function<std::vector<Eigen::MatrixXcd>(
      const dynamics::RailModel& rail, const std::vector<dynamics::RailLoadPoint>& points,
      const SectionRadiationTable& table, const std::vector<double>& grid,
      const acoustics::Fluid& fluid, int threads)>
      section_gram_table;
  /// Why the wheel has no sound (empty when it has): e.g. the table wheel.
  std::string wheel_missing;
};

/// Band sound powers, dB re 1 pW: [band][wheel, rail, sleepers, total].
using SoundBands = std::vector<std::array<double, 4>>;

struct SoundResult {
  std::vector<double> centre;             ///< Hz
  SoundBands power;                       ///< the bogie
  std::array<double, 4> power_a{};        ///< A-weighted totals of the columns, dB(A) re 1 pW
  std::vector<SoundBands> contact_power;  ///< per physical wheel (wheels' order)
  std::vector<std::array<double, 4>> contact_power_a;
  std::string wheel_note;  ///< why the wheel column is empty (NaN), if it is
  /// The wheels' power by mode family ([band][axial, radial, circumferential], dB re 1 pW): each
  /// family's modes alone (their cross terms within an order kept, those with the other families
  /// left out, so the three need not add up to the wheel column); the bogie's and each wheel's.
  /// Empty without the wheel's surface.
  std::vector<std::array<double, 3>> wheel_family;
  std::vector<std::vector<std::array<double, 3>>> contact_family;
  std::shared_ptr<const WheelRadiation> wheel;  ///< null without the wheel's surface
  std::shared_ptr<const RailRadiation> rail;
  std::vector<double> decay_vertical, decay_lateral;  ///< dB/m per band
  /// EN ISO 3095:2013's lower limits of the decay rates (dB/m; NaN outside 250 Hz - 5 kHz)
  std::vector<double> decay_limit_vertical, decay_limit_lateral;
  /// (S5): the mechanical power the contact forces put into the wheels and rails, dB re 1 pW per
  /// band (the bound of the radiated power; NaN without the loop's velocities)
  std::vector<double> input_power;
  double seconds = 0.0;  ///< wall time of the stage (s)
  /// where it went (s): the radiation tables (wheel, rail: cached), the rails' response along the
  /// line (S2, S3), the rails' section grams (R2; the waveguides), the lines' powers, the decay
  /// rates
  struct Parts {
    double tables = 0.0, rail_line = 0.0, rail_section = 0.0, lines = 0.0, decay = 0.0;
  } parts;
};

/// The Gram matrices of one rail's contacts (those of `contacts` on `side`) in their frames
/// (4 columns per contact): M^H G M, M the lever arm from each contact's offset on the head to the
/// centre line and its contact frame ((G1), (G2) of dynamics/rail_contact.hpp). Exact for the
/// beams, which move their centre-line transfer rigidly to the contact; for the waveguides, which
/// load their section at the contact, the centre line's response is that of the centre-line load
/// moved by the same lever arm (docs/sound.md Sec. 3.2): what their sleepers take (the rail's own
/// radiation comes from the section itself, `radiated`).
struct RailGram {
  std::vector<int> contacts;                     ///< indices into `contacts`, those on this side
  std::vector<Eigen::MatrixXcd> z, y, sleepers;  ///< per grid frequency, 4 m x 4 m
  /// The rail's radiation per grid frequency, W_rail = omega^2 F^H radiated F (W/m^2 N^-2 s^-2 m
  /// ...: m^2/N^2 times W/m per (m/s)^2): P_v z + P_l y where the section moves rigidly (the
  /// beams, (S2)), the wavenumber integral (R2) of rail_section_sound.hpp where it deforms (the
  /// waveguide).
  std::vector<Eigen::MatrixXcd> radiated;
};
RailGram rail_gram(const RailLineGram& line, const std::vector<noise::ContactPoint>& contacts,
                   int side);

/// The A-weighted total (IEC 61672-1) of one column of band levels; NaN when a band is not finite
/// (the table wheel's empty column).
double a_weighted_column(const std::vector<double>& centres, const std::vector<double>& levels);

/// a_weighted_column of each of the four columns of `bands`.
std::array<double, 4> a_weighted_columns(const std::vector<double>& centres,
                                         const SoundBands& bands);

/// 10 log10(10^{a/10} + 10^{b/10}) (dB); a NaN term (an empty column) is left out.
double power_sum(double a, double b);

/// A physical wheel: the contacts (indices into the loop's contacts) on it.
struct SoundWheel {
  std::vector<int> contacts;
};

/// (S1)-(S4) for the loop `loop` (lines and sources) with `contacts` (as the loop's), `wheels` the
/// physical wheels (each one or more contacts), `source_levels[e]` each source's roughness levels
/// in the bands `centres` (dB re 1 um).
SoundResult sound_power(const noise::ContactSetLoopResult& loop,
                        const std::vector<noise::ContactPoint>& contacts,
                        const std::vector<SoundWheel>& wheels,
                        const std::vector<std::vector<double>>& source_levels,
                        const std::vector<double>& centres, const dynamics::RailModel& rail,
                        const SoundCase& sound, int threads = 1);

}  // namespace rollnoise::pipeline
