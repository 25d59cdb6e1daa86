#include "contact/slip_operator.hpp"

#include <cstddef>

namespace rollnoise::contact {

template <class Coefficient>
SlipOperator SlipOperator::build(const Grid& g, Coefficient coeff) {
  SlipOperator s;
  s.grid_ = g;
  s.row_ = 2 * g.nx - 1;
  const std::size_t size = static_cast<std::size_t>(s.row_) * (2 * g.ny - 1);
  s.xx_.resize(size);
  s.xy_.resize(size);
  s.yy_.resize(size);
  for (int dj = -(g.ny - 1); dj < g.ny; ++dj)
    for (int di = -(g.nx - 1); di < g.nx; ++di) {
      const int k = s.offset_index(di, dj);
      s.xx_[k] = coeff(Component::xx, di, dj);
      s.xy_[k] = coeff(Component::xy, di, dj);
      s.yy_[k] = coeff(Component::yy, di, dj);
    }
  return s;
}

SlipOperator SlipOperator::steady(const InfluenceTable& t, double speed) {
  const double f = speed / t.grid().dx;
  return build(t.grid(), [&](Component c, int di, int dj) {
    return f * (t(c, di, dj) - t(c, di + 1, dj));  // V (A - A0)/dx
  });
}

SlipOperator SlipOperator::transient(const InfluenceTable& t, double dt) {
  return build(t.grid(), [&](Component c, int di, int dj) { return t(c, di, dj) / dt; });
}

}  // namespace rollnoise::contact
