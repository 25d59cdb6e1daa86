#include "io/statespace_output.hpp"

#include <iomanip>

#include "io/creep_output.hpp"

namespace rollnoise::io {
namespace {

const char* kInputs = "xi_x, xi_y, phi, N";
const char* kInputUnits = "-, -, rad/m, N";
const char* kOutputs = "Fx, Fy, Mz";
const char* kOutputUnits = "N, N, N m";
const char* kConvention =
    "x' = A x + B u, y = C x + D u; u = (xi~x, xi~y, phi~, N~) [-, -, rad/m, N], y = (F~x, F~y, "
    "M~z) [N, N, N m] "
    "(variations about the mean state); C (sI - A)^-1 B + D at s = 2 pi i f equals [-f(f) | g(f)]";
const char* kDiscreteConvention =
    "x_{k+1} = Ad x_k + Bd u_k, y_k = Cd x_k + Dd u_k at t_k = k dt; u_k = (xi~x, xi~y, phi~, N~) "
    "at t_k (samples), y_k = (F~x, F~y, M~z) at t_k; D + C (zI - A)^-1 B at z = exp(i 2 pi f dt) "
    "equals [-f(f) | g(f)] over the band (to /statespace/discrete/response_error); the states: "
    "the recursion's (/statespace/discrete/recursion) and 3 copies of the sampling filter's";
const char* kRecursionConvention =
    "the linear NSS recursion alone: x_{k+1} = A x_k + B v_k, y_k = C x_k + D v_k, v_k = (the "
    "creepage of step k in input_sampling: xi~(t_k) (contact), xi~(t_k - dt/2) (midstep), the mean "
    "of xi~ over [t_k - dt, t_k] (average); N~(t_k)); D + C (zI - A)^-1 B at z = exp(i 2 pi f dt) "
    "equals [-f(f)/S(f) | g(f)], S the sampling's factor 1, exp(-i pi f dt), "
    "exp(-i pi f dt) sinc(pi f dt)";
const char* kDUnits =
    "(output i)/(input j): rows Fx [N], Fy [N], Mz [N m]; columns xi_x [-], xi_y [-], phi [rad/m], "
    "N [N]";

std::vector<double> row_major(const Eigen::MatrixXd& M) {
  std::vector<double> v;
  v.reserve(M.size());
  for (Eigen::Index i = 0; i < M.rows(); ++i)
    for (Eigen::Index j = 0; j < M.cols(); ++j) v.push_back(M(i, j));
  return v;
}

void write_matrix(Hdf5Writer& w, const std::string& path, const Eigen::MatrixXd& M,
                  const std::string& units) {
  w.write(path, row_major(M), {std::size_t(M.rows()), std::size_t(M.cols())}, units);
}

// A, B, C, D of a model under `group` with its names and units.
void write_model(Hdf5Writer& w, const std::string& group, const linalg::StateSpace& m,
                 const std::string& time_unit, const std::string& suffix) {
  write_matrix(w, group + "/A" + suffix, m.A,
               time_unit == "s" ? "1/s" : "- (state per state per step)");
  write_matrix(w, group + "/B" + suffix, m.B,
               time_unit == "s" ? "(state)/(input j)/s; C B in (output i)/(input j)/s"
                                : "(state)/(input j)");
  write_matrix(w, group + "/C" + suffix, m.C, "(output i)/(state): rows Fx [N], Fy [N], Mz [N m]");
  write_matrix(w, group + "/D" + suffix, m.D, kDUnits);
  w.attribute(group, "inputs", kInputs);
  w.attribute(group, "input_units", kInputUnits);
  w.attribute(group, "outputs", kOutputs);
  w.attribute(group, "output_units", kOutputUnits);
  w.attribute(group, "order", std::uint64_t(m.order()));
}

}  // namespace

pipeline::StateSpaceOptions read_statespace_options(const CaseReader& r) {
  pipeline::StateSpaceOptions o;
  o.tolerance = r.real("statespace.tolerance");
  if (!(o.tolerance < 1.0)) r.fail("statespace.tolerance", "must be below 1 (a relative error)");
  o.max_poles = static_cast<int>(std::min(r.integer("statespace.max_poles"), 400L));
  o.hankel_tolerance = r.real("statespace.hankel_tolerance");
  if (!(o.hankel_tolerance < 1.0))
    r.fail("statespace.hankel_tolerance", "must be below 1 (relative to the largest)");
  return o;
}

void write_statespace(Hdf5Writer& w, const CaseReader& r, const pipeline::StateSpaceResult& s) {
  write_creep(w, r, s.frequency, s.creep, false);
  const linalg::RationalFit& fit = s.fit;
  write_model(w, "/statespace", fit.model, "s", "");
  w.attribute("/statespace", "convention", kConvention);
  w.write("/statespace/fit_error", fit.error, "-");
  w.attribute("/statespace/fit_error", "norm",
              "max over the fitted frequencies (/creep/frequency) of |S (H_fit - H)|_F / |S H|_F, "
              "H = [-f | g], "
              "S H = diag(1/output_scale) H diag(1/input_scale) (equilibrated: every row and "
              "column peaks at 1)");
  w.write("/statespace/element_error", fit.element_error, "-");
  w.attribute("/statespace/element_error", "norm",
              "max over frequencies and entries of |H_fit,ij - H_ij| / max_f |H_ij|");
  w.write("/statespace/worst_frequency", fit.worst_frequency, "Hz");
  w.write("/statespace/target_met", fit.reached_target ? 1.0 : 0.0,
          "- (1: fit_error is at most statespace.tolerance)");
  w.write("/statespace/band", std::vector<double>{s.band_min, s.band_max}, {2}, "Hz");
  w.write("/statespace/output_scale",
          std::vector<double>(fit.scaling.output.data(), fit.scaling.output.data() + 3), {3},
          "N, N, N m");
  w.write("/statespace/input_scale",
          std::vector<double>(fit.scaling.input.data(), fit.scaling.input.data() + 4), {4},
          "(input j)^-1: -, -, m/rad, 1/N");
  w.write("/statespace/poles", fit.poles, {fit.poles.size()}, "1/s");
  w.write("/statespace/flipped_poles", double(fit.flipped), "-");

  write_model(w, "/statespace/discrete", s.discrete, "step", "");
  w.attribute("/statespace/discrete", "convention", kDiscreteConvention);
  w.attribute("/statespace/discrete", "dt", std::to_string(s.dt) + " s");
  w.write("/statespace/discrete/dt", s.dt, "s");
  w.write("/statespace/discrete/response_error", s.discrete_error,
          "- (against /creep/f, /creep/g, the norm of /statespace/fit_error)");
  w.write("/statespace/discrete/sampling_filter_error", s.sampling_filter_error,
          "- (max over /creep/frequency of |R(exp(i 2 pi f dt)) - S(f)|, S the sampling's factor)");
  w.write("/statespace/discrete/sampling_filter_peak_gain", s.sampling_filter_peak_gain,
          "- (max |R(exp(i 2 pi f dt))| from the band's top to the Nyquist limit; |S| <= 1)");
  w.write("/statespace/discrete/sampling_filter_order", double(s.sampling_filter.order()),
          "- (states per creepage input)");

  const linalg::Realisation& d = s.recursion;
  write_model(w, "/statespace/discrete/recursion", d.model, "step", "");
  w.attribute("/statespace/discrete/recursion", "convention", kRecursionConvention);
  w.attribute("/statespace/discrete/recursion", "input_sampling",
              contact::sampling_name(s.input_sampling));
  w.write("/statespace/discrete/recursion/hankel_singular_values",
          std::vector<double>(d.singular_values.data(),
                              d.singular_values.data() + d.singular_values.size()),
          {std::size_t(d.singular_values.size())}, "- (of the equilibrated Markov parameters)");
  w.write("/statespace/discrete/recursion/markov_parameters", double(s.markov_count),
          "- (realised)");
  w.write("/statespace/discrete/recursion/markov_error", d.markov_error, "-");
  w.write("/statespace/discrete/recursion/response_error", s.recursion_error,
          "- (times the sampling's factor, against /creep/f, /creep/g; the norm of "
          "/statespace/fit_error)");
}

std::vector<std::string> statespace_csv_paths(const std::string& prefix) {
  std::vector<std::string> p;
  for (const char* m : {"A", "B", "C", "D", "Ad", "Bd", "Cd", "Dd"})
    p.push_back(prefix + "_" + m + ".csv");
  return p;
}

std::vector<TemporaryFile> write_statespace_csv(const std::string& prefix,
                                                const pipeline::StateSpaceResult& s) {
  const std::vector<std::string> paths = statespace_csv_paths(prefix);
  const linalg::StateSpace& c = s.fit.model;
  const linalg::StateSpace& d = s.discrete;
  const Eigen::MatrixXd* mats[] = {&c.A, &c.B, &c.C, &c.D, &d.A, &d.B, &d.C, &d.D};
  std::vector<TemporaryFile> files;
  for (size_t i = 0; i < paths.size(); ++i)
    files.push_back(write_text_file(paths[i], "--csv", [&](std::ostream& out) {
      const Eigen::MatrixXd& M = *mats[i];
      out << std::setprecision(17);
      for (Eigen::Index a = 0; a < M.rows(); ++a) {
        for (Eigen::Index b = 0; b < M.cols(); ++b) out << (b ? "," : "") << M(a, b);
        out << "\n";
      }
    }));
  return files;
}

}  // namespace rollnoise::io
