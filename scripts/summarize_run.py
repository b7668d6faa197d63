#!/usr/bin/env python3
"""Prints a short summary of a meshlabserver run of the VSA filter from its log."""
import argparse
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
    # "min : a max b mean : c RMS : d" in absolute terms and over the bounding-box diagonal.
    directions = re.findall(
        r"Sampled (\d+) pts .*? on (.+?) searched closest on (.+?)\n"
        r".*?min : \S+\s+max (\S+)\s+mean : (\S+)\s+RMS : (\S+)"
        r".*?Values w\.r\.t\. BBox Diag \((\S+)\)\s*\n\s*min : \S+\s+max (\S+)\s+mean : (\S+)\s+RMS : (\S+)",
        log, re.S)
    # The log is printed whole after every filter: the last two measurements are the two ways.
    directions = directions[-2:]
    for samples, sampled, target, amax, amean, arms, diag, rmax, rmean, rrms in directions:
        print(f"  Hausdorff {sampled} -> {target} ({samples} samples): max {float(amax):.6g} "
              f"({float(rmax) * 100:.3f}% of the diagonal {float(diag):.6g}), "
              f"mean {float(amean):.6g}, RMS {float(arms):.6g}")
    if len(directions) == 2:
        print(f"  Symmetric Hausdorff distance: {max(float(d[3]) for d in directions):.6g} "
              f"({max(float(d[7]) for d in directions) * 100:.3f}% of the bounding-box diagonal)")
    for saved in re.findall(r"Mesh (.*?) saved as (\S+) \((\d+) vn (\d+) fn\)", log):
        print(f"  wrote {saved[1]} ({saved[2]} vertices, {saved[3]} faces)")
    print(f"  meshlabserver wall time: {args.seconds[1] - args.seconds[0]:.2f} s (start-up and Hausdorff included)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
