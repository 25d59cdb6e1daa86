#include "linalg/hessenberg_eigenvalues.hpp"

#include <algorithm>
#include <string>
#include <vector>

#include "core/errors.hpp"
#include "linalg/lapack_section.hpp"

extern "C" void dhseqr_(const char* job, const char* compz, const int* n, const int* ilo,
                        const int* ihi, double* h, const int* ldh, double* wr, double* wi,
                        double* z, const int* ldz, double* work, const int* lwork, int* info);

namespace rollnoise::linalg {

Eigen::VectorXcd hessenberg_eigenvalues(Eigen::MatrixXd H) {
  const int n = static_cast<int>(H.rows());
  if (n == 0) return {};
  for (int j = 0; j < n; ++j)  // dhseqr reads the whole array: zero what lies below the subdiagonal
    for (int i = j + 2; i < n; ++i) H(i, j) = 0.0;
  std::vector<double> wr(n), wi(n);
  const int ilo = 1, ihi = n, one = 1;
  double z = 0.0, query = 0.0;
  int info = 0, lwork = -1;
  const LapackSection lapack;
  dhseqr_("E", "N", &n, &ilo, &ihi, H.data(), &n, wr.data(), wi.data(), &z, &one, &query, &lwork,
          &info);
  lwork = std::max(1, static_cast<int>(query));
  std::vector<double> work(lwork);
  dhseqr_("E", "N", &n, &ilo, &ihi, H.data(), &n, wr.data(), wi.data(), &z, &one, work.data(),
          &lwork, &info);
  if (info != 0)
    throw NumericalError("LAPACK dhseqr did not converge (info = " + std::to_string(info) +
                         ") on the " + std::to_string(n) + " x " + std::to_string(n) +
                         " Hessenberg eigenproblem");
  Eigen::VectorXcd out(n);
  for (int i = 0; i < n; ++i) out(i) = {wr[i], wi[i]};
  return out;
}

}  // namespace rollnoise::linalg
