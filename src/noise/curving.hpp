// Forwarding header: vehicle curving moved to src/vehicle (issue 26). Include vehicle/curving.hpp.
#pragma once

#include "vehicle/curving.hpp"
