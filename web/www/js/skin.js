// Skin panel (Ishii et al. 1991): every key of the skin preset schema as a control, the
// map set rendered live by the library at preview resolution (in strips of rows over
// Web Workers, one per core, each holding the skin and a map set per strip: an edit of
// the profiles re-profiles it and renders the maps it changes, a shading edit shades the
// held normals again, only a key that moves the cells builds it again), the material on
// a board, and the full-resolution map set of `shitsukan skin maps` exported as files,
// each file as the library's layout of the set (maps.h) says.
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

  // Builds the skin from the tree and calls fn(set) with its map set at w x h
  // (studio_skin_maps_create: the files of `shitsukan skin maps`) rendered for the maps
  // `wanted` (their names in the library's layout; every map when omitted); both are
  // freed when fn returns.
  withMaps(w, h, wanted, fn) {
    const lib = this.lib, m = lib.m;
    const skin = lib.withStrings([JSON.stringify(this.tree)], (p) => m._studio_skin_create(p, lib.err));
    if (!skin) throw new Error(lib.errorMessage());
    let set = 0;
    try {
      set = m._studio_skin_maps_create(skin, w, h, 0, h, lib.err);
      if (!set) throw new Error(lib.errorMessage());
      const which = (wanted || []).reduce((b, k) => b | (1 << this.mapInfo(k).map), 0);
      if (m._studio_skin_maps_render(set, which, lib.err) !== 0) throw new Error(lib.errorMessage());
      return fn(set);
    } finally {
      if (set) m._studio_skin_maps_destroy(set);
      m._studio_skin_destroy(skin);
    }
  }

  // The library's layout of the skin map set (studio_maps_layout): each file with its
  // sk_skin_map, name, channels, bits and codes; mapInfo: one by its name.
  mapsLayout() {
    this.layout ||= JSON.parse(this.lib.takeString(this.lib.withStrings(['skin'], (p) => this.lib.m._studio_maps_layout(p)))).maps;
    return this.layout;
  }

  mapInfo(name) { return this.mapsLayout().find((x) => x.name === name); }

  // A map of a set as a file (a Blob, or its promise): 8-bit PNG through the canvas from
  // its codes, 16-bit PNG and float EXR written here, each with the library's metadata
  // where the format takes it. The set is read before this returns.
  mapFile(set, info, w, h) {
    const lib = this.lib, m = lib.m, n = w * h;
    const meta = JSON.parse(lib.takeString(lib.withStrings(['shitsukan studio'], (s) => m._studio_skin_maps_metadata(set, info.map, s, lib.err))) || 'null');
    if (!meta) throw new Error(lib.errorMessage());
    const bytes = info.bit_depth === 32 ? 4 * info.channels : info.bit_depth === 16 ? 2 * info.channels : 4;
    const p = lib.alloc(n * bytes);
    try {
      if (info.bit_depth === 32) {
        if (m._studio_skin_maps_samples(set, info.map, p, lib.err) !== 0) throw new Error(lib.errorMessage());
        return exrFloat([new Float32Array(lib.f32(p, n))], ['Y'], w, h, meta);
      }
      if (info.bit_depth === 16) {
        if (m._studio_skin_maps_codes16(set, info.map, p, lib.err) !== 0) throw new Error(lib.errorMessage());
        return png16(new Uint16Array(lib.u16(p, n * info.channels)), w, h, info.channels, meta);
      }
      if (m._studio_skin_maps_rgba(set, info.map, p, lib.err) !== 0) throw new Error(lib.errorMessage());
      return canvasPng(new Uint8ClampedArray(lib.u8(p, n * 4)), w, h);
    } finally {
      lib.free(p);
    }
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
    const t0 = performance.now(), lib = this.lib, preview = this.mapInfo('preview');
    const out = lib.alloc(n * n * 4);
    try {
      this.withMaps(n, n, ['preview'], (set) => {
        if (lib.m._studio_skin_maps_rgba(set, preview.map, out, lib.err) !== 0) throw new Error(lib.errorMessage());
      });
    } finally { lib.free(out); }
    return performance.now() - t0;
  }

  // The map set of `shitsukan skin maps` at full resolution, as files: each file the set
  // holds (the library's layout), named as the command names it.
  async exportMaps(size) {
    const w = size, h = size, base = this.name || 'skin';
    const files = this.withMaps(w, h, null, (set) => this.mapsLayout()
      .filter((info) => this.lib.m._studio_skin_maps_holds(set, info.map))
      .map((info) => [info.file, this.mapFile(set, info, w, h)]));
    // every file made first, then downloaded together (a page's downloads spread over time
    // are dropped by the browser after the first few)
    const blobs = await Promise.all(files.map(([, blob]) => blob));
    files.forEach(([name], i) => download(`${base}-${name}`, blobs[i]));
    return files.map(([name]) => name);
  }

  activate(view) {
    view.showMaps(this.maps);
    view.setContent(this.group, { distance: 5, target: [0, 0, 0] });
  }
}
