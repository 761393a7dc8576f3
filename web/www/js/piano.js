// Piano panel: the application of the thesis's Fig. 4.21. The computer keyboard plays a
// CG piano with the hand: a key event gives input to two joint DOFs of one finger (MCP
// and PIP flexion torques, as presets/hand/piano-key.json), the coupling moves the whole
// hand, the piano key under the finger goes down (geometrically, no collision, as in the
// thesis), and Web Audio sounds the note.
import * as THREE from 'three';
import { DEG } from './hand_model.js';

const el = (tag, props = {}, ...kids) => {
  const e = Object.assign(document.createElement(tag), props);
  e.append(...kids.filter((k) => k !== null && k !== undefined));
  return e;
};

// computer key -> finger (thumb..little) and note (C4 D4 E4 F4 G4)
const KEYS = [['a', 0, 'C4', 261.63], ['s', 1, 'D4', 293.66], ['d', 2, 'E4', 329.63], ['f', 3, 'F4', 349.23], ['g', 4, 'G4', 392.0]];
const INPUTS = [['T.MCP.flex', 'T.IP.flex'], ['I.MCP.flex', 'I.PIP.flex'], ['M.MCP.flex', 'M.PIP.flex'], ['R.MCP.flex', 'R.PIP.flex'], ['L.MCP.flex', 'L.PIP.flex']];
const TORQUE = [0.9, 0.5]; // piano-key.json
const TAU_MS = 45; // the inputs ease in and out with this time constant

export class PianoPanel {
  constructor(app, container, handPanel) {
    this.app = app;
    this.hand = handPanel;
    this.container = container;
    this.held = new Array(5).fill(false);
    this.level = new Array(5).fill(0); // eased input, 0..1 of the press torques
    this.notesPlayed = 0;
    this.build();
  }

  build() {
    this.container.append(
      el('p', { textContent: 'Play with the keys ' }, ...KEYS.map(([k]) => el('kbd', { textContent: k.toUpperCase() })), ' (thumb to little finger: C D E F G).'),
      el('p', { className: 'note', textContent: 'Each key press gives torques to two joints of one finger (MCP 0.9, PIP 0.5: presets/hand/piano-key.json); the natural coupling moves the rest of the hand (Yasumuro 2000, Fig. 4.21). The constraint set is the hand panel\'s.' }));
    this.keyButtons = KEYS.map(([k, f, note]) => {
      const b = el('button', { textContent: `${k.toUpperCase()} ${note}` });
      b.onpointerdown = () => this.press(f);
      b.onpointerup = b.onpointerleave = () => this.release(f);
      return b;
    });
    this.container.append(el('div', { className: 'keys' }, ...this.keyButtons));
    window.addEventListener('keydown', (e) => {
      if (!this.active || e.repeat) return;
      const k = KEYS.find(([c]) => c === e.key.toLowerCase());
      if (k) { this.press(k[1]); e.preventDefault(); }
    });
    window.addEventListener('keyup', (e) => {
      const k = KEYS.find(([c]) => c === e.key.toLowerCase());
      if (k) this.release(k[1]);
    });
    this.group = new THREE.Group();
    this.keysGroup = new THREE.Group();
    this.group.add(this.keysGroup);
  }

  // Keys placed under the fingertips of the relaxed, palm-down hand.
  layoutKeys() {
    this.keysGroup.clear();
    const model = this.hand.model;
    const saved = [model.pinned.slice(), model.pinValue.slice(), model.torque.slice()];
    model.clearInputs();
    model.solve();
    this.hand.root.updateMatrixWorld(true);
    const tips = [0, 1, 2, 3, 4].map((f) => model.jointWorld(model.tipPoint(f)));
    [model.pinned, model.pinValue, model.torque] = saved;
    const keyTop = Math.min(...tips.map((t) => t.y)) - 0.12;
    const wood = new THREE.MeshStandardMaterial({ color: 0x3b2416, roughness: 0.45 });
    const ivory = new THREE.MeshStandardMaterial({ color: 0xf4f1e8, roughness: 0.35 });
    const width = 0.23, len = 1.5;
    // white keys C..G centred under the fingers along x (the thumb's side first)
    const xs = tips.map((t) => t.x);
    const centre = xs.reduce((a, b) => a + b, 0) / 5;
    const dir = Math.sign(xs[4] - xs[0]) || -1;
    const zTip = tips.reduce((a, t) => a + t.z, 0) / 5;
    this.pianoKeys = [];
    // each key turns about its far end (inside the piano), the fingers press its front part
    const pivotZ = zTip + 0.75 * len;
    for (let k = -2; k < 9; k++) {
      const pivot = new THREE.Group();
      pivot.position.set(centre + dir * (k - 2) * width, keyTop, pivotZ);
      const key = new THREE.Mesh(new THREE.BoxGeometry(width * 0.94, 0.14, len), ivory);
      key.position.set(0, -0.07, -0.5 * len);
      pivot.add(key);
      this.keysGroup.add(pivot);
      if (k >= 0 && k < 5) this.pianoKeys[k] = pivot;
    }
    const caseMesh = new THREE.Mesh(new THREE.BoxGeometry(width * 12, 0.5, 0.6), wood);
    caseMesh.position.set(centre + dir * 1.5 * width, keyTop + 0.1, pivotZ + 0.3);
    this.keysGroup.add(caseMesh);
    const base = new THREE.Mesh(new THREE.BoxGeometry(width * 12, 0.3, len), wood);
    base.position.set(centre + dir * 1.5 * width, keyTop - 0.32, pivotZ - 0.5 * len);
    this.keysGroup.add(base);
  }

  audio() {
    if (!this.ctx) this.ctx = new (window.AudioContext || window.webkitAudioContext)();
    if (this.ctx.state === 'suspended') this.ctx.resume();
    return this.ctx;
  }

  // A plucked-string-like tone: a few harmonics under a fast attack and a long decay.
  sound(freq) {
    const ctx = this.audio(), t = ctx.currentTime;
    const out = ctx.createGain();
    out.gain.setValueAtTime(0, t);
    out.gain.linearRampToValueAtTime(0.25, t + 0.005);
    out.gain.exponentialRampToValueAtTime(0.001, t + 2.2);
    out.connect(ctx.destination);
    [[1, 1], [2, 0.4], [3, 0.18], [4, 0.08]].forEach(([h, a]) => {
      const o = ctx.createOscillator(), g = ctx.createGain();
      o.frequency.value = freq * h;
      g.gain.value = a;
      o.connect(g).connect(out);
      o.start(t);
      o.stop(t + 2.3);
    });
    this.notesPlayed++;
    return out;
  }

  press(f) {
    if (this.held[f]) return;
    this.held[f] = true;
    this.keyButtons[f].classList.add('on');
    this.notes = this.notes || [];
    this.notes[f] = this.sound(KEYS[f][3]);
    this.kick();
  }

  release(f) {
    if (!this.held[f]) return;
    this.held[f] = false;
    this.keyButtons[f].classList.remove('on');
    const n = this.notes && this.notes[f];
    if (n && this.ctx) { const t = this.ctx.currentTime; n.gain.cancelScheduledValues(t); n.gain.setTargetAtTime(0, t, 0.08); }
    this.kick();
  }

  kick() {
    if (this.running) return;
    this.running = true;
    this.last = performance.now();
    requestAnimationFrame(() => this.tick());
  }

  // One frame: inputs eased toward the held keys, solved, keys moved, drawn.
  tick() {
    const now = performance.now(), dt = now - this.last;
    this.last = now;
    const a = 1 - Math.exp(-dt / TAU_MS);
    let moving = false;
    const model = this.hand.model;
    for (let f = 0; f < 5; f++) {
      const target = this.held[f] ? 1 : 0;
      this.level[f] += (target - this.level[f]) * a;
      if (Math.abs(target - this.level[f]) < 1e-3) this.level[f] = target;
      else moving = true;
      INPUTS[f].forEach((name, k) => { model.torque[model.index[name]] = TORQUE[k] * this.level[f]; });
      if (this.pianoKeys && this.pianoKeys[f]) this.pianoKeys[f].rotation.x = this.held[f] ? -3.5 * DEG : 0; // front edge down
    }
    this.hand.solveAndShow();
    if (moving) requestAnimationFrame(() => this.tick());
    else this.running = false;
  }

  activate(view) {
    this.active = true;
    this.hand.active = false;
    const h = this.hand;
    h.model.pinned.fill(false);
    // palm down, fingers away from the player; the camera behind and above the wrist
    h.root.rotation.set(0, 0, 0);
    h.scaled.rotation.set(Math.PI / 2, 0, 0);
    this.group.add(h.root);
    this.layoutKeys();
    h.solveAndShow();
    view.showMaps(null);
    view.setContent(this.group, { distance: 4.2, target: [0, -0.3, 1.1], direction: [0, 0.5, -0.87] });
  }

  deactivate() {
    this.active = false;
    for (let f = 0; f < 5; f++) this.release(f);
    this.level.fill(0);
    const model = this.hand.model;
    for (const pair of INPUTS) for (const n of pair) model.torque[model.index[n]] = 0;
    if (this.hand.root.parent === this.group) this.group.remove(this.hand.root);
  }
}
