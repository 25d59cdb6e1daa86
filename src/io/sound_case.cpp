#include "io/sound_case.hpp"

#include "core/task_pool.hpp"
#include "dynamics/rail_section.hpp"
#include "io/radiation_cache.hpp"

namespace rollnoise::io {

pipeline::SoundCase read_sound_case(const CaseReader& r, InputProblems& problems,
                                    const std::optional<WheelFeCase>& fe,
                                    const std::vector<Eigen::Vector2d>& rail_section) {
  pipeline::SoundCase s;
  problems.check([&] { s.on = r.string("noise.sound") == "on"; });
  problems.check([&] { s.rail_ground = r.string("sound.rail_ground") == "rigid"; });
  problems.check([&] { s.sleeper_length = r.real("sound.sleeper_length"); });
  problems.check([&] { s.sleeper_width = r.real("sound.sleeper_width"); });
  s.rail_section = rail_section.empty() ? dynamics::uic60_outline() : rail_section;
  int threads = 1;  // the tables' frequencies (not in their keys: the values do not depend on it)
  problems.check(
      [&] { threads = resolved_threads(static_cast<int>(r.integer("solver.threads"))); });
  const acoustics::Fluid fluid = s.fluid;
  const std::vector<Eigen::Vector2d> outline = s.rail_section;
  const bool ground = s.rail_ground;
  s.rail_table = [outline, ground, fluid, threads](const std::vector<double>& grid) {
    return rail_radiation_cached(outline, ground, grid, fluid, threads);
  };
  s.section_table = [outline, ground, fluid, threads](double max_k) {
    return section_radiation_table_cached(outline, ground, max_k, fluid, threads);
  };
  if (!fe) {
    s.wheel_missing =
        "wheel.model = \"table\": the mode table has no wheel surface to radiate from; "
        "the wheel's sound power needs wheel.model = \"fe\"";
    return s;
  }
  if (fe->imported) {
    s.wheel_missing =
        "wheel.model = \"shapes\": imported modes along the tread have no section surface; "
        "the wheel's sound power needs wheel.model = \"fe\"";
    return s;
  }
  const WheelFeCase wheel = *fe;
  s.wheel_options = contact_options(wheel, dynamics::wheel_fe_tread(wheel.section, wheel.options));
  s.wheel_tread = [wheel] { return wheel_tread_modes(wheel); };
  const int n_min = s.wheel_options.n_min;
  s.wheel_table = [wheel, n_min, fluid, threads](const std::vector<double>& grid) {
    return wheel_radiation_cached(wheel, n_min, grid, fluid, wheel.mode_cache, threads);
  };
  return s;
}

}  // namespace rollnoise::io
