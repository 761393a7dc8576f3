// Tissue panel (Shigemori & Kawai's fat layer): waits for the library's tissue module;
// until the build has it, the panel says so.
const el = (tag, props = {}, ...kids) => {
  const e = Object.assign(document.createElement(tag), props);
  e.append(...kids);
  return e;
};

export class TissuePanel {
  constructor(app, container) {
    this.app = app;
    this.available = typeof app.lib.m._studio_tissue_create === 'function';
    container.append(el('p', { className: 'note', id: 'tissue-status', textContent: this.available ? '' :
      'The tissue simulation (a BVH played on the arm character, its fat jiggling, with stiffness, damping and fat sliders) joins this panel when the library\'s tissue module is in the WebAssembly build.' }));
  }

  activate(view) {
    view.showMaps(null);
    view.setContent(null);
  }
}
