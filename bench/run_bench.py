#!/usr/bin/env python3
"""Benchmark our VSA against its peers on the same meshes, k and initialisation.

Per case (mesh x k x init) it runs, in one go:
  ours    vsa-bench       (our driver; $VSA_BENCH or build/bench/vsa-bench)
  cgal    cgal-vsa-bench  (CGAL 5.5's Variational_shape_approximation)
  qecd    MeshLab's "Simplification: Quadric Edge Collapse Decimation" through
          `xvfb-run -a meshlabserver`, at the face count of our output (CGAL's if ours has
          none), measured with mesh-distance
Every record goes to <out>/results.jsonl, output meshes to <out>/meshes/, and a comparison
table to stdout and <out>/table.txt. A driver that is missing or prints fewer keys only
leaves '-' in the table; an output mesh without measurements is measured with mesh-distance.

Python 3 standard library only. See bench/README.md.
"""

import argparse
import datetime
import json
import os
import shutil
import subprocess
import sys
import time

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
MESHES_DIR = os.environ.get("VSA_MESHES", os.path.join(REPO, ".deps", "cgal-data", "meshes"))

SETS = {
    # A couple of minutes: two small CAD-like meshes, every init.
    "quick": dict(meshes=["fandisk", "blade"], k=[20, 100], init=["random", "farthest", "hierarchical"]),
    "full": dict(meshes=["fandisk", "blade", "turbine", "bunny00", "armadillo"], k=[20, 100, 500, 2000],
                 init=["random", "farthest", "hierarchical"]),
}

# MeshLab 2020.09 aborts unless a script gives every parameter of the filter, in this order
# (meshfilter.cpp, FP_QUADRIC_SIMPLIFICATION). Values are MeshLab's dialog defaults except
# PreserveNormal and PreserveTopology: VSA keeps the topology and orientation, so the peer
# is asked to as well.
QECD_PARAMETERS = [
    ("RichInt", "TargetFaceNum", None),  # filled per case
    ("RichFloat", "TargetPerc", "0"),
    ("RichFloat", "QualityThr", "0.3"),
    ("RichBool", "PreserveBoundary", "false"),
    ("RichFloat", "BoundaryWeight", "0.5"),
    ("RichBool", "PreserveNormal", "true"),
    ("RichBool", "PreserveTopology", "true"),
    ("RichBool", "OptimalPlacement", "true"),
    ("RichBool", "PlanarQuadric", "false"),
    ("RichFloat", "PlanarWeight", "0.001"),
    ("RichBool", "QualityWeight", "false"),
    ("RichBool", "AutoClean", "true"),
    ("RichBool", "Selected", "false"),
]

MEASURE_KEYS = ["out_vertices", "out_faces", "manifold", "closed", "oriented", "euler_in", "euler_out",
                "degenerate_faces", "duplicate_faces", "self_intersections", "closed_in",
                "hausdorff_max", "hausdorff_mean", "hausdorff_rms", "facing_away", "normal_deviation_deg",
                "polygons", "polygons_from", "triangles_per_region"]


def find_tool(env_name, names):
    """The tool named by the environment variable, else the first build that has it."""
    if os.environ.get(env_name):
        return os.environ[env_name]
    for build in ["build", "build-cgal"]:
        for name in names:
            path = os.path.join(REPO, build, "bench", name)
            if os.access(path, os.X_OK):
                return path
    return None


def run_json(command, timeout):
    """Runs a command; returns (record, seconds). The record is its last JSON line, or a
    record with 'error' saying why there is none."""
    start = time.monotonic()
    try:
        done = subprocess.run(command, capture_output=True, text=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        return {"error": "timed out after %ds" % timeout}, time.monotonic() - start
    except OSError as e:  # e.g. $VSA_BENCH names a file that is not there
        return {"error": str(e)}, 0.0
    seconds = time.monotonic() - start
    for line in reversed(done.stdout.splitlines()):
        line = line.strip()
        if line.startswith("{"):
            try:
                return json.loads(line), seconds
            except json.JSONDecodeError:
                break
    tail = (done.stderr.strip().splitlines() or ["no JSON line"])[-1]
    return {"error": "exit %d: %s" % (done.returncode, tail)}, seconds


def measure_missing(record, mesh_path, out_mesh, mesh_distance, timeout):
    """Fills the validity and distance keys a driver did not print, from its output mesh.
    Only a driver that reports out_faces wrote an approximation to --out (before meshing
    exists, vsa-bench writes the coloured input there)."""
    if ("out_faces" not in record or "hausdorff_max" in record or not mesh_distance
            or not os.path.exists(out_mesh)):
        return
    measured, _ = run_json([mesh_distance, mesh_path, out_mesh], timeout)
    for key in MEASURE_KEYS:
        if key in measured and key not in record:
            record[key] = measured[key]
    record["measured_by"] = "mesh-distance"


def labels_path(out_mesh):
    """Where a driver writes the polygon label of each face of `out_mesh` (--polygon-labels)."""
    return os.path.splitext(out_mesh)[0] + ".labels"


def write_qecd_script(path, target_faces):
    lines = ["<!DOCTYPE FilterScript>", "<FilterScript>",
             ' <filter name="Simplification: Quadric Edge Collapse Decimation">']
    for kind, name, value in QECD_PARAMETERS:
        shown = target_faces if value is None else value
        lines.append('  <Param type="%s" value="%s" name="%s"/>' % (kind, shown, name))
    lines += [" </filter>", "</FilterScript>", ""]
    with open(path, "w") as f:
        f.write("\n".join(lines))


def run_qecd(mesh_path, target_faces, out_dir, name, mesh_distance, timeout):
    out_mesh = os.path.join(out_dir, "meshes", "%s_qecd%d.off" % (name, target_faces))
    script = os.path.join(out_dir, "meshes", "%s_qecd%d.mlx" % (name, target_faces))
    write_qecd_script(script, target_faces)
    start = time.monotonic()
    try:
        done = subprocess.run(["xvfb-run", "-a", "meshlabserver", "-i", mesh_path, "-o", out_mesh, "-s", script],
                              capture_output=True, text=True, timeout=timeout)
        failed = done.returncode != 0 or not os.path.exists(out_mesh)
        reason = "meshlabserver exit %d" % done.returncode
    except (subprocess.TimeoutExpired, OSError) as e:
        failed, reason = True, str(e)
    record = {"tool": "qecd", "target_faces": target_faces,
              # Whole meshlabserver process: start-up, reading, decimation, writing.
              "t_mesh_s": time.monotonic() - start}
    if failed:
        record["error"] = reason
        return record
    # The polygon labels beside the mesh are for bench/render_mesh.py's outlines.
    measured, _ = run_json([mesh_distance, mesh_path, out_mesh, "--polygon-labels", labels_path(out_mesh)], timeout)
    measured.pop("input", None)
    measured.pop("simplified", None)
    record.update(measured)
    return record


def fmt(value, spec="%.3g"):
    if value is None:
        return "-"
    if isinstance(value, bool):
        return "yes" if value else "no"
    if isinstance(value, float):
        return spec % value
    return str(value)


def validity_label(r):
    """'ok', or the defects found, e.g. 'nonmanifold dup16 si17'."""
    if r.get("error"):
        return "ERROR"
    if "manifold" not in r:
        return "no-output" if r.get("valid_output") is False else "-"
    problems = []
    if not r.get("manifold"):
        problems.append("nonmanifold")
    if not r.get("oriented"):
        problems.append("unoriented")
    if r.get("closed_in") and not r.get("closed"):
        problems.append("open")
    for key, tag in [("degenerate_faces", "deg"), ("duplicate_faces", "dup"), ("self_intersections", "si")]:
        if (r.get(key) or 0) > 0:
            problems.append("%s%d" % (tag, r[key]))
    return " ".join(problems) or "ok"


def per_iteration_us_per_face(r):
    try:
        return r["t_iterations_s"] / r["iterations_run"] / r["faces"] * 1e6
    except (KeyError, TypeError, ZeroDivisionError):
        return None


def table(records):
    header = ["mesh", "k", "init", "tool", "energy", "us/f/it", "t_seed", "t_iter", "t_mesh", "RSS MB",
              "out_f", "valid", "H max", "H mean", "away %"]
    rows = [header]
    for r in records:
        rows.append([r["case_mesh"], str(r["case_k"]), r["case_init"], r.get("tool", "-"),
                     fmt(r.get("energy"), "%.5g"), fmt(per_iteration_us_per_face(r), "%.3f"),
                     fmt(r.get("t_seed_s")), fmt(r.get("t_iterations_s")), fmt(r.get("t_mesh_s")),
                     fmt(r.get("peak_rss_mb"), "%.0f"), fmt(r.get("out_faces")), validity_label(r),
                     fmt(r.get("hausdorff_max"), "%.2e"), fmt(r.get("hausdorff_mean"), "%.2e"),
                     fmt(None if r.get("facing_away") is None else 100 * r["facing_away"], "%.2f")])
    widths = [max(len(row[i]) for row in rows) for i in range(len(header))]
    lines = ["  ".join(cell.ljust(w) for cell, w in zip(row, widths)).rstrip() for row in rows]
    lines.insert(1, "  ".join("-" * w for w in widths))
    lines.append("")
    lines.append("energy: the metric's total distortion; us/f/it = t_iterations_s / iterations / faces * 1e6;"
                 " times in s;")
    lines.append("qecd t_mesh is the whole meshlabserver process; H = symmetric Hausdorff / input bbox diagonal;")
    lines.append("away % = share of the output's area whose nearest input face points the other way (folds);")
    lines.append("errors: see results.jsonl.")
    return "\n".join(lines)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    sets = parser.add_mutually_exclusive_group()
    sets.add_argument("--quick", dest="set", action="store_const", const="quick", default="quick",
                      help="fandisk, blade; k 20,100; every init (the default)")
    sets.add_argument("--full", dest="set", action="store_const", const="full",
                      help="fandisk, blade, turbine, bunny00, armadillo; k 20,100,500,2000; every init")
    parser.add_argument("--meshes", help="comma-separated mesh names in %s, or paths" % MESHES_DIR)
    parser.add_argument("--k", help="comma-separated proxy counts")
    parser.add_argument("--init", help="comma-separated: random,farthest,hierarchical")
    parser.add_argument("--metric", default="l21", choices=["l21", "l2"])
    parser.add_argument("--iterations", type=int, default=30)
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--tools", default="ours,cgal,qecd", help="which of ours,cgal,qecd to run")
    parser.add_argument("--cgal-farthest-max-k", type=int, default=500,
                        help="skip CGAL's farthest seeding above this k: it adds one proxy at a time with"
                             " 5 full relaxations each (minutes at k=2000 on 50k faces)")
    parser.add_argument("--timeout", type=int, default=1800, help="seconds per process")
    parser.add_argument("--out", help="output folder (default: out/bench/<date-time>, git-ignored)")
    args = parser.parse_args()

    chosen = SETS[args.set]
    meshes = args.meshes.split(",") if args.meshes else chosen["meshes"]
    ks = [int(k) for k in args.k.split(",")] if args.k else chosen["k"]
    inits = args.init.split(",") if args.init else chosen["init"]
    tools = set(args.tools.split(","))

    ours = find_tool("VSA_BENCH", ["vsa-bench"])
    cgal = find_tool("CGAL_VSA_BENCH", ["cgal-vsa-bench"])
    mesh_distance = find_tool("MESH_DISTANCE", ["mesh-distance"])
    have_meshlab = shutil.which("meshlabserver") and shutil.which("xvfb-run")
    for tool, path in [("ours", ours), ("cgal", cgal)]:
        if tool in tools and not path:
            print("note: %s driver not found; its rows show '-'" % tool, file=sys.stderr)
    if "qecd" in tools and not (have_meshlab and mesh_distance):
        print("note: meshlabserver, xvfb-run or mesh-distance missing; no qecd rows", file=sys.stderr)

    out_dir = args.out or os.path.join(REPO, "out", "bench", datetime.datetime.now().strftime("%Y%m%d-%H%M%S"))
    os.makedirs(os.path.join(out_dir, "meshes"), exist_ok=True)
    results_path = os.path.join(out_dir, "results.jsonl")
    records = []
    qecd_done = {}  # (mesh, target faces) -> record: the decimation does not depend on init

    with open(results_path, "w") as results:
        def keep(record, mesh_name, k, init):
            record.update(case_mesh=mesh_name, case_k=k, case_init=init)
            records.append(record)
            results.write(json.dumps(record) + "\n")
            results.flush()

        for mesh in meshes:
            mesh_path = mesh if os.path.exists(mesh) else os.path.join(MESHES_DIR, mesh + ".off")
            name = os.path.splitext(os.path.basename(mesh_path))[0]
            for k in ks:
                for init in inits:
                    case = "%s_k%d_%s" % (name, k, init)
                    print("== %s" % case, file=sys.stderr, flush=True)
                    common = ["--mesh", mesh_path, "--k", str(k), "--metric", args.metric, "--init", init,
                              "--iterations", str(args.iterations), "--seed", str(args.seed)]
                    out_faces = None
                    for tool, path in [("ours", ours), ("cgal", cgal)]:
                        if tool not in tools or not path:
                            continue
                        if tool == "cgal" and init == "farthest" and k > args.cgal_farthest_max_k:
                            keep({"tool": tool, "error": "skipped: k > --cgal-farthest-max-k"}, name, k, init)
                            continue
                        out_mesh = os.path.join(out_dir, "meshes", "%s_%s.off" % (case, tool))
                        record, _ = run_json([path] + common + ["--out", out_mesh], args.timeout)
                        record.setdefault("tool", tool)
                        measure_missing(record, mesh_path, out_mesh, mesh_distance, args.timeout)
                        keep(record, name, k, init)
                        out_faces = out_faces or record.get("out_faces")
                    if "qecd" in tools and have_meshlab and mesh_distance and out_faces:
                        if (name, out_faces) not in qecd_done:
                            qecd_done[(name, out_faces)] = run_qecd(mesh_path, out_faces, out_dir, name,
                                                                    mesh_distance, args.timeout)
                        keep(dict(qecd_done[(name, out_faces)]), name, k, init)

    text = table(records)
    with open(os.path.join(out_dir, "table.txt"), "w") as f:
        f.write(text + "\n")
    print(text)
    print("\nresults: %s" % results_path)


if __name__ == "__main__":
    main()
