// The hand as the library poses it: a studio_hand in the WebAssembly module (skeleton,
// constraint set, pins and torques, the equilibrium of thesis eq. 3.17) and its drawing
// in three.js (joints, bones and palm from the solved joint positions).
import * as THREE from 'three';

const DEG = Math.PI / 180;
export const FINGERS = ['T', 'I', 'M', 'R', 'L'];
export const FINGER_NAMES = ['thumb', 'index', 'middle', 'ring', 'little'];

export class HandModel {
  constructor(lib) {
    this.lib = lib;
    const m = lib.m;
    this.ptr = m._studio_hand_create(1, lib.err);
    if (!this.ptr) throw new Error(lib.errorMessage());
    this.info = JSON.parse(lib.takeString(m._studio_hand_describe(this.ptr)));
    this.dofCount = this.info.dofs.length;
    this.index = Object.fromEntries(this.info.dofs.map((d, i) => [d.name, i]));
    this.pointsPtr = lib.alloc(this.info.points.length * 12);
    this.rotPtr = lib.alloc(this.info.links.length * 36);
    this.pinned = new Array(this.dofCount).fill(false);
    this.pinValue = new Array(this.dofCount).fill(0);
    this.torque = new Array(this.dofCount).fill(0);
    this.setName = 'none';
    this.listeners = [];
    this.buildDrawing();
    this.solve();
  }

  onPose(fn) { this.listeners.push(fn); }

  // The skin surface (thesis 4.1), when the library has it: built on this skeleton, then
  // deformed by the library at every pose (method: 1 rigid, 2 linear blend, 3 dual
  // quaternion skinning). Returns false when the build has no hand surface.
  surfaceAvailable() { return typeof this.lib.m._studio_surface_create === 'function'; }

  buildSurface(triangles = 8000) {
    if (!this.surfaceAvailable()) return false;
    const m = this.lib.m;
    const s = m._studio_surface_create(this.ptr, triangles, this.lib.err);
    if (!s) throw new Error(this.lib.errorMessage());
    this.surface = s;
    this.skinning = 3;
    const nv = m._studio_surface_vertex_count(s), nt = m._studio_surface_triangle_count(s);
    this.surfaceVertices = nv;
    this.surfaceTriangles = nt;
    this.surfacePos = this.lib.alloc(nv * 12);
    this.surfaceNrm = this.lib.alloc(nv * 12);
    // drawn as the atlas mesh (vertices on the atlas's seam split, with UVs), so the baked
    // skin texture can go on it; exportMap: the surface vertex of each drawn vertex
    const atlas = m._studio_surface_atlas(s, this.lib.err);
    if (!atlas) throw new Error(this.lib.errorMessage());
    const na = m._studio_mesh_vertex_count(atlas);
    this.exportMap = new Uint32Array(this.lib.u32(m._studio_surface_export_map(s), na));
    const g = new THREE.BufferGeometry();
    g.setAttribute('position', new THREE.BufferAttribute(new Float32Array(na * 3), 3));
    g.setAttribute('normal', new THREE.BufferAttribute(new Float32Array(na * 3), 3));
    g.setAttribute('uv', new THREE.BufferAttribute(new Float32Array(this.lib.f32(m._studio_mesh_uvs(atlas), na * 2)), 2));
    g.setIndex(new THREE.BufferAttribute(new Uint32Array(this.lib.u32(m._studio_mesh_indices(atlas), nt * 3)), 1));
    m._studio_mesh_destroy(atlas);
    this.plainMaterial = new THREE.MeshLambertMaterial({ color: 0xd9a58a });
    this.surfaceMesh = new THREE.Mesh(g, this.plainMaterial);
    this.surfaceMesh.frustumCulled = false;
    this.group.add(this.surfaceMesh);
    this.deformSurface();
    return true;
  }

  deformSurface() {
    if (!this.surface) return;
    const m = this.lib.m, nv = this.surfaceVertices;
    m._studio_surface_deform(this.surface, this.ptr, this.skinning, this.surfacePos, this.surfaceNrm);
    const g = this.surfaceMesh.geometry, map = this.exportMap;
    const pos = this.lib.f32(this.surfacePos, nv * 3), nrm = this.lib.f32(this.surfaceNrm, nv * 3);
    const gp = g.attributes.position.array, gn = g.attributes.normal.array;
    for (let e = 0; e < map.length; e++) {
      const v = 3 * map[e];
      gp[3 * e] = pos[v]; gp[3 * e + 1] = pos[v + 1]; gp[3 * e + 2] = pos[v + 2];
      gn[3 * e] = nrm[v]; gn[3 * e + 1] = nrm[v + 1]; gn[3 * e + 2] = nrm[v + 2];
    }
    g.attributes.position.needsUpdate = g.attributes.normal.needsUpdate = true;
  }

  // The atlas's skin texture baked by the library at size x size (sk_hand_texture_bake):
  // the microrelief of the skin preset trees `back` and `palm` (null: none) in the normal
  // map, the generated skin colour in the albedo. Returns RGBA bytes of both as the PNG
  // files hold them (albedo sRGB, normal map linear), top row first.
  bakeTexture(size, back, palm) {
    const lib = this.lib, n = size * size;
    const a = lib.alloc(n * 12), nm = lib.alloc(n * 12);
    try {
      const r = lib.withStrings([back ? JSON.stringify(back) : null, palm ? JSON.stringify(palm) : null],
        (b, p) => lib.m._studio_surface_texture(this.surface, size, b, p, a, nm, lib.err));
      if (r !== 0) throw new Error(lib.errorMessage());
      return { albedo: lib.rgba(a, n, 3, true), normal: lib.rgba(nm, n, 3, false) };
    } finally {
      lib.free(a);
      lib.free(nm);
    }
  }

  showSurface(on) {
    if (this.surfaceMesh) this.surfaceMesh.visible = on;
    this.joints.visible = this.bones.visible = this.palm.visible = !on || !this.surfaceMesh;
  }

  // The constraint set from its JSON text (null = none: coupling off).
  useSet(name, text) {
    const r = this.lib.withStrings([text || '', name], (t, n) => this.lib.m._studio_hand_use_set(this.ptr, t, n, this.lib.err));
    if (r !== 0) throw new Error(this.lib.errorMessage());
    this.setName = name;
  }

  pin(name, value, on = true) {
    const i = this.index[name];
    this.pinned[i] = on;
    this.pinValue[i] = value;
  }

  clearInputs() {
    this.pinned.fill(false);
    this.torque.fill(0);
  }

  pushInputs() {
    const m = this.lib.m;
    m._studio_hand_clear_inputs(this.ptr);
    for (let i = 0; i < this.dofCount; i++) {
      if (this.pinned[i]) m._studio_hand_pin(this.ptr, i, 1, this.pinValue[i]);
      if (this.torque[i]) m._studio_hand_torque(this.ptr, i, this.torque[i]);
    }
  }

  solve() {
    this.pushInputs();
    if (this.lib.m._studio_hand_solve(this.ptr, this.lib.err) !== 0) throw new Error(this.lib.errorMessage());
    this.readPose();
  }

  setDofs(values) {
    const p = this.lib.alloc(8 * this.dofCount);
    this.lib.f64(p, this.dofCount).set(values);
    this.lib.m._studio_hand_set_dofs(this.ptr, p);
    this.lib.free(p);
    this.readPose();
  }

  readPose() {
    const m = this.lib.m;
    this.dofs = Array.from(this.lib.f64(m._studio_hand_dofs(this.ptr), this.dofCount));
    m._studio_hand_pose_geometry(this.ptr, this.pointsPtr, this.rotPtr);
    this.points = new Float32Array(this.lib.f32(this.pointsPtr, this.info.points.length * 3));
    this.updateDrawing();
    this.deformSurface();
    for (const fn of this.listeners) fn(this);
  }

  // Pins the finger's reach DOFs so its tip gets nearest `target` (mm); the distance left.
  reach(finger, target) {
    this.pushInputs();
    const d = this.lib.m._studio_hand_reach(this.ptr, finger, target[0], target[1], target[2], this.lib.err);
    if (d < 0) throw new Error(this.lib.errorMessage());
    const pinned = this.lib.alloc(4 * this.dofCount), values = this.lib.alloc(8 * this.dofCount);
    this.lib.m._studio_hand_pins(this.ptr, pinned, values);
    const pm = this.lib.i32(pinned, this.dofCount), pv = this.lib.f64(values, this.dofCount);
    for (let i = 0; i < this.dofCount; i++) { this.pinned[i] = pm[i] !== 0; this.pinValue[i] = pv[i]; }
    this.lib.free(pinned);
    this.lib.free(values);
    this.readPose();
    return d;
  }

  // Frames of an animation file (the format `shitsukan hand animate` reads).
  animate(anim) {
    const fpsPtr = this.lib.alloc(8);
    const frames = this.lib.withStrings([JSON.stringify(anim)], (p) => this.lib.m._studio_hand_animate(this.ptr, p, fpsPtr, this.lib.err));
    const fps = this.lib.f64(fpsPtr, 1)[0];
    this.lib.free(fpsPtr);
    if (frames === 0) throw new Error(this.lib.errorMessage());
    const all = this.lib.f64(this.lib.m._studio_hand_animation_frames(this.ptr), frames * this.dofCount);
    const list = [];
    for (let f = 0; f < frames; f++) list.push(Array.from(all.subarray(f * this.dofCount, (f + 1) * this.dofCount)));
    return { frames: list, fps };
  }

  fingerOfPoint(p) { return p === 0 ? -1 : p <= 4 ? 0 : Math.floor((p - 5) / 5) + 1; }
  tipPoint(finger) { return finger === 0 ? 4 : 4 + 5 * finger; }
  point(i) { return new THREE.Vector3(this.points[3 * i], this.points[3 * i + 1], this.points[3 * i + 2]); }

  // Joints and bones as two instanced meshes (two draw calls: software WebGL draws
  // them several times faster than fifty meshes), coloured per finger.
  buildDrawing() {
    this.group = new THREE.Group(); // in mm; the caller scales it
    const colors = this.info.finger_colors.map((c) => new THREE.Color().setRGB(c[0], c[1], c[2]));
    const grey = new THREE.Color(0.45, 0.42, 0.4);
    const n = this.info.points.length;
    this.joints = new THREE.InstancedMesh(new THREE.SphereGeometry(1, 16, 12), new THREE.MeshLambertMaterial(), n);
    this.bones = new THREE.InstancedMesh(new THREE.CylinderGeometry(1, 1, 1, 12), new THREE.MeshLambertMaterial(), n);
    this.tipOf = new Map(); // instance (point) -> finger, for fingertips
    this.info.points.forEach((pt, i) => {
      const f = this.fingerOfPoint(i);
      this.joints.setColorAt(i, f < 0 ? grey : colors[f]);
      this.bones.setColorAt(i, f < 0 ? grey : colors[f]);
      if (pt.name.endsWith('tip')) this.tipOf.set(i, f);
    });
    this.joints.frustumCulled = this.bones.frustumCulled = false;
    this.group.add(this.joints, this.bones);
    // the palm: a translucent plate through the CMC and MCP joints
    this.palmGeometry = new THREE.BufferGeometry();
    this.palmGeometry.setAttribute('position', new THREE.BufferAttribute(new Float32Array(3 * 12), 3));
    this.palmGeometry.setIndex([0, 1, 5, 1, 6, 5, 1, 2, 6, 2, 7, 6, 2, 3, 7, 3, 8, 7, 10, 0, 1, 10, 1, 2, 10, 2, 3, 10, 11, 0]);
    this.palm = new THREE.Mesh(this.palmGeometry, new THREE.MeshLambertMaterial({ color: 0xd9b8a0, transparent: true, opacity: 0.45, side: THREE.DoubleSide, depthWrite: false }));
    this.group.add(this.palm);
  }

  // World position of a joint (for the piano's key layout).
  jointWorld(i) { return this.group.localToWorld(this.point(i)); }

  updateDrawing() {
    const up = new THREE.Vector3(0, 1, 0), m = new THREE.Matrix4(), q = new THREE.Quaternion();
    const one = new THREE.Vector3(), zero = new THREE.Matrix4().makeScale(0, 0, 0);
    for (let i = 0; i < this.info.points.length; i++) {
      const r = this.tipOf.has(i) ? 6 : 5;
      m.compose(this.point(i), q.identity(), one.set(r, r, r));
      this.joints.setMatrixAt(i, m);
      const parent = this.info.points[i].parent;
      if (parent < 0) { this.bones.setMatrixAt(i, zero); continue; }
      const a = this.point(parent), c = this.point(i);
      const d = c.clone().sub(a);
      const len = d.length();
      q.setFromUnitVectors(up, d.clone().normalize());
      m.compose(a.addScaledVector(d, 0.5), q, one.set(3, Math.max(len, 1e-3), 3));
      this.bones.setMatrixAt(i, m);
    }
    this.joints.instanceMatrix.needsUpdate = this.bones.instanceMatrix.needsUpdate = true;
    // palm corners: CMCs of I..L (0-3), MCPs of I..L (5-8), the wrist (10), thumb CMC (11)
    const ids = [5, 10, 15, 20, 20, 6, 11, 16, 21, 21, 0, 1];
    const pos = this.palmGeometry.attributes.position;
    ids.forEach((p, k) => pos.setXYZ(k, this.points[3 * p], this.points[3 * p + 1], this.points[3 * p + 2]));
    pos.needsUpdate = true;
    this.palmGeometry.computeVertexNormals();
    this.palmGeometry.computeBoundingSphere();
  }

  degrees(i) { return this.info.dofs[i].translation ? this.dofs[i] : this.dofs[i] / DEG; }
}

export { DEG };
