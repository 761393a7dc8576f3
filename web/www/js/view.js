// The 3D view: one three.js renderer, orbit controls, lights; panels put their content
// in it (the hand, the piano, a board) and their map pictures beside it.
import * as THREE from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';

export class View {
  constructor(canvas, mapsBox) {
    this.canvas = canvas;
    this.mapsBox = mapsBox;
    this.renderer = new THREE.WebGLRenderer({ canvas, antialias: false });
    this.renderer.setPixelRatio(1);
    this.scene = new THREE.Scene();
    this.scene.background = new THREE.Color(0xe9e6e1);
    this.camera = new THREE.PerspectiveCamera(40, 1, 0.01, 100);
    this.camera.position.set(0, 1.2, 4);
    this.controls = new OrbitControls(this.camera, canvas);
    this.controls.addEventListener('change', () => this.render());
    this.scene.add(new THREE.HemisphereLight(0xffffff, 0x8a7f72, 1.2));
    const sun = new THREE.DirectionalLight(0xffffff, 2.0);
    sun.position.set(2, 4, 3);
    this.scene.add(sun);
    this.sun = sun;
    this.content = null;
    new ResizeObserver(() => this.resize()).observe(canvas);
    this.resize();
  }

  resize() {
    const w = this.canvas.clientWidth || 800, h = this.canvas.clientHeight || 600;
    this.renderer.setSize(w, h, false);
    this.camera.aspect = w / h;
    this.camera.updateProjectionMatrix();
    this.render();
  }

  setContent(object, frame) {
    if (this.content) this.scene.remove(this.content);
    this.content = object;
    if (object) this.scene.add(object);
    if (frame) {
      const t = new THREE.Vector3(...frame.target);
      const dir = frame.direction ? new THREE.Vector3(...frame.direction).normalize() : new THREE.Vector3(0, 0.35, 1).normalize();
      this.camera.position.copy(t).addScaledVector(dir, frame.distance);
      this.controls.target.copy(t);
      this.controls.update();
    }
    this.render();
  }

  showMaps(element) {
    this.mapsBox.textContent = '';
    if (element) this.mapsBox.append(element);
    this.mapsBox.hidden = !element;
  }

  render() { this.renderer.render(this.scene, this.camera); }

  // Renders and waits for the GPU to finish (a one-pixel read), for timings.
  renderSync() {
    this.render();
    const gl = this.renderer.getContext();
    const px = new Uint8Array(4);
    gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, px);
  }
}
