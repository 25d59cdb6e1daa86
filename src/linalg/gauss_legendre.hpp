// Gauss-Legendre rules on [0, 1] from GSL's fixed tables (gsl_integration_glfixed), the one place
// the project asks GSL for them.
#pragma once

#include <gsl/gsl_integration.h>

#include <memory>
#include <stdexcept>
#include <vector>

namespace rollnoise::linalg {

/// The n-point Gauss-Legendre rule on [0, 1]: nodes ascending, weights summing to 1.
struct GaussRule {
  std::vector<double> nodes, weights;
};

inline GaussRule gauss_legendre_01(int n) {
  if (n < 1) throw std::invalid_argument("gauss_legendre_01: at least one point");
  const std::unique_ptr<gsl_integration_glfixed_table, void (*)(gsl_integration_glfixed_table*)>
      table(gsl_integration_glfixed_table_alloc(static_cast<std::size_t>(n)),
            gsl_integration_glfixed_table_free);
  if (!table) throw std::runtime_error("gauss_legendre_01: GSL table not allocated");
  GaussRule rule;
  rule.nodes.resize(static_cast<std::size_t>(n));
  rule.weights.resize(static_cast<std::size_t>(n));
  for (std::size_t i = 0; i < rule.nodes.size(); ++i)
    gsl_integration_glfixed_point(0.0, 1.0, i, &rule.nodes[i], &rule.weights[i], table.get());
  return rule;
}

}  // namespace rollnoise::linalg
