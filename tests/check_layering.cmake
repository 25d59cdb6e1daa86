# Fails when
#   - a source file outside src/io and src/cli includes a TOML, HDF5 or CLI11 header, or includes
#     <fstream> or opens a file (std::ifstream, std::ofstream, std::fstream, fopen): io reads and
#     writes files, the numerics folders take plain structs and arrays;
#   - any source file but src/linalg/fft.cpp includes <fftw3.h> (the project's one FFT wrapper,
#     linalg/fft.hpp, keeps the planning flags, and so the results, in one place).
file(GLOB_RECURSE files ${SRC}/*.hpp ${SRC}/*.cpp)
set(bad "")
foreach(f IN LISTS files)
  if(NOT f MATCHES "/src/linalg/fft\\.cpp$")
    file(STRINGS ${f} lines REGEX "#include *[<\"]fftw3")
    if(lines)
      list(APPEND bad "${f}: ${lines} (use linalg/fft.hpp)")
    endif()
  endif()
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
  message(FATAL_ERROR "layering rules broken:\n${bad}")
endif()
message(STATUS "layering ok")

# Dependencies point one way: a folder includes only the headers of the folders below it
# (CMakeLists.txt: contact, geometry, nss, dynamics, noise, vehicle -> pipeline -> io -> study -> cli).
set(order contact geometry nss dynamics noise vehicle pipeline io study cli)
set(wrong "")
foreach(f IN LISTS files)
  if(NOT f MATCHES "/src/([a-z]+)/")
    continue()
  endif()
  set(own ${CMAKE_MATCH_1})
  list(FIND order ${own} own_rank)
  if(own_rank LESS 0)
    continue()  # core, linalg: below everything, include nothing of the project's layers
  endif()
  file(STRINGS ${f} includes REGEX "#include \"(contact|geometry|nss|dynamics|noise|vehicle|pipeline|io|study|cli)/")
  foreach(line IN LISTS includes)
    string(REGEX MATCH "\"([a-z]+)/" _ "${line}")
    list(FIND order ${CMAKE_MATCH_1} rank)
    # the numerics folders may include each other (their CMake links say which); pipeline, io and
    # cli only what lies below them
    if(rank GREATER own_rank AND rank GREATER_EQUAL 6)
      list(APPEND wrong "${f}: ${line}")
    endif()
  endforeach()
endforeach()
if(wrong)
  message(FATAL_ERROR "includes against the layer order (contact..vehicle -> pipeline -> io -> study -> cli):\n${wrong}")
endif()
message(STATUS "include direction ok")
