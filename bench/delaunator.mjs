// Times delaunator (JavaScript) on a .bin point file (little-endian float64 x, y pairs), for
// bench/peers_table.cpp. Prints one JSON line: the time of each repetition, the triangle
// count, and the memory the first repetition added to the process.
//
//   node bench/delaunator.mjs POINTS.bin REPS NODE_MODULES_DIR
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { pathToFileURL } from 'node:url';

const [file, repsArg, modules] = process.argv.slice(2);
const { default: Delaunator } = await import(pathToFileURL(join(modules, 'delaunator', 'index.js')));
const bytes = readFileSync(file);
const coords = new Float64Array(bytes.buffer, bytes.byteOffset, bytes.length / 8);
const reps = Number(repsArg);
const times = [];
let triangles = 0;
let extra = 0;
for (let r = 0; r < reps; ++r) {
  const before = process.memoryUsage().rss;
  const t0 = process.hrtime.bigint();
  const d = new Delaunator(coords);
  times.push(Number(process.hrtime.bigint() - t0) / 1e9);
  if (r === 0) extra = process.resourceUsage().maxRSS * 1024 - before;
  triangles = d.triangles.length / 3;
}
console.log(JSON.stringify({ times, triangles, extra_rss_bytes: extra }));
