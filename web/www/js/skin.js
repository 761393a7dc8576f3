// Skin panel (Ishii et al. 1991): every key of the skin preset schema as a control, the
// map set rendered live by the library at preview resolution (in bands of rows over
// Web Workers, one per core), the material on a board, and the full-resolution map set
// of `shitsukan skin maps` exported as files.
import * as THREE from 'three';
import { PresetPanel, el } from './preset_panel.js';
import { download, canvasPng, png16, exrFloat } from './files.js';
import { SkinWorkers } from './skin_workers.js';

// Workers rendering the live maps (one per core the browser reports, at most 4).
const WORKERS = Math.max(1, Math.min(4, navigator.hardwareConcurrency || 1));

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
    for (const name of ['preview', 'height', 'normal', 'furrow', 'cells']) {
      const c = el('canvas', { id: `skin-map-${name}`, title: name });
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
  encoded(r, w, h) {
    const n = w * h, e = {};
    if (r.maps.preview) e.preview = r.maps.preview;
    if (r.maps.height) e.height = r.maps.height.map((v) => (v - r.lo) / (r.hi - r.lo));
    if (r.maps.normal) e.normal = r.maps.normal.map((v) => 0.5 * v + 0.5);
    if (r.maps.furrow) e.furrow = r.maps.furrow.map((v) => Math.min(1, v / r.furrowMax));
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

  // Renders the live maps (the workers) and shows them; a later edit supersedes a render
  // still running. idle() resolves when the last one is shown.
  update() {
    const token = (this.token = (this.token || 0) + 1);
    this.rendering = this.show(token);
  }

  idle() { return this.rendering; }

  async show(token) {
    const w = this.size, h = this.size;
    const t0 = performance.now();
    let r;
    try {
      r = await this.workers.render(this.tree, w, h, ['preview', 'height', 'normal', 'furrow', 'cells']);
    } catch (e) {
      if (token === this.token) this.errorLine.textContent = e.message;
      return;
    }
    if (token !== this.token) return;
    const t1 = performance.now();
    const e = this.encoded(r, w, h);
    const channels = { preview: 3, height: 1, normal: 3, furrow: 1, cells: 3 };
    for (const [k, c] of Object.entries(this.canvases)) {
      c.width = w;
      c.height = h;
      c.getContext('2d').putImageData(new ImageData(this.rgbaOf(e[k], channels[k], k === 'preview', w * h), w, h), 0, 0);
    }
    this.normalTex.needsUpdate = true;
    const t2 = performance.now();
    this.timings = { model_ms: t1 - t0, draw_ms: t2 - t1, total_ms: t2 - t0, size: w };
    this.info.textContent = `tile ${r.tw.toFixed(2)} × ${r.th.toFixed(2)} mm, height ${r.lo.toFixed(4)}…${r.hi.toFixed(4)} mm; ${w}² maps in ${(t2 - t0).toFixed(0)} ms`;
    this.app.emit('skin-updated', this.timings);
  }

  // Only the shaded preview at n x n, built and rendered, for the speed figures: by the
  // workers (as the live maps are) and on the page's own thread (one instance).
  async timePreview(n) {
    const t0 = performance.now();
    await this.workers.render(this.tree, n, n, ['preview']);
    return performance.now() - t0;
  }

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
