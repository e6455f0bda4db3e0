#!/usr/bin/env python3
"""The tables of bench/README.md's "2026-12-04 (third)" and "(fourth)" sections, from the runs of
this folder or, where RUN is a folder from the current directory, of that one (h200-2026-12-04d:
run there as `python3 ../h200-2026-12-04c/summarize.py smoke run6 smoke`).

  summarize.py renders RUN VARIANT,... NAME,... [REPS]   per-pass medians of `lll render --stats`
                                                         (runN/r/VARIANT-NAME-REP.json), mean of reps
  summarize.py smoke RUN VARIANT,...                     every particle pass / particles-composite,
                                                         ms, of each runN/bench-VARIANT*/ smoke bench
"""
import glob, json, lzma, os, re, sys

here = os.path.dirname(os.path.abspath(__file__))


def load(path):
    if os.path.exists(path + '.xz'):
        with lzma.open(path + '.xz', 'rt') as f:
            return json.load(f)
    with open(path) as f:
        return json.load(f)


def run_folder(run):
    return run if os.path.isdir(run) else f'{here}/{run}'


def renders(run, variants, names, reps):
    for name in names:
        table = {}
        for v in variants:
            for rep in reps:
                path = f'{run_folder(run)}/r/{v}-{name}-{rep}.json'
                if not os.path.exists(path):
                    continue
                for p in load(path)['passes']:
                    table.setdefault(p['name'], {}).setdefault(v, []).append(p['median_ms'])
        print('==', name, '  '.join(variants))
        for pass_name, values in table.items():
            cells = ['%8.4f' % (sum(values[v]) / len(values[v])) if v in values else '       -' for v in variants]
            print('  %-28s' % pass_name + ' '.join(cells))


def smoke(run, variants):
    def particle_pass(name):
        return name.startswith('particles') or name == 'glass-depth'
    rows = {}
    for v in variants:
        for folder in sorted(glob.glob(f'{run_folder(run)}/bench-{v}*/')):
            if not re.fullmatch(re.escape('bench-' + v) + r'(-\d+)?', os.path.basename(folder.rstrip('/'))):
                continue
            for r in load(folder + 'results.json')['results']:
                if r.get('particle_render') != 'compute':
                    continue
                key = (r.get('particles'), r['particle_count'], r['particle_lighting'], r['particle_resolution'])
                total = sum(p['median_ms'] for p in r['passes'] if particle_pass(p['name']))
                composite = [p['median_ms'] for p in r['passes'] if p['name'] == 'particles-composite'][0]
                rows.setdefault(key, {}).setdefault(v, []).append('%.3f/%.3f' % (total, composite))
    for key, values in rows.items():
        print('%-6s %8d %-6s %-8s' % key, '  '.join('%s: %s' % (v, ' '.join(values.get(v, []))) for v in variants))


if __name__ == '__main__':
    if sys.argv[1] == 'renders':
        renders(sys.argv[2], sys.argv[3].split(','), sys.argv[4].split(','),
                sys.argv[5].split(',') if len(sys.argv) > 5 else ['1'])
    else:
        smoke(sys.argv[2], sys.argv[3].split(','))
