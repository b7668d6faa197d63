#!/usr/bin/env python3
"""Runs the scaling table of bench/README.md (issue 30) and prints it as Markdown.

Each row is one run of `vsa-bench` (ours) or `cgal-vsa-bench` (CGAL) on CGAL's bunny00.off and
bench/make_large_meshes.sh's armadillo Loop x2, x3 and x4, L2,1, hierarchical, seed 1, each
driver's defaults otherwise; `OMP_NUM_THREADS` as the row says. The rows run one after the
other, CGAL's last, so that nothing else of ours shares the machine with them. Every run's JSON,
its `/usr/bin/time` line and our output mesh stay in --out; the table is printed at the end and
can be printed again from a finished directory with --table-only.

    python3 bench/scaling_table.py --out out/scaling/$(date +%Y%m%d-%H%M)
"""
import argparse
import json
import os
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
MESHES = {
    '75k': '.deps/cgal-data/meshes/bunny00.off',
    '832k': 'out/large/armadillo-loop2.off',
    '3.3M': 'out/large/armadillo-loop3.off',
    '13M': 'out/large/armadillo-loop4.off',
}
# (mesh, k, tool, threads), in the order they run; the table lists them by mesh and k.
ROWS = [('75k', 200, 'ours', 1), ('75k', 200, 'ours', 2), ('75k', 200, 'cgal', 1),
        ('832k', 200, 'ours', 1), ('832k', 200, 'ours', 2), ('832k', 200, 'cgal', 1),
        ('3.3M', 200, 'ours', 1), ('3.3M', 200, 'ours', 2),
        ('3.3M', 2000, 'ours', 1), ('3.3M', 2000, 'ours', 2),
        ('13M', 2000, 'ours', 1), ('13M', 2000, 'ours', 2),
        ('3.3M', 200, 'cgal', 1), ('3.3M', 2000, 'cgal', 1)]
HEADER = ('| mesh, k | tool, threads | setup | seeding | iterations (run) | split | meshing | total '
          '| energy at k | k\' | peak RSS | beyond input | wall |\n' + '|---' * 13 + '|')


def name(row):
    return '%s-%d-%s-%d' % row


def run(out, build, row):
    mesh, k, tool, threads = row
    stem = os.path.join(out, name(row))
    command = [os.path.join(build, 'bench', 'vsa-bench' if tool == 'ours' else 'cgal-vsa-bench'),
               '--mesh', os.path.join(ROOT, MESHES[mesh]), '--k', str(k), '--init', 'hierarchical',
               '--seed', '1', '--metric', 'l21']
    if tool == 'ours':
        command += ['--out', stem + '.off']
    env = dict(os.environ, OMP_NUM_THREADS=str(threads))
    with open(stem + '.json', 'w') as stdout, open(stem + '.err', 'w') as stderr:
        subprocess.run(['/usr/bin/time', '-f', '%e %M', '-o', stem + '.time'] + command,
                       stdout=stdout, stderr=stderr, env=env, check=False)
    print(name(row), open(stem + '.time').read().strip(), file=sys.stderr, flush=True)


def seconds(x):
    return '%.2f s' % x


def table_row(out, row):
    mesh, k, tool, threads = row
    stem = os.path.join(out, name(row))
    lines = open(stem + '.json').read().strip().splitlines() if os.path.exists(stem + '.json') else []
    if not lines:
        return None
    d = json.loads(lines[-1])
    wall = open(stem + '.time').read().split()[0]
    if tool == 'ours':
        split = d['t_meshable_s']
        beyond = (d['peak_rss_mb'] - d['rss_after_load_mb']) * 1048576 / d['faces']
        cells = ['ours, %d' % threads, seconds(d['t_setup_s']), seconds(d['t_seed_s']),
                 '%s (%d)' % (seconds(d['t_iterations_s']), d['iterations_run']), seconds(split),
                 seconds(d['t_mesh_s'] - split), seconds(d['t_total_s']), '%.5g' % d['energy_asked'],
                 str(d['regions_final']), '%d MB' % round(d['peak_rss_mb']), '%d B/face' % round(beyond)]
    else:
        cells = ['CGAL, %d' % threads, seconds(d['t_setup_s']), seconds(d['t_seed_s']),
                 '%s (%d)' % (seconds(d['t_iterations_s']), d.get('iterations_run', d.get('iterations', 0))),
                 '—', seconds(d['t_mesh_s']), seconds(d['t_total_s']), '%.5g' % d['energy'], str(k),
                 '%d MB' % round(d['peak_rss_mb']), '—']
    return '| %s, %d | %s | %s s |' % (mesh, k, ' | '.join(cells), wall)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument('--out', required=True, help='directory for every run\'s files')
    parser.add_argument('--build', default=os.path.join(ROOT, 'build'), help='the build directory')
    parser.add_argument('--table-only', action='store_true', help='print the table of a finished --out')
    args = parser.parse_args()
    os.makedirs(args.out, exist_ok=True)
    if not args.table_only:
        for row in ROWS:
            run(args.out, args.build, row)
    print(HEADER)
    for row in sorted(ROWS, key=lambda r: (list(MESHES).index(r[0]), r[1])):
        line = table_row(args.out, row)
        if line:
            print(line)


if __name__ == '__main__':
    main()
