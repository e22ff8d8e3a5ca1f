// polydecomp plug-in (harness/plugins.h): wraps earcut (npm package `earcut`, version pinned in
// package.json), Mapbox's ear-slicing triangulation, run on each polygon as `earcut(flat, holeIndices)`.
//
// One polygon per input line, {"points": [[x, y], ...], "holes": [[[x, y], ...], ...]} (the outer ring
// counter-clockwise, each hole clockwise; a hole's vertices are numbered after the outer ring's and the
// holes before it, which is earcut's own numbering); one line out,
// {"pieces": [[i, j, k], ...], "steiner": [], "seconds": t}. earcut already returns indices into the
// points it was given: each triangle is kept as returned, reversed only if it is clockwise (earcut
// documents its triangles as counter-clockwise; none has been seen otherwise). Nothing is added,
// dropped or repaired. `seconds` is the wall time (process.hrtime) of the earcut call alone: the
// flat coordinate array is built before the clock starts, the answer turned into JSON after it stops.
// earcut 3 is an ES module only, hence .mjs.
import earcut from 'earcut';
import { createInterface } from 'node:readline';

const orientation = (p, a, b, c) =>
  (p[b][0] - p[a][0]) * (p[c][1] - p[a][1]) - (p[c][0] - p[a][0]) * (p[b][1] - p[a][1]);

for await (const line of createInterface({ input: process.stdin, crlfDelay: Infinity })) {
  let answer;
  try {
    const { points: outer, holes } = JSON.parse(line);
    const points = outer.slice();
    const holeIndices = [];
    for (const hole of holes || []) {
      holeIndices.push(points.length);
      for (const point of hole) points.push(point);
    }
    const flat = points.flat();
    const start = process.hrtime.bigint();
    const triangles = earcut(flat, holeIndices.length ? holeIndices : undefined);
    const seconds = Number(process.hrtime.bigint() - start) / 1e9;
    const pieces = [];
    for (let t = 0; t + 2 < triangles.length; t += 3) {
      const [a, b, c] = [triangles[t], triangles[t + 1], triangles[t + 2]];
      pieces.push(orientation(points, a, b, c) < 0 ? [a, c, b] : [a, b, c]);
    }
    answer = { pieces, steiner: [], seconds };
  } catch (e) {
    answer = { error: `earcut: ${e && e.message ? e.message : String(e)}` };
  }
  process.stdout.write(JSON.stringify(answer) + '\n');
}
