// One skin worker (skin_workers.js): its own instance of the library, holding the skin of
// the last preset tree it was given and the normals of its last render. A message asks
// for strips of rows of the live maps at w x h as canvas pixels. A new tree costs what it
// changes (sk_skin_desc_changes): a key that places the cells builds the skin again and
// renders every map, in two answers (the preview, height and normal maps, then the
// furrow and cells maps); a profile, roundness, normal model or pore edit re-profiles the
// skin held (sk_skin_reprofile) and renders the preview, height and normal maps (the cells
// and furrows stay); a shading edit shades the held normals again, with no render. An
// answer carries the pixels of the maps it made, its strips one after the other, and the
// time this worker spent (performance.now() around the update and the maps so far); all
// but the last are marked partial.
import createStudio from '../wasm/studio.mjs';

const MAPS = ['preview', 'height', 'normal', 'furrow', 'cells'];
const CELLS = 1, RELIEF = 2, SHADING = 4; // sk_skin_change
const RESHADE = 1 << MAPS.length;
const ready = createStudio({ locateFile: (f) => new URL('../wasm/' + f, import.meta.url).href });
let m, err, skin = 0, json = null;
let layout = null, normals = 0; // the strips of the last render and their float normals

// The skin of `text`, the one held re-profiled or a new one; what changed.
function update(text) {
  if (text === json) return 0;
  const n = m.lengthBytesUTF8(text) + 1, p = m._malloc(n), flag = m._malloc(4);
  m.stringToUTF8(text, p, n);
  const next = m._studio_skin_update(skin, p, flag, err);
  const changes = m.HEAPU32[flag >> 2];
  m._free(p);
  m._free(flag);
  if (!next) throw new Error(m.UTF8ToString(m._studio_error_message(err)));
  skin = next;
  json = text;
  return changes;
}

// The passes an edit's changes call for, each [names, the flags of studio_skin_live_rgba]:
// new cells make the relief maps first (preview, height, normal: an answer of its own, so
// the page shows them while the rest are made), then the furrow and cells maps, whose
// render walks down only to level 1 and evaluates no relief.
function passesFor(changes) {
  if (changes & CELLS) return [[['preview', 'height', 'normal'], 7], [['furrow', 'cells'], 24]];
  if (changes & RELIEF) return [[['preview', 'height', 'normal'], 7]];
  if (changes & SHADING) return [[['preview'], 1 | RESHADE]];
  return [];
}

// Makes the maps `names` of the strips as canvas pixels (flags: studio_skin_live_rgba's),
// the strips one after the other in each map; throws the library's message.
function makeMaps(names, flags, w, h, strips, rows) {
  if (!names.length) return {};
  const bytes = w * rows * 4;
  const ptr = MAPS.map((k) => (names.includes(k) ? m._malloc(bytes) : 0));
  const ptrs = m._malloc(4 * MAPS.length);
  let done = 0, failed = null;
  for (const [y0, r] of strips) {
    MAPS.forEach((k, i) => { m.HEAPU32[(ptrs >> 2) + i] = ptr[i] ? ptr[i] + w * done * 4 : 0; });
    if (m._studio_skin_live_rgba(skin, w, h, y0, r, flags, ptrs, normals + w * done * 12, err) !== 0) {
      failed = m.UTF8ToString(m._studio_error_message(err));
      break;
    }
    done += r;
  }
  const out = {};
  if (!failed) MAPS.forEach((k, i) => { if (ptr[i]) out[k] = m.HEAPU8.slice(ptr[i], ptr[i] + bytes); });
  for (const p of ptr) if (p) m._free(p);
  m._free(ptrs);
  if (failed) throw new Error(failed);
  return out;
}

self.onmessage = async (e) => {
  const { id, json: text, w, h, strips, full } = e.data;
  m = await ready;
  if (!err) err = m._studio_error_new();
  const t0 = performance.now();
  let changes;
  try { changes = update(text); } catch (x) { self.postMessage({ id, error: x.message }); return; }
  const rows = strips.reduce((s, [, r]) => s + r, 0), key = `${w}x${h}:${strips.join(';')}`;
  if (full || key !== layout) {
    // new strips: every map, and room for their normals
    changes |= CELLS;
    m._free(normals);
    normals = m._malloc(w * rows * 12);
    layout = key;
  }
  const t1 = performance.now();
  const info = m._malloc(6 * 8);
  m._studio_skin_info(skin, 1, info);
  const [lo, hi, tw, th, furrowMax] = new Float64Array(m.HEAPU8.buffer, info, 6);
  m._free(info);
  const passes = passesFor(changes);
  if (!passes.length) passes.push([[], 0]);
  for (let p = 0; p < passes.length; p++) {
    let maps;
    try {
      maps = makeMaps(...passes[p], w, h, strips, rows);
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
