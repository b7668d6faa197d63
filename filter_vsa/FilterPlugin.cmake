# filter_vsa for MeshLab's FilterPlugin API (MeshLab 2022.02 .. 2025.07; what pymeshlab loads), next
# to the MeshLab 2020.09 plugin of filter_vsa/CMakeLists.txt. One module per MeshLab tree listed in
# VSA_FILTERPLUGIN_MESHLAB_DIR, compiled with that tree's MESHLAB_VERSION and MESHLAB_SCALAR (MeshLab
# and pymeshlab load a plugin only if both match theirs):
#   filter_vsa/meshlab-<MESHLAB_VERSION>/libfilter_vsa.so   (target filter_vsa_fp_<tag>)
# e.g. meshlab-2025.07 (float, MeshLab 2025.07) and meshlab-2025.07d (double, pymeshlab 2025.7).
# The sources are the 2020.09 plugin's but for the glue: VSA_MESHLAB_FILTERPLUGIN_API=1 selects the
# FilterPlugin-era MeshLab headers in the shared vsa_parameters.cpp / vsa_run.cpp.
set_property(GLOBAL PROPERTY VSA_FILTERPLUGIN_TAGS "")
if(NOT VSA_FILTERPLUGIN_MESHLAB_DIR)
  return()
endif()
include("${PROJECT_SOURCE_DIR}/cmake/MeshLabFilterPlugin.cmake")

foreach(dir IN LISTS VSA_FILTERPLUGIN_MESHLAB_DIR)
  vsa_import_meshlab_tree("${dir}" tag)
  get_target_property(version meshlab_fp_${tag} MESHLAB_FP_VERSION)
  set(target filter_vsa_fp_${tag})
  vsa_add_meshlab_filterplugin(${target} ${tag}
    ${CMAKE_CURRENT_LIST_DIR}/filter_vsa_fp.cpp ${CMAKE_CURRENT_LIST_DIR}/filter_vsa_fp.h
    ${CMAKE_CURRENT_LIST_DIR}/vsa_parameters.cpp ${CMAKE_CURRENT_LIST_DIR}/vsa_parameters.h
    ${CMAKE_CURRENT_LIST_DIR}/vsa_run.cpp ${CMAKE_CURRENT_LIST_DIR}/vsa_run.h)
  target_compile_definitions(${target} PRIVATE VSA_MESHLAB_FILTERPLUGIN_API=1)
  # vcg_core's headers, but not the vsa::vcg_core target: that would also put the 2020.09 vcglib on
  # the include path, in front of the tree's own vcglib which CMeshO must be compiled with.
  target_include_directories(${target} PRIVATE "${PROJECT_SOURCE_DIR}/vcg_core")
  target_compile_options(${target} PRIVATE ${VSA_WARNINGS})
  set_target_properties(${target} PROPERTIES OUTPUT_NAME filter_vsa
    LIBRARY_OUTPUT_DIRECTORY "${CMAKE_CURRENT_BINARY_DIR}/meshlab-${version}")
  set_property(GLOBAL APPEND PROPERTY VSA_FILTERPLUGIN_TAGS ${tag})
endforeach()
