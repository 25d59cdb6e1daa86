// The 21-point Gauss-Kronrod rule on [0, 1]: the 10-point Gauss-Legendre rule and the 11 nodes that
// extend it optimally (Kronrod), so that one set of 21 values gives an integral exact for
// polynomials of degree 31 and, from the 10 Gauss nodes among them, the error of the 10-point rule.
// Nodes and weights: QUADPACK's dqk21 (Piessens, de Doncker-Kapenga, Ueberhuber & Kahaner,
// QUADPACK, Springer 1983; public domain), computed by L. W. Fullerton (Bell Labs, 1981) in 80
// decimal digits; GSL exposes the rule only behind a scalar integrand (gsl_integration_qk21).
#pragma once

#include <array>
#include <cstddef>

namespace rollnoise::linalg {

struct GaussKronrod21 {
  std::array<double, 21> nodes{};    ///< on [0, 1], ascending
  std::array<double, 21> kronrod{};  ///< the 21-point weights (sum 1)
  std::array<double, 21> gauss{};    ///< the 10-point Gauss weights (0 at Kronrod nodes)
};

inline GaussKronrod21 gauss_kronrod_21_01() {
  // [-1, 1], the non-negative half, descending from the end (QUADPACK's order)
  static constexpr std::array<double, 11> x{0.995657163025808080735527280689003,
                                            0.973906528517171720077964012084452,
                                            0.930157491355708226001207180059508,
                                            0.865063366688984510732096688423493,
                                            0.780817726586416897063717578345042,
                                            0.679409568299024406234327365114874,
                                            0.562757134668604683339000099272694,
                                            0.433395394129247190799265943165784,
                                            0.294392862701460198131126603103866,
                                            0.148874338981631210884826001129720,
                                            0.0};
  static constexpr std::array<double, 11> wk{
      0.011694638867371874278064396062192, 0.032558162307964727478818972459390,
      0.054755896574351996031381300244580, 0.075039674810919952767043140916190,
      0.093125454583697605535065465083366, 0.109387158802297641899210590325805,
      0.123491976262065851077958109831074, 0.134709217311473325928054001771707,
      0.142775938577060080797094273138717, 0.147739104901338491374841515972068,
      0.149445554002916905664936468389821};
  // the Gauss weights of x[1], x[3], ..., x[9]
  static constexpr std::array<double, 5> wg{
      0.066671344308688137593568809893332, 0.149451349150580593145776339657697,
      0.219086362515982043995534934228163, 0.269266719309996355091226921569469,
      0.295524224714752870173892994651338};
  GaussKronrod21 r;
  for (std::size_t i = 0; i < 11; ++i) {
    const std::size_t lo = i, hi = 20 - i;  // -x[i] and +x[i]
    r.nodes[lo] = 0.5 * (1.0 - x[i]);
    r.nodes[hi] = 0.5 * (1.0 + x[i]);
    r.kronrod[lo] = r.kronrod[hi] = 0.5 * wk[i];
    const double g = i % 2 == 1 ? 0.5 * wg[i / 2] : 0.0;
    r.gauss[lo] = r.gauss[hi] = g;
  }
  return r;
}

}  // namespace rollnoise::linalg
