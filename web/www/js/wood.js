// Wood panel (Kawai 2000): every key of the wood preset schema as a control, the
// preset's view cut rendered live by the library, the solid texture on the faces of a
// board (each face its own cut through the same log), and the maps of `shitsukan wood
// cut --maps` exported as files.
import * as THREE from 'three';
import { PresetPanel, el } from './preset_panel.js';
import { download, canvasPng, png16, exrFloat } from './files.js';

export class WoodPanel extends PresetPanel {
  constructor(app, container) {
    super(app, container, 'wood', 'Every key of the wood presets (shitsukan wood cut --help-keys); the board\'s top is the preset\'s view. Saved files: shitsukan wood cut --preset FILE.');
    this.size = 256;
    this.group = new THREE.Group();
    this.build();
  }

  build() {
    this.canvas = el('canvas', { id: 'wood-map-shaded' });
    this.maps = el('div', {}, this.canvas);
  }

  withWood(fn) {
    const m = this.lib.m;
    const wood = this.lib.withStrings([JSON.stringify(this.tree)], (p) => m._studio_wood_create(p, this.lib.err));
    if (!wood) throw new Error(this.lib.errorMessage());
    try { return fn(wood); } finally { m._studio_wood_destroy(wood); }
  }

  // The view cut's shaded picture at w x h (in one call; bands are not needed at these sizes).
  viewShaded(wood, w, h, samples) {
    const m = this.lib.m, n = w * h, p = this.lib.alloc(n * 12);
    try {
      if (m._studio_wood_view(wood, w, h, 0, h, samples, p, 0, 0, 0, this.lib.err) !== 0) throw new Error(this.lib.errorMessage());
      return new Float32Array(this.lib.f32(p, n * 3));
    } finally {
      this.lib.free(p);
    }
  }

  update() {
    const t0 = performance.now();
    try {
      this.withWood((wood) => {
        const w = this.size, h = this.size;
        const shaded = this.viewShaded(wood, w, h, 1);
        this.canvas.width = w;
        this.canvas.height = h;
        this.canvas.getContext('2d').putImageData(new ImageData(this.rgbaOf(shaded, 3, true, w * h), w, h), 0, 0);
        this.buildBoard(wood);
      });
    } catch (e) {
      this.errorLine.textContent = e.message;
      return;
    }
    this.timings = { total_ms: performance.now() - t0 };
    this.info.textContent = `view and board in ${this.timings.total_ms.toFixed(0)} ms`;
    this.app.view.render();
  }

  // Six faces, each a cut through the log at its own plane, placed where the library
  // says its corners are (scene mm, shown at 1 unit = 100 mm).
  buildBoard(wood) {
    const m = this.lib.m;
    this.group.clear();
    const aspect = 0.35, thickness = 20;
    const resolved = this.resolvedTree;
    const widthMm = resolved.view ? resolved.view.width_mm : 100;
    const sizes = [[1, aspect], [1, aspect], [1, thickness / widthMm], [1, thickness / widthMm], [aspect, thickness / widthMm], [aspect, thickness / widthMm]];
    const corners = this.lib.alloc(9 * 4);
    let centre = null;
    const faces = [];
    for (let face = 0; face < 6; face++) {
      const [fw, fh] = sizes[face];
      const w = Math.max(8, Math.round(256 * fw)), h = Math.max(4, Math.round((w * fh) / fw));
      const buf = this.lib.alloc(w * h * 12);
      const r = m._studio_wood_board_face(wood, face, aspect, thickness, w, h, 1, buf, corners, this.lib.err);
      if (r !== 0) { this.lib.free(buf); throw new Error(this.lib.errorMessage()); }
      const rgba = this.lib.rgba(buf, w * h, 3, true);
      this.lib.free(buf);
      faces.push({ rgba, w, h, c: Array.from(this.lib.f32(corners, 9)) });
    }
    this.lib.free(corners);
    for (const { rgba, w, h, c } of faces) {
      const tl = new THREE.Vector3(c[0], c[1], c[2]), tr = new THREE.Vector3(c[3], c[4], c[5]), bl = new THREE.Vector3(c[6], c[7], c[8]);
      const br = tr.clone().add(bl).sub(tl);
      if (!centre) centre = tl.clone().add(br).multiplyScalar(0.5);
      const g = new THREE.BufferGeometry();
      g.setAttribute('position', new THREE.Float32BufferAttribute([...tl.toArray(), ...tr.toArray(), ...bl.toArray(), ...br.toArray()], 3));
      g.setAttribute('uv', new THREE.Float32BufferAttribute([0, 1, 1, 1, 0, 0, 1, 0], 2));
      g.setIndex([0, 2, 1, 1, 2, 3]);
      g.computeVertexNormals();
      const tex = new THREE.DataTexture(rgba, w, h, THREE.RGBAFormat);
      tex.flipY = true;
      tex.colorSpace = THREE.SRGBColorSpace;
      tex.needsUpdate = true;
      const mesh = new THREE.Mesh(g, new THREE.MeshBasicMaterial({ map: tex, side: THREE.FrontSide }));
      this.group.add(mesh);
    }
    // scene mm around the board's top centre, 1 unit = 100 mm
    this.group.scale.setScalar(0.01);
    this.group.position.copy(centre.multiplyScalar(-0.01));
  }

  // The shaded view and the maps of `wood cut --maps` at w x h: each map of the library's
  // layout (studio_maps_layout: its file, channels, bits and codes), as floats.
  viewWithMaps(wood, w, h, samples) {
    const m = this.lib.m, n = w * h, layout = this.mapsLayout();
    const shaded = this.lib.alloc(n * 12), ptrs = this.lib.alloc(4 * layout.length);
    const bufs = layout.map((info) => this.lib.alloc(n * info.channels * 4));
    try {
      this.lib.u32(ptrs, layout.length).set(bufs);
      if (m._studio_wood_view_maps(wood, w, h, samples, shaded, ptrs, this.lib.err) !== 0) throw new Error(this.lib.errorMessage());
      return { shaded: new Float32Array(this.lib.f32(shaded, n * 3)), maps: bufs.map((p, k) => new Float32Array(this.lib.f32(p, n * layout[k].channels))) };
    } finally {
      for (const p of [shaded, ptrs, ...bufs]) this.lib.free(p);
    }
  }

  mapsLayout() {
    this.layout ||= JSON.parse(this.lib.takeString(this.lib.withStrings(['wood'], (p) => this.lib.m._studio_maps_layout(p)))).maps;
    return this.layout;
  }

  async exportMaps(size) {
    const w = size, h = size, n = w * h;
    const { shaded, maps } = this.withWood((wood) => this.viewWithMaps(wood, w, h, 2));
    const base = this.name || 'wood';
    const files = {};
    files['cut.png'] = canvasPng(this.rgbaOf(shaded, 3, true, n), w, h);
    const planes = [0, 1, 2].map((c) => { const p = new Float32Array(n); for (let i = 0; i < n; i++) p[i] = shaded[3 * i + c]; return p; });
    files['cut.exr'] = exrFloat(planes, ['R', 'G', 'B'], w, h, { 'shitsukan:command': 'wood cut (studio)' });
    this.mapsLayout().forEach((info, k) => {
      files[info.file] = info.bit_depth === 16
        ? png16(this.codes16Of(maps[k]), w, h, info.channels, info.metadata)
        : canvasPng(this.rgbaOf(maps[k], info.channels, info.srgb, n), w, h);
    });
    // every file made first, then downloaded together (as the skin panel does)
    const names = Object.keys(files), blobs = await Promise.all(Object.values(files));
    names.forEach((name, i) => download(`${base}-${name}`, blobs[i]));
    return names;
  }

  activate(view) {
    view.showMaps(this.maps);
    if (!this.group.children.length) this.update();
    view.setContent(this.group, { distance: 2.2, target: [0, 0, 0], direction: [0.4, 0.8, 0.9] });
  }
}
