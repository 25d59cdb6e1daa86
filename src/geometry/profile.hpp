// Wheel and rail profiles: the cross-section of the running surface as a smooth function z(y).
//
// Profile frame (the frame of the Manchester-benchmark point files after their processing flags,
// see docs/geometry.md): y lateral, positive towards the field side (away from the track centre),
// z positive downwards, metres. For a rail z is the depth of the running surface below the profile
// origin; for a wheel z is the increase of the wheel radius over the nominal rolling radius, which
// the wheel has at y = 0 (the taping line). Both are the profiles of the right wheel and right rail
// in the track frame x forward, y to the right, z down.
//
// Interpolation: Steffen's monotone piecewise cubic (M. Steffen, Astron. Astrophys. 239 (1990)
// 443-450; gsl_interp_steffen). It is C1, reproduces monotone data without overshoot (no ringing at
// the steep flange and rail-corner segments), and its slopes are second-order accurate. Its second
// derivative is only piecewise continuous (it jumps at the knots), so curvatures for Hertz's theory
// are taken from a least-squares parabola over a window of the spline (Profile::curvature).
//
// A Profile is built from its points; the profile files (SIMPACK point files, CSV) are read by
// io/profile_file.hpp.
#pragma once

#include <memory>
#include <string>
#include <vector>

namespace rollnoise::geometry {

enum class ProfileKind { Rail, Wheel };

const char* to_string(ProfileKind kind);

class Profile {
 public:
  /// Points (y, z) in metres in the profile frame; y strictly increasing, at least
  /// Profile::min_points of them, all finite. `canted`: a rail profile that already includes the
  /// rail inclination (it is then not rotated again by the track geometry).
  /// Throws InputError (key `source`) for invalid points.
  Profile(std::vector<double> y, std::vector<double> z, ProfileKind kind, std::string source = "",
          bool canted = false);

  static constexpr int min_points = 4;

  ProfileKind kind() const { return kind_; }
  const std::string& source() const { return source_; }
  bool canted() const { return canted_; }
  const std::vector<double>& y_points() const { return y_; }
  const std::vector<double>& z_points() const { return z_; }
  double y_min() const { return y_.front(); }
  double y_max() const { return y_.back(); }
  bool contains(double y) const { return y >= y_.front() && y <= y_.back(); }

  /// z(y) (m). Outside [y_min, y_max] the end tangent is extrapolated linearly.
  double z(double y) const;

  /// A search hint for a run of evaluations at nearby y (a scan along the profile): the knot
  /// interval of the last evaluation, tried first before the binary search. The interval found is
  /// the one the search finds, so z(y, cursor) == z(y) to the bit. One cursor per thread.
  struct Cursor {
    std::size_t interval = 0;
  };
  double z(double y, Cursor& cursor) const;
  /// dz/dy (-).
  double slope(double y) const;
  /// d2z/dy2 of the Steffen spline (1/m): piecewise linear, discontinuous at the knots.
  double second_derivative(double y) const;
  /// d2z/dy2 smoothed: twice the quadratic coefficient of the least-squares parabola through the
  /// spline sampled on [y - half_window, y + half_window] (1/m). For a parabola it is exact.
  double smoothed_second_derivative(double y, double half_window = 1e-3) const;
  /// Signed curvature of the profile curve, kappa = z'' / (1 + z'^2)^(3/2) with the smoothed z''
  /// (1/m). Positive when z is convex in y: a rail crown, a hollow (concave) wheel tread.
  double curvature(double y, double half_window = 1e-3) const;

  /// The same profile with its points rotated about the profile origin by `angle` (rad,
  /// positive from +y towards +z) and resampled as a function of y. Used to cant a rail.
  Profile rotated(double angle) const;

 private:
  struct Spline;
  std::vector<double> y_, z_;
  ProfileKind kind_;
  std::string source_;
  bool canted_ = false;
  std::shared_ptr<const Spline> spline_;
};

}  // namespace rollnoise::geometry
