#!/usr/bin/env python3
"""Class flags of two builds on the same scans (docs/results.md, "Sparse scans and classes").

  scripts/class_flag_compare.py run --spinhash BIN --set DIR --out FILE.jsonl [--db DB] [-- EXTRA FLAGS]
  scripts/class_flag_compare.py table BEFORE.jsonl AFTER.jsonl

DIR is a folder scripts/sparse_unknowns.py wrote (rows.jsonl, scans/,
db.shdb): `run` recognizes its scans again and keeps each row's truth;
`table` prints, per condition and density band, the class right first and
the class-confident answers, right and wrong, of the first build against the
second (Markdown).
"""
import argparse, collections, json, os, subprocess, sys
from concurrent.futures import ThreadPoolExecutor

BATCH = 40  # scans per spinhash process


def run(a, extra):
    rows = [json.loads(l) for l in open(os.path.join(a.set, 'rows.jsonl'))]
    db = a.db or os.path.join(a.set, 'db.shdb')

    def batch(part):
        cmd = [a.spinhash, 'recognize', '--db', db] + extra + [os.path.join(a.set, 'scans', r['query']) for r in part]
        out = subprocess.run(cmd, capture_output=True, text=True, check=True).stdout.splitlines()
        if len(out) != len(part):
            sys.exit('class_flag_compare: %d answers for %d scans' % (len(out), len(part)))
        for r, line in zip(part, out):
            d = json.loads(line)
            r.update(model=(d.get('ranking') or [{}])[0].get('model'), confident=d.get('confident'),
                     cls=d.get('class'), class_confident=d.get('class_confident'))
        return part

    with ThreadPoolExecutor(os.cpu_count() or 2) as ex:
        done = [r for p in ex.map(batch, [rows[i:i + BATCH] for i in range(0, len(rows), BATCH)]) for r in p]
    with open(a.out, 'w') as f:
        f.writelines(json.dumps(r) + '\n' for r in done)


def band(d):
    return '10-30' if 10 <= d <= 30 else ('30-50 (and < 10)' if d < 50 else '>= 50')


def tally(rows):
    g = collections.defaultdict(collections.Counter)
    for r in rows:
        for k in [(r['cond'], band(r['density'])), ('all', 'all')]:
            c = g[k]
            c['n'] += 1
            c['right'] += r['cls'] == r['truth_class']
            c['conf'] += bool(r['class_confident'])
            c['wrong'] += bool(r['class_confident']) and r['cls'] != r['truth_class']
    return g


def table(before, after):
    b, a = (tally([json.loads(l) for l in open(p)]) for p in (before, after))
    order = ['10-30', '30-50 (and < 10)', '>= 50', 'all']
    print('| condition | density (per m^2) | scans | class right first: before -> after '
          '| class confident and right | confident in a wrong class |')
    print('| --- | --- | ---: | ---: | ---: | ---: |')
    for k in sorted(a, key=lambda k: (k[0] == 'all', k[0], order.index(k[1]))):
        x, y = b[k], a[k]
        print('| %s | %s | %d | %d -> %d | %d -> %d | %d -> %d |' % (
            k[0], k[1], y['n'], x['right'], y['right'], x['conf'] - x['wrong'], y['conf'] - y['wrong'],
            x['wrong'], y['wrong']))


def main():
    argv = sys.argv[1:]
    extra = argv[argv.index('--') + 1:] if '--' in argv else []
    argv = argv[:argv.index('--')] if '--' in argv else argv
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = p.add_subparsers(dest='cmd', required=True)
    r = sub.add_parser('run')
    r.add_argument('--spinhash', required=True)
    r.add_argument('--set', required=True)
    r.add_argument('--out', required=True)
    r.add_argument('--db')
    t = sub.add_parser('table')
    t.add_argument('before')
    t.add_argument('after')
    a = p.parse_args(argv)
    run(a, extra) if a.cmd == 'run' else table(a.before, a.after)


if __name__ == '__main__':
    main()
