# cmake -DPLUGIN=<libfilter_vsa.so> -DNAME=<archive name> -DMESHLAB_VERSION=<2025.07|2025.07d>
#       -DMESHLAB_SCALAR=<float|double> -DEXTRA_PLUGINS=<MeshLab_64bit_fp/MeshLabExtraPlugins/2025.07>
#       -DOUT=<folder> -DSOURCE=<project folder> -P MakeReleaseArchive.cmake
# Writes OUT/NAME.tar.gz holding NAME/libfilter_vsa.so, NAME/LICENSE and NAME/README.txt: one plugin
# for one MeshLab version and precision, as MeshLab's own extra-plugin releases ship theirs.
foreach(var PLUGIN NAME MESHLAB_VERSION MESHLAB_SCALAR EXTRA_PLUGINS OUT SOURCE)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "MakeReleaseArchive.cmake: -D${var}=... is missing")
  endif()
endforeach()

set(host "MeshLab ${MESHLAB_VERSION}")
if(MESHLAB_SCALAR STREQUAL "double")
  set(host "MeshLab ${MESHLAB_VERSION} (double precision) and pymeshlab based on it")
endif()

set(stage "${OUT}/${NAME}")
file(REMOVE_RECURSE "${stage}" "${OUT}/${NAME}.tar.gz")
file(MAKE_DIRECTORY "${stage}")
file(COPY "${PLUGIN}" "${SOURCE}/LICENSE" DESTINATION "${stage}")
file(WRITE "${stage}/README.txt"
"Variational Shape Approximation, a MeshLab filter plugin, for ${host} on Linux x86_64.
It loads only into a MeshLab whose version starts with ${MESHLAB_VERSION} and whose precision is
${MESHLAB_SCALAR} (pymeshlab.print_pymeshlab_version() prints the MeshLab it is based on; a
trailing d means double precision).

MeshLab: Help > Plugin Info > Load Plugins, and choose libfilter_vsa.so; or copy it into
  ~/.local/share/VCG/${EXTRA_PLUGINS}/
and restart MeshLab. The filter is in Filters > Remeshing, Simplification and Reconstruction >
Variational Shape Approximation.

pymeshlab:
  import pymeshlab
  pymeshlab.load_plugin('/path/to/${NAME}/libfilter_vsa.so')
  ms = pymeshlab.MeshSet()
  ms.load_new_mesh('your_mesh.ply')
  figures = ms.apply_filter('meshing_variational_shape_approximation', proxynum=50)
")
execute_process(COMMAND "${CMAKE_COMMAND}" -E tar czf "${NAME}.tar.gz" --mtime=2000-01-01 "${NAME}"
                WORKING_DIRECTORY "${OUT}" RESULT_VARIABLE failed)
if(failed)
  message(FATAL_ERROR "could not write ${OUT}/${NAME}.tar.gz")
endif()
message(STATUS "${OUT}/${NAME}.tar.gz")
