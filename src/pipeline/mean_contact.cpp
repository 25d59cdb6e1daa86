#include "pipeline/mean_contact.hpp"

#include "contact/normal_solver.hpp"
#include "core/assert.hpp"

namespace rollnoise::pipeline {

std::unique_ptr<nss::LinearContactModel> linear_model(const ContactCase& c,
                                                      const contact::ContactPatch& patch,
                                                      const contact::TangentialSolution& steady) {
  nss::LinearModelInput in{c.mu, c.speed, c.spin_offset, c.falling, c.linear_solver, c.sampling};
  in.threads = c.threads;
  return std::make_unique<nss::LinearContactModel>(patch, steady, in);
}

namespace {

// Squeal's transfer: the NSS model's (guarded by its Markov series) or Kalker's constant one. With
// falling friction the contact's own stability first: the transfer of an unstable contact is not
// built.
void build_transfer(const ContactCase& c, const MeanContactOptions& o,
                    const std::shared_ptr<const nss::LinearContactModel>& model,
                    std::shared_ptr<const noise::ContactTransfer>& transfer, bool& coupled,
                    double& radius) {
  if (!model) {  // Kalker's constant f, g = 0: it holds at every s (no series, no guard)
    transfer = std::make_shared<const noise::ConstantTransfer>(
        noise::ConstantTransfer::kalker(c.a, c.b, c.material));
    return;
  }
  // Falling friction: no Markov parameters (the paper form only). Constant friction: the sweep's
  // Markov parameters (their decay proves it stable).
  if (model->markov_parameters().empty()) {
    radius = model->spectral_radius();
    if (radius >= 1.0) return;
  }
  coupled = o.normal_coupling && model->has_normal_load_input();
  transfer = std::make_shared<const noise::NssTransfer>(model, coupled);
}

}  // namespace

MeanContact solve_mean_contact(ContactCase placed, CurveSetup curve, const MeanContactOptions& o) {
  ROLLNOISE_ASSERT(placed.placed || !placed.profiles, "the mean contact needs a placed case");
  MeanContact m;
  m.curve_ = std::move(curve);
  m.patch_ = std::make_shared<const contact::ContactPatch>(solve_patch(placed));
  placed.grid = m.patch_->grid;  // the case as run: profiles may have enlarged the grid
  m.contact_ = std::move(placed);
  const ContactCase& c = m.contact_;
  if (!o.frequencies.empty())
    check_nyquist(c, o.frequencies, o.frequency_key);  // once, on the final grid
  const contact::HalfSpaceOperator op(m.patch_->influence, contact::Problem::Normal, 0, c.backend);
  m.normal_stiffness_ =
      contact::normal_load_sensitivity(m.patch_->grid, op, m.patch_->normal).stiffness();
  m.steady_ = contact::solve_steady_rolling(m.patch_->influence, m.patch_->normal.pn,
                                            c.steady_input(), c.tangential);
  if (o.with_model) m.model_ = linear_model(c, *m.patch_, m.steady_);
  if (o.with_transfer) build_transfer(c, o, m.model_, m.transfer_, m.coupled_, m.spectral_radius_);
  return m;
}

MeanContact mean_contact(const ContactCase& c, const MeanContactOptions& o) {
  return solve_mean_contact(placed_contact(c), CurveSetup{}, o);
}

MeanContact curve_mean_contact(const ContactCase& c, const NoiseCase& nc,
                               const MeanContactOptions& o) {
  CurvePlacement p = resolve_curve(c, nc);
  return solve_mean_contact(std::move(p.contact), std::move(p.curve), o);
}

MeanContact wheel_mean_contact(const ContactCase& base, const noise::WheelContact& w,
                               const MeanContactOptions& o) {
  // The wheel's contact point (this side's frame: the patch of the inner wheel is computed in the
  // mirror image and reads like an outer wheel's), its normal force and creepages.
  ContactCase c = placed_contact_at(base, w.contact, w.normal_force());
  c.creepage = {w.creepage(0), w.creepage(1), w.creepage(2)};
  return solve_mean_contact(std::move(c), CurveSetup{}, o);
}

}  // namespace rollnoise::pipeline
