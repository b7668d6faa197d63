#!/usr/bin/env python3
"""Prints a short summary of a meshlabserver run of the VSA filter from its log."""
import argparse
import os
import re
import sys


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--log", required=True)
    parser.add_argument("--mesh", required=True)
    parser.add_argument("--seconds", nargs=2, type=float, required=True, metavar=("START", "END"))
    parser.add_argument("--status", type=int, required=True)
    args = parser.parse_args()
    log = open(args.log, encoding="utf-8", errors="replace").read()

    print(f"Variational Shape Approximation of {args.mesh}")
    # meshlabserver echoes each log line ("LOG: n ...") and prints the whole log again after
    # every filter: keep the first copy of each line.
    vsa_lines = []
    for line in log.splitlines():
        if "VSA:" in line and not line.startswith("LOG:"):
            text = line[line.rindex("VSA:"):].strip()  # progress messages lack newlines
            if text not in vsa_lines:
                vsa_lines.append(text)
    for line in vsa_lines:
        print("  " + line)
    if args.status != 0 or not vsa_lines:
        print(f"meshlabserver failed (exit status {args.status}); its log follows:\n")
        print(log)
        return 1

    # MeshLab's Hausdorff Distance logs, per direction, the sampled and target layers and then
    # "min : a max b mean : c RMS : d" in absolute terms and over the target's bounding-box
    # diagonal. Each measurement shows up several times (echoed with "LOG: n", then in every
    # reprint of the log): one per direction, in the order they were run, with its last figures.
    plain = re.sub(r"^LOG: \d+ ?", "", log, flags=re.M)
    measured = re.findall(
        r"Sampled (\d+) pts [^\n]*? on ([^\n]+?) searched closest on ([^\n]+?)\n"
        r"\s*min : \S+\s+max (\S+)\s+mean : (\S+)\s+RMS : (\S+)\s*\n"
        r"Values w\.r\.t\. BBox Diag \((\S+)\)", plain)
    directions = {}
    for samples, sampled, target, amax, amean, arms, diag in measured:
        directions[(sampled, target)] = (samples, float(amax), float(amean), float(arms), float(diag))
    # Distances over the input's diagonal (that of the direction searching the input), as
    # vsa-bench reports them, in both directions.
    input_layer = os.path.basename(args.mesh)
    input_diag = [d[4] for (_, target), d in directions.items() if target == input_layer]
    diagonal = input_diag[-1] if input_diag else max((d[4] for d in directions.values()), default=0)
    for (sampled, target), (samples, amax, amean, arms, _) in directions.items():
        share = f" ({amax / diagonal * 100:.3f}% of the input's diagonal {diagonal:.6g})" if diagonal > 0 else ""
        print(f"  Hausdorff {sampled} -> {target} ({samples} samples): max {amax:.6g}{share}, "
              f"mean {amean:.6g}, RMS {arms:.6g}")
    if len(directions) == 2 and diagonal > 0:
        symmetric = max(d[1] for d in directions.values())
        print(f"  Symmetric Hausdorff distance: {symmetric:.6g} ({symmetric / diagonal * 100:.3f}% of the input's "
              "bounding-box diagonal)")
    for saved in re.findall(r"Mesh (.*?) saved as (\S+) \((\d+) vn (\d+) fn\)", log):
        print(f"  wrote {saved[1]} ({saved[2]} vertices, {saved[3]} faces)")
    print(f"  meshlabserver wall time: {args.seconds[1] - args.seconds[0]:.2f} s (start-up and Hausdorff included)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
