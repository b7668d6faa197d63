# Peers to compare against: CGAL's VSA (cgal-vsa-bench) and a measuring tool for any
# simplified mesh, e.g. MeshLab's Quadric Edge Collapse output (mesh-distance).
# Both measure with bench/surface_distance.h and vcg_core's mesh_validity.h.

add_executable(mesh-distance ${CMAKE_CURRENT_LIST_DIR}/mesh_distance.cpp)
target_link_libraries(mesh-distance PRIVATE vsa::vcg_core)
target_compile_options(mesh-distance PRIVATE ${VSA_WARNINGS})

# CGAL 5.x is header-only; its CMake config also finds GMP, MPFR and Boost.
find_package(CGAL QUIET)
if(CGAL_FOUND)
  # Built when asked for (bench/README.md), not by default: no test runs them, and they took 72 s
  # of compile time (36 s on two cores) in the test command's first run.
  add_executable(cgal-vsa-bench EXCLUDE_FROM_ALL ${CMAKE_CURRENT_LIST_DIR}/cgal_vsa_bench.cpp)
  target_link_libraries(cgal-vsa-bench PRIVATE vsa::vcg_core CGAL::CGAL)
  target_compile_options(cgal-vsa-bench PRIVATE ${VSA_WARNINGS})
  # CGAL's imported target puts its headers on the normal include path; as system headers
  # its warnings stay out of ours.
  get_target_property(VSA_CGAL_INCLUDES CGAL::CGAL INTERFACE_INCLUDE_DIRECTORIES)
  if(VSA_CGAL_INCLUDES)
    target_include_directories(cgal-vsa-bench SYSTEM PRIVATE ${VSA_CGAL_INCLUDES})
  endif()
  # Makes the large meshes of bench/make_large_meshes.sh.
  add_executable(loop-subdivide EXCLUDE_FROM_ALL ${CMAKE_CURRENT_LIST_DIR}/loop_subdivide.cpp)
  target_link_libraries(loop-subdivide PRIVATE CGAL::CGAL)
  target_compile_options(loop-subdivide PRIVATE ${VSA_WARNINGS})
  if(VSA_CGAL_INCLUDES)
    target_include_directories(loop-subdivide SYSTEM PRIVATE ${VSA_CGAL_INCLUDES})
  endif()
else()
  message(STATUS "CGAL not found: cgal-vsa-bench is skipped (install libcgal-dev to build it)")
endif()
