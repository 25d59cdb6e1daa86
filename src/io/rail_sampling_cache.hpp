// The waveguide rail's frequency samplings kept between runs (track.sampling_cache = "user";
// docs/interface.md, "The rail's sampling cache").
//
// On a frequency grid the waveguide rail computes each set of coupled contact points directly at
// an adaptively chosen part of the grid (each frequency a wavenumber eigenproblem, ~2-20 ms) and
// interpolates the rest (dynamics/waveguide_frequency_sampling.hpp); on the discrete support that
// is most of a curve case's run time. What a run computes is kept in the user's cache directory
// (io/cache_files.hpp), one file per set of points and grid: the sampling and the values computed
// directly beside it (the refinement's lines), so a later run of the same rail at the same points
// on the same grid computes nothing and gives the same bits. The same for the values at complex
// frequencies that squeal's continuation asks for (one file per set of pairs: each s computed, by
// its bits), so a later run of the same squeal case computes no rail value. The key: this build,
// the model (support), the track file's and the section file's bytes, the contact position, then
// the points (offset, angle), the pairs and the grid as raw doubles. Any other case (another track,
// another contact point, another grid) computes as before.
#pragma once

#include <memory>
#include <optional>
#include <string>

#include "dynamics/waveguide_frequency_sampling.hpp"

namespace rollnoise::io {

/// Files of samplings in `directory` (dynamics::SamplingArchive).
class RailSamplingCache : public dynamics::SamplingArchive {
 public:
  explicit RailSamplingCache(std::string directory) : directory_(std::move(directory)) {}
  std::optional<dynamics::KeptSampling> read(const std::string& key) const override;
  void write(const std::string& key, const dynamics::KeptSampling& kept) const override;
  std::optional<dynamics::KeptLaplace> read_laplace(const std::string& key) const override;
  void write_laplace(const std::string& key, const dynamics::KeptLaplace& kept) const override;
  /// The file of a sampling's `key`, and of the values at complex s under `key`.
  std::string file(const std::string& key) const;
  std::string laplace_file(const std::string& key) const;

 private:
  std::string directory_;
};

/// The identity of a waveguide rail's samplings: this build, the track file's and the section
/// file's bytes (`section_file` empty: the built-in UIC60 outline) and the contact position;
/// empty when the build or a file cannot be read (then nothing is kept).
std::string rail_sampling_identity(const std::string& track_file, const std::string& section_file,
                                   double position);

}  // namespace rollnoise::io
