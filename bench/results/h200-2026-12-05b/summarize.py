#!/usr/bin/env python3
"""Medians over the runs of each variant's per-pass medians: summarize.py run1 [pass ...]."""
import collections, glob, json, statistics, sys

runs = collections.defaultdict(lambda: collections.defaultdict(list))
variants = []
for path in sorted(glob.glob(sys.argv[1] + "/*.json")):
    variant, rest = path.split("/")[-1][:-5].split("-", 1)
    scene, _rep = rest.rsplit("-", 1)
    if variant not in variants:
        variants.append(variant)
    for p in json.load(open(path))["passes"]:
        runs[(scene, p["name"])][variant].append(p["median_ms"])
passes = sys.argv[2:] or ["shade-opaque", "glass", "frame"]
print("| scene | pass | " + " | ".join(variants) + " |")
print("|---|---|" + "---|" * len(variants))
for (scene, name) in sorted(runs):
    if name in passes:
        row = runs[(scene, name)]
        print(f"| {scene} | {name} | " +
              " | ".join(f"{statistics.median(row[v]):.4f}" if v in row else "" for v in variants) + " |")
