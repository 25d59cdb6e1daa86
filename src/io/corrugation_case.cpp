#include "io/corrugation_case.hpp"

#include "io/input_problems.hpp"

namespace rollnoise::io {

pipeline::CorrugationCase read_corrugation_case(const CaseReader& r) {
  pipeline::CorrugationCase cc;
  InputProblems p;
  p.check([&] { cc.wavelength_min = r.real("corrugation.wavelength_min"); });
  p.check([&] { cc.wavelength_max = r.real("corrugation.wavelength_max"); });
  p.check([&] { cc.points = static_cast<int>(r.integer("corrugation.points")); });
  p.check([&] {
    if (!(cc.wavelength_min < cc.wavelength_max))
      r.fail("corrugation.wavelength_max",
             "corrugation.wavelength_max must be greater than corrugation.wavelength_min");
  });
  p.check([&] {
    cc.law.kind = r.string("wear.law") == "archard" ? nss::WearLaw::Kind::archard
                                                    : nss::WearLaw::Kind::frictional_work;
  });
  p.check([&] {
    const double k = r.real("wear.coefficient");
    if (r.has("wear.coefficient")) cc.law.coefficient = k;
    // the default is the frictional-work coefficient; Archard's k is dimensionless (schema help)
    else if (cc.law.kind == nss::WearLaw::Kind::archard)
      cc.law.coefficient = 1e-4;
  });
  p.check([&] { cc.law.hardness = r.real("wear.hardness"); });
  p.throw_if_any();
  return cc;
}

}  // namespace rollnoise::io
