// The studio's WebAssembly build timed in node (the V8 of Chromium, without drawing):
// the skin preview at 512 x 512 (skin built from a preset and rendered) and a hand
// slider's solve, in wall and CPU time, best of several runs; the preview's split over
// the page's workers (each building the skin and rendering a band of rows) as CPU time
// per worker. The page's own figures
// (drawing included) come from the browser tests (studio-speed.json).
//
//   node bench/bench_studio.mjs [build-wasm/www]
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { pathToFileURL } from 'node:url';

const www = process.argv[2] || 'build-wasm/www';
const { default: createStudio } = await import(pathToFileURL(path.resolve(www, 'wasm/studio.mjs')).href);
const m = await createStudio({ wasmBinary: fs.readFileSync(path.resolve(www, 'wasm/studio.wasm')) });
const err = m._studio_error_new();
const str = (s) => { const n = m.lengthBytesUTF8(s) + 1, p = m._malloc(n); m.stringToUTF8(s, p, n); return p; };
const cpu = () => { const u = process.cpuUsage(); return (u.user + u.system) / 1000; };
function time(fn, runs) {
  let wall = Infinity, cpuBest = Infinity;
  for (let k = 0; k < runs; k++) {
    const w0 = performance.now(), c0 = cpu();
    fn();
    wall = Math.min(wall, performance.now() - w0);
    cpuBest = Math.min(cpuBest, cpu() - c0);
  }
  return { wall, cpu: cpuBest };
}

console.log(`wasm ${fs.statSync(path.resolve(www, 'wasm/studio.wasm')).size} bytes; load average ${os.loadavg().map((x) => x.toFixed(2)).join(' ')}`);
for (const [preset, n] of [['back-of-hand', 512], ['back-of-hand', 256], ['fig13a', 512]]) {
  const json = str(fs.readFileSync(path.resolve(www, `presets/skin/${preset}.json`), 'utf8'));
  const buf = m._malloc(n * n * 12);
  const build = time(() => { const s = m._studio_skin_create(json, err); m._studio_skin_destroy(s); }, 5);
  const whole = time(() => {
    const s = m._studio_skin_create(json, err);
    if (m._studio_skin_render(s, n, n, 0, n, 0, 0, 0, 0, buf, 1, 1, err) !== 0) throw new Error('render');
    m._studio_skin_destroy(s);
  }, 5);
  console.log(`skin preview ${n}x${n} (${preset}): ${whole.wall.toFixed(1)} ms wall, ${whole.cpu.toFixed(1)} ms CPU (of which the cell build ${build.cpu.toFixed(1)} ms CPU)`);
  // the page's live maps: one worker per core, each building the skin and rendering its
  // band of rows; the slowest worker's CPU time is the preview's time on idle cores
  for (const workers of [2, 4]) {
    const bands = [];
    for (let i = 0; i < workers; i++) {
      const y0 = Math.floor((n * i) / workers), y1 = Math.floor((n * (i + 1)) / workers);
      bands.push(time(() => {
        const s = m._studio_skin_create(json, err);
        if (m._studio_skin_render(s, n, n, y0, y1 - y0, 0, 0, 0, 0, buf, 1, 1, err) !== 0) throw new Error('render');
        m._studio_skin_destroy(s);
      }, 5).cpu);
    }
    console.log(`  in ${workers} workers (build + a band of rows each): slowest ${Math.max(...bands).toFixed(1)} ms CPU (bands ${bands.map((b) => b.toFixed(1)).join(', ')})`);
  }
  m._free(buf);
  m._free(json);
}
const hand = m._studio_hand_create(1, err);
const natural = str(fs.readFileSync(path.resolve(www, 'presets/hand/natural.json'), 'utf8'));
m._studio_hand_use_set(hand, natural, natural, err);
let k = 0;
const solve = time(() => {
  for (let i = 0; i < 1000; i++) {
    m._studio_hand_pin(hand, 32, 1, (20 + (k++ % 60)) * Math.PI / 180);
    m._studio_hand_solve(hand, err);
  }
}, 3);
console.log(`hand slider solve + forward kinematics (natural set): ${solve.wall.toFixed(1)} us wall, ${solve.cpu.toFixed(1)} us CPU per move (1000 moves: ms = us per move)`);

// The tissue panel: the arm character built from its file, then the curl simulated at
// its fixed step, as the page steps it (CPU time per simulated second: below 1000 ms is
// faster than real time), on the shipped grid and on the coarser ones the panel offers.
const arm = JSON.parse(fs.readFileSync(path.resolve(www, 'presets/tissue/arm.json'), 'utf8'));
const curlText = fs.readFileSync(path.resolve(www, 'presets/tissue/curl.bvh'), 'utf8');
const curl = m._studio_bvh_parse(str(curlText), m.lengthBytesUTF8(curlText), str('curl'), err);
for (const spacing of [5, 7.5, 10]) {
  const c = structuredClone(arm), r = spacing / arm.skin.spacing_mm;
  c.skin.spacing_mm = spacing;
  c.skin.dilation_radius_mm *= r;
  for (const k of ['fat_stiffness', 'skin_stiffness', 'tether_stiffness']) c.material[k] *= r;
  const json = str(JSON.stringify(c));
  let t = 0;
  const build = time(() => { if (t) m._studio_tissue_destroy(t); t = m._studio_tissue_create(json, err); }, 1);
  if (!t) throw new Error(m.UTF8ToString(m._studio_error_message(err)));
  if (m._studio_tissue_play(t, curl, err) < 0) throw new Error('play');
  const sim = time(() => { for (let f = 1; f <= 30; f++) if (!m._studio_tissue_skin(t, f / 30, err)) throw new Error('skin'); }, 1);
  console.log(`tissue arm at ${spacing} mm (${m._studio_tissue_vertex_count(t)} skin vertices): built in ${build.cpu.toFixed(0)} ms CPU; 1 s of the curl (240 steps) in ${sim.wall.toFixed(0)} ms wall, ${sim.cpu.toFixed(0)} ms CPU: ${(1000 / sim.cpu).toFixed(2)} x real time on an idle core`);
  m._studio_tissue_destroy(t);
  m._free(json);
}
