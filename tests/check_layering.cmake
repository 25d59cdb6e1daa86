# Fails when a source file outside src/io and src/cli
#  - includes a TOML, HDF5 or CLI11 header, or
#  - includes <fstream> or opens a file (std::ifstream, std::ofstream, std::fstream, fopen):
# io reads and writes files, the numerics folders take plain structs and arrays.
file(GLOB_RECURSE files ${SRC}/*.hpp ${SRC}/*.cpp)
set(bad "")
foreach(f IN LISTS files)
  if(f MATCHES "/src/(io|cli)/")
    continue()
  endif()
  file(STRINGS ${f} lines REGEX "#include *[<\"](toml|hdf5|H5|CLI)")
  if(lines)
    list(APPEND bad "${f}: ${lines}")
  endif()
  file(STRINGS ${f} lines REGEX "#include *<fstream>|[^a-z_](i|o)?fstream[ ({<]|fopen *\\(")
  if(lines)
    list(APPEND bad "${f} opens files: ${lines}")
  endif()
endforeach()
if(bad)
  message(FATAL_ERROR "numerics files include I/O headers or open files:\n${bad}")
endif()
message(STATUS "layering ok")
