// MeshLab's mesh and parameter headers, which moved between the two plugin APIs the shared
// sources are built for; CMake says which one (VSA_MESHLAB_FILTERPLUGIN_API).
#ifndef FILTER_VSA_MESHLAB_HEADERS_H
#define FILTER_VSA_MESHLAB_HEADERS_H

#if !defined(VSA_MESHLAB_FILTERPLUGIN_API)
#error "VSA_MESHLAB_FILTERPLUGIN_API must be defined by the build: 0 for MeshLab 2020.09, 1 for FilterPlugin"
#elif VSA_MESHLAB_FILTERPLUGIN_API
#include <common/ml_document/cmesh.h>
#include <common/parameters/rich_parameter_list.h>
#else
#include <common/filter_parameter/rich_parameter_list.h>
#include <common/ml_mesh_type.h>
#endif

#endif  // FILTER_VSA_MESHLAB_HEADERS_H
