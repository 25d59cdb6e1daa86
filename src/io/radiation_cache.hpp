// The radiation tables kept between runs (docs/sound.md Sec. 5, docs/interface.md "The wheel's
// mode cache"): the wheel's modal radiation (pipeline::WheelRadiation) and the rail section's
// (pipeline::RailRadiation) depend only on the geometry, the modes, the air and the frequency grid,
// not on the case's contact. They go into the same cache directory as the wheel's modes, under the
// same rules (io/cache_files.hpp: keyed by this build, compared in full, best effort, written
// whole or not at all); ROLLNOISE_CACHE_DIR=off switches them off.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "dynamics/rail_model.hpp"
#include "io/wheel_fe_case.hpp"
#include "pipeline/sound_power.hpp"
#include "pipeline/sound_radiation.hpp"

namespace rollnoise::io {

/// The wheel's radiation on `grid`: from the cache, else computed (the FE modes with their mesh,
/// wheel_fe_modes_once) and stored. `cache`: wheel.mode_cache = "user".
std::shared_ptr<const pipeline::WheelRadiation> wheel_radiation_cached(
    const WheelFeCase& c, int n_min, const std::vector<double>& grid, const acoustics::Fluid& fluid,
    bool cache, int threads = 1);

/// The rail section's radiation on `grid`: from the cache, else computed and stored.
std::shared_ptr<const pipeline::RailRadiation> rail_radiation_cached(
    const std::vector<Eigen::Vector2d>& outline, bool ground, const std::vector<double>& grid,
    const acoustics::Fluid& fluid, int threads = 1);

/// What a rail's response along its length depends on, for the cache's key: `model` (the rail
/// model's identity: file, model, support, position, section) and every value of `track`, so that a
/// changed pad, support, spacing or damping never reads another track's values.
std::string rail_identity(const std::string& model, const dynamics::TrackParameters& track);

/// The rail's line Gram matrices (pipeline::rail_line_gram) at `positions` on `grid`: from the
/// cache under `identity` (rail_identity), else computed and stored. Kept in this process too.
std::shared_ptr<const pipeline::RailLineGram> rail_line_gram_cached(
    const dynamics::RailModel& rail, const std::string& identity,
    const std::vector<double>& positions, const std::vector<double>& grid, int gauss,
    int threads = 1);

/// The section's 2D power table up to max_k (pipeline::section_radiation_table): from the cache,
/// else computed and stored.
std::shared_ptr<const pipeline::SectionRadiationTable> section_radiation_table_cached(
    const std::vector<Eigen::Vector2d>& outline, bool ground, double max_k,
    const acoustics::Fluid& fluid, int threads = 1);

/// The section Gram matrices (R2) of loads at `points` on `grid` (pipeline::section_grams): from
/// the cache under `identity` (rail_identity), the points and the table's air and ground, else
/// computed and stored, those of the rail's load basis from basis_section_grams_cached (a later
/// run of the same case reads the points' own; another contact state at the same positions the
/// basis'). Kept in this process too.
std::vector<Eigen::MatrixXcd> section_grams_cached(
    const dynamics::RailModel& rail, const std::string& identity,
    const std::vector<dynamics::RailLoadPoint>& points,
    const pipeline::SectionRadiationTable& table, const std::vector<double>& grid,
    const acoustics::Fluid& fluid, int threads = 1);

/// The section Gram matrices (R2) of the rail's load basis at positions `x` on `grid`
/// (pipeline::basis_section_grams: the head's distributions, whatever the contacts' offsets and
/// angles): from the cache under `identity` (rail_identity), the positions and the table's air
/// and ground, else computed and stored. Kept in this process too.
std::vector<Eigen::MatrixXcd> basis_section_grams_cached(
    const dynamics::RailModel& rail, const std::string& identity, const std::vector<double>& x,
    const pipeline::SectionRadiationTable& table, const std::vector<double>& grid,
    const acoustics::Fluid& fluid, int threads = 1);

}  // namespace rollnoise::io
