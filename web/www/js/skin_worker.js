// One skin worker (skin_workers.js): its own instance of the library; a message asks for
// rows [y0, y0 + rows) of a preset tree's maps at w x h, the answer carries them.
import createStudio from '../wasm/studio.mjs';

const CHANNELS = { height: 1, normal: 3, furrow: 1, cells: 1, preview: 3 };
const ready = createStudio({ locateFile: (f) => new URL('../wasm/' + f, import.meta.url).href });

self.onmessage = async (e) => {
  const { id, json, w, h, y0, rows, wanted } = e.data;
  const m = await ready;
  const err = m._studio_error_new();
  const str = (s) => { const n = m.lengthBytesUTF8(s) + 1, p = m._malloc(n); m.stringToUTF8(s, p, n); return p; };
  const fail = () => self.postMessage({ id, error: m.UTF8ToString(m._studio_error_message(err)) });
  const p = str(json);
  const skin = m._studio_skin_create(p, err);
  m._free(p);
  if (!skin) { fail(); m._free(err); return; }
  const info = m._malloc(6 * 8);
  m._studio_skin_info(skin, 1, info);
  const [lo, hi, tw, th, furrowMax] = new Float64Array(m.HEAPU8.buffer, info, 6);
  m._free(info);
  const ptr = {};
  for (const k of wanted) ptr[k] = m._malloc(w * rows * CHANNELS[k] * 4);
  const r = m._studio_skin_render(skin, w, h, y0, rows, ptr.height || 0, ptr.normal || 0, ptr.furrow || 0, ptr.cells || 0,
    ptr.preview || 0, 1, 1, err);
  if (r !== 0) fail();
  else {
    const maps = {};
    for (const k of wanted) {
      const n = w * rows * CHANNELS[k];
      maps[k] = k === 'cells' ? new Uint32Array(m.HEAPU8.buffer, ptr[k], n).slice() : new Float32Array(m.HEAPU8.buffer, ptr[k], n).slice();
    }
    self.postMessage({ id, maps, lo, hi, tw, th, furrowMax }, Object.values(maps).map((a) => a.buffer));
  }
  for (const k of wanted) m._free(ptr[k]);
  m._studio_skin_destroy(skin);
  m._free(err);
};
