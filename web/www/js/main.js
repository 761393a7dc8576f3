// The studio page: loads the library (WebAssembly), the presets index, the arm character
// and the panels.
import { Library } from './wasm.js';
import { View } from './view.js';
import { SkinPanel } from './skin.js';
import { WoodPanel } from './wood.js';
import { HandPanel } from './hand.js';
import { PianoPanel } from './piano.js';
import { TissuePanel } from './tissue.js';

const status = document.getElementById('status');

class App {
  constructor(lib, presets, character) {
    this.lib = lib;
    this.presets = presets;
    this.listeners = {};
    this.view = new View(document.getElementById('scene'), document.getElementById('maps'));
    this.readout = document.getElementById('readout');
    const panel = (name) => document.querySelector(`[data-panel="${name}"]`);
    this.panels = {};
    this.panels.hand = new HandPanel(this, panel('hand'));
    this.panels.piano = new PianoPanel(this, panel('piano'), this.panels.hand);
    this.panels.skin = new SkinPanel(this, panel('skin'));
    this.panels.wood = new WoodPanel(this, panel('wood'));
    this.panels.tissue = new TissuePanel(this, panel('tissue'), character);
    for (const b of document.querySelectorAll('#tabs button')) b.onclick = () => this.show(b.dataset.tab);
    this.show('hand');
  }

  on(name, fn) { (this.listeners[name] ||= []).push(fn); }
  emit(name, data) { for (const fn of this.listeners[name] || []) fn(data); }

  show(tab) {
    this.tab = tab;
    for (const b of document.querySelectorAll('#tabs button')) b.classList.toggle('active', b.dataset.tab === tab);
    for (const p of document.querySelectorAll('.panel')) p.hidden = p.dataset.panel !== tab;
    for (const [name, p] of Object.entries(this.panels)) if (name !== tab && p.deactivate) p.deactivate();
    this.readout.textContent = '';
    this.panels[tab].activate(this.view);
  }
}

async function start() {
  try {
    const json = (url) => fetch(url).then((r) => r.json());
    // the tissue panel starts on the arm character
    const [lib, presets, arm] = await Promise.all([Library.load(), json('presets/index.json'), json('presets/tissue/arm.json')]);
    const app = new App(lib, presets, arm);
    window.studio = app;
    status.textContent = 'ready';
    document.body.dataset.ready = '1';
  } catch (e) {
    status.textContent = `error: ${e.message}`;
    status.className = 'error';
    console.error(e);
  }
}
start();
