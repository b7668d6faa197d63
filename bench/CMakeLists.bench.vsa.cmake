# vsa-bench: times our partitioning on a mesh file, one JSON line out (bench/README.md).
add_executable(vsa-bench ${CMAKE_CURRENT_LIST_DIR}/vsa_bench.cpp)
target_link_libraries(vsa-bench PRIVATE vsa::vcg_core vsa::vcg_ply)
# GCC's flow analysis flags vcglib's OBJ importer once it is inlined here (a false positive in
# vcglib, not in our code); everything else stays at -Wall -Wextra.
target_compile_options(vsa-bench PRIVATE ${VSA_WARNINGS} -Wno-maybe-uninitialized)
