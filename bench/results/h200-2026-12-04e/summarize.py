#!/usr/bin/env python3
"""Prints shade-opaque and frame medians (ms) of a run's renders, per scene and variant.

Usage, in this folder: python3 summarize.py runN   (reads runN/r.tar.xz: r/VARIANT-NAME-REP.json)
"""
import collections
import json
import sys
import tarfile

run = sys.argv[1] if len(sys.argv) > 1 else "run2"
rows = collections.defaultdict(list)
with tarfile.open(f"{run}/r.tar.xz") as tar:
    for member in sorted(tar.getmembers(), key=lambda m: m.name):
        if not member.name.endswith(".json"):
            continue
        variant, rest = member.name[2:-5].split("-", 1)
        name, _rep = rest.rsplit("-", 1)
        passes = {p["name"]: p["median_ms"] for p in json.load(tar.extractfile(member))["passes"]}
        rows[(name, variant)].append((passes.get("shade-opaque", 0.0), passes.get("glass", 0.0), passes["frame"]))
for name in sorted({k[0] for k in rows}):
    print(name)
    for variant in sorted({k[1] for k in rows if k[0] == name}):
        r = rows[(name, variant)]
        print(f"  {variant}: shade-opaque {' '.join(f'{x[0]:.4f}' for x in r)}  glass {' '.join(f'{x[1]:.4f}' for x in r)}"
              f"  frame {' '.join(f'{x[2]:.4f}' for x in r)}")
