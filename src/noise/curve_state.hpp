// Forwarding header: the curve contact state moved to src/vehicle (issue 26). Include
// vehicle/curve_state.hpp.
#pragma once

#include "vehicle/curve_state.hpp"
