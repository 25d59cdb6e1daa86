#include "contact/transient_rolling.hpp"

namespace rollnoise::contact {

TransientRolling::TransientRolling(const InfluenceTable& A, const GridField& pn, double mu,
                                   double speed, double spin_offset, Backend backend,
                                   const TangentialSolverSettings& settings)
    : A_(A),
      pn_(pn),
      mu_(mu),
      speed_(speed),
      spin_offset_(spin_offset),
      dt_(A.grid().dx / speed),
      A0_(A, Problem::Tangential, 1, backend),
      newton_(SlipOperator::transient(A, A.grid().dx / speed), sweep_order(A.grid(), pn),
              [&] {
                GridField b(pn.size());
                for (size_t k = 0; k < pn.size(); ++k) b[k] = mu * pn[k];
                return b;
              }()),
      settings_(settings) {
  check_rolling_input(mu, speed, Creepage{});
  const int n = A.grid().size();
  current_.px.assign(n, 0.0);
  current_.py.assign(n, 0.0);
  current_.sx.assign(n, 0.0);
  current_.sy.assign(n, 0.0);
  current_.state.assign(n, 0);
}

void TransientRolling::set_tractions(const GridField& px, const GridField& py) {
  current_.px = px;
  current_.py = py;
  previous_.clear();
}

const TangentialSolution& TransientRolling::step(const Creepage& c) {
  check_rolling_input(mu_, speed_, c);
  const Grid& g = A_.grid();
  const int n = g.size();
  // rhs = w(t_k) - A0 p_{k-1} / dt
  std::vector<double> p0(2 * n), u0(2 * n);
  std::copy(current_.px.begin(), current_.px.end(), p0.begin());
  std::copy(current_.py.begin(), current_.py.end(), p0.begin() + n);
  A0_.apply(p0.data(), u0.data());
  GridField rx, ry;
  rigid_slip(g, speed_, c, spin_offset_, rx, ry);
  for (int k = 0; k < n; ++k) {
    rx[k] -= u0[k] / dt_;
    ry[k] -= u0[n + k] / dt_;
  }
  // Start value: the tractions extrapolated linearly from the last two steps (the Newton solve
  // projects them onto the traction bound); the previous tractions after a reset.
  GridField sx = current_.px, sy = current_.py;
  if (previous_.size() == 2 * static_cast<size_t>(n))
    for (int k = 0; k < n; ++k) {
      sx[k] = 2.0 * current_.px[k] - previous_[k];
      sy[k] = 2.0 * current_.py[k] - previous_[n + k];
    }
  previous_ = std::move(p0);
  current_ = newton_.solve(rx, ry, sx, sy, settings_, "transient tangential solver");
  return current_;
}

}  // namespace rollnoise::contact
