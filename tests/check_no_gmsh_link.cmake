# The program and the test programs do not link libgmsh: src/fem/gmsh_library.cpp loads it at the
# first mesh, so commands that never mesh do not pay for loading its ~125 shared libraries. Fails
# if a NEEDED entry of a file's dynamic section names libgmsh.
#   cmake -DOBJDUMP=<objdump> "-DFILES=<program>;<test program>..." -P check_no_gmsh_link.cmake
foreach(f IN LISTS FILES)
  execute_process(COMMAND ${OBJDUMP} -p ${f} OUTPUT_VARIABLE dynamic RESULT_VARIABLE status)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "${OBJDUMP} -p ${f} failed (status ${status})")
  endif()
  if(NOT dynamic MATCHES "NEEDED +lib")
    message(FATAL_ERROR "no NEEDED entries read from ${f}: is it a dynamically linked program?")
  endif()
  if(dynamic MATCHES "NEEDED +(libgmsh[^ \n]*)")
    message(FATAL_ERROR "${f} links ${CMAKE_MATCH_1}; gmsh is to be loaded at run time only")
  endif()
endforeach()
message(STATUS "not linked to libgmsh: ${FILES}")
