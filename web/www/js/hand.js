// Hand panel: the thesis's GUI (Yasumuro 2000, sec. 4.2.1, Fig. 4.16): a slider per DOF
// grouped by finger, whole-hand rotation, coupling on/off and the constraint set
// (natural, Table 3.2, a user's calibrated file); moving a slider pins that DOF and the
// library's equilibrium moves the coupled joints; keyframes set, edited and played
// (sec. 4.2.2); a fingertip dragged pins its finger at the reach that puts it there.
import * as THREE from 'three';
import { HandModel, FINGERS, FINGER_NAMES, DEG } from './hand_model.js';
import { download, jsonBlob, pickFile } from './files.js';

const el = (tag, props = {}, ...kids) => {
  const e = Object.assign(document.createElement(tag), props);
  e.append(...kids.filter((k) => k !== null && k !== undefined));
  return e;
};

// The surface's material: a plain colour, or the atlas baked with the skin presets'
// microrelief (back-of-hand on the back, palm on the palm, as `hand mesh --texture`), or
// with the skin panel's current skin on the back.
const MATERIALS = [['plain', 'plain colour'], ['baked', 'skin texture (back-of-hand, palm)'], ['skin-panel', 'skin panel\'s skin on the back']];

const SETS = [['natural', 'natural (published couplings)'], ['yasumuro-table-3.2', 'thesis Table 3.2'], ['file', 'calibrated file…']];

export class HandPanel {
  constructor(app, container) {
    this.app = app;
    this.lib = app.lib;
    this.container = container;
    this.model = new HandModel(this.lib);
    this.setTexts = {};
    this.coupling = true;
    this.setChoice = 'natural';
    this.keys = [];
    this.timings = {};
    this.materialChoice = 'plain';
    this.textureSize = 512;
    this.presetTrees = {};
    this.root = new THREE.Group(); // whole-hand rotation
    this.scaled = new THREE.Group();
    this.scaled.scale.setScalar(0.01);
    this.scaled.add(this.model.group);
    this.root.add(this.scaled);
    this.build();
    this.ready = this.applySet();
  }

  async setText(name) {
    if (!this.setTexts[name]) this.setTexts[name] = await (await fetch(`presets/hand/${name}.json`)).text();
    return this.setTexts[name];
  }

  // The set in use: none with coupling off, else the chosen one.
  async applySet() {
    try {
      if (!this.coupling) this.model.useSet('none', null);
      else if (this.setChoice === 'file') this.model.useSet(this.userSet.name, this.userSet.text);
      else this.model.useSet(this.setChoice, await this.setText(this.setChoice));
      this.errorLine.textContent = '';
    } catch (e) {
      this.errorLine.textContent = e.message;
    }
    this.solveAndShow();
  }

  build() {
    const c = this.container;
    const setSel = el('select', { id: 'hand-set' });
    for (const [v, t] of SETS) setSel.append(el('option', { value: v, textContent: t }));
    setSel.onchange = async () => {
      if (setSel.value === 'file') {
        const f = await pickFile('.json');
        if (!f) { setSel.value = this.setChoice; return; }
        this.userSet = f;
      }
      this.setChoice = setSel.value;
      this.applySet();
    };
    const coupling = el('input', { type: 'checkbox', checked: true, id: 'hand-coupling' });
    coupling.onchange = () => { this.coupling = coupling.checked; this.applySet(); };
    const release = el('button', { textContent: 'Release pins', id: 'hand-release' });
    release.onclick = () => { this.model.clearInputs(); this.solveAndShow(); };
    this.errorLine = el('div', { className: 'error-line' });
    // the skin surface, when the library has it (built on first use)
    const surface = el('input', { type: 'checkbox', id: 'hand-surface', disabled: !this.model.surfaceAvailable() });
    const skinning = el('select', { id: 'hand-skinning', disabled: true });
    for (const [v, t] of [[3, 'dual quaternion'], [2, 'linear blend'], [1, 'rigid (thesis)']]) skinning.append(el('option', { value: v, textContent: t }));
    surface.onchange = () => {
      try {
        if (surface.checked && !this.model.surface) {
          const t0 = performance.now();
          this.model.buildSurface();
          this.timings.surface_build_ms = performance.now() - t0;
          if (this.materialChoice !== 'plain') this.useMaterial(this.materialChoice);
        }
        this.model.showSurface(surface.checked);
        skinning.disabled = !surface.checked;
      } catch (e) { this.errorLine.textContent = e.message; }
      this.app.view.render();
    };
    skinning.onchange = () => { this.model.skinning = Number(skinning.value); this.model.deformSurface(); this.app.view.render(); };
    // the skin material on the surface: the atlas's texture baked by the library
    const material = el('select', { id: 'hand-material', disabled: !this.model.surfaceAvailable() });
    for (const [v, t] of MATERIALS) material.append(el('option', { value: v, textContent: t }));
    material.onchange = () => this.useMaterial(material.value);
    const texSize = el('select', { id: 'hand-texture-size', disabled: !this.model.surfaceAvailable() });
    for (const n of [256, 512, 1024]) texSize.append(el('option', { value: n, textContent: `${n}²`, selected: n === this.textureSize }));
    texSize.onchange = () => { this.textureSize = Number(texSize.value); this.useMaterial(this.materialChoice); };
    this.app.on('skin-updated', () => { if (this.materialChoice === 'skin-panel') this.textureDirty = true; });
    // shown by default once the page is up (building it takes about a second)
    if (this.model.surfaceAvailable()) setTimeout(() => { surface.checked = true; surface.onchange(); }, 0);
    c.append(el('div', { className: 'row' }, 'constraints ', setSel),
      el('div', { className: 'row' }, el('label', {}, coupling, ' coupling'), release),
      el('div', { className: 'row', title: this.model.surfaceAvailable() ? 'the skin surface of thesis 4.1, deformed by the library' : 'this build of the library has no hand surface yet' },
        el('label', {}, surface, ' skin surface'), skinning),
      el('div', { className: 'row', title: 'the atlas texture baked by the library (sk_hand_texture_bake): skin colour and the microrelief of the skin presets in the normal map' },
        'material ', material, texSize),
      el('p', { className: 'note', textContent: 'Moving a slider pins that joint (bold); the others settle by the natural coupling (green: moved by it). Drag a fingertip in the view to pin its finger there.' }),
      this.errorLine);
    // whole-hand rotation (the thesis GUI's object rotation)
    const rot = el('details', { open: true }, el('summary', { textContent: 'whole hand' }));
    for (const [axis, label] of [['y', 'turn'], ['x', 'tilt']]) {
      const s = el('input', { type: 'range', min: -180, max: 180, step: 1, value: 0, id: `hand-rotate-${axis}` });
      s.oninput = () => { this.root.rotation[axis] = Number(s.value) * DEG; this.app.view.render(); };
      rot.append(el('div', { className: 'dof' }, el('label', { textContent: label }), s, el('span'), el('span')));
    }
    c.append(rot);
    // a slider per DOF, grouped: wrist, then each finger
    this.sliders = {};
    const groups = [['wrist', (n) => n.startsWith('wrist.')], ...FINGERS.map((f, i) => [FINGER_NAMES[i], (n) => n.startsWith(f + '.')])];
    for (const [title, test] of groups) {
      const d = el('details', { open: title !== 'wrist' }, el('summary', { textContent: title }));
      this.model.info.dofs.forEach((dof, i) => {
        if (!test(dof.name)) return;
        const unit = dof.translation ? 1 : DEG;
        const s = el('input', { type: 'range', min: dof.min / unit, max: dof.max / unit, step: dof.translation ? 0.5 : 0.5 });
        s.dataset.dof = dof.name;
        const val = el('span', { className: 'val' });
        const free = el('button', { className: 'reset', textContent: '×', title: 'release the pin' });
        free.onclick = () => { this.model.pinned[i] = false; this.solveAndShow(); };
        s.oninput = () => this.setSlider(dof.name, Number(s.value));
        const row = el('div', { className: 'dof', title: `${dof.name}: ${dof.meaning}` }, el('label', { textContent: dof.name.replace(/^[A-Z]\./, '') }), s, val, free);
        this.sliders[dof.name] = { input: s, val, row, i };
        d.append(row);
      });
      c.append(d);
    }
    // keyframes
    const kf = el('details', { open: true }, el('summary', { textContent: 'keyframes' }));
    this.keyList = el('div', { className: 'keys', id: 'hand-keys' });
    const setKey = el('button', { textContent: 'Set key', id: 'hand-set-key' });
    setKey.onclick = () => { this.keys.push(this.currentKey()); this.editing = this.keys.length - 1; this.showKeys(); };
    const updKey = el('button', { textContent: 'Update key' });
    updKey.onclick = () => { if (this.editing !== undefined) { this.keys[this.editing] = this.currentKey(); this.showKeys(); } };
    const delKey = el('button', { textContent: 'Delete key' });
    delKey.onclick = () => { if (this.editing !== undefined) { this.keys.splice(this.editing, 1); this.editing = undefined; this.showKeys(); } };
    this.steps = el('input', { type: 'number', value: 24, min: 1, max: 1000, style: 'width:56px' });
    this.fps = el('input', { type: 'number', value: 24, min: 1, max: 240, style: 'width:56px' });
    this.interp = el('select');
    for (const v of ['bezier', 'catmull-rom']) this.interp.append(el('option', { value: v, textContent: v }));
    const play = el('button', { textContent: 'Play', id: 'hand-play' });
    play.onclick = () => this.play();
    const save = el('button', { textContent: 'Save JSON', id: 'hand-save' });
    save.onclick = () => download('hand-animation.json', jsonBlob(this.animationJson()));
    const load = el('button', { textContent: 'Load JSON…' });
    load.onclick = async () => { const f = await pickFile('.json'); if (f) this.loadAnimation(JSON.parse(f.text)); };
    const shipped = el('select', { id: 'hand-shipped' });
    shipped.append(el('option', { value: '', textContent: 'shipped animation…' }));
    for (const n of ['little-mcp', 'little-dip', 'piano-key']) shipped.append(el('option', { value: n, textContent: n }));
    shipped.onchange = async () => { if (shipped.value) this.loadAnimation(await (await fetch(`presets/hand/${shipped.value}.json`)).json()); };
    kf.append(el('div', { className: 'row' }, setKey, updKey, delKey),
      el('div', { className: 'row' }, 'steps ', this.steps, ' fps ', this.fps, ' ', this.interp),
      el('div', { className: 'row' }, play, save, load, shipped), this.keyList,
      el('p', { className: 'note', textContent: 'A key holds the pins (and torques) set when it was taken. Saved files are what shitsukan hand animate FILE reads.' }));
    c.append(kf);
    this.setupDrag();
  }

  async skinTree(name) {
    if (!this.presetTrees[name]) this.presetTrees[name] = await (await fetch(`presets/skin/${name}.json`)).json();
    return this.presetTrees[name];
  }

  // The surface's material (MATERIALS): the atlas's texture baked by the library with the
  // chosen skins, its albedo as the colour map and its normal map bending the shading.
  async useMaterial(choice) {
    this.materialChoice = choice;
    this.textureDirty = false;
    const model = this.model;
    if (!model.surface) return;
    if (choice === 'plain') {
      model.surfaceMesh.material = model.plainMaterial;
      this.app.view.render();
      return;
    }
    const back = choice === 'skin-panel' ? this.app.panels.skin.tree : await this.skinTree('back-of-hand');
    const palm = await this.skinTree('palm');
    const n = this.textureSize, t0 = performance.now();
    let tex;
    try { tex = model.bakeTexture(n, back, palm); } catch (e) { this.errorLine.textContent = e.message; return; }
    this.timings.texture_bake_ms = performance.now() - t0;
    this.texture = { size: n, ...tex };
    const canvasOf = (rgba) => {
      const c = document.createElement('canvas');
      c.width = c.height = n;
      c.getContext('2d').putImageData(new ImageData(rgba, n, n), 0, 0);
      return c;
    };
    const map = new THREE.CanvasTexture(canvasOf(tex.albedo));
    map.colorSpace = THREE.SRGBColorSpace;
    const normalMap = new THREE.CanvasTexture(canvasOf(tex.normal));
    normalMap.colorSpace = THREE.NoColorSpace;
    for (const t of [map, normalMap]) t.anisotropy = 4;
    if (this.skinMaterial) { this.skinMaterial.map.dispose(); this.skinMaterial.normalMap.dispose(); this.skinMaterial.dispose(); }
    this.skinMaterial = new THREE.MeshStandardMaterial({ map, normalMap, roughness: 0.62, metalness: 0 });
    model.surfaceMesh.material = this.skinMaterial;
    this.app.view.render();
  }

  // A key of the animation format: pins in degrees (mm for translations), torques.
  currentKey() {
    const key = {};
    this.model.info.dofs.forEach((d, i) => {
      if (this.model.pinned[i]) (key.pin ||= {})[d.name] = d.translation ? this.model.pinValue[i] : this.model.pinValue[i] / DEG;
      if (this.model.torque[i]) (key.torque ||= {})[d.name] = this.model.torque[i];
    });
    return key;
  }

  applyKey(key) {
    this.model.clearInputs();
    for (const [n, v] of Object.entries(key.pin || {})) {
      const d = this.model.info.dofs[this.model.index[n]];
      this.model.pin(n, d.translation ? v : v * DEG);
    }
    for (const [n, v] of Object.entries(key.torque || {})) this.model.torque[this.model.index[n]] = v;
    this.solveAndShow();
  }

  constraintsName() { return !this.coupling ? 'none' : this.setChoice === 'file' ? this.userSet.name : this.setChoice; }

  animationJson() {
    const keys = this.keys.length ? this.keys : [this.currentKey()];
    return { description: 'made in shitsukan studio', constraints: this.constraintsName(), interpolation: this.interp.value,
      steps: Number(this.steps.value), fps: Number(this.fps.value), keys };
  }

  async loadAnimation(anim) {
    this.keys = (anim.keys || []).map((k) => ({ ...(k.pin ? { pin: k.pin } : {}), ...(k.torque ? { torque: k.torque } : {}) }));
    if (anim.steps) this.steps.value = anim.steps;
    if (anim.fps) this.fps.value = anim.fps;
    if (anim.interpolation) this.interp.value = anim.interpolation;
    if (anim.constraints === 'none') { this.coupling = false; document.getElementById('hand-coupling').checked = false; }
    else if (anim.constraints === 'natural' || anim.constraints === 'yasumuro-table-3.2') {
      this.coupling = true;
      document.getElementById('hand-coupling').checked = true;
      this.setChoice = anim.constraints;
      document.getElementById('hand-set').value = anim.constraints;
    }
    await this.applySet();
    this.editing = this.keys.length ? 0 : undefined;
    if (this.keys.length) this.applyKey(this.keys[0]);
    this.showKeys();
  }

  showKeys() {
    this.keyList.textContent = '';
    this.keys.forEach((k, i) => {
      const b = el('button', { textContent: `key ${i + 1}`, className: i === this.editing ? 'on' : '', title: JSON.stringify(k) });
      b.onclick = () => { this.editing = i; this.applyKey(k); this.showKeys(); };
      this.keyList.append(b);
    });
  }

  play() {
    let anim;
    try { anim = this.model.animate(this.animationJson()); } catch (e) { this.errorLine.textContent = e.message; return; }
    cancelAnimationFrame(this.playing);
    const t0 = performance.now();
    const step = () => {
      const f = Math.min(anim.frames.length - 1, Math.floor(((performance.now() - t0) / 1000) * anim.fps));
      this.model.setDofs(anim.frames[f]);
      this.playedFrame = f;
      this.showPose();
      if (f < anim.frames.length - 1) this.playing = requestAnimationFrame(step);
      else this.playing = 0;
    };
    step();
    return anim.frames.length;
  }

  // The slider of one DOF moved to `value` (degrees, mm for translations): pin, solve,
  // redraw. Returns the time it took (ms), the solve and drawing included.
  setSlider(name, value) {
    const t0 = performance.now();
    const d = this.model.info.dofs[this.model.index[name]];
    this.model.pin(name, d.translation ? value : value * DEG);
    this.solveAndShow(false);
    const t1 = performance.now();
    this.app.view.renderSync();
    const t2 = performance.now();
    this.timings = { model_ms: t1 - t0, render_ms: t2 - t1, slider_ms: t2 - t0 };
    return t2 - t0;
  }

  solveAndShow(draw = true) {
    const before = this.model.dofs ? this.model.dofs.slice() : null;
    try { this.model.solve(); } catch (e) { this.errorLine.textContent = e.message; }
    this.showPose(before, draw);
  }

  showPose(before, draw = true) {
    for (const { input, val, row, i } of Object.values(this.sliders)) {
      const v = this.model.degrees(i);
      if (document.activeElement !== input) input.value = v;
      val.textContent = v.toFixed(1);
      row.classList.toggle('pinned', this.model.pinned[i]);
      if (before) row.classList.toggle('coupled', !this.model.pinned[i] && Math.abs(this.model.dofs[i] - before[i]) > 1e-4);
    }
    if (draw) this.app.view.render();
  }

  // Fingertip drag: a tip picked in the view follows the pointer on the plane through it
  // facing the camera; the library pins that finger where its tip comes nearest.
  setupDrag() {
    const canvas = this.app.view.canvas, view = this.app.view;
    const ray = new THREE.Raycaster(), ndc = new THREE.Vector2();
    const pick = (e) => {
      const r = canvas.getBoundingClientRect();
      ndc.set(((e.clientX - r.left) / r.width) * 2 - 1, -((e.clientY - r.top) / r.height) * 2 + 1);
      ray.setFromCamera(ndc, view.camera);
    };
    canvas.addEventListener('pointerdown', (e) => {
      if (!this.active) return;
      pick(e);
      const hit = ray.intersectObject(this.model.joints).find((h) => this.model.tipOf.has(h.instanceId));
      if (!hit) return;
      const normal = view.camera.getWorldDirection(new THREE.Vector3());
      this.drag = { finger: this.model.tipOf.get(hit.instanceId), plane: new THREE.Plane().setFromNormalAndCoplanarPoint(normal, hit.point) };
      view.controls.enabled = false;
      canvas.setPointerCapture(e.pointerId);
    });
    canvas.addEventListener('pointermove', (e) => {
      if (!this.drag) return;
      pick(e);
      const p = ray.ray.intersectPlane(this.drag.plane, new THREE.Vector3());
      if (!p) return;
      this.dragTo(this.drag.finger, p);
    });
    const end = () => { if (this.drag) { this.drag = null; view.controls.enabled = true; } };
    canvas.addEventListener('pointerup', end);
    canvas.addEventListener('pointercancel', end);
  }

  // Moves a fingertip toward a world point (the view's coordinates); distance left, mm.
  dragTo(finger, world) {
    const local = this.model.group.worldToLocal(world.clone());
    let d;
    try { d = this.model.reach(finger, [local.x, local.y, local.z]); } catch (e) { this.errorLine.textContent = e.message; return -1; }
    this.showPose();
    return d;
  }

  activate(view) {
    this.active = true;
    if (this.textureDirty) this.useMaterial(this.materialChoice);
    this.root.rotation.set(Number(document.getElementById('hand-rotate-x').value) * DEG, Number(document.getElementById('hand-rotate-y').value) * DEG, 0);
    this.root.position.set(0, 0, 0);
    this.scaled.rotation.set(0, Math.PI, 0); // the back of the hand toward the camera
    view.showMaps(null);
    view.setContent(this.root, { distance: 4.2, target: [0, 1.0, 0], direction: [0, 0.15, 1] });
  }

  deactivate() { this.active = false; }
}
