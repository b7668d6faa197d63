#!/usr/bin/env python3
"""The sweep of issue 29: does our output look like a clean polyhedron, against CGAL and QECD?

Per case (mesh x k x seeding) it runs ours (vsa-bench --polygonal 1), CGAL (cgal-vsa-bench) and
MeshLab's Quadric Edge Collapse Decimation asked for k' triangles, k' = our final region count
(the VSA paper's comparison at equal planar facets), all measured by bench/output_quality.h.
Meshes: a subset of CGAL's sample meshes (CGAL_MESHES below) and the CAD corpus of
bench/make_cad_corpus.sh (out/cad/*.off). k >= the mesh's faces is skipped.

Out: <out>/results.jsonl (one record per case: the input's own validity, the three tools'
records, each target's verdict), <out>/summary.txt and summary.json (each target's pass rate and
worst cases), <out>/meshes/ and <out>/pictures/<case>.png (input | ours | CGAL | QECD, see
bench/render_mesh.py; needs numpy and Pillow, bench/requirements-pictures.txt, else none).

    out/venv/bin/python bench/sweep_clean_output.py                   # everything (hours)
    out/venv/bin/python bench/sweep_clean_output.py --set cad --k 20,200 --init hierarchical
    out/venv/bin/python bench/sweep_clean_output.py --meshes fandisk,out/cad/gear.off --pictures failing

See bench/README.md.
"""

import argparse
import datetime
import glob
import json
import math
import os
import sys
import textwrap

from run_bench import MESHES_DIR, REPO, find_tool, fmt, labels_path, run_json, run_qecd, validity_label

# CGAL's sample meshes, one or two of each kind issue 29 is about. CAD: fandisk (sharp and
# smooth, 13k faces), blade (piecewise planar, 16k), turbine (curved blades, 18k), rotor (small,
# 1.2k), mech-holes-shark (through holes, 10k), couplingdown (genus, 3.7k); organic: elephant
# (thin legs, 5.6k), bull (12k), armadillo (the thin features of a scan, 52k); cheese: holes and
# handles (18k). bunny00 (75k) is left out for time: armadillo covers large organic scans.
CGAL_MESHES = ["fandisk", "blade", "turbine", "rotor", "mech-holes-shark", "couplingdown", "elephant", "bull",
               "armadillo", "cheese"]
CAD_DIR = os.path.join(REPO, "out", "cad")
KS = [20, 50, 200, 1000]
INITS = ["random", "farthest", "hierarchical"]

# Thresholds of issue 29, in one place.
MAX_FACING_AWAY = 0.01         # share of the output's area
MAX_TRIANGLES_PER_REGION = 6   # a clean polygon of a few corners needs no more
MAX_REGIONS_PER_PROXY = 2      # k' <= 2k


def regions_of(record):
    """The final region count: ours reports regions_out, CGAL the proxies it made."""
    return record.get("regions_out", record.get("proxies"))


def measured(record, key):
    """A measured key; infinity when the output has none (nothing to measure counts as worst)."""
    value = record.get(key) if has_output(record) else None
    return math.inf if value is None else value


def has_output(record):
    return bool(record) and not record.get("error") and record.get("out_faces") is not None


def planar_polygon_value(record):
    """How far the output is from one planar polygon per region: the polygons too many or too
    few, plus the polygons that bend (a triangle more than 0.5 degree off the polygon's mean
    normal); infinity when there is nothing to measure."""
    if not (has_output(record) and regions_of(record)) or record.get("bent_polygons") is None:
        return math.inf
    return abs(record["polygons"] - regions_of(record)) + record["bent_polygons"]


def clean_input(case):
    i = case["input"]
    return (i.get("manifold") is True and i.get("self_intersections") == 0 and i.get("degenerate_faces") == 0
            and i.get("duplicate_faces") == 0)


def unwelded_input(case):
    """Every face its own three vertices (an STL never welded): a bad input, to be refused with
    the hint to weld it first rather than approximated by itself."""
    i = case["input"]
    faces = i.get("out_faces") or 0
    return faces >= 2 and i.get("out_vertices") == 3 * faces and i.get("euler_out") == faces


WELD_HINT = "weld it first"


def weld_hint_value(case, r):
    """On an unwelded input: 0 when the tool refused it with the hint, else 1."""
    if not unwelded_input(case):
        return None
    return 0 if WELD_HINT in (r.get("error") or "") else 1


def self_intersection_value(case, r):
    """Intersecting pairs beyond what is allowed (0 when the target is met)."""
    if not has_output(r) or r.get("self_intersections") is None:
        return None
    allowed = 0 if clean_input(case) else case["input"].get("self_intersections") or 0
    return max(0, r["self_intersections"] - allowed)


def versus_qecd(case, r):
    """The larger of our Hausdorff and normal deviation over QECD's at k' triangles (< 1 passes)."""
    q = case.get("qecd") or {}
    if not has_output(q) or q.get("hausdorff_max") is None or not has_output(r):
        return None
    ratios = []
    for key in ["hausdorff_max", "normal_deviation_deg"]:
        ours, theirs = measured(r, key), measured(q, key)
        ratios.append(ours / theirs if theirs > 0 else (1.0 if ours == 0 else math.inf))
    return max(ratios)


def time_ratio(case, r):
    """Our whole time over CGAL's; a CGAL run that timed out counts as slower than ours."""
    c = case.get("cgal") or {}
    if r is not case.get("ours") or not c or "skipped" in (c.get("error") or ""):
        return None
    if not has_output(r):
        return math.inf
    if "timed out" in (c.get("error") or ""):
        return 0.0
    return r["t_total_s"] / c["t_total_s"] if c.get("t_total_s") else None


# Each target of issue 29: key, statement, required pass rate, value(case, record) -> a number
# (larger is worse) or None where it does not apply, and whether the value passes.
TARGETS = [
    ("valid", "valid output", 1.0, lambda c, r: 0 if has_output(r) and r.get("valid_output") else 1,
     lambda v: v == 0),
    ("degenerate", "zero degenerate faces", 1.0,
     lambda c, r: measured(r, "degenerate_faces"), lambda v: v == 0),
    ("self_intersections", "no self-intersection on clean inputs, never more pairs than the input", 1.0,
     lambda c, r: self_intersection_value(c, r) if has_output(r) else 1, lambda v: v == 0),
    ("facing_away", "facing_away <= %g%%" % (100 * MAX_FACING_AWAY), 1.0,
     lambda c, r: measured(r, "facing_away"), lambda v: v <= MAX_FACING_AWAY),
    ("one_polygon_per_region", "polygons == regions_out", 1.0,
     lambda c, r: abs(r["polygons"] - regions_of(r)) if has_output(r) and regions_of(r) else math.inf,
     lambda v: v == 0),
    ("planar_polygon_per_region", "polygons == regions_out, each within 0.5 degree of its mean normal", 1.0,
     lambda c, r: planar_polygon_value(r), lambda v: v == 0),
    ("triangles_per_region", "triangles per region <= %d" % MAX_TRIANGLES_PER_REGION, 1.0,
     lambda c, r: r["out_faces"] / regions_of(r) if has_output(r) and regions_of(r) else math.inf,
     lambda v: v <= MAX_TRIANGLES_PER_REGION),
    ("regions_vs_k", "k' <= %dk" % MAX_REGIONS_PER_PROXY, 0.95,
     lambda c, r: regions_of(r) / c["k"] if has_output(r) and regions_of(r) else math.inf,
     lambda v: v <= MAX_REGIONS_PER_PROXY),
    ("beats_qecd", "Hausdorff and normal deviation below QECD's at k' triangles", 0.90, versus_qecd,
     lambda v: v < 1),
    ("time_vs_cgal", "our whole time <= CGAL's", 1.0, time_ratio, lambda v: v <= 1),
    ("weld_hint", "an unwelded input is refused with the hint to '%s'" % WELD_HINT, 1.0, weld_hint_value,
     lambda v: v == 0),
]


def verdicts(case, tool):
    """{target: [value, passed]} for one tool's record; targets that do not apply are left out.
    An infinite value (no output to measure) is kept as null, which JSON has."""
    record = case.get(tool) or {}
    if (record.get("error") or "").startswith("skipped"):
        return {}
    out = {}
    refused = weld_hint_value(case, record) == 0  # a bad input refused as it should be: nothing to measure
    for key, _, _, value, passes in TARGETS:
        if refused and key != "weld_hint":
            continue
        v = value(case, record)
        if v is not None:
            out[key] = [v if math.isfinite(v) else None, bool(passes(v))]
    return out


def caption(tool, r):
    """Under a tool's picture: the figures the targets look at."""
    head = "%s: %d faces, %s polygons" % (tool, r["out_faces"], fmt(r.get("polygons")))
    if r.get("coplanar_polygons") is not None:
        head += " (%d coplanar)" % r["coplanar_polygons"]
    if regions_of(r):
        head += ", %d regions" % regions_of(r)
    away = r.get("facing_away")
    return "\n".join([head,
                      "away %s%%  dev %s deg" % (fmt(None if away is None else 100 * away, "%.2f"),
                                                 fmt(r.get("normal_deviation_deg"), "%.1f")),
                      "H max %s  %s" % (fmt(r.get("hausdorff_max"), "%.2e"), validity_label(r)),
                      "time %s s" % fmt(r.get("t_total_s", r.get("t_mesh_s")), "%.3g")])


def draw_panel(case, out_png, size):
    import render_mesh  # numpy and Pillow: only when pictures are asked for
    items = [(case["mesh_path"], None, "input: %d faces\n%s k=%d %s" % (case["faces"], case["mesh"], case["k"],
                                                                         case["init"]))]
    for tool in ["ours", "cgal", "qecd"]:
        r = case.get(tool) or {}
        mesh = r.get("out_mesh")
        if has_output(r) and os.path.exists(mesh):
            items.append((mesh, labels_path(mesh) if os.path.exists(labels_path(mesh)) else None, caption(tool, r)))
        elif r.get("error") and not r["error"].startswith("skipped"):  # a refusal or a failure says why
            items.append((None, None, "\n".join(textwrap.wrap("%s: %s" % (tool, r["error"]), size // 6))))
    render_mesh.panel(items, out_png, up=case["up"], size=size)


def badness(case_verdict):
    """Sort key, worst first: a missing value (no output) before any measured one."""
    value = case_verdict[1][0]
    return -math.inf if value is None else -value


def picture(case, folder, args):
    """Draws the case's panel into `folder` if --pictures asks for it; without numpy or Pillow,
    says so once and draws no more."""
    missed = [t for t, (_, ok) in case["verdicts"].get("ours", {}).items() if not ok]
    if args.pictures == "none" or (args.pictures == "failing" and not missed):
        return
    path = os.path.join(folder, case["case"] + ".png")
    try:
        draw_panel(case, path, args.picture_size)
        case["picture"] = path
    except ImportError as e:
        print("note: no pictures (%s): see bench/requirements-pictures.txt" % e, file=sys.stderr)
        args.pictures = "none"


def pass_rate(cases, tool, key):
    """(passed, cases) of a target over the cases where it applies."""
    results = [c["verdicts"][tool][key][1] for c in cases if key in c["verdicts"].get(tool, {})]
    return sum(results), len(results)


def corpus_of(case):
    return "CAD corpus" if os.path.abspath(case["mesh_path"]).startswith(CAD_DIR) else "CGAL meshes"


def summary(cases):
    lines, table = [], {}
    header = "%-25s %-9s %-17s %-17s  %s" % ("target", "required", "ours", "cgal", "statement")
    lines += [header, "-" * len(header)]
    for key, statement, required, _, _ in TARGETS:
        row = {}
        for tool in ["ours", "cgal"]:
            results = [(c, c["verdicts"][tool][key]) for c in cases if key in c["verdicts"].get(tool, {})]
            passed = sum(1 for _, (_, ok) in results if ok)
            row[tool] = {"passed": passed, "cases": len(results),
                         "rate": passed / len(results) if results else None,
                         "worst": [[c["case"], v] for c, (v, ok) in
                                   sorted(results, key=badness)[:5] if not ok]}
        table[key] = dict(statement=statement, required=required, **row)

        def cell(t):
            return "-" if row[t]["rate"] is None else "%5.1f%% (%d/%d)" % (100 * row[t]["rate"], row[t]["passed"],
                                                                         row[t]["cases"])
        rate = row["ours"]["rate"]
        verdict = "   [no case]" if rate is None else "" if rate >= required else "   [NOT MET]"
        lines.append("%-25s %-9s %-17s %-17s  %s%s" % (key, "%g%%" % (100 * required), cell("ours"), cell("cgal"),
                                                      statement, verdict))
    corpora = sorted({corpus_of(c) for c in cases})
    if len(corpora) > 1:
        lines += ["", "Ours by corpus:", ("%-25s " % "target" + " ".join("%-17s" % name for name in corpora)).rstrip()]
        for key, _, _, _, _ in TARGETS:
            cells = []
            for name in corpora:
                passed, total = pass_rate([c for c in cases if corpus_of(c) == name], "ours", key)
                cells.append("%-17s" % ("-" if not total else "%5.1f%% (%d/%d)" % (100 * passed / total, passed, total)))
            lines.append(("%-25s " % key + " ".join(cells)).rstrip())
    lines.append("")
    lines.append("Worst cases of ours per target (value: larger is worse):")
    for key in table:
        for name, value in table[key]["ours"]["worst"]:
            lines.append("  %-25s %-45s %s" % (key, name, fmt(value, "%.4g")))
    return "\n".join(lines), table


def mesh_list(args):
    if args.meshes:
        names = args.meshes.split(",")
    else:
        names = (CGAL_MESHES if args.set in ["cgal", "all"] else []) + \
                (sorted(glob.glob(os.path.join(CAD_DIR, "*.off"))) if args.set in ["cad", "all"] else [])
    meshes = []
    for name in names:
        path = name if os.path.exists(name) else os.path.join(MESHES_DIR, name + ".off")
        # OpenSCAD's parts stand on z; CGAL's sample meshes mostly on y.
        up = "z" if os.path.abspath(path).startswith(CAD_DIR) else "y"
        meshes.append((os.path.splitext(os.path.basename(path))[0], path, up))
    return meshes


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--set", default="all", choices=["all", "cgal", "cad"],
                        help="CGAL's sample meshes (CGAL_MESHES), the CAD corpus (out/cad), or both")
    parser.add_argument("--meshes", help="comma-separated CGAL mesh names or OFF paths (instead of --set)")
    parser.add_argument("--k", help="comma-separated proxy counts (default %s)" % ",".join(map(str, KS)))
    parser.add_argument("--init", help="comma-separated seedings (default %s)" % ",".join(INITS))
    parser.add_argument("--tools", default="ours,cgal,qecd")
    parser.add_argument("--ours-args", default="",
                        help="more vsa-bench options for ours, as one string, e.g. '--max-proxy-factor 100'")
    parser.add_argument("--iterations", type=int, default=30)
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--timeout-ours", type=int, default=600, help="seconds")
    parser.add_argument("--timeout-cgal", type=int, default=300, help="seconds; a CGAL timeout counts as slower")
    parser.add_argument("--timeout-qecd", type=int, default=300, help="seconds")
    parser.add_argument("--cgal-farthest-max-k", type=int, default=200,
                        help="skip CGAL's farthest seeding above this k (one proxy at a time, 5 relaxations"
                             " each: minutes at k=1000)")
    parser.add_argument("--pictures", default="all", choices=["all", "failing", "none"],
                        help="a panel per case, only for cases where ours misses a target, or none")
    parser.add_argument("--picture-size", type=int, default=300, help="pixels per picture side")
    parser.add_argument("--out", help="output folder (default: out/bench/<date-time>, git-ignored)")
    parser.add_argument("--summarize", metavar="DIR",
                        help="only (re)write DIR's summary from its results.jsonl, e.g. of a sweep cut short")
    parser.add_argument("--redraw", action="store_true",
                        help="with --summarize: draw DIR's pictures again (those --pictures asks for)")
    args = parser.parse_args()
    if args.summarize:
        with open(os.path.join(args.summarize, "results.jsonl")) as f:
            cases = [json.loads(line) for line in f]
        for case in cases:  # with today's targets and thresholds
            case["verdicts"] = {tool: verdicts(case, tool) for tool in ["ours", "cgal"] if tool in case}
            if args.redraw:
                picture(case, os.path.join(args.summarize, "pictures"), args)
        write_summary(cases, args.summarize)
        return

    ks = [int(k) for k in args.k.split(",")] if args.k else KS
    inits = args.init.split(",") if args.init else INITS
    tools = set(args.tools.split(","))
    ours = find_tool("VSA_BENCH", ["vsa-bench"])
    cgal = find_tool("CGAL_VSA_BENCH", ["cgal-vsa-bench"])
    mesh_distance = find_tool("MESH_DISTANCE", ["mesh-distance"])
    if not (ours and mesh_distance):
        sys.exit("sweep: build vsa-bench and mesh-distance first (bench/README.md)")

    # Absolute, so that the records' mesh paths hold wherever --summarize --redraw runs from.
    out_dir = os.path.abspath(args.out or os.path.join(REPO, "out", "bench",
                                                       datetime.datetime.now().strftime("%Y%m%d-%H%M%S")))
    for sub in ["meshes", "pictures"]:
        os.makedirs(os.path.join(out_dir, sub), exist_ok=True)
    cases = []
    with open(os.path.join(out_dir, "results.jsonl"), "w") as results:
        for name, path, up in mesh_list(args):
            # The input measured against itself: its own validity and self-intersections.
            input_record, _ = run_json([mesh_distance, path, path], args.timeout_ours)
            faces = input_record.get("out_faces") or 0
            qecd_done = {}
            for k in [k for k in ks if k < faces]:
                for init in inits:
                    case_name = "%s_k%d_%s" % (name, k, init)
                    print("== %s" % case_name, file=sys.stderr, flush=True)
                    case = dict(case=case_name, mesh=name, mesh_path=path, up=up, k=k, init=init, faces=faces,
                                input=input_record)
                    common = ["--mesh", path, "--k", str(k), "--init", init, "--iterations", str(args.iterations),
                              "--seed", str(args.seed)]
                    for tool, binary, extra, timeout in [("ours", ours, ["--polygonal", "1"] + args.ours_args.split(),
                                                          args.timeout_ours),
                                                         ("cgal", cgal, [], args.timeout_cgal)]:
                        if tool not in tools or not binary:
                            continue
                        if tool == "cgal" and init == "farthest" and k > args.cgal_farthest_max_k:
                            case[tool] = {"error": "skipped: k > --cgal-farthest-max-k"}
                            continue
                        out_mesh = os.path.join(out_dir, "meshes", "%s_%s.off" % (case_name, tool))
                        record, _ = run_json([binary] + common + extra +
                                             ["--out", out_mesh, "--polygon-labels", labels_path(out_mesh)], timeout)
                        record["out_mesh"] = out_mesh
                        case[tool] = record
                    if has_output(case.get("ours")):
                        # Whether our polygons are planar: the written file has no faux edges.
                        measured, _ = run_json([mesh_distance, path, case["ours"]["out_mesh"]], args.timeout_ours)
                        case["ours"]["coplanar_polygons"] = measured.get("polygons")
                    k_prime = regions_of(case.get("ours") or {})
                    if "qecd" in tools and k_prime:
                        if k_prime not in qecd_done:
                            qecd_done[k_prime] = run_qecd(path, k_prime, out_dir, name, mesh_distance,
                                                          args.timeout_qecd)
                            qecd_done[k_prime]["out_mesh"] = os.path.join(out_dir, "meshes",
                                                                          "%s_qecd%d.off" % (name, k_prime))
                        case["qecd"] = qecd_done[k_prime]
                    case["verdicts"] = {tool: verdicts(case, tool) for tool in ["ours", "cgal"] if tool in case}
                    picture(case, os.path.join(out_dir, "pictures"), args)
                    results.write(json.dumps(case) + "\n")
                    results.flush()
                    cases.append(case)

    write_summary(cases, out_dir)


def write_summary(cases, out_dir):
    text, table = summary(cases)
    with open(os.path.join(out_dir, "summary.txt"), "w") as f:
        f.write(text + "\n")
    with open(os.path.join(out_dir, "summary.json"), "w") as f:
        json.dump(table, f, indent=1)
    print(text)
    print("\n%d cases; results: %s" % (len(cases), os.path.join(out_dir, "results.jsonl")))


if __name__ == "__main__":
    main()
