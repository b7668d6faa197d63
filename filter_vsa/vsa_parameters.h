// The filter's parameters: their names, defaults and help text, shared by every MeshLab API
// the plugin is built for. Scripts (.mlx, pymeshlab) depend on these exact names.
#ifndef FILTER_VSA_PARAMETERS_H
#define FILTER_VSA_PARAMETERS_H

#include <vsa/approximate_shape.h>

#include <QString>

class RichParameterList;
class CMeshO;

/// Everything one run of the filter needs, read from the dialog or script.
struct VsaFilterSettings
{
    vcg::tri::vsa::ShapeApproximationParam core;
    bool colorizeRegions = true;
    bool anchorLayer = false;
};

/// Adds the filter's parameters, with defaults scaled to `mesh`.
void DefineVsaParameters(RichParameterList &parameters, const CMeshO &mesh);

/// Reads the parameters back; the core checks their ranges against the mesh.
VsaFilterSettings ReadVsaParameters(const RichParameterList &parameters);

/// The filter's help text, shown in the dialog and in `meshlabserver -d`.
QString VsaFilterInfo();

#endif  // FILTER_VSA_PARAMETERS_H
