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

# Installing: MeshLab 2022.02+ loads the plugins of the user's extra-plugins folder at start (Help >
# Plugin Info > Load Plugins copies a plugin there): <AppData>/MeshLab_64bit_<fp|dp>/MeshLabExtraPlugins/
# <version>, where <AppData> is QStandardPaths' data location for MeshLab's organisation, "VCG".
if(DEFINED ENV{XDG_DATA_HOME} AND NOT "$ENV{XDG_DATA_HOME}" STREQUAL "")
  set(_vsa_user_data "$ENV{XDG_DATA_HOME}/VCG")
else()
  set(_vsa_user_data "$ENV{HOME}/.local/share/VCG")
endif()
set(VSA_MESHLAB_USER_DATA_DIR "${_vsa_user_data}" CACHE PATH
    "MeshLab 2022.02+ user data folder (holds MeshLab_64bit_fp/ and MeshLab_64bit_dp/): where \
`cmake --install` puts the FilterPlugin builds")
# Release archives, one per MeshLab version and precision, laid out as MeshLab's extra plugins are:
# build/release/filter_vsa-<version>-MeshLab-<MeshLab version>-linux.tar.gz.
add_custom_target(release_archives)

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
  if(OpenMP_CXX_FOUND)  # MeshLab itself links GCC's libgomp: the plugin shares its thread pool
    target_link_libraries(${target} PRIVATE OpenMP::OpenMP_CXX)
  endif()
  target_compile_options(${target} PRIVATE ${VSA_WARNINGS})
  set_target_properties(${target} PROPERTIES OUTPUT_NAME filter_vsa
    LIBRARY_OUTPUT_DIRECTORY "${CMAKE_CURRENT_BINARY_DIR}/meshlab-${version}")
  set_property(GLOBAL APPEND PROPERTY VSA_FILTERPLUGIN_TAGS ${tag})

  get_target_property(scalar meshlab_fp_${tag} MESHLAB_FP_SCALAR)
  set(precision fp)
  if(scalar STREQUAL "double")
    set(precision dp)
  endif()
  set(extra_plugins "MeshLab_64bit_${precision}/MeshLabExtraPlugins/${version}")
  install(TARGETS ${target} LIBRARY DESTINATION "${VSA_MESHLAB_USER_DATA_DIR}/${extra_plugins}"
    COMPONENT meshlab-${version})
  set(archive "filter_vsa-${PROJECT_VERSION}-MeshLab-${version}-linux")
  set(archive_file "${CMAKE_BINARY_DIR}/release/${archive}.tar.gz")
  add_custom_command(OUTPUT "${archive_file}"
    COMMAND ${CMAKE_COMMAND} -DPLUGIN=$<TARGET_FILE:${target}> -DNAME=${archive} -DMESHLAB_VERSION=${version}
            -DMESHLAB_SCALAR=${scalar} -DEXTRA_PLUGINS=${extra_plugins} -DOUT=${CMAKE_BINARY_DIR}/release -DSOURCE=${PROJECT_SOURCE_DIR}
            -P ${PROJECT_SOURCE_DIR}/cmake/MakeReleaseArchive.cmake
    DEPENDS ${target} ${PROJECT_SOURCE_DIR}/cmake/MakeReleaseArchive.cmake ${PROJECT_SOURCE_DIR}/LICENSE
    COMMENT "Release archive release/${archive}.tar.gz")
  # Built with everything: the tests unpack and load it as a user does.
  add_custom_target(release_archive_${tag} ALL DEPENDS "${archive_file}")
  set_target_properties(${target} PROPERTIES VSA_RELEASE_ARCHIVE "${archive_file}"
    VSA_INSTALLED_FILE "${VSA_MESHLAB_USER_DATA_DIR}/${extra_plugins}/libfilter_vsa.so")
  add_dependencies(release_archives release_archive_${tag})
endforeach()
