#!/usr/bin/env python3
"""GUI test of the VSA filter in the real MeshLab 2020.09, under its own Xvfb.

MeshLab is the private prefix's (build/meshlab-prefix, filter_vsa/CMakeLists.txt), whose plugin
folder holds ours. The test opens the mesh, goes Filters > Remeshing, Simplification and
Reconstruction > Variational Shape Approximation, checks the dialog shows every parameter, types
the number of proxies, presses Apply and checks the new layer, the log's line and that the input
is hidden (meshlab_gui.py).

It fails when the filter is missing from the menu, when the dialog lacks a parameter, when
Apply adds no layer (a "Filter Failure" box, a crash, or no new layer in time), and when the
input is still shown after Apply. Screenshots of
every step stay in --artifacts; their paths are printed. Exit status: 0 pass, 1 fail, 77 skip
(a needed tool is missing).
"""
import sys
from pathlib import Path

import meshlab_gui

if __name__ == "__main__":
    sys.exit(meshlab_gui.main(__doc__, meshlab_gui.run_filter_dialog, default_meshlab=str(
        Path(__file__).resolve().parents[2] / "build/meshlab-prefix/bin/meshlab")))
