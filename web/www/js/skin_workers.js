// The skin maps rendered by several copies of the library at once, each in its own Web
// Worker (its own WebAssembly instance: no shared memory, so no cross-origin isolation
// and any static server will do). Every worker builds the skin from the same preset tree
// and renders its own band of rows; rows do not depend on one another, so the maps are
// the same values a single render gives.
const CHANNELS = { height: 1, normal: 3, furrow: 1, cells: 1, preview: 3 };

export class SkinWorkers {
  // count: workers (at most the cores the browser reports, at least 1).
  constructor(count) {
    this.workers = [];
    for (let i = 0; i < count; i++) {
      const w = new Worker(new URL('./skin_worker.js', import.meta.url), { type: 'module' });
      this.workers.push({ w, pending: new Map() });
      w.onmessage = (e) => {
        const slot = this.workers[i], job = slot.pending.get(e.data.id);
        slot.pending.delete(e.data.id);
        if (e.data.error) job.reject(new Error(e.data.error)); else job.resolve(e.data);
      };
      w.onerror = (e) => { for (const job of this.workers[i].pending.values()) job.reject(new Error(e.message || 'skin worker failed')); };
    }
    this.next = 1;
  }

  get count() { return this.workers.length; }

  call(i, message) {
    const id = this.next++;
    return new Promise((resolve, reject) => {
      this.workers[i].pending.set(id, { resolve, reject });
      this.workers[i].w.postMessage({ id, ...message });
    });
  }

  // The maps `wanted` of the tree at w x h, in bands of rows over the workers; the same
  // result as SkinPanel.renderMaps.
  async render(tree, w, h, wanted) {
    const n = Math.min(this.count, h), json = JSON.stringify(tree);
    const bands = [];
    for (let i = 0; i < n; i++) bands.push([Math.floor((h * i) / n), Math.floor((h * (i + 1)) / n)]);
    const parts = await Promise.all(bands.map(([y0, y1], i) => this.call(i, { json, w, h, y0, rows: y1 - y0, wanted })));
    const out = {};
    for (const k of wanted) out[k] = k === 'cells' ? new Uint32Array(w * h) : new Float32Array(w * h * CHANNELS[k]);
    parts.forEach((p, i) => { for (const k of wanted) out[k].set(p.maps[k], w * bands[i][0] * CHANNELS[k]); });
    const { lo, hi, tw, th, furrowMax } = parts[0];
    return { maps: out, lo, hi, tw, th, furrowMax };
  }
}
