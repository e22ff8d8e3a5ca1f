// polydecomp plug-in (harness/plugins.h): wraps poly-decomp (npm package `poly-decomp`, version pinned
// in package.json; the convex decomposition matter.js uses). `node poly-decomp.mjs quick` runs its
// quickDecomp (Bayazit's heuristic, which may add points), `node poly-decomp.mjs optimal` its decomp
// (the minimum number of diagonals, by exhaustive recursion), each with the library's defaults.
//
// One polygon per input line, {"points": [[x, y], ...], "holes": []}, counter-clockwise (what
// poly-decomp wants); one line out, {"pieces": [[i, ...], ...], "steiner": [[x, y], ...], "seconds": t}.
// The library gets fresh [x, y] arrays and returns polygons of [x, y] arrays; each vertex is mapped
// back by exact coordinate equality: to the input point with those coordinates, or else to a Steiner
// point (index n + k, the k-th new point, each distinct point once, coordinates as computed). A vertex
// decomp returns that is no input point is reported as a Steiner point too, for validation to judge.
// A piece is kept as returned, reversed only if it is clockwise; nothing is added, dropped or
// repaired. `seconds` is the wall time (process.hrtime) of the library call alone: building its input
// and mapping its output are outside the clock. Holes are refused (the manifest says it takes none).
import decomp from 'poly-decomp';
import { createInterface } from 'node:readline';

const mode = process.argv[2];
const run = { quick: (polygon) => decomp.quickDecomp(polygon), optimal: (polygon) => decomp.decomp(polygon) }[mode];
if (!run) {
  process.stderr.write('usage: node poly-decomp.mjs quick|optimal\n');
  process.exit(2);
}

const signedArea = (ring) => {
  let twice = 0;
  for (let i = 0; i < ring.length; ++i) {
    const [x0, y0] = ring[i], [x1, y1] = ring[(i + 1) % ring.length];
    twice += x0 * y1 - x1 * y0;
  }
  return twice / 2;
};

for await (const line of createInterface({ input: process.stdin, crlfDelay: Infinity })) {
  let answer;
  try {
    const { points, holes } = JSON.parse(line);
    if (holes && holes.length) throw new Error('holes are not supported by this wrapper');
    const polygon = points.map(([x, y]) => [x, y]);
    const start = process.hrtime.bigint();
    const result = run(polygon);
    const seconds = Number(process.hrtime.bigint() - start) / 1e9;
    const index = new Map(points.map(([x, y], i) => [`${x},${y}`, i]));  // String(-0) is "0", as -0 === 0
    const steiner = [];
    const pieces = result.map((ring) => {
      const cycle = ring.map(([x, y]) => {
        if (!Number.isFinite(x) || !Number.isFinite(y)) throw new Error(`returned the vertex [${x}, ${y}]`);
        const key = `${x},${y}`;
        if (!index.has(key)) {
          index.set(key, points.length + steiner.length);
          steiner.push([x, y]);
        }
        return index.get(key);
      });
      return signedArea(ring) < 0 ? cycle.reverse() : cycle;
    });
    answer = { pieces, steiner, seconds };
  } catch (e) {
    answer = { error: `poly-decomp ${mode}: ${e && e.message ? e.message : String(e)}` };
  }
  process.stdout.write(JSON.stringify(answer) + '\n');
}
