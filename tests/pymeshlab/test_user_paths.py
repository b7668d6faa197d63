"""What a pymeshlab user runs: the example, the README's snippet, a release archive, `cmake --install`."""
import filecmp
import os
import pathlib
import re
import subprocess
import sys
import tarfile

import pymeshlab
import pytest

from conftest import FILTER

SOURCE = pathlib.Path(os.environ.get("VSA_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))

# Loads a plugin and approximates fandisk in a fresh process, as a user's script does.
LOAD_AND_RUN = f"""
import sys, pymeshlab
pymeshlab.load_plugin(sys.argv[1])
ms = pymeshlab.MeshSet()
ms.load_new_mesh(sys.argv[2])
figures = ms.apply_filter('{FILTER}', proxynum=30)
print('faces_out', figures['faces_out'], ms.current_mesh().face_number(), figures['proxy_count'],
      ms.current_mesh().label())
"""


def run_python(*arguments, cwd=None):
    return subprocess.run([sys.executable, *map(str, arguments)], capture_output=True, text=True, timeout=300,
                          cwd=cwd)


def assert_loads_and_runs(plugin, fandisk_path):
    run = run_python("-c", LOAD_AND_RUN, plugin, fandisk_path)
    assert run.returncode == 0, run.stderr
    _, reported, faces, k, *label = run.stdout.split()
    assert int(reported) == int(faces) > 30 and 30 <= int(k) <= 60 and " ".join(label) == f"fandisk VSA k={k}"


def test_the_example_on_a_users_mesh(plugin_path, fandisk_path, tmp_path):
    run = run_python(SOURCE / "examples" / "vsa_pymeshlab.py", fandisk_path, "--k", "40", "--init", "Farthest",
                     "--out-dir", tmp_path, "--plugin", plugin_path)
    assert run.returncode == 0, run.stderr
    k = int(re.search(r"proxy_count +(\d+)\n", run.stdout).group(1))
    assert 40 <= k <= 80 and f"fandisk VSA k={k}" in run.stdout
    assert re.search(r"Hausdorff approximation -> input: max 0\.00\d+", run.stdout)
    polygons = int(re.search(r"\((\d+) polygons\)", run.stdout).group(1))
    assert polygons >= k

    ms = pymeshlab.MeshSet()
    ms.load_new_mesh(str(tmp_path / "fandisk_vsa.ply"))
    faces_out = int(re.search(r"faces_out +(\d+)", run.stdout).group(1))
    assert ms.current_mesh().face_number() == faces_out
    assert len(ms.current_mesh().polygonal_face_list()) == polygons  # the face flags came back
    off = (tmp_path / "fandisk_vsa_polygons.off").read_text().split("\n")
    assert off[0] == "OFF" and int(off[1].split()[1]) == polygons
    ms.load_new_mesh(str(tmp_path / "fandisk_regions.ply"))
    assert ms.current_mesh().face_number() == 12946 and ms.current_mesh().has_face_scalar()


def test_the_example_reports_bad_input(plugin_path, tmp_path):
    cloud = tmp_path / "cloud.off"
    cloud.write_text("OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 0\n")
    run = run_python(SOURCE / "examples" / "vsa_pymeshlab.py", cloud, "--plugin", plugin_path)
    assert run.returncode == 1 and "point cloud of 3 vertices" in run.stderr


def test_the_readme_snippet_as_pasted(plugin_path):
    """The README's pymeshlab block, run as it is from the project's folder."""
    readme = (SOURCE / "README.md").read_text()
    block = re.search(r"<!-- pymeshlab snippet -->\n```sh\n(.*?)```", readme, re.S)
    assert block, "README.md has no block marked <!-- pymeshlab snippet -->"
    script = block.group(1)
    assert str(plugin_path.relative_to(SOURCE)) in script  # the plugin this test loads is the one it names
    run = subprocess.run(["bash", "-euo", "pipefail", "-c", script], cwd=SOURCE, capture_output=True, text=True,
                         timeout=300)
    assert run.returncode == 0, run.stderr
    assert re.search(r"^(4\d|[5-7]\d|80) \d+ \S+ True$", run.stdout, re.M), run.stdout  # k' in [40, 80]


def test_the_release_archive_unpacks_and_loads(fandisk_path, tmp_path):
    archive = pathlib.Path(os.environ["VSA_RELEASE_ARCHIVE"])
    with tarfile.open(archive) as tar:
        names = sorted(tar.getnames())
        tar.extractall(tmp_path, filter="data")
    top = archive.name.removesuffix(".tar.gz")
    assert names == [top, f"{top}/LICENSE", f"{top}/README.txt", f"{top}/libfilter_vsa.so"]
    assert "pymeshlab.load_plugin" in (tmp_path / top / "README.txt").read_text()
    assert_loads_and_runs(tmp_path / top / "libfilter_vsa.so", fandisk_path)


def test_cmake_install_puts_the_plugin_where_meshlab_looks(plugin_path, fandisk_path, tmp_path):
    installed = pathlib.Path(os.environ["VSA_INSTALLED_PLUGIN"])
    assert installed.is_absolute() and "/VCG/MeshLab_64bit_" in str(installed)
    run = subprocess.run([os.environ["VSA_CMAKE"], "--install", os.environ["VSA_BUILD_DIR"],
                          "--component", os.environ["VSA_INSTALL_COMPONENT"]],
                         env={**os.environ, "DESTDIR": str(tmp_path)}, capture_output=True, text=True, timeout=120)
    assert run.returncode == 0, run.stderr
    staged = tmp_path / installed.relative_to("/")
    assert filecmp.cmp(staged, plugin_path, shallow=False)
    assert sorted(p.name for p in tmp_path.rglob("*") if p.is_file()) == ["libfilter_vsa.so"]
    assert_loads_and_runs(staged, fandisk_path)
