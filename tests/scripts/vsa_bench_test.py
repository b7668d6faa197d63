#!/usr/bin/env python3
"""Tests that vsa-bench measures the pipeline users get (ApproximateShape, as the plugin and
pymeshlab run it), not a copy of its stages.

    vsa_bench_test.py VSA_BENCH CGAL_MESHES_DIR
"""
import json
import os
import subprocess
import sys
import unittest

BENCH, MESHES = sys.argv[1], sys.argv[2]


def bench(mesh, k, *extra):
    run = subprocess.run([BENCH, "--mesh", os.path.join(MESHES, mesh), "--k", str(k), "--metric", "l21",
                          "--init", "hierarchical", "--iterations", "30", "--seed", "1", *extra],
                         capture_output=True, text=True, timeout=300)
    return run.returncode, json.loads(run.stdout)


class VsaBench(unittest.TestCase):
    def test_an_invalid_split_keeps_the_regions_asked_for(self):
        # bull.off meets itself in 3 face pairs; at k = 1000 the split partition's output keeps
        # them, and ApproximateShape then keeps the 1000 regions asked for, whose output is valid.
        # A driver that ran the stages itself reported the invalid output (stop 64's finding).
        rc, line = bench("bull.off", 1000)
        self.assertEqual(rc, 0, line)
        self.assertTrue(line["valid_output"], line)
        self.assertEqual(line["self_intersections"], 0)
        self.assertIn(line["kept_asked"], (True, False))
        if line["kept_asked"]:
            self.assertEqual(line["regions_out"], line["k"])

    def test_reports_the_energy_at_k_before_the_split(self):
        rc, line = bench("fandisk.off", 40)
        self.assertEqual(rc, 0, line)
        self.assertGreater(line["regions_final"], 40)  # fandisk at 40 needs splits (README)
        self.assertGreater(line["energy_asked"], 0)
        self.assertLess(line["energy"], line["energy_asked"])  # more regions fit better
        self.assertGreaterEqual(line["peak_rss_mb"], line["peak_rss_meshable_mb"])
        self.assertGreaterEqual(line["peak_rss_meshable_mb"], line["peak_rss_partition_mb"])
        for stage in ("setup", "seeding", "iterations", "meshable", "meshing"):
            self.assertIn("max_progress_gap_%s_s" % stage, line)

    def test_a_refusal_is_an_error_line(self):
        rc, line = bench("fandisk.off", 0)
        self.assertEqual(rc, 1)
        self.assertIn("at least 1", line["error"])


if __name__ == "__main__":
    unittest.main(argv=sys.argv[:1])
