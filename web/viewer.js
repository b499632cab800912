// three.js scene: the input mesh (semi-transparent, with its wireframe) and the kernel, drawn
// from the stream of step events so any prefix of the stream can be shown (the scrubber).

import * as THREE from 'three';
import { OrbitControls } from 'three/examples/jsm/controls/OrbitControls.js';

export const KERNEL_BLUE = 0x1e6fff;
const KERNEL_EDGE = 0x0a2f80;
const FRONT_COLOR = 0xffb000;

function cssColor(name, fallback) {
  const v = getComputedStyle(document.documentElement).getPropertyValue(name).trim();
  return v || fallback;
}

// A growable Float32 attribute (xyz) whose draw range is set separately.
class GrowableBuffer {
  constructor(geometry, name = 'position', itemSize = 3) {
    this.geometry = geometry;
    this.name = name;
    this.itemSize = itemSize;
    this.count = 0;
    this.alloc(256);
  }
  alloc(items) {
    const array = new Float32Array(items * this.itemSize);
    if (this.attr) array.set(this.attr.array.subarray(0, this.count * this.itemSize));
    this.attr = new THREE.BufferAttribute(array, this.itemSize);
    this.attr.setUsage(THREE.DynamicDrawUsage);
    this.geometry.setAttribute(this.name, this.attr);
  }
  push(x, y, z) {
    if (this.count * this.itemSize >= this.attr.array.length) this.alloc(this.count * 2);
    const o = this.count * this.itemSize;
    this.attr.array[o] = x;
    this.attr.array[o + 1] = y;
    this.attr.array[o + 2] = z;
    this.count++;
    this.attr.needsUpdate = true;
  }
  reset() {
    this.count = 0;
    this.alloc(256);
  }
}

// The kernel as a timeline of step events. `push(event)` records an event; `show(k)` draws the
// state after the first k events (vertices as points, edges as lines, faces filled).
export class KernelView {
  constructor() {
    this.group = new THREE.Group();
    this.pointsGeo = new THREE.BufferGeometry();
    this.linesGeo = new THREE.BufferGeometry();
    this.facesGeo = new THREE.BufferGeometry();
    this.pointBuf = new GrowableBuffer(this.pointsGeo);
    this.lineBuf = new GrowableBuffer(this.linesGeo);
    this.faceBuf = new GrowableBuffer(this.facesGeo);
    this.points = new THREE.Points(this.pointsGeo, new THREE.PointsMaterial({ color: KERNEL_EDGE, size: 6, sizeAttenuation: false }));
    this.lines = new THREE.LineSegments(this.linesGeo, new THREE.LineBasicMaterial({ color: KERNEL_EDGE }));
    this.faces = new THREE.Mesh(
      this.facesGeo,
      new THREE.MeshStandardMaterial({
        color: KERNEL_BLUE, flatShading: true, roughness: 0.55, metalness: 0.0, side: THREE.DoubleSide,
        polygonOffset: true, polygonOffsetFactor: 1, polygonOffsetUnits: 1,
      }),
    );
    this.frontGeo = new THREE.BufferGeometry();
    this.frontGeo.setAttribute('position', new THREE.BufferAttribute(new Float32Array(6), 3));
    this.front = new THREE.LineSegments(this.frontGeo, new THREE.LineBasicMaterial({ color: FRONT_COLOR }));
    this.frontPoint = new THREE.Points(
      this.frontGeo, new THREE.PointsMaterial({ color: FRONT_COLOR, size: 10, sizeAttenuation: false }));
    for (const o of [this.faces, this.lines, this.points, this.front, this.frontPoint]) {
      o.frustumCulled = false;
      this.group.add(o);
    }
    this.offset = new THREE.Vector3();
    this.dirty = true;
    this.reset();
  }

  reset() {
    this.events = [];
    this.prefix = [[0, 0, 0]]; // after k events: [points, edges, face triangles]
    this.vertexPos = new Map(); // id → [x, y, z] (centered)
    this.counts = { vertices: 0, edges: 0, faces: 0 };
    this.countsAt = [{ vertices: 0, edges: 0, faces: 0 }];
    this.pointBuf.reset();
    this.lineBuf.reset();
    this.faceBuf.reset();
    this.shown = -1;
    this.show(0);
  }

  get length() {
    return this.events.length;
  }

  push(ev) {
    const o = this.offset;
    if (ev.type === 'vertex') {
      const p = [ev.position[0] - o.x, ev.position[1] - o.y, ev.position[2] - o.z];
      this.vertexPos.set(ev.id, p);
      this.pointBuf.push(...p);
      this.counts.vertices++;
    } else if (ev.type === 'edge') {
      const a = this.vertexPos.get(ev.a), b = this.vertexPos.get(ev.b);
      if (!a || !b) return false; // an edge before its vertices: ignored (never expected)
      this.lineBuf.push(...a);
      this.lineBuf.push(...b);
      this.counts.edges++;
    } else if (ev.type === 'face') {
      const loop = Array.from(ev.loop, (id) => this.vertexPos.get(id));
      if (loop.some((p) => !p) || loop.length < 3) return false;
      for (let k = 1; k + 1 < loop.length; k++) {
        this.faceBuf.push(...loop[0]);
        this.faceBuf.push(...loop[k]);
        this.faceBuf.push(...loop[k + 1]);
      }
      this.counts.faces++;
    } else {
      return false;
    }
    this.events.push(ev);
    this.prefix.push([this.pointBuf.count, this.lineBuf.count, this.faceBuf.count]);
    this.countsAt.push({ ...this.counts });
    return true;
  }

  // Draws the state after the first k events; returns the partial counts.
  show(k) {
    k = Math.max(0, Math.min(this.events.length, Math.floor(k)));
    if (k !== this.shown) {
      const [np, nl, nf] = this.prefix[k];
      this.pointsGeo.setDrawRange(0, np);
      this.linesGeo.setDrawRange(0, nl);
      this.facesGeo.setDrawRange(0, nf);
      // Highlight the newest element: the last edge, or the last vertex.
      const pos = this.frontGeo.getAttribute('position');
      const ev = this.events[k - 1];
      let n = 0;
      if (ev?.type === 'edge') {
        pos.array.set(this.vertexPos.get(ev.a), 0);
        pos.array.set(this.vertexPos.get(ev.b), 3);
        n = 2;
      } else if (ev?.type === 'vertex') {
        pos.array.set(this.vertexPos.get(ev.id), 0);
        pos.array.set(this.vertexPos.get(ev.id), 3);
        n = 2;
      }
      pos.needsUpdate = true;
      this.frontGeo.setDrawRange(0, n);
      this.front.visible = this.frontPoint.visible = k < this.events.length || ev?.type !== 'face';
      this.shown = k;
      this.dirty = true;
    }
    return this.countsAt[k];
  }
}

function isSoftwareGL() {
  try {
    const gl = document.createElement('canvas').getContext('webgl2');
    if (!gl) return false;
    const info = gl.getExtension('WEBGL_debug_renderer_info');
    const name = String(gl.getParameter(info ? info.UNMASKED_RENDERER_WEBGL : gl.RENDERER));
    gl.getExtension('WEBGL_lose_context')?.loseContext();
    return /swiftshader|llvmpipe|softpipe|software/i.test(name);
  } catch {
    return false;
  }
}

// The mesh's unique edges as an indexed line geometry sharing the mesh's position attribute
// (WireframeGeometry copies positions and dedupes with string keys: slow on large meshes).
// The input's edges: each face's loop once per edge (polygons without their drawing diagonals).
function wireframe(meshGeo, indices, faceSizes, nv) {
  const seen = new Set();
  const lines = [];
  const faces = faceSizes ?? { length: indices.length / 3 };
  for (let f = 0, at = 0; f < faces.length; f++) {
    const k = faceSizes ? faceSizes[f] : 3;
    for (let j = 0; j < k; j++) {
      const a = indices[at + j], b = indices[at + ((j + 1) % k)];
      const key = a < b ? a * nv + b : b * nv + a;
      if (!seen.has(key)) {
        seen.add(key);
        lines.push(a, b);
      }
    }
    at += k;
  }
  const geo = new THREE.BufferGeometry();
  geo.setAttribute('position', meshGeo.getAttribute('position'));
  geo.setIndex(new THREE.BufferAttribute(Uint32Array.from(lines), 1));
  return geo;
}

// Triangles to draw the faces with (the kernel is computed on the polygons themselves): each
// polygon is split by three.js's earcut in the projection along its largest normal axis (a fan
// would fold over a non-convex one).
function drawnTriangles(positions, indices, faceSizes) {
  if (!faceSizes) return indices;
  const out = [];
  for (let f = 0, at = 0; f < faceSizes.length; at += faceSizes[f], f++) {
    const k = faceSizes[f];
    const loop = indices.subarray(at, at + k);
    if (k === 3) {
      out.push(loop[0], loop[1], loop[2]);
      continue;
    }
    const n = [0, 0, 0];
    for (let i = 0; i < k; i++) {
      const a = 3 * loop[i], b = 3 * loop[(i + 1) % k];
      for (let c = 0; c < 3; c++) {
        const c1 = (c + 1) % 3, c2 = (c + 2) % 3;
        n[c] += (positions[a + c1] - positions[b + c1]) * (positions[a + c2] + positions[b + c2]);
      }
    }
    const axis = Math.abs(n[0]) >= Math.abs(n[1]) && Math.abs(n[0]) >= Math.abs(n[2]) ? 0 : Math.abs(n[1]) >= Math.abs(n[2]) ? 1 : 2;
    const u = (axis + 1) % 3, w = (axis + 2) % 3;
    const contour = Array.from(loop, (v) => new THREE.Vector2(positions[3 * v + u], positions[3 * v + w]));
    for (const [p, q, r] of THREE.ShapeUtils.triangulateShape(contour, [])) out.push(loop[p], loop[q], loop[r]);
  }
  return Uint32Array.from(out);
}

export class Viewer {
  constructor(container) {
    this.container = container;
    // Software GL (SwiftShader, llvmpipe) renders on the CPU cores the kernel worker needs: no
    // MSAA there, and fewer frames while a computation runs (see render()).
    this.softwareGL = isSoftwareGL();
    this.renderer = new THREE.WebGLRenderer({ antialias: !this.softwareGL });
    this.renderer.setPixelRatio(this.softwareGL ? 1 : Math.min(window.devicePixelRatio, 2));
    this.renderMs = 0; // moving average of the time one frame takes to submit
    this.lastRender = 0;
    container.appendChild(this.renderer.domElement);
    this.renderer.domElement.id = 'viewport-canvas';
    this.scene = new THREE.Scene();
    this.camera = new THREE.PerspectiveCamera(40, 1, 0.01, 100);
    this.camera.up.set(0, 0, 1);
    this.scene.add(this.camera);
    this.scene.add(new THREE.HemisphereLight(0xffffff, 0x667080, 1.6));
    const key = new THREE.DirectionalLight(0xffffff, 1.8);
    key.position.set(0.5, 1, 1.5);
    this.camera.add(key); // the light follows the view
    this.controls = new OrbitControls(this.camera, this.renderer.domElement);
    this.controls.enableDamping = true;
    this.dirty = true; // render on demand: only when something changed
    this.controls.addEventListener('change', () => { this.dirty = true; });

    this.inputGroup = new THREE.Group();
    this.scene.add(this.inputGroup);
    this.kernel = new KernelView();
    this.scene.add(this.kernel.group);
    // The kernel point (the LP's kernel vertex): a fixed-size marker at any zoom.
    const kpGeo = new THREE.BufferGeometry();
    kpGeo.setAttribute('position', new THREE.BufferAttribute(new Float32Array(3), 3));
    this.kernelPoint = new THREE.Points(kpGeo, new THREE.PointsMaterial({ color: 0xff3060, size: 11, sizeAttenuation: false }));
    this.kernelPoint.frustumCulled = false;
    this.kernelPoint.visible = false;
    this.scene.add(this.kernelPoint);

    this.radius = 1;
    this.applyTheme();
    window.matchMedia?.('(prefers-color-scheme: dark)').addEventListener?.('change', () => this.applyTheme());
    new ResizeObserver(() => this.resize()).observe(container);
    this.resize();
  }

  applyTheme() {
    this.dirty = true;
    this.scene.background = new THREE.Color(cssColor('--scene-bg', '#f3f4f7'));
    const dark = window.matchMedia?.('(prefers-color-scheme: dark)').matches;
    if (this.inputMaterial) {
      this.inputMaterial.opacity = dark ? 0.16 : 0.22;
      this.wireMaterial.color.set(dark ? 0xc9a26a : 0x7a5a2a);
    }
  }

  resize() {
    const w = Math.max(1, this.container.clientWidth), h = Math.max(1, this.container.clientHeight);
    this.renderer.setSize(w, h, false);
    this.camera.aspect = w / h;
    this.camera.updateProjectionMatrix();
    this.dirty = true;
  }

  clearInput() {
    this.dirty = true;
    for (const o of [...this.inputGroup.children]) {
      o.geometry.dispose();
      this.inputGroup.remove(o);
    }
  }

  // Shows the input mesh; everything is drawn relative to its bounding-box centre (float32
  // rendering of far-from-origin models stays accurate).
  // positions: xyz; indices: triangles, or polygon loops one after another with faceSizes.
  setInput(positions, indices, faceSizes = undefined) {
    this.clearInput();
    const nv = positions.length / 3;
    const box = new THREE.Box3();
    const v = new THREE.Vector3();
    for (let i = 0; i < nv; i++) {
      v.set(positions[3 * i], positions[3 * i + 1], positions[3 * i + 2]);
      if (Number.isFinite(v.x) && Number.isFinite(v.y) && Number.isFinite(v.z)) box.expandByPoint(v);
    }
    const center = box.isEmpty() ? new THREE.Vector3() : box.getCenter(new THREE.Vector3());
    this.radius = box.isEmpty() ? 1 : Math.max(1e-30, box.getSize(new THREE.Vector3()).length() / 2);
    this.kernel.offset.copy(center);
    this.kernel.reset();
    this.kernelPoint.visible = false;

    // Draw only indices that refer to existing vertices (bad files are reported by the package).
    const drawable = indices.every((i) => i < nv);
    if (drawable && nv > 0) {
      const pos = new Float32Array(3 * nv);
      for (let i = 0; i < 3 * nv; i++) pos[i] = positions[i] - center.getComponent(i % 3);
      const geo = new THREE.BufferGeometry();
      geo.setAttribute('position', new THREE.BufferAttribute(pos, 3));
      geo.setIndex(new THREE.BufferAttribute(drawnTriangles(positions, indices, faceSizes), 1));
      this.inputMaterial = new THREE.MeshStandardMaterial({
        color: 0xe3a04a, transparent: true, opacity: 0.22, depthWrite: false, side: THREE.DoubleSide,
        flatShading: true, roughness: 0.8,
      });
      this.wireMaterial = new THREE.LineBasicMaterial({ color: 0x7a5a2a, transparent: true, opacity: 0.28, depthWrite: false });
      const mesh = new THREE.Mesh(geo, this.inputMaterial);
      mesh.renderOrder = 2;
      const wire = new THREE.LineSegments(wireframe(geo, indices, faceSizes, nv), this.wireMaterial);
      wire.renderOrder = 3;
      this.inputGroup.add(mesh, wire);
      this.applyTheme();
    }
    this.camera.far = this.radius * 100;
    this.fit();
  }

  setKernelPoint(p) {
    if (!p) {
      this.kernelPoint.visible = false;
      return;
    }
    const o = this.kernel.offset;
    const pos = this.kernelPoint.geometry.getAttribute('position');
    pos.array.set([p[0] - o.x, p[1] - o.y, p[2] - o.z]);
    pos.needsUpdate = true;
    this.kernelPoint.visible = true;
    this.dirty = true;
  }

  // Fits the input mesh (or, with kernel = true, the kernel shown so far) into the view.
  fit(kernel = false) {
    const center = new THREE.Vector3();
    let r = this.radius;
    if (kernel && this.kernel.pointBuf.count > 0) {
      const sphere = new THREE.Sphere().setFromPoints(
        Array.from({ length: this.kernel.pointBuf.count }, (_, i) => new THREE.Vector3().fromArray(this.kernel.pointBuf.attr.array, 3 * i)));
      center.copy(sphere.center);
      r = Math.max(sphere.radius, this.radius * 1e-4);
    }
    // The bounding-box sphere overestimates most shapes: 0.9 of the sphere-fitting distance.
    const dist = (r / Math.sin(THREE.MathUtils.degToRad(this.camera.fov / 2))) * 0.9;
    const dir = this.camera.position.clone().sub(this.controls.target);
    if (!kernel || dir.lengthSq() === 0) dir.set(1.0, -1.35, 0.9);
    dir.normalize();
    this.controls.target.copy(center);
    this.camera.position.copy(center).addScaledVector(dir, dist);
    this.camera.near = Math.max(r / 100, this.radius * 1e-5);
    this.camera.updateProjectionMatrix();
    this.camera.lookAt(center);
    this.controls.update();
    this.dirty = true;
  }

  // Renders when the view or the scene changed (controls keep damping for a few frames). While
  // `busy` (a computation runs) and frames are expensive, at most ~4 frames per second.
  render(busy = false) {
    const moved = this.controls.update();
    if (!(moved || this.dirty || this.kernel.dirty)) return;
    const now = performance.now();
    if (busy && !moved && (this.softwareGL || this.renderMs > 30) && now - this.lastRender < 250) return;
    this.renderer.render(this.scene, this.camera);
    const t = performance.now();
    this.renderMs = this.renderMs ? 0.8 * this.renderMs + 0.2 * (t - now) : t - now;
    this.lastRender = t;
    this.dirty = this.kernel.dirty = false;
  }
}
