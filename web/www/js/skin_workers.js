// The skin maps rendered by several copies of the library at once, each in its own Web
// Worker (its own WebAssembly instance: no shared memory, so no cross-origin isolation
// and any static server will do). Every worker holds the skin of the last preset tree
// (re-profiled in place by an edit that leaves the cells, built again otherwise) and
// makes its share of the rows as canvas pixels, only of the maps the edit changes. The rows go out in strips dealt in
// turn (strip s to worker s mod n), so each worker gets rows from all over the map and
// the shares cost about the same; rows do not depend on one another, so the maps are the
// same pixels a single render gives.
const STRIP_ROWS = 16;
const MAPS = ['preview', 'height', 'normal', 'furrow', 'cells'];

export class SkinWorkers {
  // count: workers (at most the cores the browser reports, at least 1).
  constructor(count) {
    this.workers = [];
    for (let i = 0; i < count; i++) {
      const w = new Worker(new URL('./skin_worker.js', import.meta.url), { type: 'module' });
      this.workers.push({ w, pending: new Map() });
      w.onmessage = (e) => {
        const slot = this.workers[i], job = slot.pending.get(e.data.id);
        if (e.data.partial) { job.partial(e.data); return; }
        slot.pending.delete(e.data.id);
        if (e.data.error) job.reject(new Error(e.data.error)); else job.resolve(e.data);
      };
      w.onerror = (e) => { for (const job of this.workers[i].pending.values()) job.reject(new Error(e.message || 'skin worker failed')); };
    }
    this.next = 1;
  }

  get count() { return this.workers.length; }

  // Worker i's answer to `message`; its partial answers go to partial(data).
  call(i, message, partial) {
    const id = this.next++;
    return new Promise((resolve, reject) => {
      this.workers[i].pending.set(id, { resolve, reject, partial });
      this.workers[i].w.postMessage({ id, ...message });
    });
  }

  // The five live maps (preview, height, normal, furrow, cells) of the tree at w x h as
  // RGBA bytes, each w x h x 4, kept here between renders: an edit's answer brings only
  // the maps it changed (`changed`). With the tile and ranges, and per worker what it
  // found changed and its time updating and making the maps. When the workers answer in
  // parts (new cells: the preview, height and normal maps first), onPart gets the maps
  // of each part as soon as every worker has sent it, in the same form.
  async render(tree, w, h, onPart) {
    const n = Math.min(this.count, Math.ceil(h / STRIP_ROWS)), json = JSON.stringify(tree);
    const strips = Array.from({ length: n }, () => []);
    for (let y0 = 0, s = 0; y0 < h; y0 += STRIP_ROWS, s++) strips[s % n].push([y0, Math.min(STRIP_ROWS, h - y0)]);
    const full = !this.held || this.held.w !== w || this.held.h !== h;
    if (full) this.held = { w, h, rgba: Object.fromEntries(MAPS.map((k) => [k, new Uint8ClampedArray(w * h * 4)])) };
    const held = this.held, early = [];
    const partial = (i, p) => {
      early[i] = p;
      if (onPart && early.filter((x) => x).length === n) onPart(this.gather(held, strips, early));
    };
    let parts;
    try {
      parts = await Promise.all(strips.map((share, i) => this.call(i, { json, w, h, strips: share, full }, (p) => partial(i, p))));
    } catch (e) {
      this.held = null; // the next render makes every map again
      throw e;
    }
    const r = this.gather(held, strips, parts);
    // the maps of the earlier parts count as changed too
    const changed = new Set([...r.changed, ...early.flatMap((p) => (p ? Object.keys(p.maps) : []))]);
    return { ...r, changed: MAPS.filter((k) => changed.has(k)) };
  }

  // Each worker's answer p (its maps' strips one after the other) put into the held maps.
  gather(held, strips, parts) {
    const changed = new Set(), w = held.w;
    parts.forEach((p, i) => {
      let at = 0;
      for (const [y0, rows] of strips[i]) {
        const len = w * rows * 4;
        for (const [k, bytes] of Object.entries(p.maps)) held.rgba[k].set(bytes.subarray(at, at + len), w * y0 * 4);
        at += len;
      }
      for (const k of Object.keys(p.maps)) changed.add(k);
    });
    const { lo, hi, tw, th, furrowMax } = parts[0];
    const workers = parts.map((p) => ({ changes: p.changes, update_ms: p.update_ms, maps_ms: p.maps_ms }));
    return { rgba: held.rgba, changed: MAPS.filter((k) => changed.has(k)), lo, hi, tw, th, furrowMax, workers };
  }
}
