#include "contact/element_operator.hpp"

#include <stdexcept>

namespace rollnoise::contact {

ElementOperator::ElementOperator(std::shared_ptr<const HalfSpaceOperator> grid_operator,
                                 const Grid& grid, std::vector<int> elements, double divisor)
    : ElementOperator(std::move(grid_operator), grid, std::move(elements), {}, {}, divisor) {}

ElementOperator::ElementOperator(std::shared_ptr<const HalfSpaceOperator> grid_operator,
                                 const Grid& grid, std::vector<int> elements,
                                 std::vector<char> directed, std::vector<Eigen::Vector2d> direction,
                                 double divisor)
    : op_(std::move(grid_operator)),
      grid_size_(grid.size()),
      elements_(std::move(elements)),
      directed_(std::move(directed)),
      t_(std::move(direction)),
      divisor_(divisor) {
  const int m = static_cast<int>(elements_.size());
  if (directed_.empty()) directed_.assign(m, 0);
  if (static_cast<int>(directed_.size()) != m || (t_.size() != directed_.size() && !t_.empty()))
    throw std::invalid_argument("ElementOperator: one flag and one direction per element");
  if (op_->size() != 2 * grid_size_)
    throw std::invalid_argument("ElementOperator: the grid operator must be tangential on the grid");
  offset_.resize(m);
  for (int a = 0; a < m; ++a) {
    offset_[a] = size_;
    size_ += directed_[a] ? 1 : 2;
  }
  p_.assign(2 * grid_size_, 0.0);
  u_.assign(2 * grid_size_, 0.0);
}

void ElementOperator::apply(const double* x, double* y) const {
  const int m = static_cast<int>(elements_.size()), N = grid_size_;
  for (int a = 0; a < m; ++a) {  // Pi x: tractions on the grid (exterior elements stay zero)
    const int k = elements_[a], o = offset_[a];
    if (directed_[a]) {
      p_[k] = t_[a](0) * x[o];
      p_[N + k] = t_[a](1) * x[o];
    } else {
      p_[k] = x[o];
      p_[N + k] = x[o + 1];
    }
  }
  op_->apply(p_.data(), u_.data());
  for (int a = 0; a < m; ++a) {  // Pi' u / divisor
    const int k = elements_[a], o = offset_[a];
    if (directed_[a]) {
      y[o] = (t_[a](0) * u_[k] + t_[a](1) * u_[N + k]) / divisor_;
    } else {
      y[o] = u_[k] / divisor_;
      y[o + 1] = u_[N + k] / divisor_;
    }
  }
}

void ElementOperator::apply(const Eigen::Ref<const Eigen::MatrixXd>& X, Eigen::Ref<Eigen::MatrixXd> Y) const {
  for (Eigen::Index j = 0; j < X.cols(); ++j) apply(X.col(j).data(), Y.col(j).data());
}

Eigen::MatrixXd ElementOperator::operator*(const Eigen::Ref<const Eigen::MatrixXd>& X) const {
  Eigen::MatrixXd Y(X.rows(), X.cols());
  apply(X, Y);
  return Y;
}

}  // namespace rollnoise::contact
