// One skin worker (skin_workers.js): its own instance of the library, holding the skin of
// the last preset tree it was given and a map set of each strip of its last render (the
// library's sk_skin_maps, whose kept normals shade the preview again). A message asks
// for strips of rows of the live maps at w x h as canvas pixels. A new tree costs what it
// changes (sk_skin_desc_changes): a key that places the cells builds the skin again and
// renders every map, in two answers (the preview, height and normal maps, then the
// furrow and cells maps); a profile, roundness, normal model or pore edit re-profiles the
// skin held (sk_skin_reprofile) and renders the preview, height and normal maps (the cells
// and furrows stay); a shading edit shades the sets' normals again, with no render. An
// answer carries the pixels of the maps it made, its strips one after the other, and the
// time this worker spent (performance.now() around the update and the maps so far); all
// but the last are marked partial.
import createStudio from '../wasm/studio.mjs';

// The live maps, by their names in the library's layout of the skin map set.
const MAPS = ['preview', 'height', 'normal', 'furrow', 'cells'];
const CELLS = 1, RELIEF = 2, SHADING = 4; // sk_skin_change
const ready = createStudio({ locateFile: (f) => new URL('../wasm/' + f, import.meta.url).href });
let m, err, skin = 0, json = null;
let index = null; // each live map's sk_skin_map, from the library's layout of the set
let layout = null, sets = []; // the strips of the last render and their map sets

// fn(p) with `text` in the module's memory at p, freed afterwards.
function withString(text, fn) {
  const n = m.lengthBytesUTF8(text) + 1, p = m._malloc(n);
  m.stringToUTF8(text, p, n);
  try { return fn(p); } finally { m._free(p); }
}

// The sk_skin_map of each live map, from the library's layout of the set.
function mapIndex() {
  const p = withString('skin', (s) => m._studio_maps_layout(s));
  const maps = JSON.parse(m.UTF8ToString(p)).maps;
  m._free(p);
  return Object.fromEntries(MAPS.map((k) => [k, maps.find((x) => x.name === k).map]));
}

const bits = (names) => names.reduce((b, k) => b | (1 << index[k]), 0);
const message = () => m.UTF8ToString(m._studio_error_message(err));

// The skin of `text`, the one held re-profiled or a new one; what changed.
function update(text) {
  if (text === json) return 0;
  const flag = m._malloc(4);
  const next = withString(text, (p) => m._studio_skin_update(skin, p, flag, err));
  const changes = m.HEAPU32[flag >> 2];
  m._free(flag);
  if (!next) throw new Error(message());
  skin = next;
  json = text;
  return changes;
}

// The passes an edit's changes call for, each [names, render]: new cells make the relief
// maps first (preview, height, normal: an answer of its own, so the page shows them while
// the rest are made), then the furrow and cells maps, whose render walks down only to
// level 1 and evaluates no relief; a shading edit renders nothing: the preview is shaded
// again from the normals the sets hold.
function passesFor(changes) {
  if (changes & CELLS) return [[['preview', 'height', 'normal'], true], [['furrow', 'cells'], true]];
  if (changes & RELIEF) return [[['preview', 'height', 'normal'], true]];
  if (changes & SHADING) return [[['preview'], false]];
  return [];
}

// A map set per strip (studio_skin_maps_create) for the skin held.
function makeSets(w, h, strips) {
  for (const s of sets) m._studio_skin_maps_destroy(s);
  sets = [];
  for (const [y0, r] of strips) {
    const s = m._studio_skin_maps_create(skin, w, h, y0, r, err);
    if (!s) throw new Error(message());
    sets.push(s);
  }
}

// Makes the maps `names` of the strips as canvas pixels (rendering what they are made
// from first when `render`), the strips one after the other in each map; throws the
// library's message.
function makeMaps(names, render, w, strips, rows) {
  if (!names.length) return {};
  const bytes = w * rows * 4, out = {};
  for (const k of names) out[k] = new Uint8ClampedArray(bytes);
  const buf = m._malloc(w * Math.max(...strips.map(([, r]) => r)) * 4);
  let done = 0, failed = null;
  for (let s = 0; s < strips.length && !failed; s++) {
    if (render && m._studio_skin_maps_render(sets[s], bits(names), err) !== 0) { failed = message(); break; }
    const n = w * strips[s][1] * 4;
    for (const k of names) {
      if (m._studio_skin_maps_rgba(sets[s], index[k], buf, err) !== 0) { failed = message(); break; }
      out[k].set(m.HEAPU8.subarray(buf, buf + n), w * done * 4);
    }
    done += strips[s][1];
  }
  m._free(buf);
  if (failed) throw new Error(failed);
  return out;
}

self.onmessage = async (e) => {
  const { id, json: text, w, h, strips, full } = e.data;
  m = await ready;
  if (!err) err = m._studio_error_new();
  if (!index) index = mapIndex();
  const t0 = performance.now();
  let changes;
  try { changes = update(text); } catch (x) { self.postMessage({ id, error: x.message }); return; }
  const rows = strips.reduce((s, [, r]) => s + r, 0), key = `${w}x${h}:${strips.join(';')}`;
  if (full || key !== layout) changes |= CELLS; // new strips: every map
  try {
    // the sets read the skin they were made for: new cells (a new skin) or strips, new sets
    if (changes & CELLS) makeSets(w, h, strips);
  } catch (x) {
    layout = null;
    self.postMessage({ id, error: x.message });
    return;
  }
  layout = key;
  const t1 = performance.now();
  const info = m._malloc(6 * 8);
  m._studio_skin_info(skin, 1, info);
  const [lo, hi, tw, th, furrowMax] = new Float64Array(m.HEAPU8.buffer, info, 6);
  m._free(info);
  const passes = passesFor(changes);
  if (!passes.length) passes.push([[], false]);
  for (let p = 0; p < passes.length; p++) {
    let maps;
    try {
      maps = makeMaps(...passes[p], w, strips, rows);
    } catch (x) {
      layout = null; // the next render makes every map again
      self.postMessage({ id, error: x.message });
      return;
    }
    const last = p === passes.length - 1;
    self.postMessage({ id, maps, lo, hi, tw, th, furrowMax, changes, update_ms: t1 - t0, maps_ms: performance.now() - t1, partial: !last },
      Object.values(maps).map((a) => a.buffer));
  }
};
