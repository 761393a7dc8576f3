// Files the page writes: downloads, 8-bit PNG through the canvas (the browser's own
// encoder), 16-bit PNG (chunks written here, deflate by the browser's CompressionStream)
// and uncompressed float EXR (written here), with the codes and values the library gives.

export function download(name, blob) {
  const a = document.createElement('a');
  a.href = URL.createObjectURL(blob);
  a.download = name;
  document.body.append(a);
  a.click();
  a.remove();
  setTimeout(() => URL.revokeObjectURL(a.href), 10000);
}

export function jsonBlob(obj) {
  return new Blob([JSON.stringify(obj, null, 2) + '\n'], { type: 'application/json' });
}

// RGBA bytes (already the file's codes) to a PNG through a canvas.
export function canvasPng(rgba, width, height) {
  const c = document.createElement('canvas');
  c.width = width;
  c.height = height;
  c.getContext('2d').putImageData(new ImageData(rgba, width, height), 0, 0);
  return new Promise((resolve) => c.toBlob(resolve, 'image/png'));
}

const CRC_TABLE = (() => {
  const t = new Uint32Array(256);
  for (let n = 0; n < 256; n++) {
    let c = n;
    for (let k = 0; k < 8; k++) c = c & 1 ? 0xedb88320 ^ (c >>> 1) : c >>> 1;
    t[n] = c >>> 0;
  }
  return t;
})();

function crc32(bytes) {
  let c = 0xffffffff;
  for (let i = 0; i < bytes.length; i++) c = CRC_TABLE[(c ^ bytes[i]) & 0xff] ^ (c >>> 8);
  return (c ^ 0xffffffff) >>> 0;
}

function chunk(type, data) {
  const out = new Uint8Array(12 + data.length);
  const dv = new DataView(out.buffer);
  dv.setUint32(0, data.length);
  for (let i = 0; i < 4; i++) out[4 + i] = type.charCodeAt(i);
  out.set(data, 8);
  dv.setUint32(8 + data.length, crc32(out.subarray(4, 8 + data.length)));
  return out;
}

async function deflate(bytes) {
  const stream = new Blob([bytes]).stream().pipeThrough(new CompressionStream('deflate'));
  return new Uint8Array(await new Response(stream).arrayBuffer());
}

// A 16-bit grey (channels 1) or RGB (3) PNG of `codes` (Uint16Array, interleaved,
// width x height pixels), with tEXt entries.
export async function png16(codes, width, height, channels, text = {}) {
  const stride = 2 * width * channels;
  const raw = new Uint8Array(height * (1 + stride));
  for (let y = 0; y < height; y++) {
    const row = y * (1 + stride);
    raw[row] = 0; // filter: none
    for (let i = 0; i < width * channels; i++) {
      const v = codes[y * width * channels + i];
      raw[row + 1 + 2 * i] = v >> 8;
      raw[row + 2 + 2 * i] = v & 0xff;
    }
  }
  const ihdr = new Uint8Array(13);
  const dv = new DataView(ihdr.buffer);
  dv.setUint32(0, width);
  dv.setUint32(4, height);
  ihdr[8] = 16; // bit depth
  ihdr[9] = channels === 3 ? 2 : 0; // RGB or grey
  const parts = [new Uint8Array([137, 80, 78, 71, 13, 10, 26, 10]), chunk('IHDR', ihdr)];
  const enc = new TextEncoder();
  for (const [k, v] of Object.entries(text)) parts.push(chunk('tEXt', enc.encode(`${k}\0${v}`)));
  parts.push(chunk('IDAT', await deflate(raw)), chunk('IEND', new Uint8Array(0)));
  return new Blob(parts, { type: 'image/png' });
}

// An uncompressed scanline OpenEXR file of 32-bit float channels (names in file order,
// e.g. ['Y']; `planes` one Float32Array of width x height per channel), with string
// attributes. Layout of the OpenEXR 2 file format: magic, version 2, header attributes,
// an offset table of one entry per scanline, then each line's y, size and channels.
export function exrFloat(planes, names, width, height, attributes = {}) {
  const enc = new TextEncoder();
  const head = [];
  const u8 = (...b) => head.push(new Uint8Array(b));
  const i32 = (v) => { const a = new Uint8Array(4); new DataView(a.buffer).setInt32(0, v, true); head.push(a); };
  const f32 = (v) => { const a = new Uint8Array(4); new DataView(a.buffer).setFloat32(0, v, true); head.push(a); };
  const str0 = (s) => { head.push(enc.encode(s)); u8(0); };
  const attr = (name, type, size, write) => { str0(name); str0(type); i32(size); write(); };
  i32(20000630); // magic
  i32(2); // version 2, scanline, short names
  // channels are stored sorted by name
  const order = names.map((n, i) => [n, i]).sort((a, b) => (a[0] < b[0] ? -1 : a[0] > b[0] ? 1 : 0));
  const chlistSize = order.reduce((s, [n]) => s + n.length + 1 + 16, 1);
  attr('channels', 'chlist', chlistSize, () => {
    for (const [n] of order) { str0(n); i32(2); u8(0, 0, 0, 0); i32(1); i32(1); } // FLOAT, not linear, sampling 1 1
    u8(0);
  });
  attr('compression', 'compression', 1, () => u8(0)); // NO_COMPRESSION
  const box = () => { i32(0); i32(0); i32(width - 1); i32(height - 1); };
  attr('dataWindow', 'box2i', 16, box);
  attr('displayWindow', 'box2i', 16, box);
  attr('lineOrder', 'lineOrder', 1, () => u8(0)); // INCREASING_Y
  attr('pixelAspectRatio', 'float', 4, () => f32(1));
  attr('screenWindowCenter', 'v2f', 8, () => { f32(0); f32(0); });
  attr('screenWindowWidth', 'float', 4, () => f32(1));
  for (const [k, v] of Object.entries(attributes)) {
    const bytes = enc.encode(v);
    attr(k, 'string', bytes.length, () => head.push(bytes));
  }
  u8(0); // end of header
  const headerBytes = head.reduce((s, a) => s + a.length, 0);
  const lineBytes = 4 * width * names.length;
  const tableBytes = 8 * height;
  const total = headerBytes + tableBytes + height * (8 + lineBytes);
  const out = new Uint8Array(total);
  let p = 0;
  for (const a of head) { out.set(a, p); p += a.length; }
  const dv = new DataView(out.buffer);
  let chunkAt = headerBytes + tableBytes;
  for (let y = 0; y < height; y++) {
    dv.setBigUint64(p, BigInt(chunkAt + y * (8 + lineBytes)), true);
    p += 8;
  }
  for (let y = 0; y < height; y++) {
    dv.setInt32(p, y, true);
    dv.setInt32(p + 4, lineBytes, true);
    p += 8;
    for (const [, c] of order) {
      const plane = planes[c];
      for (let x = 0; x < width; x++, p += 4) dv.setFloat32(p, plane[y * width + x], true);
    }
  }
  return new Blob([out], { type: 'image/x-exr' });
}

// Reads a file the user picked as text.
export function pickFile(accept) {
  return new Promise((resolve) => {
    const input = document.createElement('input');
    input.type = 'file';
    input.accept = accept;
    input.onchange = () => {
      const f = input.files[0];
      if (!f) return resolve(null);
      f.text().then((text) => resolve({ name: f.name, text }));
    };
    input.click();
  });
}
