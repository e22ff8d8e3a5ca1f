#!/usr/bin/python3
"""A polydecomp plug-in: the fan triangulation of a convex polygon, from vertex 0.

polydecomp starts this once and sends one polygon per line, {"points": [[x, y], ...], "holes": []},
counter-clockwise; each answer is one line, {"pieces": [[i, j, k], ...], "steiner": [], "seconds": t}
or {"error": "..."}. The manifest beside it (fan.json) says it takes convex polygons only.
"""
import json
import sys
import time

for line in sys.stdin:
    polygon = json.loads(line)
    start = time.process_time()
    n = len(polygon["points"])
    pieces = [[0, i, i + 1] for i in range(1, n - 1)]
    seconds = time.process_time() - start
    print(json.dumps({"pieces": pieces, "steiner": [], "seconds": seconds}), flush=True)
