// A preset tree (the JSON the CLI reads) edited by key paths such as
// "levels[1].profile[0].points[2]": the same paths as --set and --help-keys.

export function parsePath(path) {
  const parts = [];
  for (const m of path.matchAll(/([^.[\]]+)|\[(\d+)\]/g)) parts.push(m[1] !== undefined ? m[1] : Number(m[2]));
  return parts;
}

export function getPath(obj, path) {
  let v = obj;
  for (const p of parsePath(path)) {
    if (v === undefined || v === null) return undefined;
    v = v[p];
  }
  return v;
}

// Sets a value, creating objects and arrays along the way.
export function setPath(obj, path, value) {
  const parts = parsePath(path);
  let v = obj;
  for (let i = 0; i < parts.length - 1; i++) {
    const p = parts[i];
    if (v[p] === undefined || v[p] === null) v[p] = typeof parts[i + 1] === 'number' ? [] : {};
    v = v[p];
  }
  v[parts[parts.length - 1]] = value;
}

export function removePath(obj, path) {
  const parts = parsePath(path);
  let v = obj;
  for (let i = 0; i < parts.length - 1; i++) {
    v = v[parts[i]];
    if (v === undefined) return;
  }
  const last = parts[parts.length - 1];
  if (Array.isArray(v) && typeof last === 'number') return; // array slots keep their place
  delete v[last];
}

export const clone = (x) => JSON.parse(JSON.stringify(x));
