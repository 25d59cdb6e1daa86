// gmsh's C API (gmshc.h of Debian libgmsh-dev), loaded on first use with dlopen: the program does
// not link libgmsh, whose ~125 dependent shared libraries (OpenCASCADE, FLTK, X11, OpenGL, image
// codecs, ...) the dynamic loader would otherwise map and relocate at the start of every command,
// also of those that never mesh. Only the calls mesh_polygon (fem/mesh.cpp) makes are exposed.
#pragma once

extern "C" {  // gmshc.h declares C functions without a linkage block; only their types are used
#include <gmshc.h>
}

#include <string>

namespace rollnoise::fem {

/// The functions of gmsh's C API the mesher calls, resolved from one loaded libgmsh. Each takes
/// `int* ierr` last (non-zero: the call failed); arrays gmsh returns are freed with `free`.
struct GmshApi {
  decltype(&::gmshFree) free = nullptr;
  decltype(&::gmshInitialize) initialize = nullptr;
  decltype(&::gmshFinalize) finalize = nullptr;
  decltype(&::gmshOptionSetNumber) option_set_number = nullptr;
  decltype(&::gmshModelAdd) model_add = nullptr;
  decltype(&::gmshModelGeoAddPoint) geo_add_point = nullptr;
  decltype(&::gmshModelGeoAddLine) geo_add_line = nullptr;
  decltype(&::gmshModelGeoAddCurveLoop) geo_add_curve_loop = nullptr;
  decltype(&::gmshModelGeoAddPlaneSurface) geo_add_plane_surface = nullptr;
  decltype(&::gmshModelGeoSynchronize) geo_synchronize = nullptr;
  decltype(&::gmshModelMeshGenerate) mesh_generate = nullptr;
  decltype(&::gmshModelMeshSetOrder) mesh_set_order = nullptr;
  decltype(&::gmshModelMeshGetNodes) mesh_get_nodes = nullptr;
  decltype(&::gmshModelMeshGetElementsByType) mesh_get_elements_by_type = nullptr;
};

/// Loads the shared library at `path` (a file name or path, as dlopen takes it) and resolves the
/// GmshApi functions from it. Throws std::runtime_error (an environment error: exit status 1 in
/// the CLI) naming the file and the Debian package that provides the build's libgmsh when the
/// library cannot be loaded, or naming the missing function when it lacks one. The library stays
/// loaded for the rest of the process (as a linked library would).
GmshApi load_gmsh_library(const std::string& path);

/// The libgmsh this build found (CMake: GMSH_LIBRARY's SONAME), loaded once per process at the
/// first call, thread-safe; a failed load throws at every call.
const GmshApi& gmsh_library();

/// The file gmsh_library() loads (its SONAME, with the directory the build found it in).
std::string gmsh_library_file();

}  // namespace rollnoise::fem
