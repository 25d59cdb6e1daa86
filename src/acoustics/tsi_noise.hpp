// The pass-by limits of the TSI Noise: Commission Regulation (EU) No 1304/2014 (technical
// specification for interoperability relating to the subsystem "rolling stock - noise"), as
// amended by Commission Implementing Regulation (EU) 2019/774, Annex:
//
//  - clause 4.2.3, Table 4: the limit values of L_pAeq,Tp at 80 km/h, 7.5 m from the track
//    centre and 1.2 m above the top of rail (EN ISO 3095), per category of rolling stock:
//      electric locomotives and OTMs with electric traction  84 dB
//      diesel locomotives and OTMs with diesel traction      85 dB
//      EMUs                                                   80 dB
//      DMUs                                                   81 dB
//      coaches                                                79 dB
//      wagons (normalised to APL = 0.225 m^-1)                83 dB
//    (the wagons' value is for a wagon of 0.225 axles per metre; APL = axles / length over buffers;
//    this table is the regulation's; the normalisation of wagons to APL is left out);
//  - clause 6.2.2.3.2: a pass-by measured at a test speed v_test is normalised to 80 km/h by
//      L_pAeq,Tp(80 km/h) = L_pAeq,Tp(v_test) - 30 lg(v_test / 80 km/h).                   (T1)
#pragma once

#include <string>
#include <vector>

namespace rollnoise::acoustics {

/// The categories of Table 4 (the names passby.category takes), in the table's order.
const std::vector<std::string>& tsi_categories();

/// The limit of L_pAeq,Tp(80 km/h) for `category` (dB(A)); std::invalid_argument for a name not
/// in tsi_categories().
double tsi_passby_limit(const std::string& category);

/// (T1): `level` (dB(A)) at `speed` (m/s) normalised to 80 km/h.
double tsi_normalised_80(double level, double speed);

}  // namespace rollnoise::acoustics
