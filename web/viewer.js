// three.js scene: the input mesh (semi-transparent, with its faces' edges when asked) and the
// kernel, drawn from the stream of step events so any prefix of the stream can be shown (the
// scrubber). The input arrives prepared (draw-prep.js: float32, centred, triangulated), so
// showing a million-triangle mesh costs this thread only the GPU upload.

import * as THREE from 'three';
import { OrbitControls } from 'three/examples/jsm/controls/OrbitControls.js';
import { prepareDrawing } from './draw-prep.js';

export const KERNEL_BLUE = 0x1e6fff;
const KERNEL_EDGE = 0x0a2f80;
const FRONT_COLOR = 0xffb000;

function cssColor(name, fallback) {
  const v = getComputedStyle(document.documentElement).getPropertyValue(name).trim();
  return v || fallback;
}

// A growable Float32 attribute (xyz) whose draw range is set separately. Only the items added
// since the last frame are uploaded (upload()): re-sending a kernel of a million elements every
// frame would cost more than drawing it.
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
    this.uploaded = this.count; // a new attribute is uploaded whole on its first draw
  }
  push(x, y, z) {
    if (this.count * this.itemSize >= this.attr.array.length) this.alloc(this.count * 2);
    const o = this.count * this.itemSize;
    this.attr.array[o] = x;
    this.attr.array[o + 1] = y;
    this.attr.array[o + 2] = z;
    this.count++;
  }
  // Marks the items pushed since the last call for upload.
  upload() {
    if (this.count === this.uploaded) return;
    // Ranges add up until the next draw uploads them (three.js clears them then): a frame can be
    // skipped between two calls.
    this.attr.addUpdateRange(this.uploaded * this.itemSize, (this.count - this.uploaded) * this.itemSize);
    this.attr.needsUpdate = true;
    this.uploaded = this.count;
  }
  reset() {
    this.count = 0;
    this.alloc(256);
  }
}

// A growable typed array of plain numbers (no three.js attribute).
class GrowableArray {
  constructor(Type, initial = 1024) {
    this.Type = Type;
    this.array = new Type(initial);
    this.length = 0;
  }
  push(x) {
    if (this.length === this.array.length) {
      const bigger = new this.Type(2 * this.array.length);
      bigger.set(this.array);
      this.array = bigger;
    }
    this.array[this.length++] = x;
  }
}

const KIND = { vertex: 1, edge: 2, face: 3 };
const BIG_KERNEL_VERTICES = 20000;
const BIG_KERNEL_EDGES = 30000;

// The kernel as a timeline of step events. `push(event)` records an event; `show(k)` draws the
// state after the first k events (vertices as points, edges as lines, faces filled). Everything
// is kept in typed arrays (a kernel can have a million events) and show(k) only sets draw ranges,
// so a frame costs the same whatever k and the kernel's size.
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
    // Lambert shading: with software WebGL every pixel of PBR shading is paid on the CPU, and
    // the page's thread waits for the frame (see Viewer.render).
    this.faces = new THREE.Mesh(
      this.facesGeo,
      new THREE.MeshLambertMaterial({
        color: KERNEL_BLUE, flatShading: true, side: THREE.DoubleSide,
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
    this.kinds = new GrowableArray(Uint8Array);
    // After k events: points, line vertices, face-triangle vertices, faces (4 numbers per k).
    this.prefix = new GrowableArray(Uint32Array);
    for (let i = 0; i < 4; i++) this.prefix.push(0);
    this.slot = []; // vertex id → its point index
    this.nFaces = 0;
    this.pointBuf.reset();
    this.lineBuf.reset();
    this.faceBuf.reset();
    this.shown = -1;
    this.show(0);
  }

  get length() {
    return this.kinds.length;
  }

  pointAt(i) {
    const a = this.pointBuf.attr.array;
    return [a[3 * i], a[3 * i + 1], a[3 * i + 2]];
  }

  // Records one step event; false when it cannot be drawn (an edge before its vertices).
  push(ev) {
    const o = this.offset;
    const kind = KIND[ev.type];
    if (kind === KIND.vertex) {
      this.slot[ev.id] = this.pointBuf.count;
      this.pointBuf.push(ev.position[0] - o.x, ev.position[1] - o.y, ev.position[2] - o.z);
    } else if (kind === KIND.edge) {
      const a = this.slot[ev.a], b = this.slot[ev.b];
      if (a === undefined || b === undefined) return false;
      this.lineBuf.push(...this.pointAt(a));
      this.lineBuf.push(...this.pointAt(b));
    } else if (kind === KIND.face) {
      const loop = Array.from(ev.loop, (id) => this.slot[id]);
      if (loop.length < 3 || loop.some((i) => i === undefined)) return false;
      const p0 = this.pointAt(loop[0]);
      for (let k = 1; k + 1 < loop.length; k++) {
        this.faceBuf.push(...p0);
        this.faceBuf.push(...this.pointAt(loop[k]));
        this.faceBuf.push(...this.pointAt(loop[k + 1]));
      }
      this.nFaces++;
    } else {
      return false;
    }
    this.kinds.push(kind);
    this.prefix.push(this.pointBuf.count);
    this.prefix.push(this.lineBuf.count);
    this.prefix.push(this.faceBuf.count);
    this.prefix.push(this.nFaces);
    return true;
  }

  countsAt(k) {
    const p = this.prefix.array;
    return { vertices: p[4 * k], edges: p[4 * k + 1] / 2, faces: p[4 * k + 3] };
  }

  // Draws the state after the first k events; returns the partial counts.
  show(k) {
    k = Math.max(0, Math.min(this.length, Math.floor(k)));
    for (const b of [this.pointBuf, this.lineBuf, this.faceBuf]) b.upload();
    if (k !== this.shown) {
      const p = this.prefix.array;
      // Big kernels: vertex dots and edge lines only while there are few enough to read (and
      // to draw: software WebGL pays for every primitive); the faces show the shape.
      this.points.visible = p[4 * k] <= BIG_KERNEL_VERTICES;
      this.lines.visible = p[4 * k + 1] / 2 <= BIG_KERNEL_EDGES;
      this.pointsGeo.setDrawRange(0, p[4 * k]);
      this.linesGeo.setDrawRange(0, p[4 * k + 1]);
      this.facesGeo.setDrawRange(0, p[4 * k + 2]);
      // Highlight the newest element: the last edge, or the last vertex.
      const pos = this.frontGeo.getAttribute('position');
      const kind = k > 0 ? this.kinds.array[k - 1] : 0;
      let n = 0;
      if (kind === KIND.edge) {
        const lines = this.lineBuf.attr.array, e = 3 * (p[4 * k + 1] - 2);
        pos.array.set(lines.subarray(e, e + 6), 0);
        n = 2;
      } else if (kind === KIND.vertex) {
        const v = this.pointAt(p[4 * k] - 1);
        pos.array.set(v, 0);
        pos.array.set(v, 3);
        n = 2;
      }
      pos.needsUpdate = true;
      this.frontGeo.setDrawRange(0, n);
      this.front.visible = this.frontPoint.visible = k < this.length || kind !== KIND.face;
      this.shown = k;
      this.dirty = true;
    }
    return this.countsAt(k);
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

export class Viewer {
  constructor(container) {
    this.container = container;
    // Software GL (SwiftShader, llvmpipe) renders on the CPU cores the kernel worker needs: no
    // MSAA there, and fewer frames while a computation runs (see render()).
    this.softwareGL = isSoftwareGL();
    this.renderer = new THREE.WebGLRenderer({ antialias: !this.softwareGL });
    // With a software compositor the page's thread waits for every frame to be rasterized: half
    // the resolution (a quarter of the pixels) keeps a frame under 100 ms while the kernel worker
    // takes a core (3/4 gave frames of 85-150 ms on a loaded 2-core machine).
    this.renderer.setPixelRatio(this.softwareGL ? 0.5 : Math.min(window.devicePixelRatio, 2));
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
    this.opacity = 0.22;
    this.edgesVisible = true;
    this.makeInputMaterials();
    this.applyTheme();
    window.matchMedia?.('(prefers-color-scheme: dark)').addEventListener?.('change', () => this.applyTheme());
    new ResizeObserver(() => this.resize()).observe(container);
    this.resize();
    this.warmUp();
  }

  // Draws one frame with a triangle of every material at page load: compiling a shader and, with
  // software WebGL, generating its pipeline on first use cost a few hundred ms, which would
  // otherwise fall in the middle of a file's computation.
  warmUp() {
    // A 100 × 100 grid (20k triangles) filling the view in front of the camera (at the origin,
    // looking down -z until the first fit()): software rasterizers build their pixel stage and
    // start their threads only when fragments are drawn, and a drawing of this size is what a
    // big input costs.
    const geo = new THREE.PlaneGeometry(2, 2, 100, 100);
    geo.translate(0, 0, -1);
    geo.setIndex(new THREE.BufferAttribute(Uint32Array.from(geo.index.array), 1));
    // One dummy per material in the scene (kernel, newest edge, kernel point) and the input's.
    const dummies = [new THREE.Mesh(geo, this.inputMaterial), new THREE.LineSegments(geo, this.wireMaterial)];
    dummies[0].renderOrder = 2;
    this.scene.traverse((o) => {
      if (o.isMesh) dummies.push(new THREE.Mesh(geo, o.material));
      else if (o.isLineSegments) dummies.push(new THREE.LineSegments(geo, o.material));
      else if (o.isPoints) dummies.push(new THREE.Points(geo, o.material));
    });
    this.inputGroup.add(...dummies);
    this.renderer.render(this.scene, this.camera);
    this.inputGroup.remove(...dummies);
    geo.dispose();
    this.dirty = true;
  }

  // Materials live as long as the page: a new material would cost a shader compile per mesh.
  makeInputMaterials() {
    // The input is pushed back in depth: the kernel's faces lie in some of its face planes and
    // must win there (no z-fighting stripes of amber over blue).
    // One pass for both sides (three draws a transparent double-sided mesh twice by default):
    // half the fill cost, and a translucent overlay needs no back-to-front accuracy.
    this.inputMaterial = new THREE.MeshLambertMaterial({
      color: 0xe3a04a, transparent: true, opacity: this.opacity, depthWrite: false, side: THREE.DoubleSide,
      forceSinglePass: true, flatShading: true, polygonOffset: true, polygonOffsetFactor: 2, polygonOffsetUnits: 4,
    });
    this.wireMaterial = new THREE.LineBasicMaterial({ color: 0x7a5a2a, transparent: true, opacity: 0.28, depthWrite: false });
  }

  applyTheme() {
    this.dirty = true;
    this.scene.background = new THREE.Color(cssColor('--scene-bg', '#f3f4f7'));
    const dark = window.matchMedia?.('(prefers-color-scheme: dark)').matches;
    this.wireMaterial.color.set(dark ? 0xc9a26a : 0x7a5a2a);
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
    this.inputMesh = this.inputWire = null;
  }

  /** The input shape's opacity, 0 (hidden) to 1 (opaque). */
  setOpacity(x) {
    this.opacity = x;
    this.inputMaterial.opacity = x;
    // Opaque: write depth so the shape hides what is behind it, as a solid does.
    this.inputMaterial.transparent = x < 1;
    this.inputMaterial.depthWrite = x >= 1;
    this.inputMaterial.needsUpdate = true;
    if (this.inputMesh) this.inputMesh.visible = x > 0;
    this.dirty = true;
  }

  /** Shows or hides the input's face edges (set with setInputEdges). */
  setEdgesVisible(on) {
    this.edgesVisible = on;
    if (this.inputWire) this.inputWire.visible = on;
    this.dirty = true;
  }

  // Shows a small input mesh prepared here (samples); big ones come prepared by the draw worker.
  setInput(positions, indices, faceSizes = undefined) {
    this.setInputDrawing(prepareDrawing({ positions, indices, faceSizes: faceSizes ?? null }, { edges: true }));
  }

  /** Shows an input prepared by prepareDrawing(); the kernel is drawn relative to its centre. */
  setInputDrawing(d) {
    this.clearInput();
    this.radius = d.radius;
    this.kernel.offset.set(d.center[0], d.center[1], d.center[2]);
    this.kernel.reset();
    this.kernelPoint.visible = false;
    if (d.drawable) {
      const geo = new THREE.BufferGeometry();
      geo.setAttribute('position', new THREE.BufferAttribute(d.positions, 3));
      geo.setIndex(new THREE.BufferAttribute(d.triangles, 1));
      this.inputMesh = new THREE.Mesh(geo, this.inputMaterial);
      this.inputMesh.renderOrder = 2;
      this.inputMesh.frustumCulled = false; // no bounding sphere to compute over every vertex
      this.inputMesh.visible = this.opacity > 0;
      this.inputGroup.add(this.inputMesh);
      if (d.edges) this.setInputEdges(d.edges);
    }
    this.camera.far = this.radius * 100;
    this.fit();
  }

  /** The input's face edges (vertex-id pairs into the drawn positions). */
  setInputEdges(edges) {
    if (!this.inputMesh) return;
    if (this.inputWire) {
      this.inputWire.geometry.dispose();
      this.inputGroup.remove(this.inputWire);
    }
    const geo = new THREE.BufferGeometry();
    geo.setAttribute('position', this.inputMesh.geometry.getAttribute('position'));
    geo.setIndex(new THREE.BufferAttribute(edges, 1));
    this.inputWire = new THREE.LineSegments(geo, this.wireMaterial);
    this.inputWire.renderOrder = 3;
    this.inputWire.frustumCulled = false;
    this.inputWire.visible = this.edgesVisible;
    this.inputGroup.add(this.inputWire);
    this.dirty = true;
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
