#include "pipeline/corrugation.hpp"

#include <algorithm>
#include <cmath>

#include "core/constants.hpp"
#include "core/errors.hpp"
#include "core/stopwatch.hpp"
#include "core/task_pool.hpp"
#include "noise/loop.hpp"

namespace rollnoise::pipeline {

std::vector<double> corrugation_wavelengths(const CorrugationCase& cc) {
  std::vector<double> lambda(cc.points);
  const double lo = std::log(cc.wavelength_min), hi = std::log(cc.wavelength_max);
  for (int i = 0; i < cc.points; ++i)
    lambda[i] =
        cc.points == 1 ? cc.wavelength_max : std::exp(hi + (lo - hi) * i / double(cc.points - 1));
  return lambda;
}

namespace {

// Stage 2: the noise loop on the wavelengths' frequencies; the Nyquist check names the
// corrugation's key.
NoiseResult corrugation_loop(ContactCase c, const NoiseCase& nc,
                             const std::vector<double>& frequency) {
  if (!nc.use_nss)
    throw InputError(
        "noise.contact_model",
        "corrugation needs the patch's traction and slip fields: noise.contact_model = \"nss\"");
  BandAxis axis;
  axis.frequency = frequency;
  try {
    return run_noise_loop(std::move(c), nc, std::move(axis));
  } catch (const InputError& e) {
    if (e.key() != "noise.band_max") throw;
    throw InputError(
        "corrugation.wavelength_min",
        std::string("V / corrugation.wavelength_min lies above the grid's Nyquist limit (raise "
                    "corrugation.wavelength_min or refine grid.nx): ") +
            e.what());
  }
}

// Stage 3: each contact's wear transfer, the contacts on `threads` threads.
void wear_transfers(CorrugationResult& r, const CorrugationCase& cc, int threads) {
  const std::vector<WheelNoise>& wheels = r.noise.wheels;
  r.contacts.resize(wheels.size());
  for (const WheelNoise& w : wheels)
    if (w.mean.model()->falling_friction())
      throw InputError("friction.law",
                       "corrugation: the element fields need constant friction (friction.law)");
  TaskPool pool(wheels.size(), threads, [&](std::size_t a, int) {
    const auto t0 = Clock::now();
    const MeanContact& m = wheels[a].mean;
    const nss::WearTransfer T(*m.model(), m.steady(), m.contact().speed, m.contact().mu, cc.law);
    ContactCorrugation& out = r.contacts[a];
    out.wheel = wheels[a].wheel;
    out.side = noise::is_outer(out.wheel) ? 1 : -1;
    out.transfer = T.depth(r.frequency);
    std::vector<double> k;
    for (double l : r.wavelength) k.push_back(2.0 * kPi / l);
    out.filter = nss::rail_roughness_filter(m.patch(), k);
    out.roughness_transfer =
        nss::RoughnessWearTransfer(m.patch(), *m.model(), m.steady(), m.contact().speed,
                                   m.contact().mu, cc.law, *std::max_element(k.begin(), k.end()))
            .depth(k);
    out.steps = T.steps();
    out.seconds = seconds_since(t0);
  });
  pool.finish();
}

// Stage 4 at frequency k for the rail `side`: the loop's forces under the rail's roughness met
// with the wheelbase phase and seen through each patch (W6), each contact's inputs u_a and its
// G_a (header).
void rail_inputs(CorrugationResult& r, int side, std::size_t k) {
  const noise::ContactSetLoopResult& loop = r.noise.loops.main;
  const double wavenumber = 2.0 * kPi / r.wavelength[k];
  const std::size_t n = r.contacts.size();
  Eigen::VectorXcd rho =
      Eigen::VectorXcd::Zero(loop.rho.rows());  // rho_b = H_b(k) e^{-ik d_b} on the rail
  for (std::size_t b = 0; b < n; ++b)
    if (r.contacts[b].side == side)
      rho(b) = r.contacts[b].filter[k] * std::polar(1.0, -wavenumber * r.contacts[b].distance);
  const Eigen::VectorXcd sources = loop.rho.transpose().cast<std::complex<double>>() * rho;
  const Eigen::VectorXcd F = loop.force[k] * sources;
  for (std::size_t a = 0; a < n; ++a) {
    ContactCorrugation& c = r.contacts[a];
    if (c.side != side) continue;
    const noise::ContactCoefficients& fg = r.noise.wheels[a].coefficients;
    const bool coupled = r.noise.coupled && !fg.load.empty();
    const ContactWear w =
        contact_wear(F.segment<4>(4 * a), fg.creep[k], coupled ? &fg.load[k] : nullptr,
                     c.transfer[k], c.roughness_transfer[k], wavenumber, c.distance);
    c.input[k] = w.input;
    c.depth[k] = w.depth;
    c.growth[k] = c.depth[k].real();
  }
}

// Stage 5: per rail, the sum of its contacts.
void rail_sums(CorrugationResult& r) {
  for (int side : {1, -1}) {
    RailCorrugation rail;
    rail.side = side;
    rail.depth.assign(r.frequency.size(), 0.0);
    bool any = false;
    for (const ContactCorrugation& c : r.contacts) {
      if (c.side != side) continue;
      any = true;
      for (std::size_t k = 0; k < r.frequency.size(); ++k) rail.depth[k] += c.depth[k];
    }
    if (!any) continue;
    for (const auto& d : rail.depth) rail.growth.push_back(d.real());
    r.rails.push_back(std::move(rail));
  }
}

// What the loop responds to: the peaks of the reported contact's forces under its own roughness,
// and of the rail's and the wheel's receptances at its contact point (vertical and lateral).
std::vector<LoopPeak> loop_peaks(const CorrugationResult& r, const NoiseCase& nc) {
  const std::size_t a = r.noise.reported;
  const noise::ContactSetLoopResult& loop = r.noise.loops.main;
  int source = -1;
  for (Eigen::Index e = 0; e < loop.rho.cols(); ++e)
    if (loop.rho(a, e) != 0.0) source = static_cast<int>(e);
  std::vector<LoopPeak> peaks;
  auto add = [&](const std::vector<double>& v, const std::string& label) {
    for (LoopPeak& p : local_peaks(r.frequency, v, label)) peaks.push_back(std::move(p));
  };
  const char* force_names[] = {"contact force Fz", "contact force Fx", "contact force Fy"};
  for (int i = 0; source >= 0 && i < 3; ++i) {
    std::vector<double> v;
    for (const auto& F : loop.force) v.push_back(std::abs(F(4 * a + i, source)));
    add(v, std::string(force_names[i]) + " peak (the loop's resonance)");
  }
  const noise::ContactPosition& pos = r.noise.wheels[a].position;
  const std::vector<noise::Receptance4> rail =
      noise::rail_contact_receptances(*nc.rail, r.frequency, pos);
  std::vector<double> rz, ry, wz, wy;
  for (std::size_t k = 0; k < r.frequency.size(); ++k) {
    rz.push_back(std::abs(rail[k](0, 0)));
    ry.push_back(std::abs(rail[k](2, 2)));
    const noise::Receptance4 w = noise::to_contact_frame(
        noise::wheel_receptance6(*nc.wheel, r.frequency[k], pos.wheel_shift_y), pos.contact_angle);
    wz.push_back(std::abs(w(0, 0)));
    wy.push_back(std::abs(w(2, 2)));
  }
  add(rz, "rail normal receptance peak");
  add(ry, "rail lateral receptance peak");
  add(wz, "wheel normal receptance peak (wheel mode)");
  add(wy, "wheel lateral receptance peak (wheel mode)");
  std::sort(peaks.begin(), peaks.end(),
            [](const LoopPeak& x, const LoopPeak& y) { return x.frequency < y.frequency; });
  return peaks;
}

}  // namespace

ContactWear contact_wear(const Eigen::Vector4cd& force, const Eigen::Matrix3cd& creep,
                         const Eigen::Vector3cd* load, const nss::WearRow& transfer,
                         std::complex<double> roughness_transfer, double wavenumber,
                         double distance) {
  const std::complex<double> Fz = force(0);
  Eigen::Vector3cd Ft = force.tail<3>();
  if (load) Ft -= *load * Fz;
  const Eigen::Vector3cd xi = -creep.partialPivLu().solve(Ft);  // (C3): F~t = -f xi~ + g Fz
  ContactWear out;
  out.input << xi, Fz;
  out.depth = std::polar(1.0, wavenumber * distance) * (transfer * out.input)(0) +
              roughness_transfer;  // (W5)
  return out;
}

std::vector<LoopPeak> local_peaks(const std::vector<double>& frequency,
                                  const std::vector<double>& values, const std::string& label) {
  std::vector<LoopPeak> out;
  for (std::size_t i = 1; i + 1 < values.size(); ++i)
    if (values[i] > values[i - 1] && values[i] >= values[i + 1])
      out.push_back({frequency[i], label});
  return out;
}

std::vector<GrowingBand> growing_bands(const CorrugationResult& r, const RailCorrugation& rail) {
  std::vector<GrowingBand> out;
  const std::size_t n = rail.growth.size();
  for (std::size_t i = 0; i < n;) {
    if (!(rail.growth[i] > 0.0)) {
      ++i;
      continue;
    }
    GrowingBand b;
    b.side = rail.side;
    b.wavelength_max = r.wavelength[i];
    for (; i < n && rail.growth[i] > 0.0; ++i) {
      b.wavelength_min = r.wavelength[i];
      if (rail.growth[i] > b.peak_growth)
        b.peak_growth = rail.growth[i], b.peak_wavelength = r.wavelength[i],
        b.peak_frequency = r.frequency[i];
    }
    double best = 1e300;
    for (const LoopPeak& p : r.peaks) {
      const double d = std::abs(std::log(p.frequency / b.peak_frequency));
      if (d < best) best = d, b.nearest = p;
    }
    out.push_back(b);
  }
  return out;
}

CorrugationResult run_corrugation(ContactCase c, const NoiseCase& nc, const CorrugationCase& cc) {
  const auto t0 = Clock::now();
  CorrugationResult r;
  r.wavelength = corrugation_wavelengths(cc);
  for (double l : r.wavelength) r.frequency.push_back(c.speed / l);
  const int threads = resolved_threads(c.threads, nss::kMaxThreads);
  r.noise = corrugation_loop(std::move(c), nc, r.frequency);
  r.seconds_loop = seconds_since(t0);
  const auto t1 = Clock::now();
  wear_transfers(r, cc, threads);
  for (std::size_t a = 0; a < r.contacts.size(); ++a) {
    ContactCorrugation& x = r.contacts[a];
    x.distance = noise::is_leading(x.wheel) ? 0.0 : nc.wheelbase;
    x.input.resize(r.frequency.size());
    x.depth.assign(r.frequency.size(), 0.0);
    x.growth.assign(r.frequency.size(), 0.0);
  }
  for (int side : {1, -1})
    for (std::size_t k = 0; k < r.frequency.size(); ++k) rail_inputs(r, side, k);
  rail_sums(r);
  r.seconds_wear = seconds_since(t1);
  r.peaks = loop_peaks(r, nc);
  for (const RailCorrugation& rail : r.rails)
    for (GrowingBand& b : growing_bands(r, rail)) r.growing.push_back(std::move(b));
  r.seconds_total = seconds_since(t0);
  return r;
}

}  // namespace rollnoise::pipeline
