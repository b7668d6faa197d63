"""The plugin inside the real pymeshlab wheel from PyPI (tests/pymeshlab/requirements.txt).

ctest runs this directory with .venv's Python and these variables:
  VSA_PYMESHLAB_PLUGIN   our plugin built for the wheel's MeshLab (build/filter_vsa/meshlab-2025.07d)
  VSA_FOREIGN_PLUGIN     optional: our plugin built for a MeshLab of the other precision
  VSA_RESOURCES          the project's resources/ folder
  VSA_CGAL_MESHES        optional: CGAL's sample meshes (.deps/cgal-data/meshes)
"""
import os
import pathlib

import numpy as np
import pymeshlab
import pytest

FILTER = "meshing_variational_shape_approximation"


def _path(variable):
    value = os.environ.get(variable)
    if not value:
        pytest.exit(f"{variable} is not set: run these tests through ctest (scripts/run_tests.sh)", returncode=2)
    return pathlib.Path(value)


@pytest.fixture(scope="session")
def plugin_path():
    return _path("VSA_PYMESHLAB_PLUGIN")


@pytest.fixture(scope="session")
def vsa_loaded(plugin_path):
    """Loads our plugin once per process, as a user's script does."""
    pymeshlab.load_plugin(str(plugin_path))
    return plugin_path


@pytest.fixture(scope="session")
def fandisk_path():
    return _path("VSA_RESOURCES") / "meshes" / "fandisk.off"


@pytest.fixture
def fandisk(vsa_loaded, fandisk_path):
    ms = pymeshlab.MeshSet()
    ms.load_new_mesh(str(fandisk_path))
    return ms


# pymeshlab 2025.7.post1 keeps a pointer to the log of the last MeshSet a filter ran in, and leaves it
# there when the filter fails; once that MeshSet is gone, the next mesh loaded into any MeshSet logs
# through freed memory (a crash in 2 of 3 runs of this suite, before this; the same with MeshLab's own
# filters). MeshSets a filter failed in are kept until the end of the session.
FAILED_MESHSETS = []


def snapshot(ms):
    """What a failed filter must leave as it was: the layers, the current one, every mesh's arrays."""
    meshes = []
    for i in range(ms.mesh_number()):
        m = ms.mesh(i)
        arrays = [m.vertex_matrix(), m.face_matrix()]
        if m.has_face_color():
            arrays.append(m.face_color_matrix())
        meshes.append((m.id(), m.label(), m.is_visible(), [a.tobytes() for a in arrays]))
    return ms.mesh_number(), ms.current_mesh_id(), meshes


def new_meshset(vertices, faces):
    ms = pymeshlab.MeshSet()
    mesh = pymeshlab.Mesh(np.asarray(vertices, dtype=np.float64), np.asarray(faces, dtype=np.int32))
    ms.add_mesh(mesh, "input")
    return ms
