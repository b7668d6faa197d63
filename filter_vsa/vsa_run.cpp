#include "vsa_run.h"

#include "meshlab_headers.h"

#include <vcg/complex/allocate.h>

#include <QFileInfo>
#include <QRegularExpression>

#include <exception>
#include <new>

namespace vsa = vcg::tri::vsa;

namespace {

const char *MetricName(vsa::MetricKind metric) { return metric == vsa::MetricKind::L21 ? "L2,1" : "L2"; }

const char *InitName(vsa::SeedingMethod init)
{
    switch (init) {
    case vsa::SeedingMethod::Random: return "random";
    case vsa::SeedingMethod::Farthest: return "farthest";
    case vsa::SeedingMethod::Hierarchical: return "hierarchical";
    }
    return "?";
}

vcg::Color4b RegionColor(int region, int regionCount)
{
    return vcg::Color4b::Scatter(std::max(regionCount, 1), region, 0.4f, 0.9f);
}

void Describe(const vsa::ShapeApproximationResult &r, const VsaFilterSettings &settings, VsaRunOutcome &outcome)
{
    const vsa::ApproximationResult &p = r.partition;
    const vsa::MeshingReport &m = r.meshing;
    QStringList &log = outcome.log;
    log << QString("VSA: input: %1").arg(QString::fromStdString(r.input.Summary()));
    for (const std::string &message : p.messages) log << QString("VSA: %1").arg(QString::fromStdString(message));
    log << QString("VSA: k=%1 proxies, %2 metric, %3 seeding, %4 Lloyd iterations, "
                   "distortion %5 (%6 of one proxy per component)")
               .arg(p.proxyCount)
               .arg(MetricName(settings.core.partition.metric))
               .arg(InitName(settings.core.partition.init))
               .arg(p.iterations)
               .arg(p.energy, 0, 'g', 6)
               .arg(p.referenceEnergy > 0 ? p.energy / p.referenceEnergy : 0.0, 0, 'g', 4);
    log << QString("VSA: faces in %1 -> faces out %2 (%3 vertices, %4 anchors)")
               .arg(r.input.faces)
               .arg(m.validity.faces)
               .arg(m.validity.vertices)
               .arg(m.anchors);
    log << QString("VSA: regions meshed by flooding %1, by ear-clipping fallback %2, with an extra vertex %3, "
                   "kept as input faces against self-intersections %4, cut into discs %5; "
                   "cells halved against self-intersections %6, pieces carved out of cells %7")
               .arg(m.regionsByFlooding)
               .arg(m.regionsByEarClipping)
               .arg(m.regionsWithSteinerVertex)
               .arg(m.regionsKeptAsInput)
               .arg(m.regionsCut)
               .arg(m.cellsHalved)
               .arg(m.piecesCarved);
    log << QString("VSA: output: %1").arg(QString::fromStdString(m.validity.Summary()));
    if (m.closePairs > 0)
        log << QString("VSA: warning: %1 face pairs of the output come closer than text files (OFF, OBJ, ASCII PLY "
                       "or STL) keep them apart: read back, they may intersect; binary PLY keeps them exactly")
                   .arg(m.closePairs);
    log << QString("VSA: time: setup %1 s, seeding %2 s, iterations %3 s, meshable split %4 s, meshing %5 s (%6), "
                   "total %7 s")
               .arg(r.secondsSetup, 0, 'f', 3)
               .arg(r.secondsSeeding, 0, 'f', 3)
               .arg(r.secondsIterations, 0, 'f', 3)
               .arg(r.secondsMeshable, 0, 'f', 3)
               .arg(r.secondsMeshing, 0, 'f', 3)
               .arg(m.passes == 1 ? QString("1 pass") : QString("%1 passes").arg(m.passes))
               .arg(r.secondsSetup + r.secondsSeeding + r.secondsIterations + r.secondsMeshable + r.secondsMeshing, 0,
                    'f', 3);

    auto &f = outcome.figures;
    f["proxy_count"] = p.proxyCount;
    f["iterations"] = p.iterations;
    f["energy"] = p.energy;
    f["faces_in"] = r.input.faces;
    f["faces_out"] = m.validity.faces;
    f["vertices_out"] = m.validity.vertices;
    f["anchors"] = m.anchors;
    f["regions_fallback"] = m.regionsByEarClipping + m.regionsWithSteinerVertex + m.regionsKeptAsInput;
    f["regions_kept_as_input"] = m.regionsKeptAsInput;
    f["cells_halved"] = m.cellsHalved;
    f["pieces_carved"] = m.piecesCarved;
    f["close_pairs"] = m.closePairs;
    f["manifold"] = m.validity.IsTwoManifold();
    f["closed"] = m.validity.IsClosed();
    f["oriented"] = m.validity.IsOriented();
    f["seconds_setup"] = r.secondsSetup;
    f["seconds_seeding"] = r.secondsSeeding;
    f["seconds_iterations"] = r.secondsIterations;
    f["seconds_meshable"] = r.secondsMeshable;
    f["seconds_meshing"] = r.secondsMeshing;
    f["meshing_passes"] = m.passes;
}

}  // namespace

VsaRunOutcome RunVsa(const CMeshO &input, const VsaFilterSettings &settings, CMeshO &approximation,
                     CMeshO *anchors, vcg::CallBackPos *cb)
{
    VsaRunOutcome outcome;
    try {
        approximation.Clear();
        if (settings.colorizeRegions) approximation.face.EnableColor();
        const vsa::ShapeApproximationResult r = vsa::ApproximateShape(input, approximation, settings.core, cb);
        if (!r.ok) {
            outcome.error = QString::fromStdString(r.error);
            return outcome;
        }
        Describe(r, settings, outcome);
        outcome.regionCount = r.partition.proxyCount;
        outcome.faceRegion = r.inputFaceRegion;
        if (settings.colorizeRegions)
            for (size_t f = 0; f < approximation.face.size(); ++f)
                approximation.face[f].C() = RegionColor(r.meshing.faceRegion[f], outcome.regionCount);
        if (anchors) {
            anchors->Clear();
            // The meshing writes the anchors first, then any extra (fan) vertices.
            for (int v = 0; v < r.meshing.anchors; ++v)
                vcg::tri::Allocator<CMeshO>::AddVertex(*anchors, approximation.vert[v].cP());
        }
        outcome.ok = true;
    } catch (const std::bad_alloc &) {
        outcome.error = "Out of memory.";
    } catch (const std::exception &e) {
        outcome.error = QString::fromStdString(e.what());
    } catch (...) {
        outcome.error = "Unknown error.";
    }
    return outcome;
}

void ColorizeRegions(CMeshO &mesh, const std::vector<int> &faceRegion, int regionCount)
{
    for (size_t f = 0; f < mesh.face.size() && f < faceRegion.size(); ++f) {
        if (faceRegion[f] < 0) continue;
        mesh.face[f].C() = RegionColor(faceRegion[f], regionCount);
        mesh.face[f].Q() = CMeshO::ScalarType(faceRegion[f]);
    }
}

namespace {

/// "fandisk" for the layer "fandisk.off", and for "fandisk VSA k=129", an earlier output of ours.
QString SourceMeshName(const QString &inputLabel)
{
    // An approximation approximated again is named after the mesh it came from, not "... VSA k=129 VSA k=40".
    static const QRegularExpression ourSuffix("( VSA k=\\d+)+$");
    return QFileInfo(inputLabel).completeBaseName().remove(ourSuffix);
}

}  // namespace

QString ApproximationLayerName(const QString &inputLabel, int regionCount)
{
    return QString("%1 VSA k=%2").arg(SourceMeshName(inputLabel)).arg(regionCount);
}

QString AnchorLayerName(const QString &inputLabel)
{
    return SourceMeshName(inputLabel) + " VSA anchors";
}
