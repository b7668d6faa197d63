"""Variational Shape Approximation through the real pymeshlab, as a user's script runs it."""
import os
import subprocess
import sys

import numpy as np
import pymeshlab
import pytest

from conftest import FAILED_MESHSETS, FILTER, new_meshset, snapshot

FANDISK_FACES = 12946

# The figures the filter returns and the Python type pymeshlab gives each (it drops other types).
FIGURE_TYPES = {
    "proxy_count": int, "iterations": int, "energy": float, "faces_in": int, "faces_out": int,
    "vertices_out": int, "anchors": int, "regions_fallback": int, "regions_kept_as_input": int,
    "cells_halved": int, "pieces_carved": int, "close_pairs": int, "manifold": bool, "closed": bool,
    "oriented": bool, "seconds_setup": float, "seconds_seeding": float, "seconds_iterations": float,
    "seconds_meshable": float, "seconds_meshing": float, "meshing_passes": int,
}
TIMES = {"seconds_setup", "seconds_seeding", "seconds_iterations", "seconds_meshable", "seconds_meshing"}


def test_the_filter_is_listed_with_its_parameters(vsa_loaded, capfd):
    pymeshlab.print_filter_parameter_list(FILTER)  # printed by the C++ side: capfd, not capsys
    listed = capfd.readouterr().out
    for line in ("proxynum : int", "targeterror : float = 0", "metric : str = 'L2,1'",
                 "init : str = 'Hierarchical'", "maxiterations : int = 30", "randomseed : int = 0",
                 "teleport : bool = True", "anchorthreshold : float = 0.2", "projectanchors : bool = True",
                 "polygonal : bool = True", "colorizeregions : bool = True", "anchorlayer : bool = False"):
        assert line in listed


@pytest.mark.parametrize("metric", [0, 1, "L2,1", "L2"])
@pytest.mark.parametrize("init", [0, 1, 2, "Random", "Farthest", "Hierarchical"])
def test_every_metric_and_initialization(fandisk, metric, init):
    figures = fandisk.apply_filter(FILTER, proxynum=30, metric=metric, init=init, maxiterations=10)
    k = figures["proxy_count"]  # k', when regions that would not mesh as one polygon were split
    assert 30 <= k <= 60
    assert figures["faces_in"] == FANDISK_FACES
    assert figures["manifold"] and figures["closed"] and figures["oriented"]

    assert fandisk.mesh_number() == 2
    output = fandisk.current_mesh()
    assert output.label() == f"fandisk VSA k={k}"
    assert output.face_number() == figures["faces_out"] > 0
    assert output.vertex_number() == figures["vertices_out"]
    # Face colours only: MeshLab draws a layer in its vertex colour when it has one.
    assert output.has_face_color() and not output.has_vertex_color()
    assert 2 * k - 4 <= output.face_number() <= 20 * k  # a closed genus-0 surface of k planar regions

    # The input: region index as face quality, each region's colour; the output wears the same colours.
    source = fandisk.mesh(0)
    regions = source.face_scalar_array()
    assert np.array_equal(regions, np.round(regions))
    assert set(np.unique(regions).astype(int)) == set(range(k))
    input_colors = {tuple(c) for c in source.face_color_matrix()}
    output_colors = {tuple(c) for c in output.face_color_matrix()}
    assert len(input_colors) == k
    assert output_colors == input_colors


def test_the_figures_and_their_python_types(fandisk):
    figures = fandisk.apply_filter(FILTER, proxynum=40, init="Farthest")
    assert set(figures) == set(FIGURE_TYPES)
    for key, kind in FIGURE_TYPES.items():
        assert type(figures[key]) is kind, key
    assert 40 <= figures["proxy_count"] <= 80 and figures["faces_in"] == FANDISK_FACES
    assert 0 < figures["energy"] and 1 <= figures["iterations"] <= 30
    assert figures["anchors"] <= figures["vertices_out"]
    assert figures["close_pairs"] == 0 and figures["meshing_passes"] >= 1
    assert all(figures[t] >= 0 for t in TIMES)


def test_the_output_is_shown_alone_and_named_after_the_source(fandisk):
    fandisk.apply_filter(FILTER, proxynum=60)
    assert not fandisk.mesh(0).is_visible()
    assert fandisk.mesh(1).is_visible() and fandisk.current_mesh_id() == 1
    # Approximated again: named after fandisk, not "fandisk VSA k=60 VSA k=20".
    again = fandisk.apply_filter(FILTER, proxynum=20)
    assert fandisk.current_mesh().label() == f"fandisk VSA k={again['proxy_count']}"
    assert not fandisk.mesh(1).is_visible()


def test_anchor_layer_and_no_colouring(fandisk):
    assert not fandisk.current_mesh().has_face_color()
    figures = fandisk.apply_filter(FILTER, proxynum=25, anchorlayer=True, colorizeregions=False)
    assert fandisk.mesh_number() == 3
    output, anchors = fandisk.mesh(1), fandisk.mesh(2)
    assert output.label() == f"fandisk VSA k={figures['proxy_count']}" and anchors.label() == "fandisk VSA anchors"
    assert anchors.face_number() == 0 and anchors.vertex_number() == figures["anchors"]
    # The anchors are the output's first vertices.
    assert np.array_equal(anchors.vertex_matrix(), output.vertex_matrix()[: figures["anchors"]])
    assert not fandisk.mesh(0).has_face_color() and not fandisk.mesh(0).has_face_scalar()


def test_target_error_adds_proxies_until_it_is_met(fandisk):
    coarse = fandisk.apply_filter(FILTER, targeterror=0.2)
    fine = fandisk.apply_filter(FILTER, targeterror=0.02)
    assert 1 <= coarse["proxy_count"] < fine["proxy_count"]


def test_polygonal_output_marks_one_polygon_per_region(vsa_loaded, fandisk_path, tmp_path):
    counts, saved = {}, {}
    for polygonal in (True, False):
        ms = pymeshlab.MeshSet()
        ms.load_new_mesh(str(fandisk_path))
        figures = ms.apply_filter(FILTER, proxynum=40, polygonal=polygonal, init="Farthest")
        counts[polygonal] = len(ms.current_mesh().polygonal_face_list())
        assert counts[polygonal] <= figures["faces_out"]
        # MeshLab's OBJ writer joins the faces of a polygonal layer across its faux edges.
        obj = tmp_path / f"polygonal_{polygonal}.obj"
        ms.save_current_mesh(str(obj), save_polygonal=True)
        saved[polygonal] = sum(line.startswith("f ") for line in obj.read_text().splitlines())
    assert counts[False] == saved[False] == ms.current_mesh().face_number()  # triangles only
    assert 40 <= counts[True] < counts[False] // 2
    assert saved[True] == counts[True]


def test_same_seed_same_output(vsa_loaded, fandisk_path):
    def run(seed):
        ms = pymeshlab.MeshSet()
        ms.load_new_mesh(str(fandisk_path))
        figures = ms.apply_filter(FILTER, proxynum=50, init="Random", randomseed=seed)
        out = ms.current_mesh()
        return ({k: v for k, v in figures.items() if k not in TIMES},
                out.vertex_matrix().tobytes(), out.face_matrix().tobytes(), ms.mesh(0).face_scalar_array().tobytes())

    first = run(7)
    assert run(7) == first
    assert run(8) != first


def test_a_pipeline_with_meshlabs_own_filters(fandisk, tmp_path):
    fandisk.apply_filter(FILTER, proxynum=100, init="Hierarchical")
    diagonal = fandisk.mesh(0).bounding_box().diagonal()
    to_input = fandisk.get_hausdorff_distance(sampledmesh=1, targetmesh=0, samplenum=20000)
    from_input = fandisk.get_hausdorff_distance(sampledmesh=0, targetmesh=1, samplenum=20000)
    # fandisk's 100 planes follow it within about 1% of its diagonal (README's figures).
    assert 0 < to_input["max"] / diagonal < 0.02
    assert 0 < from_input["max"] / diagonal < 0.02
    assert to_input["mean"] < to_input["max"]

    fandisk.set_current_mesh(1)
    saved = tmp_path / "fandisk_vsa.ply"
    fandisk.save_current_mesh(str(saved), binary=True)
    fandisk.set_current_mesh(0)
    fandisk.save_current_mesh(str(tmp_path / "fandisk_regions.ply"), save_face_quality=True)
    again = pymeshlab.MeshSet()
    again.load_new_mesh(str(saved))
    assert np.array_equal(again.current_mesh().face_matrix(), fandisk.mesh(1).face_matrix())
    assert np.array_equal(again.current_mesh().vertex_matrix().astype(np.float32),
                          fandisk.mesh(1).vertex_matrix().astype(np.float32))


# A closed tetrahedron, valid input for the cases below that break it in one way each.
TETRA_V = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]]
TETRA_F = [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]]
# Three triangles on one edge: a non-manifold edge.
FIN_V = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, -1, 0], [0, 0, 1]]
FIN_F = [[0, 1, 2], [1, 0, 3], [0, 1, 4]]


def bad_inputs(fandisk_path, folder):
    """(name, MeshSet, parameters, what the message says)"""
    def fandisk():
        ms = pymeshlab.MeshSet()
        ms.load_new_mesh(str(fandisk_path))
        return ms

    # pymeshlab.Mesh() refuses to be empty; a file can be.
    (folder / "empty.off").write_text("OFF\n0 0 0\n")
    empty = pymeshlab.MeshSet()
    empty.load_new_mesh(str(folder / "empty.off"))
    cloud = pymeshlab.MeshSet()
    cloud.add_mesh(pymeshlab.Mesh(vertex_matrix=np.array(TETRA_V, dtype=np.float64)), "cloud")
    nan_v = np.array(TETRA_V, dtype=np.float64)
    nan_v[3, 2] = np.nan
    return [
        ("empty mesh", empty, {"proxynum": 1}, "The mesh is empty."),
        ("point cloud", cloud, {"proxynum": 1}, "The mesh has no faces (it is a point cloud of 4 vertices)"),
        ("proxynum 0", fandisk(), {"proxynum": 0}, "The number of proxies must be at least 1 (got 0)."),
        ("proxynum above the faces", fandisk(), {"proxynum": FANDISK_FACES + 1},
         f"The number of proxies ({FANDISK_FACES + 1}) exceeds the number of faces ({FANDISK_FACES})"),
        ("negative target error", fandisk(), {"targeterror": -1.0}, "The target error must be a finite number >= 0"),
        ("NaN coordinate", new_meshset(nan_v, TETRA_F), {"proxynum": 2}, "1 vertices with NaN or infinite"),
        ("non-manifold edge", new_meshset(FIN_V, FIN_F), {"proxynum": 1}, "The mesh cannot be approximated"),
        # pymeshlab's meshes are double: beyond float's range, areas and moments would overflow.
        ("beyond the float range", new_meshset(np.array(TETRA_V) * 1e200, TETRA_F), {"proxynum": 2},
         "beyond 3.40282e+38 (the float range)"),
        # and below it, their moments (fourth powers) would underflow.
        ("below the float range", new_meshset(np.array(TETRA_V) * 1e-200, TETRA_F), {"proxynum": 2},
         "below 1.17549e-38 (the smallest normal float)"),
    ]


BAD_INPUTS = ["empty mesh", "point cloud", "proxynum 0", "proxynum above the faces", "negative target error",
              "NaN coordinate", "non-manifold edge", "beyond the float range", "below the float range"]


@pytest.mark.parametrize("case", range(len(BAD_INPUTS)), ids=BAD_INPUTS)
def test_bad_input_raises_our_message_and_changes_nothing(vsa_loaded, fandisk_path, tmp_path, case):
    name, ms, parameters, message = bad_inputs(fandisk_path, tmp_path)[case]
    before = snapshot(ms)
    FAILED_MESHSETS.append(ms)
    with pytest.raises(pymeshlab.PyMeshLabException) as raised:
        ms.apply_filter(FILTER, **parameters)
    assert message in str(raised.value), name
    assert snapshot(ms) == before, name


@pytest.mark.parametrize("scale, offset", [(3e38, 0), (1, 1e12), (1e-30, 0)],
                         ids=["near the float limit", "far from the origin", "tiny"])
def test_extreme_but_finite_coordinates_give_a_valid_output(vsa_loaded, scale, offset):
    # Four planes fit a tetrahedron exactly: its corners come back, wherever it is.
    ms = new_meshset(np.array(TETRA_V) * scale + offset, TETRA_F)
    figures = ms.apply_filter(FILTER, proxynum=4, metric="L2", init="Random")
    corners = np.sort(ms.mesh(0).vertex_matrix(), axis=0)
    output = np.sort(ms.current_mesh().vertex_matrix(), axis=0)
    assert np.isfinite(output).all() and figures["manifold"] and figures["closed"] and figures["faces_out"] == 4
    assert np.allclose(output, corners, rtol=1e-12, atol=1e-9 * scale)


def test_valid_small_input_still_works(vsa_loaded):
    # The tetrahedron the bad inputs are made from is itself accepted: the refusals above are theirs.
    ms = new_meshset(TETRA_V, TETRA_F)
    figures = ms.apply_filter(FILTER, proxynum=4)
    assert figures["proxy_count"] == 4 and figures["faces_out"] == 4 and figures["manifold"]


@pytest.mark.skipif(not os.environ.get("VSA_FOREIGN_PLUGIN"), reason="no plugin of the other precision built")
def test_a_plugin_of_the_other_precision_is_refused():
    # In a process of its own: a refused plugin stays loaded in the process.
    script = "import pymeshlab, sys\npymeshlab.load_plugin(sys.argv[1])\n"
    run = subprocess.run([sys.executable, "-c", script, os.environ["VSA_FOREIGN_PLUGIN"]],
                         capture_output=True, text=True, timeout=120)
    assert run.returncode != 0
    assert "PyMeshLabException" in run.stderr
    assert "different floating point precision" in run.stderr
