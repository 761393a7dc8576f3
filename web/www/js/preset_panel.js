// What the skin, wood and tissue panels share: a module's preset tree (the JSON the
// command line reads) with a control per schema key, a shipped-preset menu, saving and
// loading the tree as a file, an export size (panels with maps), and the library's codes
// for pictures and files.
import { SchemaForm } from './schema_form.js';
import { download, jsonBlob, pickFile } from './files.js';

export const el = (tag, props = {}, ...kids) => {
  const e = Object.assign(document.createElement(tag), props);
  e.append(...kids.filter((k) => k !== null && k !== undefined));
  return e;
};

export class PresetPanel {
  // module: "skin", "wood" or "tissue"; note: a line on the keys and the command that
  // reads them; options.maps: false for a panel without map export; options.tree: the
  // tree to start from (default {}).
  constructor(app, container, module, note, options = {}) {
    Object.assign(this, { app, lib: app.lib, container, module });
    this.tree = options.tree || {};
    this.timings = {};
    this.schema = this.lib.schema(module);
    this.select = el('select', { id: `${module}-preset` });
    this.select.append(el('option', { value: '', textContent: '(defaults)' }));
    for (const p of app.presets[module] || []) this.select.append(el('option', { value: p, textContent: p }));
    this.select.onchange = () => this.loadPreset(this.select.value);
    const save = el('button', { textContent: 'Save JSON', id: `${module}-save` });
    save.onclick = () => download(`${this.name || module}.json`, jsonBlob(this.tree));
    const load = el('button', { textContent: 'Load JSON…' });
    load.onclick = async () => { const f = await pickFile('.json'); if (f) this.setTree(JSON.parse(f.text), f.name); };
    this.exportSize = el('input', { type: 'number', value: 1024, min: 16, max: 8192, step: 1, id: `${module}-export-size` });
    const exp = el('button', { textContent: 'Export maps', id: `${module}-export` });
    exp.onclick = () => this.exportMaps(Number(this.exportSize.value));
    this.presetRow = el('div', { className: 'row' }, 'preset ', this.select);
    this.errorLine = el('div', { className: 'error-line' });
    this.info = el('div', { className: 'note' });
    this.formBox = el('div');
    this.fileRow = el('div', { className: 'row' }, save, load);
    container.append(...[this.presetRow, this.fileRow,
      options.maps === false ? null : el('div', { className: 'row' }, 'export ', this.exportSize, ' px ', exp),
      el('p', { className: 'note', textContent: note }), this.errorLine, this.info, this.formBox].filter((x) => x));
    this.resolvedTree = this.lib.resolved(module, this.tree);
    this.form = new SchemaForm(this.formBox, this.schema, () => this.tree, () => this.resolvedTree,
      (path, structural) => this.edited(path, structural));
  }

  // A shipped preset's file is fetched once (its text kept: each choice parses a fresh
  // tree to edit); a preset chosen while an earlier one is still on its way wins.
  async loadPreset(name) {
    const ticket = (this.presetTicket = (this.presetTicket || 0) + 1);
    this.presetTexts ||= new Map();
    if (name && !this.presetTexts.has(name)) this.presetTexts.set(name, await (await fetch(`presets/${this.module}/${name}.json`)).text());
    if (ticket === this.presetTicket) this.setTree(name ? JSON.parse(this.presetTexts.get(name)) : {}, name);
  }

  setTree(tree, name) {
    this.tree = tree;
    if (name !== undefined) this.name = String(name).replace(/\.json$/, '');
    this.edited('', true);
  }

  // After an edit: the values the model uses (or the library's message), the panel's
  // pictures, then the controls when the tree's shape changed (afterPictures).
  edited(path, structural) {
    try {
      this.resolvedTree = this.lib.resolved(this.module, this.tree);
      this.errorLine.textContent = '';
    } catch (e) {
      this.errorLine.textContent = e.message;
      return;
    }
    this.update();
    if (structural) this.afterPictures(() => this.form.render());
  }

  // Runs fn once the pictures update() started are shown: at once here; the skin panel,
  // whose workers render on every core, waits for its first maps, so that making the
  // controls does not take a core from them.
  afterPictures(fn) { fn(); }

  // RGBA bytes of float samples with the PNG writer's codes.
  rgbaOf(samples, channels, srgb, n) {
    const p = this.lib.alloc(samples.length * 4);
    this.lib.f32(p, samples.length).set(samples);
    const rgba = this.lib.rgba(p, n, channels, srgb);
    this.lib.free(p);
    return rgba;
  }

  // 16-bit linear codes of float samples (16-bit PNG maps).
  codes16Of(samples) {
    const p = this.lib.alloc(samples.length * 4);
    this.lib.f32(p, samples.length).set(samples);
    const codes = this.lib.codes16(p, samples.length);
    this.lib.free(p);
    return codes;
  }
}
