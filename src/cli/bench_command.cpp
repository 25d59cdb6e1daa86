// rollnoise bench: run time against error under grid refinement for a Hertzian case.
// The study itself (what is measured on each grid, the errors, the half-step phase lead, the
// length of the transient runs) is pipeline/grid_study.hpp; the observed orders of convergence are
// linalg/convergence.hpp. This file reads the options, runs the grids, prints the tables and
// writes them to HDF5 (/bench/*, default CASENAME.bench.h5) and as CSV (postprocess/plot_bench.py draws it).
#include <cmath>
#include <cstdio>
#include <ostream>
#include <string>
#include <vector>

#include "cli/commands.hpp"
#include "cli/progress.hpp"
#include "core/errors.hpp"
#include "io/bench_output.hpp"
#include "io/contact_case.hpp"
#include "io/output_files.hpp"
#include "linalg/convergence.hpp"
#include "noise/kalker_linear.hpp"
#include "pipeline/grid_study.hpp"

namespace rollnoise::cli {
namespace {

// A tabulated error (io/bench_output.hpp): name, CSV column, printed header, values per grid.
using Quantity = io::BenchColumn;

}  // namespace

pipeline::GridStudyCase bench_study_case(const io::CaseReader& reader, const io::ContactCase& base) {
  pipeline::GridStudyCase c;
  c.material = base.material;
  c.normal_force = base.normal_force;
  c.a = base.a, c.b = base.b;
  c.scale = reader.real("grid.scale");
  c.steady = base.steady_input();
  c.backend = base.backend;
  c.tangential = base.tangential;
  c.sampling = base.sampling;
  return c;
}

namespace {

void print_header(const std::string& name, const pipeline::GridStudyCase& c, const pipeline::GridStudySettings& s,
                  const pipeline::GridStudyExcitation& e) {
  const contact::Creepage& m = c.steady.creepage;
  std::printf(
      "%s: grid refinement, mean creepage (%g, %g, %g rad/m); transient: variation "
      "(%g, %g, %g rad/m) at %g Hz for %.3g ms (%g contact lengths + %d periods, fitted over "
      "the periods)\n",
      name.c_str(), m.xi_x, m.xi_y, m.phi, e.amplitude[0], e.amplitude[1], e.amplitude[2],
      s.transient_frequency, e.duration * 1e3, s.settle_lengths, s.fit_periods);
}

std::vector<pipeline::GridMeasurement> measure_grids(const pipeline::GridStudyCase& c, const pipeline::GridStudySettings& s,
                                                const pipeline::GridStudyExcitation& e, const std::vector<int>& grids,
                                                bool quiet) {
  std::vector<pipeline::GridMeasurement> res;
  Progress progress("bench", long(grids.size()), quiet, "grids");
  for (int nx : grids) {
    res.push_back(pipeline::measure_grid(c, s, e, nx));
    progress.update(long(res.size()));
  }
  progress.finish();
  return res;
}

std::vector<Quantity> quantities(const pipeline::GridStudyErrors& err) {
  std::vector<Quantity> q = {{"steady forces (Fx, Fy)", "err_force_rel", "err F", &err.force},
                             {"steady Mz", "err_mz_rel", "err Mz", &err.mz}};
  const char* fname[] = {"100Hz", "1kHz", "5kHz"};
  const char* fpretty[] = {"100 Hz", "1 kHz", "5 kHz"};
  for (size_t i = 0; i < err.f.size(); ++i) {
    q.push_back({std::string("f11/f22/f23 at ") + fpretty[i], std::string("err_f_") + fname[i] + "_rel",
                 std::string("f ") + fname[i], &err.f[i]});
    q.push_back({std::string("f11/f22 at ") + fpretty[i] + ", phase-corrected",
                 std::string("err_f11f22_") + fname[i] + "_pc_rel", i == 1 ? "f11/22 1k*" : "",
                 &err.f_direct_corrected[i]});
    q.push_back({std::string("f23 at ") + fpretty[i], std::string("err_f23_") + fname[i] + "_rel",
                 i == 1 ? "f23 1kHz" : "", &err.f23[i]});
  }
  q.push_back({"transient (Fx, Fy) at 1 kHz", "err_transient_rel", "transient", &err.transient});
  q.push_back({"transient, phase-corrected", "err_transient_pc_rel", "transient*", &err.transient_corrected});
  q.push_back({"C11 (against the finest grid)", "err_C11_rel", "", &err.c11});
  return q;
}

void print_grids(const std::vector<pipeline::GridMeasurement>& res, const pipeline::GridStudyErrors& err,
                 const pipeline::GridStudySettings& s, const io::ContactCase& base, double c11_table) {
  std::printf("%5s %5s %8s %7s %10s %10s %10s %6s %8s %9s\n", "nx", "ny", "dx [mm]", "contact",
              "steady [s]", "creep [s]", "trans. [s]", "steps", "C11", "err C11");
  for (size_t i = 0; i < res.size(); ++i) {
    const pipeline::GridMeasurement& r = res[i];
    std::printf("%5d %5d %8.4f %7d %10.3f %10.3f %10.3f %6ld %8.4f %9.2e\n", r.nx, r.ny, r.dx * 1e3,
                r.contact, r.t_steady, r.t_creep, r.t_transient, r.steps, r.c11, err.c11_table[i]);
  }
  std::printf(
      "  (steady: normal + steady problem; creep: linear model set-up + f at %g, %g, %g Hz; "
      "trans.: %g contact lengths + %d periods of unsteady rolling; err C11: against "
      "Kalker's table, %.4f at a/b = %.3f, nu = %.2f)\n",
      s.frequencies[0], s.frequencies[1], s.frequencies[2], s.settle_lengths, s.fit_periods, c11_table,
      base.a / base.b, base.material.nu);
}

void print_errors(const std::vector<pipeline::GridMeasurement>& res, const pipeline::GridStudyErrors& err,
                  const std::vector<Quantity>& quantities, const pipeline::GridStudySettings& s) {
  std::printf("%5s", "nx");
  for (const auto& q : quantities)
    if (!q.header.empty()) std::printf(" %10s", q.header.c_str());
  std::printf(" %10s\n", "tr-lin");
  for (size_t i = 0; i < res.size(); ++i) {
    std::printf("%5d", res[i].nx);
    for (const auto& q : quantities)
      if (!q.header.empty()) std::printf(" %10.2e", (*q.err)[i]);
    std::printf(" %10.2e\n", err.transient_vs_linear[i]);
  }
  std::printf(
      "  (relative errors against the finest grid; f: largest of f11, f22, f23; transient: complex "
      "amplitudes of Fx, Fy at %g Hz; *: phase-corrected by w dt/2; tr-lin: transient against the "
      "linear model -f(w) xi^ on the same grid; fit window error %.1e)\n",
      s.transient_frequency, err.window_error);
}

void print_orders(const std::vector<pipeline::GridMeasurement>& res, const pipeline::GridStudyErrors& err,
                  const std::vector<Quantity>& quantities) {
  if (res.size() < 3) return;
  const pipeline::GridMeasurement& ref = res.back();
  std::printf("observed order of convergence, fitting err = C (dx^p - dx_%d^p) to grids %d..%d:\n", ref.nx,
              res[0].nx, res[res.size() - 2].nx);
  const std::string own = "own error " + std::to_string(ref.nx) + "x" + std::to_string(ref.ny);
  std::printf("  %-36s %6s %8s %18s\n", "", "order", "scatter", own.c_str());
  for (const auto& q : quantities) {
    const linalg::ObservedOrder o = linalg::observed_order(err.dx, *q.err);
    std::printf("  %-36s %6.2f %8.2f %18.2e\n", q.name.c_str(), o.p, o.scatter, o.error_at(ref.dx));
  }
}

void write_table(std::ostream& out, const std::string& case_file, const std::vector<pipeline::GridMeasurement>& res,
                 const pipeline::GridStudyErrors& err, const std::vector<Quantity>& quantities,
                 const pipeline::GridStudySettings& s, double c11_table) {
  out << "# rollnoise bench " << case_file << ": errors relative to the finest grid (nx = " << res.back().nx
      << "); err_C11_kalker against Kalker's table (" << c11_table
      << "); err_f: largest of f11, f22, f23; err_transient: complex amplitudes of Fx, Fy at "
      << s.transient_frequency
      << " Hz; _pc: phase-corrected by w dt/2; times in s (t_steady: normal + steady problem, "
         "t_C11: normal + C11 solve)\n";
  out << "nx,ny,dx_m,contact_elements,t_steady_s,t_creep_s,t_transient_s,t_C11_s,"
         "transient_steps,Fx_N,Fy_N,Mz_Nm,C11,err_C11_kalker_rel";
  for (const auto& q : quantities) out << "," << q.column;
  out << ",err_transient_vs_linear_rel\n";
  out.precision(8);
  for (size_t i = 0; i < res.size(); ++i) {
    const pipeline::GridMeasurement& r = res[i];
    out << r.nx << "," << r.ny << "," << r.dx << "," << r.contact << "," << r.t_steady << "," << r.t_creep
        << "," << r.t_transient << "," << r.t_normal + r.t_kalker << "," << r.steps << "," << r.force(0)
        << "," << r.force(1) << "," << r.force(2) << "," << r.c11 << "," << err.c11_table[i];
    for (const auto& q : quantities) out << "," << (*q.err)[i];
    out << "," << err.transient_vs_linear[i] << "\n";
  }
}

// The table as CSV, written atomically (io/output_files.hpp).
void write_csv(const std::string& csv, const std::string& case_file, const std::vector<pipeline::GridMeasurement>& res,
               const pipeline::GridStudyErrors& err, const std::vector<Quantity>& quantities,
               const pipeline::GridStudySettings& s, double c11_table) {
  io::write_text_file(csv, "--csv", [&](std::ostream& out) {
    write_table(out, case_file, res, err, quantities, s, c11_table);
  }).commit();
  const std::string png =
      (csv.size() > 4 && csv.substr(csv.size() - 4) == ".csv" ? csv.substr(0, csv.size() - 4) : csv) + ".png";
  std::printf("wrote %s\ndraw it (from the source tree): /usr/bin/python3 postprocess/plot_bench.py %s -o %s\n",
              csv.c_str(), csv.c_str(), png.c_str());
}

// ---- The creepage-sampling study (rolling.creepage_sampling, docs/accuracy.md): per grid the time
// of a sweep of settings.sweep_count frequencies and the errors of f11, f22, f23 at the accuracy
// frequencies against the grid-converged f, for every sampling (pipeline::sampling_accuracy). ----

constexpr int kSamplings = static_cast<int>(pipeline::kStudySamplings.size());
const char* sampling_label(int sm) { return contact::sampling_name(pipeline::kStudySamplings[sm]); }

std::string frequency_label(double f) {
  char text[32];
  std::snprintf(text, sizeof text, f >= 1000.0 ? "%gkHz" : "%gHz", f >= 1000.0 ? f / 1000.0 : f);
  return text;
}

// The error columns of the sampling study (pointers into `a`).
std::vector<Quantity> sampling_columns(const pipeline::SamplingAccuracy& a, const pipeline::GridStudySettings& s) {
  const char* entry[3] = {"f11", "f22", "f23"};
  std::vector<Quantity> q;
  for (int sm = 0; sm < kSamplings; ++sm)
    for (size_t i = 0; i < s.accuracy_frequencies.size(); ++i)
      for (int e = 0; e < 3; ++e) {
        const std::string f = frequency_label(s.accuracy_frequencies[i]);
        q.push_back({std::string(entry[e]) + " at " + f + ", " + sampling_label(sm) +
                         " sampling, against the grid-converged f",
                     std::string("err_") + entry[e] + "_" + f + "_" + sampling_label(sm) + "_rel",
                     std::string(entry[e]) + " " + f, &a.error[sm][i][e]});
      }
  return q;
}

void print_sampling_accuracy(const std::vector<pipeline::GridMeasurement>& res, const pipeline::SamplingAccuracy& a,
                             const std::vector<Quantity>& columns, const pipeline::GridStudySettings& s) {
  std::printf("creepage sampling: errors of f against the grid-converged f (Richardson on the three finest grids of "
              "the second-order sampling with the smaller estimated error):\n");
  for (size_t i = 0; i < s.accuracy_frequencies.size(); ++i) {
    const auto& c = a.converged[i];
    std::printf("  %s: f11 = %.5g %+.5gi N (+- %.1e), f22 = %.5g %+.5gi N (+- %.1e), f23 = %.5g %+.5gi N m; "
                "from %s, orders %.2f %.2f %.2f\n",
                frequency_label(s.accuracy_frequencies[i]).c_str(), c(0, 0).real(), c(0, 0).imag(),
                a.converged_error[i](0, 0) / std::abs(c(0, 0)), c(1, 1).real(), c(1, 1).imag(),
                a.converged_error[i](1, 1) / std::abs(c(1, 1)), c(1, 2).real(), c(1, 2).imag(),
                sampling_label(a.reference[i]), a.order[i](0), a.order[i](1), a.order[i](2));
    for (int sm = 0; sm < kSamplings; ++sm)
      if (sm != a.reference[i])
        std::printf("      %s-sampling extrapolation differs by %.1e %.1e %.1e\n", sampling_label(sm),
                    a.spread[sm][i](0), a.spread[sm][i](1), a.spread[sm][i](2));
  }
  const size_t per = columns.size() / kSamplings;
  for (int sm = 0; sm < kSamplings; ++sm) {
    std::printf("%8s %5s %9s", sampling_label(sm), "ny", "sweep [s]");
    for (size_t q = 0; q < per; ++q) std::printf(" %10s", columns[sm * per + q].header.c_str());
    std::printf("\n");
    for (size_t g = 0; g < res.size(); ++g) {
      std::printf("%8d %5d %9.3f", res[g].nx, res[g].ny, res[g].sampling[sm].seconds);
      for (size_t q = 0; q < per; ++q) std::printf(" %10.2e", (*columns[sm * per + q].err)[g]);
      std::printf("\n");
    }
  }
  std::printf("  (sweep: linear model set-up + f at %d frequencies over [100 Hz, 5 kHz]; relative errors, NaN above "
              "Nyquist)\n",
              s.sweep_count);
}

}  // namespace

int run_bench(const CommonOptions& o, const std::vector<int>& grids, const std::string& csv) {
  const io::CaseReader reader = io::CaseReader::from_file(o.case_file, o.overrides);
  const io::ContactCase base = io::read_contact_case(reader);
  if (base.geometry != "hertz") reader.fail("contact.geometry", "bench needs a Hertzian case");
  const pipeline::GridStudyCase study = bench_study_case(reader, base);
  pipeline::check_study_grids(study, grids);  // before any solve
  const pipeline::GridStudySettings settings;
  const pipeline::GridStudyExcitation excitation = pipeline::grid_study_excitation(study, settings);

  print_header(reader.name(), study, settings, excitation);
  const std::vector<pipeline::GridMeasurement> res = measure_grids(study, settings, excitation, grids, o.quiet);
  const double c11_table = noise::kalker_coefficients(base.a / base.b, base.material.nu).C11;
  const pipeline::GridStudyErrors err = pipeline::grid_study_errors(res, settings, base.speed, c11_table, study.sampling);
  const std::vector<Quantity> table = quantities(err);

  print_grids(res, err, settings, base, c11_table);
  print_errors(res, err, table, settings);
  print_orders(res, err, table);
  const pipeline::SamplingAccuracy sampling = pipeline::sampling_accuracy(res, settings);
  const std::vector<Quantity> sampling_table = sampling_columns(sampling, settings);
  print_sampling_accuracy(res, sampling, sampling_table, settings);
  std::vector<Quantity> csv_columns = table;
  csv_columns.insert(csv_columns.end(), sampling_table.begin(), sampling_table.end());
  std::vector<Quantity> columns = csv_columns;
  columns.push_back({"C11 against Kalker's table", "err_C11_kalker_rel", "", &err.c11_table});
  columns.push_back({"transient against the linear model on the same grid", "err_transient_vs_linear_rel", "",
                     &err.transient_vs_linear});
  const std::string out = output_path(o, reader.name());
  io::Hdf5Writer w(out);
  io::write_bench(w, reader, res, columns, c11_table);
  io::write_bench_sampling(w, res, sampling, settings.accuracy_frequencies);
  w.commit();
  std::printf("wrote %s\n", out.c_str());
  if (csv.empty())
    std::printf("(--csv FILE writes the table; postprocess/plot_bench.py FILE draws it)\n");
  else
    write_csv(csv, o.case_file, res, err, csv_columns, settings, c11_table);
  return 0;
}

}  // namespace rollnoise::cli
