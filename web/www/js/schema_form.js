// Controls for every key of a module's preset schema (from the library's own schema:
// types, ranges, enum names, docs), grouped as in the presets: an object is a group, an
// array of objects one group per element. Edits go into the preset tree; a key not in
// the tree shows the value the model uses (grey) and a key can be reset to it.
import { getPath, setPath, removePath, clone } from './tree.js';

const el = (tag, props = {}, ...kids) => {
  const e = Object.assign(document.createElement(tag), props);
  for (const k of kids) if (k !== null && k !== undefined) e.append(k);
  return e;
};

// Values as shown (the tree keeps what was typed): six significant digits.
const round = (x) => Number(Number(x).toPrecision(6));

export class SchemaForm {
  // schema: studio_schema(); getTree/getResolved: current tree and resolved values;
  // onEdit(path): called after the tree changed.
  constructor(container, schema, getTree, getResolved, onEdit) {
    Object.assign(this, { container, schema, getTree, getResolved, onEdit });
    this.render();
  }

  render() {
    const open = new Set([...this.container.querySelectorAll('details[open]')].map((d) => d.dataset.path));
    this.container.textContent = '';
    this.open = open;
    this.fields(this.container, this.schema.fields, '');
  }

  fields(parent, fields, prefix) {
    for (const f of fields) {
      const path = f.key === null ? prefix : prefix ? `${prefix}.${f.key}` : f.key;
      if (f.type === 'object') {
        const d = el('details', { open: this.open.has(path) || !prefix });
        d.dataset.path = path;
        d.append(el('summary', { textContent: f.key, title: f.doc || '' }));
        this.fields(d, f.fields, path);
        parent.append(d);
      } else if (f.type === 'array') {
        this.array(parent, f, path);
      } else {
        parent.append(this.control(f, path));
      }
    }
  }

  // The array's current elements: the tree's, else the resolved ones.
  arrayValue(path) {
    const t = getPath(this.getTree(), path);
    return Array.isArray(t) ? t : getPath(this.getResolved(), path) || [];
  }

  // Edits inside an array copy the resolved array into the tree first (each enclosing
  // array the tree lacks, outermost first), so the edited element keeps the rest of its
  // values and the array its length.
  materialize(path) {
    const re = /\[\d+\]/g;
    let m;
    while ((m = re.exec(path))) {
      const arrayPath = path.slice(0, m.index);
      const tree = this.getTree();
      if (!Array.isArray(getPath(tree, arrayPath))) {
        const r = getPath(this.getResolved(), arrayPath);
        if (Array.isArray(r)) setPath(tree, arrayPath, clone(r));
      }
    }
  }

  array(parent, f, path) {
    const items = this.arrayValue(path);
    const d = el('details', { open: this.open.has(path) || path.split('.').length === 1 });
    d.dataset.path = path;
    const add = el('button', { textContent: '+', title: `add an element (at most ${f.max_count})` });
    const del = el('button', { textContent: '−', title: `remove the last (at least ${f.min_count})` });
    add.disabled = items.length >= f.max_count;
    del.disabled = items.length <= f.min_count;
    add.onclick = (e) => { e.preventDefault(); this.resize(path, items.length + 1); };
    del.onclick = (e) => { e.preventDefault(); this.resize(path, items.length - 1); };
    d.append(el('summary', { textContent: `${path.split('.').pop()} (${items.length}) `, title: f.doc || '' }, add, del));
    const bare = f.fields.length === 1 && f.fields[0].key === null;
    items.forEach((_, i) => {
      const p = `${path}[${i}]`;
      if (bare) {
        this.fields(d, f.fields, p);
      } else {
        const g = el('fieldset', {}, el('legend', { textContent: `${path.split('.').pop()}[${i}]` }));
        this.fields(g, f.fields, p);
        d.append(g);
      }
    });
    parent.append(d);
  }

  resize(path, n) {
    this.materialize(path + '[0]');
    const tree = this.getTree();
    let arr = getPath(tree, path);
    if (!Array.isArray(arr)) { arr = clone(this.arrayValue(path)); setPath(tree, path, arr); }
    while (arr.length > n) arr.pop();
    while (arr.length < n) arr.push(arr.length ? clone(arr[arr.length - 1]) : {});
    this.onEdit(path, true);
  }

  value(path) {
    const t = getPath(this.getTree(), path);
    return t !== undefined ? { v: t, set: true } : { v: getPath(this.getResolved(), path), set: false };
  }

  set(path, v) {
    this.materialize(path);
    setPath(this.getTree(), path, v);
    this.onEdit(path, false);
  }

  control(f, path) {
    const { v, set } = this.value(path);
    const name = path.split('.').pop();
    const row = el('div', { className: 'ctl' + (set ? '' : ' default'), title: `${path}: ${f.doc || ''}${f.default ? `; ${f.default}` : ''}` });
    row.dataset.key = path;
    const label = el('label', { textContent: name });
    const reset = el('button', { className: 'reset', textContent: '×', title: 'back to the default' });
    reset.onclick = () => { removePath(this.getTree(), path); this.onEdit(path, true); };
    if (f.type === 'floats') {
      row.className += ' multi';
      const box = el('div', { className: 'values' });
      const arr = Array.isArray(v) ? v : [];
      const n = Math.max(arr.length, f.min_count);
      for (let i = 0; i < n; i++) {
        const inp = el('input', { type: 'number', min: f.min, max: f.max, step: 'any', value: round(arr[i] ?? 0) });
        inp.onchange = () => {
          const cur = [...box.querySelectorAll('input')].map((x) => Number(x.value));
          this.set(path, cur);
        };
        box.append(inp);
      }
      row.append(label, box, reset);
      return row;
    }
    let input;
    if (f.type === 'bool') {
      input = el('input', { type: 'checkbox', checked: !!v });
      input.onchange = () => this.set(path, input.checked);
      row.append(label, input, el('span'), reset);
      return row;
    }
    if (f.type === 'enum') {
      input = el('select');
      for (const n of f.names) input.append(el('option', { value: n, textContent: n, selected: n === v }));
      input.onchange = () => this.set(path, input.value);
      row.append(label, input, el('span'), reset);
      return row;
    }
    if (f.type === 'string') {
      input = el('input', { type: 'text', value: v ?? '', maxLength: f.max_length });
      input.onchange = () => this.set(path, input.value);
      row.append(label, input, el('span'), reset);
      return row;
    }
    // numbers: a slider over the schema's range (when it is a usable one) and a box
    const integer = f.type === 'int' || f.type === 'seed';
    const lo = f.min, hi = f.type === 'seed' ? 1e6 : f.max;
    const num = el('input', { type: 'number', min: f.min, max: f.max, step: integer ? 1 : 'any', value: integer ? v ?? 0 : round(v ?? 0) });
    const slider = el('input', { type: 'range', min: lo, max: hi, step: integer ? 1 : (hi - lo) / 1000, value: v ?? 0 });
    slider.oninput = () => { num.value = slider.value; this.set(path, Number(slider.value)); };
    num.onchange = () => {
      const x = Number(num.value);
      slider.value = x;
      this.set(path, integer ? Math.round(x) : x);
    };
    row.append(label, slider, num, reset);
    return row;
  }
}
