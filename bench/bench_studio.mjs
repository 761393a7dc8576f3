// The studio's WebAssembly build timed in node (the V8 of Chromium, without drawing):
// the skin preview at 512 x 512 (skin built from a preset and rendered), the live maps
// after a preset change, a profile edit and a shading edit split over the page's workers
// (CPU time per worker), a hand slider's solve and the tissue arm, in wall and CPU time, best of
// several runs. The page's own figures
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
// The skin panel's live maps (the five maps as canvas pixels from a map set per strip,
// studio_skin_maps_*), in strips of 16 rows dealt to the workers in turn as the page does:
// after a preset change (each worker builds the skin and makes every map), a profile edit
// (each re-profiles the skin it holds, sk_skin_reprofile, and renders the preview, height
// and normal maps) and a shading edit (each shades its sets' normals again). The slowest
// worker's CPU time is the preview's time on idle cores.
const STRIP = 16;
const layout = JSON.parse(m.UTF8ToString(m._studio_maps_layout(str('skin')))).maps;
const mapOf = (name) => layout.find((x) => x.name === name).map;
const bitsOf = (names) => names.reduce((b, k) => b | (1 << mapOf(k)), 0);
const ALL = ['preview', 'height', 'normal', 'furrow', 'cells'], RELIEF = ['preview', 'height', 'normal'];
const CELLS_FURROW = ['furrow', 'cells'];
const setsOf = (skin, n, strips) => strips.map(([y0, rows]) => m._studio_skin_maps_create(skin, n, n, y0, rows, err));
const dropSets = (sets) => sets.forEach((x) => m._studio_skin_maps_destroy(x));
// Renders the maps `names` into each strip's set (unless `render` is false) and reads
// them as canvas pixels into `out`.
function liveRgba(sets, names, render, out) {
  for (const set of sets) {
    if (render && m._studio_skin_maps_render(set, bitsOf(names), err) !== 0) throw new Error('render');
    for (const k of names) if (m._studio_skin_maps_rgba(set, mapOf(k), out, err) !== 0) throw new Error('rgba');
  }
}
function stripsOf(n, workers) {
  const s = Array.from({ length: workers }, () => []);
  for (let y0 = 0, k = 0; y0 < n; y0 += STRIP, k++) s[k % workers].push([y0, Math.min(STRIP, n - y0)]);
  return s;
}
// The preset edited in a key that leaves the cells: level 1's roundness, or the light.
function edited(tree, kind, k) {
  const t = structuredClone(tree);
  if (kind === 'profile') t.levels[0].roundness = 0.2 + 0.05 * (k % 4);
  else t.shading = { ...(t.shading || {}), light_azimuth_deg: 30 + 10 * (k % 4) };
  return str(JSON.stringify(t));
}
const flag = m._malloc(4);
for (const [preset, n] of [['back-of-hand', 512], ['back-of-hand', 256], ['fig13a', 512]]) {
  const text = fs.readFileSync(path.resolve(www, `presets/skin/${preset}.json`), 'utf8');
  const json = str(text), tree = JSON.parse(text);
  const out = m._malloc(n * n * 4);
  const build = time(() => { const s = m._studio_skin_create(json, err); m._studio_skin_destroy(s); }, 5);
  const whole = time(() => {
    const s = m._studio_skin_create(json, err), sets = setsOf(s, n, [[0, n]]);
    liveRgba(sets, ['preview'], true, out);
    dropSets(sets);
    m._studio_skin_destroy(s);
  }, 5);
  console.log(`skin preview ${n}x${n} (${preset}): ${whole.wall.toFixed(1)} ms wall, ${whole.cpu.toFixed(1)} ms CPU (of which the cell build ${build.cpu.toFixed(1)} ms CPU)`);
  let held = m._studio_skin_create(json, err), k = 0;
  const edits = { profile: [], shading: [] };
  for (const kind of Object.keys(edits)) for (let i = 0; i < 4; i++) edits[kind].push(edited(tree, kind, i));
  const update = (kind) => {
    held = m._studio_skin_update(held, edits[kind][k++ % 4], flag, err);
    if (!held || m.HEAPU32[flag >> 2] & 1) throw new Error('reprofile');
  };
  const reprofile = time(() => update('profile'), 5);
  const one = setsOf(held, n, stripsOf(n, 1)[0]);
  const live = time(() => liveRgba(one, ALL, true, out), 3);
  dropSets(one);
  console.log(`  live maps (five, as canvas pixels) on one thread: ${live.cpu.toFixed(1)} ms CPU; re-profiling the built skin ${reprofile.cpu.toFixed(2)} ms CPU`);
  for (const workers of [2, 4]) {
    const shares = stripsOf(n, workers), list = (v) => v.map((b) => b.toFixed(1)).join(', ');
    const heldSets = shares.map((share) => setsOf(held, n, share));
    heldSets.forEach((sets) => liveRgba(sets, ALL, true, out));
    // a preset change as the page makes it: the build and the relief maps (the first
    // answer: preview, height, normal), then the furrow and cells maps
    const change = (share, names) => time(() => {
      const s = m._studio_skin_create(json, err), sets = setsOf(s, n, share);
      liveRgba(sets, names, true, out);
      dropSets(sets);
      m._studio_skin_destroy(s);
    }, 3).cpu;
    const figures = {
      'preset change to the first answer (build + preview, height, normal)': shares.map((share) => change(share, RELIEF)),
      'then the furrow and cells maps': heldSets.map((sets) => time(() => liveRgba(sets, CELLS_FURROW, true, out), 3).cpu),
      'preset change in one pass (build + every map)': shares.map((share) => change(share, ALL)),
      'profile edit (re-profile + preview, height, normal)': heldSets.map((sets) => time(() => { update('profile'); liveRgba(sets, RELIEF, true, out); }, 3).cpu),
      'shading edit (re-profile + preview shaded from the held normals)': heldSets.map((sets) => time(() => { update('shading'); liveRgba(sets, ['preview'], false, out); }, 3).cpu),
    };
    heldSets.forEach(dropSets);
    console.log(`  in ${workers} workers, CPU of the slowest worker: ${Object.entries(figures).map(([what, v]) => `${what} ${Math.max(...v).toFixed(1)} ms (${list(v)})`).join('; ')}`);
  }
  m._studio_skin_destroy(held);
  for (const e of [...edits.profile, ...edits.shading]) m._free(e);
  m._free(out);
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
