// fem/gmsh_library: libgmsh loaded at run time. A missing library or one without gmsh's C API gives
// an error naming the file (and the Debian package); the build's library resolves every call.
// Cheap: no mesh is made here (mesh_test.cpp meshes through the loaded library).
#include "fem/gmsh_library.hpp"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

using namespace rollnoise::fem;

namespace {

// The message of the std::runtime_error load_gmsh_library(path) throws ("" if none is thrown).
std::string gmsh_load_error(const std::string& path) {
  try {
    load_gmsh_library(path);
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(GmshLibrary, MissingLibraryErrorNamesTheFileAndThePackage) {
  const std::string path = "/nonexistent/libgmsh.so.4.8";
  const std::string message = gmsh_load_error(path);
  ASSERT_FALSE(message.empty()) << "loading " << path << " did not fail";
  EXPECT_NE(message.find("cannot load the gmsh library " + path), std::string::npos) << message;
  EXPECT_NE(message.find("Debian package libgmsh"), std::string::npos) << message;
}

TEST(GmshLibrary, LibraryWithoutGmshsCApiRefused) {
  // libm: a shared library every system has, without gmsh in it.
  const std::string message = gmsh_load_error("libm.so.6");
  EXPECT_NE(message.find("libm.so.6 does not define gmshFree"), std::string::npos) << message;
}

TEST(GmshLibrary, BuildsLibraryLoadsOnce) {
  EXPECT_NE(gmsh_library_file().find("libgmsh"), std::string::npos) << gmsh_library_file();
  const GmshApi* api = nullptr;
  ASSERT_NO_THROW(api = &gmsh_library());
  EXPECT_EQ(api, &gmsh_library()) << "loaded once per process";
  EXPECT_NE(api->mesh_get_elements_by_type, nullptr);  // the last function resolved
}
