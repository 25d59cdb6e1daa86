#include "io/wheel_fe_case.hpp"

#include <cstdio>
#include <future>
#include <map>
#include <mutex>

#include "core/errors.hpp"
#include "core/task_pool.hpp"
#include "io/tread_shapes_file.hpp"
#include "io/wheel_modes_cache.hpp"
#include "io/wheel_section_file.hpp"

namespace rollnoise::io {

namespace {

// Keys that only one model uses: an error with another.
void check_unused_keys(const CaseReader& r, const std::string& model, InputProblems& problems) {
  const auto refuse = [&](const char* key, const char* used_with) {
    problems.check([&] {
      if (r.has(key)) r.fail(key, std::string("only used with wheel.model = ") + used_with);
    });
  };
  if (model != "fe")
    for (const char* key :
         {"wheel.section", "wheel.bore", "wheel.youngs_modulus", "wheel.poisson_ratio",
          "wheel.density", "wheel.mesh_size", "wheel.n_max", "wheel.f_max", "wheel.mode_cache"})
      refuse(key, "\"fe\"");
  if (model == "table")
    for (const char* key :
         {"wheel.damping_n0", "wheel.damping_n1", "wheel.damping_axial", "wheel.damping_radial",
          "wheel.damping_circumferential", "wheel.rotation"})
      refuse(key, "\"fe\" or \"shapes\"");
  if (model != "shapes") refuse("wheel.shapes", "\"shapes\"");
}

void read_damping_and_rotation(const CaseReader& r, InputProblems& problems, WheelFeCase& c) {
  auto& d = c.contact.damping;
  problems.check([&] { d.n0 = r.real("wheel.damping_n0"); });
  problems.check([&] { d.n1 = r.real("wheel.damping_n1"); });
  problems.check([&] { d.axial = r.real("wheel.damping_axial"); });
  problems.check([&] { d.radial = r.real("wheel.damping_radial"); });
  problems.check([&] { d.circumferential = r.real("wheel.damping_circumferential"); });
  for (const char* key : {"wheel.damping_n0", "wheel.damping_n1", "wheel.damping_axial",
                          "wheel.damping_radial", "wheel.damping_circumferential"})
    problems.check([&] {
      if (r.real(key) >= 1.0) r.fail(key, "a modal damping ratio must be below 1");
    });
  problems.check([&] { c.rotation_split = r.string("wheel.rotation") == "split"; });
  problems.check([&] { c.rolling_speed = r.real("rolling.speed"); });
}

}  // namespace

std::optional<WheelFeCase> read_wheel_fe_case(const CaseReader& r, InputProblems& problems) {
  std::string model = "table";
  problems.check([&] { model = r.string("wheel.model"); });
  check_unused_keys(r, model, problems);
  if (model == "table") return std::nullopt;
  WheelFeCase c;
  read_damping_and_rotation(r, problems, c);
  if (model == "shapes") {
    problems.check([&] {
      if (!r.has("wheel.shapes")) r.fail("wheel.shapes", "required with wheel.model = \"shapes\"");
      c.section_file = resolve_model_file(r, "wheel.shapes");
      c.imported =
          std::make_shared<const dynamics::WheelFeModes>(read_tread_shapes(c.section_file));
    });
    c.id = "imported wheel shapes " + c.section_file;
    return c;
  }
  problems.check([&] {
    c.section_file = resolve_model_file(r, "wheel.section");
    c.section = read_wheel_section(c.section_file);
  });
  // the bore: "clamped" is the only value (the schema's allowed list rejects any other)
  problems.check([&] { r.string("wheel.bore"); });
  auto& m = c.options.material;
  problems.check([&] { m.youngs_modulus = r.real("wheel.youngs_modulus"); });
  problems.check([&] {
    m.poisson_ratio = r.real("wheel.poisson_ratio");
    if (!(m.poisson_ratio > -1.0 && m.poisson_ratio < 0.5))
      r.fail("wheel.poisson_ratio", "must lie in (-1, 0.5)");
  });
  problems.check([&] { m.density = r.real("wheel.density"); });
  problems.check([&] {
    c.options.mesh_size = r.real("wheel.mesh_size");
    if (c.options.mesh_size > 0.1)
      r.fail("wheel.mesh_size", "above 0.1 m leaves a wheel section unresolved");
  });
  problems.check([&] { c.options.n_max = static_cast<int>(r.integer("wheel.n_max")); });
  problems.check([&] { c.options.f_max = r.real("wheel.f_max"); });
  problems.check([&] { c.mode_cache = r.string("wheel.mode_cache") == "user"; });
  // the orders' threads (not in the id: the modes do not depend on them)
  problems.check([&] { c.options.threads = static_cast<int>(r.integer("solver.threads")); });
  char text[200];
  std::snprintf(text, sizeof text, ", E %.17g, nu %.17g, rho %.17g, h %.17g, n_max %d, f_max %.17g",
                m.youngs_modulus, m.poisson_ratio, m.density, c.options.mesh_size, c.options.n_max,
                c.options.f_max);
  c.id = "fe wheel " + c.section_file + text;
  return c;
}

std::shared_ptr<const dynamics::WheelFeModes> wheel_fe_modes_once(const WheelFeCase& c) {
  if (c.imported) return c.imported;
  static std::mutex mutex;
  static std::map<std::string, std::shared_ptr<const dynamics::WheelFeModes>> computed;
  std::lock_guard<std::mutex> lock(mutex);
  auto& slot = computed[c.id];
  if (!slot)
    slot = std::make_shared<const dynamics::WheelFeModes>(
        dynamics::wheel_fe_modes(c.section, c.options));
  return slot;
}

std::shared_ptr<const dynamics::WheelFeModes> wheel_tread_modes(const WheelFeCase& c) {
  if (c.imported || !c.mode_cache) return wheel_fe_modes_once(c);
  // one process, one wheel: the first caller reads (or computes and stores) them, the others share
  static std::mutex mutex;
  static std::map<std::string, std::shared_ptr<const dynamics::WheelFeModes>> read;
  std::lock_guard<std::mutex> lock(mutex);
  auto& slot = read[c.id];
  if (slot) return slot;
  const std::optional<std::string> directory = mode_cache_directory();
  const std::string key = directory ? mode_cache_key(c) : std::string{};
  if (!key.empty())
    if (std::optional<dynamics::WheelFeModes> cached = read_cached_modes(*directory, key))
      return slot = std::make_shared<const dynamics::WheelFeModes>(std::move(*cached));
  slot = wheel_fe_modes_once(c);
  if (!key.empty()) write_cached_modes(*directory, key, *slot);
  return slot;
}

dynamics::WheelFeContactOptions contact_options(const WheelFeCase& c,
                                                const dynamics::WheelFeModes& w) {
  dynamics::WheelFeContactOptions o = c.contact;
  o.spin_speed = c.rotation_split ? c.rolling_speed / dynamics::tread_radius_at(w, 0.0) : 0.0;
  return o;
}

dynamics::WheelModel fe_wheel_model(const WheelFeCase& c, const dynamics::RigidWheelset& wheelset) {
  // Omega = V / r(0) needs the tread samples only, which do not need the modes
  const dynamics::WheelFeContactOptions o =
      contact_options(c, c.imported ? *c.imported : dynamics::wheel_fe_tread(c.section, c.options));
  if (c.imported || resolved_threads(c.options.threads) == 1) {  // the modes now, on this thread
    const std::shared_ptr<const dynamics::WheelFeModes> modes = wheel_tread_modes(c);
    return dynamics::WheelModel(
        wheelset, dynamics::contact_mode_table(*modes, 0.0, o),
        [modes, o](double shift_y) { return dynamics::contact_mode_table(*modes, shift_y, o); });
  }
  // The modes on a thread of their own (gmsh's loading and the meshing and assembly are serial:
  // the caller's work runs beside them). The future's last copy joins that thread when the model
  // is destroyed without having used them (an error elsewhere in the case).
  using Later = std::shared_future<std::shared_ptr<const dynamics::WheelFeModes>>;
  const Later modes = std::async(std::launch::async, [c] { return wheel_tread_modes(c); }).share();
  std::shared_future<std::vector<dynamics::WheelMode>> table =
      std::async(std::launch::deferred, [modes, o] {
        return dynamics::contact_mode_table(*modes.get(), 0.0, o);
      }).share();
  return dynamics::WheelModel(wheelset, std::move(table), [modes, o](double shift_y) {
    return dynamics::contact_mode_table(*modes.get(), shift_y, o);
  });
}

}  // namespace rollnoise::io
