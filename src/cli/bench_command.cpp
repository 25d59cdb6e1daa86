// rollnoise bench: run time against error under grid refinement for a Hertzian case (issue 7).
//
// For each grid (nx elements in x, ny = nx b/a rounded, the case's grid.scale) it times and
// measures: the steady forces at the case's mean creepage; f11, f22, f23 at 100 Hz, 1 kHz and 5 kHz
// (fast sweep; NaN above the grid's Nyquist limit); and Kalker's C11 in the full-adhesion limit
// (creepage 1e-6) against his table. Errors are relative to the finest grid (and to Kalker's table
// for C11). Prints the table with the observed orders of convergence and writes it as CSV.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <sstream>

#include "cli/commands.hpp"
#include "contact/forces.hpp"
#include "contact/hertz.hpp"
#include "contact/patch.hpp"
#include "contact/steady_rolling.hpp"
#include "core/errors.hpp"
#include "io/contact_case.hpp"
#include "noise/kalker_linear.hpp"
#include "nss/linear_model.hpp"

namespace rollnoise::cli {
namespace {

using Clock = std::chrono::steady_clock;
double seconds(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }
const double kNaN = std::numeric_limits<double>::quiet_NaN();

struct GridResult {
  int nx = 0, ny = 0, contact = 0;
  double dx = 0.0;
  double t_steady = 0.0, t_creep = 0.0, t_kalker = 0.0;
  Eigen::Vector3d force = Eigen::Vector3d::Zero();
  std::vector<nss::CreepMatrix> f;  // at kFreq
  double c11 = 0.0;
};

const std::vector<double> kFreq = {100.0, 1000.0, 5000.0};

}  // namespace

int run_bench(const CommonOptions& o, const std::vector<int>& grids, const std::string& csv) {
  const io::CaseReader reader = io::CaseReader::from_file(o.case_file, o.overrides);
  const io::ContactCase base = io::read_contact_case(reader);
  if (base.geometry != "hertz") reader.fail("contact.geometry", "bench needs a Hertzian case");
  const double scale = reader.real("grid.scale");
  const contact::HertzContact hz = contact::hertz_from_semi_axes(base.a, base.b, base.normal_force, base.material);
  std::vector<GridResult> res;
  std::printf("%s: grid refinement, mean creepage (%g, %g, %g rad/m)\n", reader.name().c_str(),
              base.creepage.xi_x, base.creepage.xi_y, base.creepage.phi);
  for (int nx : grids) {
    GridResult r;
    r.nx = nx;
    r.ny = std::max(4, static_cast<int>(std::lround(nx * base.b / base.a)));
    // coarse grids need a wider margin around the ellipse (at least ~1.25 elements each side)
    const double s_i = std::max(scale, 1.0 + 2.5 / std::min(r.nx, r.ny));
    const contact::Grid g = contact::Grid::around_ellipse(r.nx, r.ny, base.a, base.b, s_i);
    r.dx = g.dx;
    auto t = Clock::now();
    const contact::ContactPatch patch =
        contact::solve_patch(g, base.material, contact::quadratic_distance(g, hz.A, hz.B), base.normal_force);
    const auto s = contact::solve_steady_rolling(patch.influence, patch.normal.pn, base.steady_input(), base.tangential);
    r.t_steady = seconds(t);
    r.contact = patch.normal.contact_elements();
    const auto F = contact::total_forces(g, s.px, s.py);
    r.force << F.Fx, F.Fy, F.Mz;
    t = Clock::now();
    const nss::LinearContactModel m(patch, s, {base.mu, base.speed, base.spin_offset});
    std::vector<double> ok;
    for (double f : kFreq)
      if (f <= m.nyquist_frequency()) ok.push_back(f);
    const auto fk = m.creep_coefficients(ok);
    r.t_creep = seconds(t);
    for (size_t i = 0; i < kFreq.size(); ++i)
      r.f.push_back(i < fk.size() ? fk[i] : nss::CreepMatrix::Constant(kNaN));
    t = Clock::now();
    contact::SteadyRollingInput lin = base.steady_input();
    lin.creepage = {1e-6, 0.0, 0.0};
    const auto sk = contact::solve_steady_rolling(patch.influence, patch.normal.pn, lin, base.tangential);
    const double G = base.material.shear_modulus();
    r.c11 = -contact::total_forces(g, sk.px, sk.py).Fx / (G * base.a * base.b * 1e-6);
    r.t_kalker = seconds(t);
    res.push_back(std::move(r));
    std::fprintf(stderr, "  %d x %d done\n", res.back().nx, res.back().ny);
  }
  const GridResult& ref = res.back();
  const double c11_table = noise::kalker_coefficients(base.a / base.b, base.material.nu).C11;
  auto ferr = [&](const GridResult& r) {  // max relative error of f11, f22, f23 over kFreq
    double e = 0.0;
    for (size_t i = 0; i < kFreq.size(); ++i)
      for (auto [j, k] : {std::pair{0, 0}, std::pair{1, 1}, std::pair{1, 2}}) {
        const double d = std::abs(r.f[i](j, k) - ref.f[i](j, k)) / std::abs(ref.f[i](j, k));
        if (std::isfinite(d)) e = std::max(e, d);
      }
    return e;
  };
  std::ostringstream table;
  table << "nx,ny,dx_m,contact_elements,t_steady_s,t_creep_s,err_force_rel,err_mz_rel,err_creep_rel,"
           "C11,err_C11_kalker_rel\n";
  std::printf("%5s %5s %9s %7s %10s %10s %11s %11s %11s %8s %11s\n", "nx", "ny", "dx [mm]", "contact",
              "steady [s]", "creep [s]", "err F", "err Mz", "err f_jk", "C11", "err C11");
  std::vector<double> ef;
  for (const auto& r : res) {
    const double e_f = (r.force.head<2>() - ref.force.head<2>()).norm() / ref.force.head<2>().norm();
    const double e_m = std::abs(r.force(2) - ref.force(2)) / std::abs(ref.force(2));
    const double e_c = ferr(r), e_k = std::abs(r.c11 / c11_table - 1);
    ef.push_back(e_f);
    std::printf("%5d %5d %9.4f %7d %10.3f %10.3f %11.3e %11.3e %11.3e %8.4f %11.3e\n", r.nx, r.ny, r.dx * 1e3,
                r.contact, r.t_steady, r.t_creep, e_f, e_m, e_c, r.c11, e_k);
    table << r.nx << "," << r.ny << "," << r.dx << "," << r.contact << "," << r.t_steady << "," << r.t_creep << ","
          << e_f << "," << e_m << "," << e_c << "," << r.c11 << "," << e_k << "\n";
  }
  // observed order from the errors against the finest grid (all but the finest two)
  if (res.size() >= 4) {
    const size_t a = 0, b = res.size() - 3;
    const double p = std::log(ef[a] / ef[b]) / std::log(res[a].dx / res[b].dx);
    std::printf("observed order of convergence of the steady forces (grids %d..%d against %d): %.2f\n", res[a].nx,
                res[b].nx, ref.nx, p);
  }
  std::printf("Kalker's C11 at a/b = %.3f, nu = %.2f: %.4f\n", base.a / base.b, base.material.nu, c11_table);
  if (!csv.empty()) {
    std::ofstream out(csv);
    if (!out) throw InputError("--csv", "cannot write " + csv);
    out << "# rollnoise bench " << o.case_file << ": errors against the finest grid (nx = " << ref.nx
        << "); err_C11_kalker against Kalker's table; times in s\n"
        << table.str();
    std::printf("wrote %s\n", csv.c_str());
  }
  return 0;
}

}  // namespace rollnoise::cli
