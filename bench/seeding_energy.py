#!/usr/bin/env python3
"""The seeding's energy protocol (docs/tuning.md, "Seeding on patches"): the energy after 30
Lloyd iterations, L2,1, hierarchical, seeds 1 to 5, on the meshes where a change of the seeding
shows: armadillo Loop x2 at k = 200 and 2000, fandisk and gear midpoint-subdivided three times
at k = 20, 50 and 200 (40 cases; `bench/make_large_meshes.sh` makes the meshes, the gear once
`bench/make_cad_corpus.sh` has made out/cad/gear.off).

    python3 bench/seeding_energy.py --out out/seeding/main.jsonl [--vsa-bench build/bench/vsa-bench]
    python3 bench/seeding_energy.py --compare out/seeding/main.jsonl out/seeding/tried.jsonl

A run writes one JSON record per case (vsa-bench's, with the case's mesh, k and seed) and runs
with `--meshable 0`: the split would move the energy for reasons of its own. --compare prints,
per mesh and k, the geometric mean of the second file's energies over the first's, each seed's
ratio, and the geometric mean over all the cases both files have.

Python 3 standard library only.
"""
import argparse
import json
import math
import os
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
CASES = [('out/large/armadillo-loop2.off', [200, 2000]),
         ('out/large/fandisk-mid3.off', [20, 50, 200]),
         ('out/large/gear-mid3.off', [20, 50, 200])]
SEEDS = [1, 2, 3, 4, 5]


def run(args):
    os.makedirs(os.path.dirname(os.path.abspath(args.out)), exist_ok=True)
    with open(args.out, 'w') as out:
        for mesh, ks in CASES:
            path = os.path.join(ROOT, mesh)
            if not os.path.exists(path):
                sys.exit('missing %s: run bench/make_large_meshes.sh' % mesh)
            for k in ks:
                for seed in args.seeds:
                    command = [args.vsa_bench, '--mesh', path, '--k', str(k), '--seed', str(seed),
                               '--init', 'hierarchical', '--metric', 'l21', '--iterations', '30',
                               '--meshable', '0']
                    done = subprocess.run(command, capture_output=True, text=True, check=False)
                    lines = [l for l in done.stdout.splitlines() if l.startswith('{')]
                    if done.returncode != 0 or not lines:
                        sys.exit('failed: %s\n%s' % (' '.join(command), done.stderr[-2000:]))
                    record = json.loads(lines[-1])
                    record.update(case_mesh=os.path.basename(mesh), case_k=k, case_seed=seed)
                    out.write(json.dumps(record) + '\n')
                    out.flush()
                    print('%s k=%d seed=%d energy %.6g seeding %.3f s' %
                          (os.path.basename(mesh), k, seed, record['energy'], record['t_seed_s']), flush=True)


def load(path):
    with open(path) as f:
        return {(r['case_mesh'], r['case_k'], r['case_seed']): r for r in map(json.loads, f)}


def compare(before_path, after_path):
    before, after = load(before_path), load(after_path)
    groups = {}
    for key in sorted(set(before) & set(after)):
        groups.setdefault(key[:2], []).append((key[2], after[key]['energy'] / before[key]['energy']))
    logs = []
    for (mesh, k), ratios in groups.items():
        logs += [math.log(r) for _, r in ratios]
        mean = math.exp(sum(math.log(r) for _, r in ratios) / len(ratios))
        print('%-22s k=%-5d %+6.2f%%   %s' % (mesh, k, 100 * (mean - 1),
                                            ' '.join('%d:%+.2f%%' % (s, 100 * (r - 1)) for s, r in ratios)))
    if logs:
        print('all %d cases: %+.2f%%' % (len(logs), 100 * (math.exp(sum(logs) / len(logs)) - 1)))


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument('--out', help='JSON lines file to write')
    parser.add_argument('--vsa-bench', default=os.path.join(ROOT, 'build', 'bench', 'vsa-bench'))
    parser.add_argument('--seeds', default=','.join(map(str, SEEDS)),
                        help='comma-separated seeds (default 1 to 5)')
    parser.add_argument('--compare', nargs=2, metavar=('BEFORE', 'AFTER'))
    args = parser.parse_args()
    if args.compare:
        compare(*args.compare)
    elif args.out:
        args.seeds = [int(s) for s in args.seeds.split(',')]
        run(args)
    else:
        parser.error('give --out or --compare')


if __name__ == '__main__':
    main()
