// Skin panel (Ishii et al. 1991): every key of the skin preset schema as a control, the
// map set rendered live by the library at preview resolution (in strips of rows over
// Web Workers, one per core, each holding the skin: an edit of the profiles re-profiles
// it and renders the maps it changes, a shading edit shades the held normals again, only
// a key that moves the cells builds it again),
// the material on a board, and the full-resolution map set of `shitsukan skin maps`
// exported as files.
import * as THREE from 'three';
import { PresetPanel, el } from './preset_panel.js';
import { download, canvasPng, png16, exrFloat } from './files.js';
import { SkinWorkers } from './skin_workers.js';

// Workers rendering the live maps (one per core the browser reports, at most 4).
const WORKERS = Math.max(1, Math.min(4, navigator.hardwareConcurrency || 1));
// The live maps, as the workers name them (a canvas each).
const LIVE_MAPS = ['preview', 'height', 'normal', 'furrow', 'cells'];

export class SkinPanel extends PresetPanel {
  constructor(app, container) {
    super(app, container, 'skin', 'Every key of the skin presets (shitsukan skin maps --help-keys). Files saved here are presets the command line reads: shitsukan skin maps --preset FILE.');
    this.size = 512;
    this.workers = new SkinWorkers(WORKERS);
    this.rendering = Promise.resolve();
    this.build();
  }

  build() {
    const sizeSel = el('select', { id: 'skin-size' });
    for (const s of [128, 256, 512]) sizeSel.append(el('option', { value: s, textContent: `${s}²`, selected: s === this.size }));
    sizeSel.onchange = () => { this.size = Number(sizeSel.value); this.update(); };
    this.presetRow.append(' preview ', sizeSel);
    // map canvases
    this.canvases = {};
    this.maps = el('div', { className: 'maps-skin' });
    const big = el('div', { className: 'row' });
    const small = el('div', { className: 'row' });
    for (const name of LIVE_MAPS) {
      const c = el('canvas', { id: `skin-map-${name}`, title: name, width: this.size, height: this.size });
      this.canvases[name] = c;
      (name === 'preview' ? big : small).append(c);
    }
    for (const c of small.children) { c.style.width = '96px'; c.style.height = '96px'; }
    this.maps.append(big, small);
    // the material on a board in the 3D view
    this.normalTex = new THREE.CanvasTexture(this.canvases.normal);
    this.normalTex.colorSpace = THREE.NoColorSpace;
    this.normalTex.wrapS = this.normalTex.wrapT = THREE.RepeatWrapping;
    this.normalTex.repeat.set(3, 3);
    this.material = new THREE.MeshStandardMaterial({ color: 0xcc8a6b, roughness: 0.55, normalMap: this.normalTex });
    const board = new THREE.Mesh(new THREE.BoxGeometry(3, 0.2, 3), this.material);
    this.group = new THREE.Group();
    this.group.add(board);
    this.update();
  }

  // Builds the skin from the tree and renders the maps at w x h in bands; returns the
  // float maps (the caller frees nothing: buffers are freed here).
  renderMaps(w, h, wanted) {
    const lib = this.lib, m = lib.m;
    const skin = lib.withStrings([JSON.stringify(this.tree)], (p) => m._studio_skin_create(p, lib.err));
    if (!skin) throw new Error(lib.errorMessage());
    const info = lib.alloc(6 * 8);
    m._studio_skin_info(skin, 1, info);
    const [lo, hi, tw, th, furrowMax] = lib.f64(info, 6);
    lib.free(info);
    const band = Math.max(1, Math.min(h, Math.floor((1 << 22) / w)));
    const ch = { height: 1, normal: 3, furrow: 1, cells: 1, preview: 3 };
    const out = {};
    for (const k of wanted) out[k] = k === 'cells' ? new Uint32Array(w * h) : new Float32Array(w * h * ch[k]);
    const ptr = {};
    for (const k of wanted) ptr[k] = lib.alloc(w * band * ch[k] * 4);
    try {
      for (let y0 = 0; y0 < h; y0 += band) {
        const rows = Math.min(band, h - y0);
        const r = m._studio_skin_render(skin, w, h, y0, rows, ptr.height || 0, ptr.normal || 0, ptr.furrow || 0,
          ptr.cells || 0, ptr.preview || 0, 1, 1, lib.err);
        if (r !== 0) throw new Error(lib.errorMessage());
        for (const k of wanted) {
          const n = w * rows * ch[k];
          const view = k === 'cells' ? lib.u32(ptr[k], n) : lib.f32(ptr[k], n);
          out[k].set(view, w * y0 * ch[k]);
        }
      }
    } finally {
      for (const k of wanted) lib.free(ptr[k]);
      m._studio_skin_destroy(skin);
    }
    return { maps: out, lo, hi, tw, th, furrowMax };
  }

  // The maps as the files encode them (linear floats in [0, 1] per channel).
  // (the library's scaling, studio_skin_scale_maps, as the live maps have it).
  encoded(r, w, h) {
    const n = w * h, e = {}, lib = this.lib;
    if (r.maps.preview) e.preview = r.maps.preview;
    const scaled = ['height', 'normal', 'furrow'].map((k) => {
      if (!r.maps[k]) return 0;
      const p = lib.alloc(r.maps[k].length * 4);
      lib.f32(p, r.maps[k].length).set(r.maps[k]);
      return p;
    });
    lib.m._studio_skin_scale_maps(n, ...scaled, r.lo, r.hi, r.furrowMax);
    ['height', 'normal', 'furrow'].forEach((k, i) => {
      if (scaled[i]) e[k] = new Float32Array(lib.f32(scaled[i], r.maps[k].length));
      lib.free(scaled[i]);
    });
    if (r.maps.cells) {
      const ids = this.lib.alloc(n * 4), rgb = this.lib.alloc(n * 12);
      this.lib.u32(ids, n).set(r.maps.cells);
      this.lib.m._studio_skin_cell_colors(ids, n, rgb);
      e.cells = new Float32Array(this.lib.f32(rgb, n * 3));
      this.lib.free(ids);
      this.lib.free(rgb);
    }
    return e;
  }

  // Renders the live maps (the workers) and shows them. Edits that come while a render
  // runs are folded into one render of the latest tree when it ends (a slider dragged
  // does not queue a render per step); idle() resolves when the last edit is shown.
  update() {
    this.dirty = true;
    if (!this.running) this.rendering = this.renderLoop();
  }

  async renderLoop() {
    this.running = true;
    try {
      while (this.dirty) {
        this.dirty = false;
        await this.show();
      }
    } finally {
      this.running = false;
    }
  }

  idle() { return this.rendering; }

  // (PresetPanel) fn runs when the next maps are on their canvases, or the render failed.
  afterPictures(fn) { (this.whenShown ||= []).push(fn); }

  // Runs what waits for the maps (afterPictures).
  shown() {
    const waiting = this.whenShown || [];
    this.whenShown = [];
    for (const fn of waiting) fn();
  }

  async show() {
    const w = this.size, h = this.size;
    const t0 = performance.now();
    const resized = this.canvases.preview.width !== w;
    // new cells come in two parts: the preview, height and normal maps (and the board)
    // are shown while the furrow and cells maps are made
    let first = null;
    const part = (p) => {
      this.draw(p, w, resized && !first);
      first = { at: performance.now(), maps: p.changed };
      this.app.emit('skin-part', first);
      this.shown();
    };
    let r;
    try {
      r = await this.workers.render(this.tree, w, h, part);
    } catch (e) {
      this.errorLine.textContent = e.message;
      this.shown();
      return;
    }
    const t1 = performance.now();
    // what the first part showed is on its canvases already
    this.draw({ ...r, changed: first ? r.changed.filter((k) => !first.maps.includes(k)) : r.changed }, w, resized && !first);
    const t2 = performance.now();
    const rebuilt = r.workers.some((x) => x.changes & 1);
    this.timings = { model_ms: t1 - t0, draw_ms: t2 - t1, total_ms: t2 - t0, shown_at: t2, size: w, rebuilt, maps: r.changed, workers: r.workers,
      first_shown_at: first ? first.at : t2, first_maps: first ? first.maps : r.changed };
    const what = rebuilt ? 'cells built' : r.changed.length > 1 ? 'relief re-profiled' : r.changed.length ? 'shaded again' : 'unchanged';
    const firstNote = first ? `, the preview ${(first.at - t0).toFixed(0)} ms` : '';
    this.info.textContent = `tile ${r.tw.toFixed(2)} × ${r.th.toFixed(2)} mm, height ${r.lo.toFixed(4)}…${r.hi.toFixed(4)} mm; ${w}² maps in ${(t2 - t0).toFixed(0)} ms${firstNote} (${what})`;
    this.app.emit('skin-updated', this.timings);
    this.shown();
  }

  // Puts the maps r.changed of a render (r.rgba) on their canvases (every canvas sized
  // w x w first when `resized`), and the board in the 3D view takes a new normal map at the
  // next frame (a texture of another size is a new one for WebGL).
  draw(r, w, resized) {
    for (const [k, c] of Object.entries(this.canvases)) {
      if (resized) c.width = c.height = w;
      if (r.changed.includes(k)) c.getContext('2d').putImageData(new ImageData(r.rgba[k], w, w), 0, 0);
    }
    if (resized) this.normalTex.dispose();
    if (resized || r.changed.includes('normal')) this.normalTex.needsUpdate = true;
    if ((resized || r.changed.includes('normal')) && this.app.tab === 'skin' && !this.boardPending) {
      this.boardPending = true;
      requestAnimationFrame(() => { this.boardPending = false; this.app.view.render(); });
    }
  }

  // Only the shaded preview at n x n, built and rendered on the page's own thread (one
  // instance), for the speed figures.
  timePreviewOneThread(n) {
    const t0 = performance.now();
    this.renderMaps(n, n, ['preview']);
    return performance.now() - t0;
  }

  // The map set of `shitsukan skin maps` at full resolution, as files.
  async exportMaps(size) {
    const w = size, h = size;
    const r = this.renderMaps(w, h, ['preview', 'height', 'normal', 'furrow', 'cells']);
    const e = this.encoded(r, w, h);
    const base = this.name || 'skin';
    const meta = { 'shitsukan:tile_mm': `${r.tw} x ${r.th}`, 'shitsukan:mm_per_px': `${r.tw / w}`, Software: 'shitsukan studio' };
    const files = {};
    files['preview.png'] = await canvasPng(this.rgbaOf(e.preview, 3, true, w * h), w, h);
    files['normal.png'] = await canvasPng(this.rgbaOf(e.normal, 3, false, w * h), w, h);
    files['cells.png'] = await canvasPng(this.rgbaOf(e.cells, 3, false, w * h), w, h);
    files['height.png'] = await png16(this.codes16Of(e.height), w, h, 1, { ...meta, 'shitsukan:decode': `height_mm = ${r.lo} + value * ${r.hi - r.lo} (value = code / 65535)` });
    files['furrow.png'] = await png16(this.codes16Of(e.furrow), w, h, 1, { ...meta, 'shitsukan:decode': `distance_mm = value * ${r.furrowMax} (clamped there)` });
    files['height.exr'] = exrFloat([r.maps.height], ['Y'], w, h, { ...meta, 'shitsukan:units': 'mm' });
    for (const [name, blob] of Object.entries(files)) download(`${base}-${name}`, blob);
    return Object.keys(files);
  }

  activate(view) {
    view.showMaps(this.maps);
    view.setContent(this.group, { distance: 5, target: [0, 0, 0] });
  }
}
