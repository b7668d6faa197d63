# cmake -P script: lays out a private MeshLab prefix (see filter_vsa/CMakeLists.txt).
set(libdir "${PREFIX}/lib/x86_64-linux-gnu/meshlab")
file(MAKE_DIRECTORY "${PREFIX}/bin" "${libdir}/plugins" "${PREFIX}/share")
foreach(exe meshlab meshlabserver)
  # Copies, not links: MeshLab resolves links to find its plugin folder.
  file(COPY "${MESHLAB_BINARY_DIR}/${exe}" DESTINATION "${PREFIX}/bin" FILE_PERMISSIONS
       OWNER_READ OWNER_WRITE OWNER_EXECUTE GROUP_READ GROUP_EXECUTE WORLD_READ WORLD_EXECUTE)
endforeach()
file(CREATE_LINK "${MESHLAB_COMMON_LIBRARY}" "${libdir}/libmeshlab-common.so" SYMBOLIC)
if(EXISTS /usr/share/meshlab AND NOT EXISTS "${PREFIX}/share/meshlab")
  file(CREATE_LINK /usr/share/meshlab "${PREFIX}/share/meshlab" SYMBOLIC)
endif()
file(GLOB stock "${STOCK_PLUGINS}/*.so")
foreach(plugin ${stock})
  get_filename_component(name "${plugin}" NAME)
  if(NOT name STREQUAL "libfilter_vsa.so")  # an installed copy of ours must not shadow the build
    file(CREATE_LINK "${plugin}" "${libdir}/plugins/${name}" SYMBOLIC)
  endif()
endforeach()
file(CREATE_LINK "${OUR_PLUGIN}" "${libdir}/plugins/libfilter_vsa.so" SYMBOLIC)
