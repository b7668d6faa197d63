# The modern MeshLab plugin API (FilterPlugin, MeshLab 2022.02+; what pymeshlab loads).
#
#   include(cmake/MeshLabFilterPlugin.cmake)
#   vsa_import_meshlab_tree(<dir> <tag_var>)
#       <dir>: a tree made by scripts/setup_filterplugin.sh (.deps/meshlab-modern/<ML_VERSION>, or
#       its build/), the pymeshlab wheel's MeshLab described by scripts/setup_pymeshlab.sh
#       (.deps/pymeshlab), or the CMake build directory of any MeshLab 2022.02+ checkout in which
#       meshlab-common was built.
#       Creates the imported target meshlab_fp_<tag>: libmeshlab-common with MeshLab's src/, its
#       vcglib and Eigen as (system) include directories and the compile definitions the library
#       was built with, MESHLAB_VERSION and MESHLAB_SCALAR. Every plugin must use exactly these:
#       PluginManager::checkPlugin rejects a plugin whose scalar precision differs, or whose
#       version differs in its first 6 characters ("2025.0").
#       <tag> is MESHLAB_VERSION made identifier-safe: "2025_07" (float), "2025_07d" (double).
#       The target carries the tree's facts as properties MESHLAB_FP_VERSION, MESHLAB_FP_SCALAR,
#       MESHLAB_FP_SOURCE_DIR, MESHLAB_FP_VCGLIB_DIR, MESHLAB_FP_COMMON_LIBRARY,
#       MESHLAB_FP_PLUGIN_DIR (MeshLab's own plugins there: io_base, filter_measure, ...),
#       MESHLAB_FP_APPLICATION (the `meshlab` executable built with the library, if any),
#       MESHLAB_FP_HOST ("meshlab": a MeshLab built here, which our own test host links to;
#       "pymeshlab": the wheel's, loaded only by pymeshlab itself), MESHLAB_FP_PYTHON (pymeshlab's
#       interpreter) and MESHLAB_FP_ORIGIN (Debian version + tarball sha256, the wheel, or the
#       build directory).
#   vsa_add_meshlab_filterplugin(<target> <tag> <sources...>)
#       a Qt plugin MODULE (lib<target>.so, AUTOMOC) for that tree.
#   vsa_add_meshlab_filterplugin_variant(<target> <tag> <version> <scalar> <sources...>)
#       tests only: a plugin compiled with another MESHLAB_VERSION / MESHLAB_SCALAR than the tree.
# DIRECTORY: Qt5::* and Eigen3::Eigen are imported per directory, and every directory that uses
# the meshlab_fp_<tag> targets needs them.
include_guard(DIRECTORY)

find_package(Qt5 5.15 COMPONENTS Core Gui Widgets OpenGL Xml Network REQUIRED)
find_package(Eigen3 3.3 REQUIRED NO_MODULE)

# Reads what scripts/setup_filterplugin.sh recorded, or works it out from a MeshLab build
# directory (its CMakeCache.txt and the flags meshlab-common was compiled with).
function(_vsa_read_meshlab_tree dir)
  foreach(info "${dir}/meshlab-build-info.cmake" "${dir}/build/meshlab-build-info.cmake")
    if(EXISTS "${info}")
      include("${info}")
      if(DEFINED MESHLAB_FP_ORIGIN_TEXT)
        set(origin "${MESHLAB_FP_ORIGIN_TEXT}")
      else()
        set(origin "Debian meshlab ${MESHLAB_FP_DEBIAN_VERSION}, tarball sha256 ${MESHLAB_FP_TARBALL_SHA256}")
      endif()
      break()
    endif()
  endforeach()
  if(NOT DEFINED MESHLAB_FP_VERSION)
    set(flags "${dir}/src/common/CMakeFiles/meshlab-common.dir/flags.make")
    if(NOT EXISTS "${dir}/CMakeCache.txt" OR NOT EXISTS "${flags}")
      message(FATAL_ERROR "${dir} is neither a tree made by scripts/setup_filterplugin.sh nor a MeshLab "
                          "build directory in which meshlab-common was built")
    endif()
    load_cache("${dir}" READ_WITH_PREFIX _ml_ MeshLab_SOURCE_DIR VCGLib_SOURCE_DIR)
    file(STRINGS "${flags}" defines REGEX "^CXX_DEFINES")
    string(REGEX MATCH "-DMESHLAB_VERSION=([^ ]+)" _ "${defines}")
    set(MESHLAB_FP_VERSION "${CMAKE_MATCH_1}")
    string(REGEX MATCH "-DMESHLAB_SCALAR=([^ ]+)" _ "${defines}")
    set(MESHLAB_FP_SCALAR "${CMAKE_MATCH_1}")
    set(MESHLAB_FP_SOURCE_DIR "${_ml_MeshLab_SOURCE_DIR}/src")
    set(MESHLAB_FP_VCGLIB_DIR "${_ml_VCGLib_SOURCE_DIR}")
    if(NOT MESHLAB_FP_VCGLIB_DIR)
      set(MESHLAB_FP_VCGLIB_DIR "${MESHLAB_FP_SOURCE_DIR}/vcglib")
    endif()
    file(GLOB_RECURSE libs LIST_DIRECTORIES false "${dir}/libmeshlab-common.so")
    if(libs)
      list(GET libs 0 MESHLAB_FP_COMMON_LIBRARY)
    endif()
    get_filename_component(distrib "${MESHLAB_FP_COMMON_LIBRARY}" DIRECTORY)
    set(MESHLAB_FP_PLUGIN_DIR "${distrib}/plugins")
    if(EXISTS "${distrib}/meshlab")
      set(MESHLAB_FP_APPLICATION "${distrib}/meshlab")
    endif()
    set(origin "MeshLab build directory ${dir}")
  endif()
  if(NOT MESHLAB_FP_VERSION OR NOT MESHLAB_FP_SCALAR OR NOT EXISTS "${MESHLAB_FP_COMMON_LIBRARY}"
     OR NOT EXISTS "${MESHLAB_FP_SOURCE_DIR}/common/plugins/interfaces/filter_plugin.h")
    message(FATAL_ERROR "${dir}: no FilterPlugin-era MeshLab there (MESHLAB_VERSION '${MESHLAB_FP_VERSION}', "
                        "MESHLAB_SCALAR '${MESHLAB_FP_SCALAR}', library '${MESHLAB_FP_COMMON_LIBRARY}', "
                        "sources '${MESHLAB_FP_SOURCE_DIR}')")
  endif()
  if(NOT DEFINED MESHLAB_FP_HOST)
    set(MESHLAB_FP_HOST "meshlab")
  endif()
  foreach(var VERSION SCALAR SOURCE_DIR VCGLIB_DIR COMMON_LIBRARY PLUGIN_DIR APPLICATION HOST PYTHON)
    set(MESHLAB_FP_${var} "${MESHLAB_FP_${var}}" PARENT_SCOPE)
  endforeach()
  set(MESHLAB_FP_ORIGIN "${origin}" PARENT_SCOPE)
endfunction()

function(vsa_import_meshlab_tree dir tag_var)
  get_filename_component(dir "${dir}" ABSOLUTE)
  _vsa_read_meshlab_tree("${dir}")
  string(REGEX REPLACE "[^A-Za-z0-9_]" "_" tag "${MESHLAB_FP_VERSION}")
  set(target meshlab_fp_${tag})
  if(TARGET ${target})
    get_target_property(lib ${target} MESHLAB_FP_COMMON_LIBRARY)
    if(NOT lib STREQUAL MESHLAB_FP_COMMON_LIBRARY)
      message(FATAL_ERROR "Two MeshLab trees with MESHLAB_VERSION ${MESHLAB_FP_VERSION}: ${lib} and "
                          "${MESHLAB_FP_COMMON_LIBRARY}; give one of them")
    endif()
    set(${tag_var} ${tag} PARENT_SCOPE)
    return()
  endif()
  add_library(${target} SHARED IMPORTED GLOBAL)
  set_target_properties(${target} PROPERTIES
    IMPORTED_LOCATION "${MESHLAB_FP_COMMON_LIBRARY}"
    IMPORTED_SONAME "libmeshlab-common.so"
    # SYSTEM: MeshLab's, vcglib's and Eigen's headers do not compile warning-free.
    INTERFACE_SYSTEM_INCLUDE_DIRECTORIES "${MESHLAB_FP_SOURCE_DIR};${MESHLAB_FP_VCGLIB_DIR}"
    INTERFACE_INCLUDE_DIRECTORIES "${MESHLAB_FP_SOURCE_DIR};${MESHLAB_FP_VCGLIB_DIR}"
    INTERFACE_COMPILE_DEFINITIONS "MESHLAB_VERSION=${MESHLAB_FP_VERSION};MESHLAB_SCALAR=${MESHLAB_FP_SCALAR}"
    INTERFACE_LINK_LIBRARIES "Qt5::Core;Qt5::Gui;Qt5::Widgets;Qt5::OpenGL;Qt5::Xml;Qt5::Network;Eigen3::Eigen")
  foreach(var VERSION SCALAR SOURCE_DIR VCGLIB_DIR COMMON_LIBRARY PLUGIN_DIR APPLICATION HOST PYTHON ORIGIN)
    set_property(TARGET ${target} PROPERTY MESHLAB_FP_${var} "${MESHLAB_FP_${var}}")
  endforeach()
  message(STATUS "MeshLab FilterPlugin API: ${MESHLAB_FP_VERSION} (${MESHLAB_FP_SCALAR}) from ${MESHLAB_FP_ORIGIN}: "
                 "${MESHLAB_FP_COMMON_LIBRARY}")
  set(${tag_var} ${tag} PARENT_SCOPE)
endfunction()

# A MeshLab FilterPlugin module: lib<target>.so, like MeshLab's own plugins.
function(vsa_add_meshlab_filterplugin target tag)
  add_library(${target} MODULE ${ARGN})
  # No run path: the host has loaded libmeshlab-common and Qt before it loads a plugin, and one
  # pointing into this build tree (or at pymeshlab's .venv) has no place in a released plugin.
  set_target_properties(${target} PROPERTIES AUTOMOC ON PREFIX "lib" SKIP_BUILD_RPATH ON)
  target_link_libraries(${target} PRIVATE meshlab_fp_${tag})
  # MeshLab builds its plugins with -Wl,--no-undefined: so do we, to catch missing symbols at
  # link time rather than at QPluginLoader time.
  target_link_options(${target} PRIVATE "LINKER:--no-undefined")
endfunction()

# For tests of the PluginManager's checks only: a plugin compiled with another MESHLAB_VERSION /
# MESHLAB_SCALAR than the library it links to (no --no-undefined: with another scalar type, the
# Scalarm-typed symbols it uses do not exist in that library).
function(vsa_add_meshlab_filterplugin_variant target tag version scalar)
  add_library(${target} MODULE ${ARGN})
  set_target_properties(${target} PROPERTIES AUTOMOC ON PREFIX "lib")
  get_target_property(sources meshlab_fp_${tag} MESHLAB_FP_SOURCE_DIR)
  get_target_property(vcglib meshlab_fp_${tag} MESHLAB_FP_VCGLIB_DIR)
  get_target_property(lib meshlab_fp_${tag} MESHLAB_FP_COMMON_LIBRARY)
  target_include_directories(${target} SYSTEM PRIVATE "${sources}" "${vcglib}")
  target_compile_definitions(${target} PRIVATE MESHLAB_VERSION=${version} MESHLAB_SCALAR=${scalar})
  target_link_libraries(${target} PRIVATE "${lib}" Qt5::Core Qt5::Gui Qt5::Widgets Qt5::OpenGL Qt5::Xml
                        Qt5::Network Eigen3::Eigen)
endfunction()

# The tags of the FilterPlugin builds (VSA_FILTERPLUGIN_TAGS) whose MeshLab is <host>: "meshlab" or
# "pymeshlab".
function(vsa_filterplugin_tags_of_host host out_var)
  get_property(tags GLOBAL PROPERTY VSA_FILTERPLUGIN_TAGS)
  set(result "")
  foreach(tag IN LISTS tags)
    get_target_property(tag_host meshlab_fp_${tag} MESHLAB_FP_HOST)
    if(tag_host STREQUAL host)
      list(APPEND result ${tag})
    endif()
  endforeach()
  set(${out_var} ${result} PARENT_SCOPE)
endfunction()

# Our plugin files built for MeshLabs of another precision than <tag>'s, which <tag>'s MeshLab must refuse.
function(vsa_filterplugin_foreign_plugins tag out_var)
  get_property(tags GLOBAL PROPERTY VSA_FILTERPLUGIN_TAGS)
  get_target_property(scalar meshlab_fp_${tag} MESHLAB_FP_SCALAR)
  set(result "")
  foreach(other IN LISTS tags)
    get_target_property(other_scalar meshlab_fp_${other} MESHLAB_FP_SCALAR)
    if(NOT other_scalar STREQUAL scalar)
      list(APPEND result "$<TARGET_FILE:filter_vsa_fp_${other}>")
    endif()
  endforeach()
  set(${out_var} ${result} PARENT_SCOPE)
endfunction()
