// The library compiled to WebAssembly, and small helpers over its memory: strings in
// and out, errors, float and integer buffers. Every model runs in C (web/wasm/*.c).
import createStudio from '../wasm/studio.mjs';

export class Library {
  static async load() {
    const lib = new Library();
    lib.m = await createStudio({ locateFile: (f) => new URL('../wasm/' + f, import.meta.url).href });
    lib.err = lib.m._studio_error_new();
    return lib;
  }

  // Calls `fn(ptrs...)` with JS strings copied into the heap, freed afterwards.
  withStrings(strings, fn) {
    const ptrs = strings.map((s) => {
      if (s === null || s === undefined) return 0;
      const n = this.m.lengthBytesUTF8(s) + 1;
      const p = this.m._malloc(n);
      this.m.stringToUTF8(s, p, n);
      return p;
    });
    try { return fn(...ptrs); } finally { ptrs.forEach((p) => p && this.m._free(p)); }
  }

  // A string the library allocated (freed here).
  takeString(ptr) {
    if (!ptr) return null;
    const s = this.m.UTF8ToString(ptr);
    this.m._studio_free(ptr);
    return s;
  }

  errorMessage() { return this.m.UTF8ToString(this.m._studio_error_message(this.err)); }

  // Throws the library's message when `result` is an error (non-zero) or a NULL object.
  check(result, what) {
    if (result === 0 && what !== 'object') return result;
    if (what === 'object' && result !== 0) return result;
    throw new Error(this.errorMessage() || 'failed');
  }

  alloc(bytes) { return this.m._studio_alloc(bytes); }
  free(p) { if (p) this.m._studio_free(p); }
  f32(ptr, count) { return new Float32Array(this.m.HEAPU8.buffer, ptr, count); }
  f64(ptr, count) { return new Float64Array(this.m.HEAPU8.buffer, ptr, count); }
  u8(ptr, count) { return new Uint8Array(this.m.HEAPU8.buffer, ptr, count); }
  u16(ptr, count) { return new Uint16Array(this.m.HEAPU8.buffer, ptr, count); }
  u32(ptr, count) { return new Uint32Array(this.m.HEAPU8.buffer, ptr, count); }
  i32(ptr, count) { return new Int32Array(this.m.HEAPU8.buffer, ptr, count); }

  schema(module) { return JSON.parse(this.withStrings([module], (p) => this.takeString(this.m._studio_schema(p)))); }

  // The values the model uses for a preset tree (every default filled in), or throws.
  resolved(module, tree) {
    const text = this.withStrings([module, JSON.stringify(tree)], (a, b) => this.m._studio_resolved(a, b, this.err));
    if (!text) throw new Error(this.errorMessage());
    return JSON.parse(this.takeString(text));
  }

  // RGBA bytes of float samples with the PNG writer's codes (srgb or linear).
  rgba(samplesPtr, pixels, channels, srgb) {
    const scratch = this.alloc(pixels * channels);
    const out = this.alloc(pixels * 4);
    this.m._studio_rgba8(samplesPtr, pixels, channels, srgb ? 1 : 0, scratch, out);
    const bytes = new Uint8ClampedArray(this.u8(out, pixels * 4));
    this.free(scratch);
    this.free(out);
    return bytes;
  }

  codes16(samplesPtr, count) {
    const out = this.alloc(count * 2);
    this.m._studio_codes16(samplesPtr, count, out);
    const codes = new Uint16Array(this.u16(out, count));
    this.free(out);
    return codes;
  }
}
