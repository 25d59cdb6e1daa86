// Loading libgmsh with dlopen (see gmsh_library.hpp for why it is not linked).
//
// Symbols: libgmsh exports its own instances of Eigen's templates (e.g. PartialPivLU<MatrixXd>,
// built without -march=native). While the program linked libgmsh, the static linker exported the
// program's instances of the same templates (a shared library in the link defined them), the
// dynamic linker bound libgmsh's calls to those, and the differing alignment crashed; the link
// option -Wl,--exclude-libs,ALL kept them local. Now no libgmsh is in the link, so the program
// exports none of its Eigen instances (no -rdynamic) and libgmsh's references resolve to its own;
// RTLD_LOCAL keeps libgmsh's symbols out of the global scope, so nothing loaded later binds to
// them either. (RTLD_DEEPBIND would force the first point but AddressSanitizer refuses it.)
// RTLD_NOW: every relocation at load time, so a broken installation fails here with dlerror's
// message rather than later inside a meshing call; measured no slower than RTLD_LAZY for the
// noise case (docs/record/performance.md Sec. 12).
#include "fem/gmsh_library.hpp"

#include <dlfcn.h>

#include <mutex>
#include <stdexcept>

#ifndef ROLLNOISE_GMSH_LIBRARY
#error "ROLLNOISE_GMSH_LIBRARY (the libgmsh file to load) is set by CMakeLists.txt"
#endif
#ifndef ROLLNOISE_GMSH_PACKAGE
#define ROLLNOISE_GMSH_PACKAGE "libgmsh"
#endif

namespace rollnoise::fem {
namespace {

// Resolves `name` into `function`; throws naming the library and the symbol.
template <class Function>
void resolve_gmsh_symbol(void* handle, const std::string& path, const char* name,
                         Function& function) {
  dlerror();  // clear
  void* symbol = dlsym(handle, name);
  if (symbol == nullptr)
    throw std::runtime_error("the gmsh library " + path + " does not define " + name +
                             " (is it gmsh's C API?)");
  function = reinterpret_cast<Function>(symbol);
}

}  // namespace

GmshApi load_gmsh_library(const std::string& path) {
  void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (handle == nullptr) {
    const char* reason = dlerror();
    throw std::runtime_error(
        "cannot load the gmsh library " + path + ", needed to mesh a cross-section (" +
        (reason ? reason : "no reason given") +
        "); it is in the Debian package " ROLLNOISE_GMSH_PACKAGE " (scripts/setup.sh installs it)");
  }
  GmshApi api;
  try {
    resolve_gmsh_symbol(handle, path, "gmshFree", api.free);
    resolve_gmsh_symbol(handle, path, "gmshInitialize", api.initialize);
    resolve_gmsh_symbol(handle, path, "gmshFinalize", api.finalize);
    resolve_gmsh_symbol(handle, path, "gmshOptionSetNumber", api.option_set_number);
    resolve_gmsh_symbol(handle, path, "gmshModelAdd", api.model_add);
    resolve_gmsh_symbol(handle, path, "gmshModelGeoAddPoint", api.geo_add_point);
    resolve_gmsh_symbol(handle, path, "gmshModelGeoAddLine", api.geo_add_line);
    resolve_gmsh_symbol(handle, path, "gmshModelGeoAddCurveLoop", api.geo_add_curve_loop);
    resolve_gmsh_symbol(handle, path, "gmshModelGeoAddPlaneSurface", api.geo_add_plane_surface);
    resolve_gmsh_symbol(handle, path, "gmshModelGeoSynchronize", api.geo_synchronize);
    resolve_gmsh_symbol(handle, path, "gmshModelMeshGenerate", api.mesh_generate);
    resolve_gmsh_symbol(handle, path, "gmshModelMeshSetOrder", api.mesh_set_order);
    resolve_gmsh_symbol(handle, path, "gmshModelMeshGetNodes", api.mesh_get_nodes);
    resolve_gmsh_symbol(handle, path, "gmshModelMeshGetElementsByType",
                        api.mesh_get_elements_by_type);
  } catch (...) {
    dlclose(handle);  // not gmsh: nothing of it was called
    throw;
  }
  // The handle is never closed: gmsh registers static destructors, and the functions stay in use.
  return api;
}

std::string gmsh_library_file() {
  return ROLLNOISE_GMSH_LIBRARY;
}

const GmshApi& gmsh_library() {
  static std::once_flag loaded;
  static GmshApi api;
  // A throwing call leaves the flag unset: the next call tries (and reports) again.
  std::call_once(loaded, [] { api = load_gmsh_library(gmsh_library_file()); });
  return api;
}

}  // namespace rollnoise::fem
