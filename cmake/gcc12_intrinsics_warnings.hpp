// Included first in every C++ file when the compiler is GCC 12.1 or 12.2 (CMakeLists.txt).
//
// GCC 12.1-12.2 (Debian 12 ships 12.2) defines _mm512_undefined_pd() and its siblings in
// <avx512fintrin.h> as `__m512d __Y = __Y;`. When Eigen's AVX-512 kernels (enabled by
// -march=native on a machine with AVX-512) are inlined into our functions, -Wmaybe-uninitialized
// reports that self-initialisation once per inlined call, attributed to the system header but
// not suppressed as a system-header warning: about 900 warnings per build, none about our code.
// It is GCC bug 105593, fixed in GCC 12.3 and 13. The warning state of a location is that of the
// pragmas around it, so including the intrinsics here, before anything else, under an "ignored"
// pragma silences exactly the lines of the intrinsic headers; our own code keeps the warning.
// The pragmas change no generated code (the object files are identical with and without them).
#pragma once
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#pragma GCC diagnostic ignored "-Wuninitialized"
#include <immintrin.h>
#pragma GCC diagnostic pop
