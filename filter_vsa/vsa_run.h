// One run of the filter on a MeshLab mesh, independent of the plugin API: the shared wrapper
// between the dialog's parameters, vcg_core and the layers the glue adds.
#ifndef FILTER_VSA_RUN_H
#define FILTER_VSA_RUN_H

#include "vsa_parameters.h"

#include <QString>
#include <QStringList>
#include <QVariant>

#include <map>
#include <string>
#include <vector>

class CMeshO;

struct VsaRunOutcome
{
    bool ok = false;
    QString error;                              ///< why the run failed, for the user
    QStringList log;                            ///< what happened, one line each
    std::map<std::string, QVariant> figures;    ///< the run's numbers (FilterPlugin returns them)
    int regionCount = 0;
    std::vector<int> faceRegion;                ///< per input face (container order); -1 if deleted
};

/// Runs the whole pipeline on `input`; fills `approximation` and, when given, `anchors` (a
/// point cloud). Never throws and never changes `input`: failures come back in `error`.
VsaRunOutcome RunVsa(const CMeshO &input, const VsaFilterSettings &settings, CMeshO &approximation,
                     CMeshO *anchors, vcg::CallBackPos *cb);

/// Colours the faces of `mesh` by region and stores the region index as per-face quality.
/// Needs per-face colour and quality enabled on `mesh`.
void ColorizeRegions(CMeshO &mesh, const std::vector<int> &faceRegion, int regionCount);

/// "fandisk VSA k=40" for the layer "fandisk.off" or "fandisk VSA k=129".
QString ApproximationLayerName(const QString &inputLabel, int regionCount);

/// "fandisk VSA anchors" for the layer "fandisk.off" or "fandisk VSA k=129".
QString AnchorLayerName(const QString &inputLabel);

#endif  // FILTER_VSA_RUN_H
