// The FE wheel's keys of a case ([wheel] model = "fe", docs/interface.md): the section file, the
// material, mesh and range options, modal damping by family and the rotation split, read and
// validated (errors name the key); and the modes, computed once per wheel in a process (a study's
// cases with equal section and options share them).
#pragma once

#include <memory>
#include <optional>
#include <string>

#include "dynamics/wheel_fe.hpp"
#include "io/case_reader.hpp"
#include "io/input_problems.hpp"

namespace rollnoise::io {

struct WheelFeCase {
  std::string section_file;  ///< as resolved
  dynamics::WheelSection section;
  dynamics::WheelFeOptions options;
  dynamics::WheelFeContactOptions contact;  ///< damping; spin_speed set from V / r0
  bool rotation_split = true;
  double rolling_speed = 0.0;  ///< V (m/s), for Omega = V / r0
  /// What the modes depend on (file as resolved, material, mesh, range): equal ids, equal modes.
  std::string id;
  /// wheel.model = "shapes": the user's modes as read (no section, no FE solve).
  std::shared_ptr<const dynamics::WheelFeModes> imported;
  /// wheel.mode_cache = "user": the contact path keeps the modes along the tread between runs
  /// (io/wheel_modes_cache.hpp).
  bool mode_cache = true;
};

/// The [wheel] FE keys (model = "fe") or the imported shapes (model = "shapes"); nullopt when
/// wheel.model = "table". Problems are recorded in `problems`.
std::optional<WheelFeCase> read_wheel_fe_case(const CaseReader& r, InputProblems& problems);

/// The modes of the case's wheel, computed at the first call for an id and shared afterwards.
std::shared_ptr<const dynamics::WheelFeModes> wheel_fe_modes_once(const WheelFeCase& c);

/// What the contact path needs of the modes, along the tread: as wheel_fe_modes_once, or, with
/// c.mode_cache, from the user's mode cache (no mesh and no section shapes then;
/// io/wheel_modes_cache.hpp), which a computation fills.
std::shared_ptr<const dynamics::WheelFeModes> wheel_tread_modes(const WheelFeCase& c);

/// The contact options of the case: Omega = V / r0 (r0 the tread radius at s = 0) when the split is
/// on.
dynamics::WheelFeContactOptions contact_options(const WheelFeCase& c,
                                                const dynamics::WheelFeModes& w);

/// The wheel model of the case's FE wheel: the rigid wheelset plus the FE modes with n >= 2 (modes
/// once per wheel) at the reference point s = 0 that follow the contact across the tread
/// (WheelModel::modes_at), damping and the +-n Omega split (Omega = V / r(0)) as the case says;
/// `id` receives what the model depends on besides the wheelset. With more than one thread
/// (solver.threads) the FE modes are computed on a thread of their own, started here, while the
/// caller goes on (a noise run solves its contact meanwhile): the model waits for them at their
/// first use, and an error of their computation is thrown there (WheelModel's `later` table). On
/// one thread, and for imported shapes, they are computed here, as before. The modes are the same
/// either way (the same computation, bit for bit).
dynamics::WheelModel fe_wheel_model(const WheelFeCase& c, const dynamics::RigidWheelset& wheelset);

}  // namespace rollnoise::io
