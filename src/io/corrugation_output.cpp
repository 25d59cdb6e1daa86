#include "io/corrugation_output.hpp"

#include "io/contact_output.hpp"
#include "io/noise_output.hpp"

namespace rollnoise::io {

const char* rail_name(int side) {
  return side > 0 ? "outer" : "inner";
}

namespace {

const char* kGrowthUnits =
    "1/passage: Re(wear depth per passage / roughness amplitude), > 0 grows (docs/corrugation.md "
    "Sec. 4)";
const char* kDepthUnits =
    "-: complex wear depth per passage per roughness amplitude (roughness positive for a "
    "depression, loop.hpp)";

void write_contact(Hdf5Writer& w, const std::string& g, const pipeline::ContactCorrugation& c) {
  const std::size_t nf = c.depth.size();
  w.write(g + "/growth_rate", c.growth, {nf}, std::string(kGrowthUnits) + "; one wheel passage");
  w.write(g + "/depth_ratio", c.depth, {nf}, kDepthUnits);
  std::vector<std::complex<double>> T, u;
  for (std::size_t k = 0; k < nf; ++k)
    for (int i = 0; i < 4; ++i) T.push_back(c.transfer[k](i)), u.push_back(c.input[k](i));
  w.write(g + "/wear_transfer", T, {nf, 4},
          "m per passage per unit xi_x (-), xi_y (-), phi (rad/m), N~ (N): the depth at the rail "
          "position where "
          "the input's phase is 0 (nss/wear_transfer.hpp W4)");
  w.write(g + "/input", u, {nf, 4},
          "xi_x (-), xi_y (-), phi (rad/m) per m, Fz (N/m): the contact's inputs per unit "
          "roughness of its rail");
  w.write(g + "/distance", c.distance, "m behind the leading axle");
  w.write(g + "/roughness_filter", c.filter, {nf},
          "-: the roughness the frozen patch sees per unit rail roughness uniform across the rail "
          "(W6)");
  w.write(g + "/roughness_wear_transfer", c.roughness_transfer, {nf},
          "m per passage per m of roughness: the wear of the pressure the roughness moves within "
          "the frozen patch at a given load (nss/wear_transfer.hpp W8)");
  w.attribute(g, "rail", rail_name(c.side));
  w.write(g + "/impulse_steps", std::vector<int>{c.steps}, {},
          "time steps of the element fields' impulse response");
}

}  // namespace

void write_corrugation(Hdf5Writer& w, const CaseReader& reader, const pipeline::NoiseCase& nc,
                       const pipeline::CorrugationCase& cc, const pipeline::CorrugationResult& r) {
  const pipeline::MeanContact& m = r.noise.mean;
  write_mean_state(w, case_as_run(reader, m.contact(), m.curve()), m.patch(), m.contact().creepage,
                   m.steady());
  write_contact_state(w, "/corrugation/contact", nc, m.contact(), m.curve(), m.normal_stiffness());
  const std::size_t nf = r.frequency.size();
  w.write("/corrugation/wavelength", r.wavelength, {nf}, "m");
  w.write("/corrugation/frequency", r.frequency, {nf}, "Hz: V / wavelength");
  for (const pipeline::RailCorrugation& rail : r.rails) {
    const std::string g = std::string("/corrugation/") + rail_name(rail.side);
    w.write(g + "/growth_rate", rail.growth, {nf},
            std::string(kGrowthUnits) + "; one bogie passage (the sum of the rail's contacts)");
    w.write(g + "/depth_ratio", rail.depth, {nf}, kDepthUnits);
  }
  for (const pipeline::ContactCorrugation& c : r.contacts)
    write_contact(w, std::string("/corrugation/contacts/") + noise::wheel_name(c.wheel), c);
  std::vector<double> pf;
  std::vector<std::string> pl;
  for (const auto& p : r.peaks) pf.push_back(p.frequency), pl.push_back(p.label);
  w.write("/corrugation/peaks/frequency", pf, {pf.size()},
          "Hz: local maxima of the loop's forces and receptances");
  if (!pl.empty()) w.write("/corrugation/peaks/label", pl, "-");
  w.attribute("/corrugation", "wear_law",
              cc.law.kind == nss::WearLaw::Kind::archard ? "archard" : "frictional_work");
  w.write("/corrugation/wear_coefficient", cc.law.coefficient,
          cc.law.kind == nss::WearLaw::Kind::archard ? "-" : "m^3/J");
  w.write("/corrugation/wear_hardness", cc.law.hardness, "Pa");
}

}  // namespace rollnoise::io
