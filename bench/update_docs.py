#!/usr/bin/env python3
"""Copies the benchmark charts into docs/img/ and replaces the generated section of
docs/BENCHMARKS.md (between the BEGIN/END GENERATED markers) with RESULTS/tables.md.
Usage: update_docs.py RESULTS_DIR REPO_TOP"""
import os, shutil, sys

res, top = sys.argv[1], sys.argv[2]
img = os.path.join(top, "docs", "img")
os.makedirs(img, exist_ok=True)
for name in ("speed_accuracy.png", "scaling.png"):
    src = os.path.join(res, name)
    if os.path.exists(src):
        shutil.copyfile(src, os.path.join(img, "bench_" + name))
doc = os.path.join(top, "docs", "BENCHMARKS.md")
begin, end = "<!-- BEGIN GENERATED (make bench) -->", "<!-- END GENERATED -->"
tables = open(os.path.join(res, "tables.md")).read().strip()
if os.path.exists(doc):
    text = open(doc).read()
    if begin in text and end in text:
        pre, rest = text.split(begin, 1)
        _, post = rest.split(end, 1)
        open(doc, "w").write(pre + begin + "\n" + tables + "\n" + end + post)
        print("bench: docs/BENCHMARKS.md tables and docs/img/bench_*.png updated")
        sys.exit(0)
print("bench: docs/BENCHMARKS.md has no generated-section markers; tables left in " + res)
