#!/usr/bin/env python3
"""Tests of scripts/summarize_run.py on a meshlabserver log laid out as MeshLab 2020.09 writes it."""
import os
import subprocess
import sys
import tempfile
import unittest

SCRIPT = os.path.join(os.path.dirname(__file__), "..", "..", "scripts", "summarize_run.py")

VSA_LOG = ["VSA: input: 12946 faces, 6475 vertices, 1 component(s)",
           "VSA: faces in 12946 -> faces out 186 (95 vertices, 95 anchors)"]


def measurement(sampled, target, amax, diag):
    """One Hausdorff Distance measurement as the filter logs it (relative values over `diag`)."""
    return ["Hausdorff Distance computed",
            f"     Sampled 200000 pts (rng: 0) on {sampled} searched closest on {target}",
            f"     min : 0.000000   max {amax:.6f}   mean : 0.001000   RMS : 0.002000",
            f"Values w.r.t. BBox Diag ({diag:.6f})",
            f"     min : 0.000000   max {amax / diag:.6f}   mean : 0.000700   RMS : 0.001400", ""]


def meshlabserver_log(measurements):
    """Each filter's lines echoed with "LOG: 2 ", then the whole log so far printed again."""
    log, so_far = [], list(VSA_LOG)
    log += ["LOG: 2 " + line for line in VSA_LOG] + so_far
    for m in measurements:
        log += ["filter: Hausdorff Distance"] + ["LOG: 2 " + line for line in m if line]
        so_far += m
        log += [""] + so_far
    return "\n".join(log) + "\n"


def summarize(log_text, mesh="/data/fandisk.off"):
    with tempfile.TemporaryDirectory() as tmp:
        path = os.path.join(tmp, "meshlabserver.log")
        with open(path, "w") as f:
            f.write(log_text)
        run = subprocess.run([sys.executable, SCRIPT, "--log", path, "--mesh", mesh, "--seconds", "0", "1",
                              "--status", "0"], capture_output=True, text=True, check=True)
        return [line.strip() for line in run.stdout.splitlines()]


class SummarizeRunTest(unittest.TestCase):
    def test_each_direction_once_with_its_own_figures(self):
        # The larger distance in the first direction measured: a summary that read one
        # direction twice would miss it.
        lines = summarize(meshlabserver_log([measurement("fandisk VSA k=50", "fandisk.off", 0.02, 1.5),
                                             measurement("fandisk.off", "fandisk VSA k=50", 0.009, 1.4)]))
        hausdorff = [line for line in lines if line.startswith("Hausdorff ")]
        self.assertEqual(hausdorff, [
            "Hausdorff fandisk VSA k=50 -> fandisk.off (200000 samples): max 0.02 "
            "(1.333% of the input's diagonal 1.5), mean 0.001, RMS 0.002",
            "Hausdorff fandisk.off -> fandisk VSA k=50 (200000 samples): max 0.009 "
            "(0.600% of the input's diagonal 1.5), mean 0.001, RMS 0.002"])
        self.assertIn("Symmetric Hausdorff distance: 0.02 (1.333% of the input's bounding-box diagonal)", lines)

    def test_one_direction_gives_no_symmetric_distance(self):
        lines = summarize(meshlabserver_log([measurement("fandisk VSA k=50", "fandisk.off", 0.02, 1.5)]))
        self.assertEqual(len([line for line in lines if line.startswith("Hausdorff ")]), 1)
        self.assertFalse(any(line.startswith("Symmetric") for line in lines))

    def test_vsa_lines_once_each(self):
        lines = summarize(meshlabserver_log([]))
        self.assertEqual([line for line in lines if line.startswith("VSA:")], VSA_LOG)


if __name__ == "__main__":
    unittest.main()
