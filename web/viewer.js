// three.js scene: the input mesh (semi-transparent, with its faces' edges when asked) and the
// kernel, drawn from the stream of step events so any prefix of the stream can be shown (the
// scrubber). The input arrives prepared (draw-prep.js: float32, centred, triangulated), so
// showing a million-triangle mesh costs this thread only the GPU upload.

import * as THREE from 'three';
import { OrbitControls } from 'three/examples/jsm/controls/OrbitControls.js';
import { prepareDrawing } from './draw-prep.js';
import { SectionPlane } from './section.js';

export const KERNEL_BLUE = 0x1e6fff;
const KERNEL_EDGE = 0x0a2f80;
const FRONT_COLOR = 0xffb000;
const BALL_GREEN = 0x17a34a;
const OPEN_EDGE_RED = 0xe8141c;
const WITNESS_MAGENTA = 0xd4168f;
const BOX_FACET_GREY = 0xa9adb8;
// Vertical field of view of the whole canvas (the visible area above the play bar gets its share).
const FOV = 40;

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
    this.points = new THREE.Points(
      this.pointsGeo,
      new THREE.PointsMaterial({ color: KERNEL_EDGE, size: 6, sizeAttenuation: false }),
    );
    this.lines = new THREE.LineSegments(this.linesGeo, new THREE.LineBasicMaterial({ color: KERNEL_EDGE }));
    // Lambert shading: with software WebGL every pixel of PBR shading is paid on the CPU, and
    // the page's thread waits for the frame (see Viewer.render).
    this.faces = new THREE.Mesh(
      this.facesGeo,
      new THREE.MeshLambertMaterial({
        color: KERNEL_BLUE,
        flatShading: true,
        side: THREE.DoubleSide,
        polygonOffset: true,
        polygonOffsetFactor: 1,
        polygonOffsetUnits: 1,
      }),
    );
    this.frontGeo = new THREE.BufferGeometry();
    this.frontGeo.setAttribute('position', new THREE.BufferAttribute(new Float32Array(6), 3));
    this.front = new THREE.LineSegments(this.frontGeo, new THREE.LineBasicMaterial({ color: FRONT_COLOR }));
    this.frontPoint = new THREE.Points(
      this.frontGeo,
      new THREE.PointsMaterial({ color: FRONT_COLOR, size: 10, sizeAttenuation: false }),
    );
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
      const a = this.slot[ev.a],
        b = this.slot[ev.b];
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
        const lines = this.lineBuf.attr.array,
          e = 3 * (p[4 * k + 1] - 2);
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

// The bounding box of float xyz positions ({ lo, hi }), at least `minSize` across.
function boxOf(positions, minSize) {
  const lo = [Infinity, Infinity, Infinity],
    hi = [-Infinity, -Infinity, -Infinity];
  for (let i = 0; i < positions.length; i += 3) {
    for (let c = 0; c < 3; c++) {
      const x = positions[i + c];
      if (x < lo[c]) lo[c] = x;
      if (x > hi[c]) hi[c] = x;
    }
  }
  if (!(lo[0] <= hi[0])) return { lo: [-minSize, -minSize, -minSize], hi: [minSize, minSize, minSize] };
  for (let c = 0; c < 3; c++) {
    if (hi[c] - lo[c] < minSize) {
      const m = (lo[c] + hi[c]) / 2;
      lo[c] = m - minSize / 2;
      hi[c] = m + minSize / 2;
    }
  }
  return { lo, hi };
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
    // The stencil buffer closes the section plane's cuts (section.js).
    this.renderer = new THREE.WebGLRenderer({ antialias: !this.softwareGL, stencil: true });
    this.renderer.localClippingEnabled = true;
    // With a software compositor the page's thread waits for every frame to be rasterized: half
    // the resolution (a quarter of the pixels) keeps a frame under 100 ms while the kernel worker
    // takes a core (3/4 gave frames of 85-150 ms on a loaded 2-core machine).
    this.renderer.setPixelRatio(this.softwareGL ? 0.5 : Math.min(window.devicePixelRatio, 2));
    this.renderMs = 0; // moving average of the time one frame takes to submit
    this.lastRender = 0;
    container.appendChild(this.renderer.domElement);
    this.renderer.domElement.id = 'viewport-canvas';
    this.scene = new THREE.Scene();
    this.camera = new THREE.PerspectiveCamera(FOV, 1, 0.01, 100);
    this.insetBottom = 0; // pixels at the bottom of the canvas covered by the play bar
    this.camera.up.set(0, 0, 1);
    this.scene.add(this.camera);
    this.scene.add(new THREE.HemisphereLight(0xffffff, 0x667080, 1.6));
    const key = new THREE.DirectionalLight(0xffffff, 1.8);
    key.position.set(0.5, 1, 1.5);
    this.camera.add(key); // the light follows the view
    this.controls = new OrbitControls(this.camera, this.renderer.domElement);
    this.controls.enableDamping = true;
    this.dirty = true; // render on demand: only when something changed
    this.controls.addEventListener('change', () => {
      this.dirty = true;
    });

    this.inputGroup = new THREE.Group();
    this.scene.add(this.inputGroup);
    this.kernel = new KernelView();
    this.scene.add(this.kernel.group);
    // The kernel point (the LP's kernel vertex): a fixed-size marker at any zoom.
    const kpGeo = new THREE.BufferGeometry();
    kpGeo.setAttribute('position', new THREE.BufferAttribute(new Float32Array(3), 3));
    this.kernelPoint = new THREE.Points(
      kpGeo,
      new THREE.PointsMaterial({ color: 0xff3060, size: 11, sizeAttenuation: false }),
    );
    this.kernelPoint.frustumCulled = false;
    this.kernelPoint.visible = false;
    this.scene.add(this.kernelPoint);
    this.makeInsideMarkers();
    this.section = new SectionPlane(this.scene);
    this.kernelClosed = false;

    this.radius = 1;
    this.box = { lo: [-1, -1, -1], hi: [1, 1, 1] }; // the drawn input's bounding box (centred frame)
    this.opacity = 0.22;
    this.inputVisible = true;
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
      color: 0xe3a04a,
      transparent: true,
      opacity: this.opacity,
      depthWrite: false,
      side: THREE.DoubleSide,
      forceSinglePass: true,
      flatShading: true,
      polygonOffset: true,
      polygonOffsetFactor: 2,
      polygonOffsetUnits: 4,
    });
    this.wireMaterial = new THREE.LineBasicMaterial({
      color: 0x7a5a2a,
      transparent: true,
      opacity: 0.28,
      depthWrite: false,
    });
  }

  applyTheme() {
    this.dirty = true;
    this.scene.background = new THREE.Color(cssColor('--scene-bg', '#f3f4f7'));
    const dark = window.matchMedia?.('(prefers-color-scheme: dark)').matches;
    this.wireMaterial.color.set(dark ? 0xc9a26a : 0x7a5a2a);
  }

  resize() {
    const w = Math.max(1, this.container.clientWidth),
      h = Math.max(1, this.container.clientHeight);
    this.renderer.setSize(w, h, false);
    this.updateProjection();
  }

  /** The canvas's bottom `px` pixels are covered (by the play bar): views are centred above them. */
  setInsetBottom(px) {
    if (Math.abs(px - this.insetBottom) < 1) return;
    this.insetBottom = px;
    this.updateProjection();
  }

  // The centre of projection is put in the middle of the visible band (above the play bar), with
  // the same scale (pixels per radian) as a plain camera of FOV over the whole canvas: the camera
  // renders the window [0, h) of a taller image, 2h - hv high, whose centre is hv / 2 down.
  updateProjection() {
    const w = Math.max(1, this.container.clientWidth),
      h = Math.max(1, this.container.clientHeight);
    const hv = this.visibleHeight();
    const full = 2 * h - hv;
    const t = Math.tan(THREE.MathUtils.degToRad(FOV / 2));
    this.camera.fov = 2 * THREE.MathUtils.radToDeg(Math.atan((t * full) / h));
    this.camera.aspect = w / full;
    if (hv < h) this.camera.setViewOffset(w, full, 0, h - hv, w, h);
    else this.camera.clearViewOffset();
    this.camera.updateProjectionMatrix();
    this.dirty = true;
  }

  visibleHeight() {
    const h = Math.max(1, this.container.clientHeight);
    return Math.max(h * 0.4, h - this.insetBottom);
  }

  clearInput() {
    this.dirty = true;
    for (const o of [...this.inputGroup.children]) {
      o.geometry.dispose();
      this.inputGroup.remove(o);
    }
    this.inputMesh = this.inputWire = null;
    this.section.inputCap.setGeometry(null);
    this.setOpenEdges(null);
    this.setWitnessFaces(null);
  }

  /** The input shape's opacity, 0 (hidden) to 1 (opaque). */
  setOpacity(x) {
    this.opacity = x;
    this.inputMaterial.opacity = x;
    // Opaque: write depth so the shape hides what is behind it, as a solid does.
    this.inputMaterial.transparent = x < 1;
    this.inputMaterial.depthWrite = x >= 1;
    this.inputMaterial.needsUpdate = true;
    this.updateInputVisibility();
  }

  /** Shows or hides the input (its faces, face edges and section cap) whatever its opacity. */
  setInputVisible(on) {
    this.inputVisible = on;
    this.updateInputVisibility();
  }

  updateInputVisibility() {
    if (this.inputMesh) this.inputMesh.visible = this.inputVisible && this.opacity > 0;
    if (this.inputWire) this.inputWire.visible = this.inputVisible && this.edgesVisible;
    this.section.updateVisibility(this.inputVisible, this.kernelClosed);
    this.dirty = true;
  }

  /** Shows or hides the input's face edges (set with setInputEdges). */
  setEdgesVisible(on) {
    this.edgesVisible = on;
    this.updateInputVisibility();
  }

  // Shows a small input mesh prepared here (samples); big ones come prepared by the draw worker.
  setInput(positions, indices, faceSizes = undefined) {
    this.setInputDrawing(prepareDrawing({ positions, indices, faceSizes: faceSizes ?? null }, { edges: true }));
  }

  /** Shows an input prepared by prepareDrawing(); the kernel is drawn relative to its centre. */
  setInputDrawing(d) {
    this.clearInput();
    this.radius = d.radius;
    this.box = boxOf(d.positions, d.radius);
    this.kernel.offset.set(d.center[0], d.center[1], d.center[2]);
    this.kernel.reset();
    this.kernelPoint.visible = false;
    this.setBall(null);
    this.setBoxFacets(null);
    if (d.drawable) {
      const geo = new THREE.BufferGeometry();
      geo.setAttribute('position', new THREE.BufferAttribute(d.positions, 3));
      geo.setIndex(new THREE.BufferAttribute(d.triangles, 1));
      this.inputMesh = new THREE.Mesh(geo, this.inputMaterial);
      this.inputMesh.renderOrder = 2;
      this.inputMesh.frustumCulled = false; // no bounding sphere to compute over every vertex
      this.inputGroup.add(this.inputMesh);
      this.section.inputCap.setGeometry(geo);
      if (d.edges) this.setInputEdges(d.edges);
    }
    this.updateInputVisibility();
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
    this.inputGroup.add(this.inputWire);
    this.updateInputVisibility();
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

  // Fits the input mesh (or, with kernel = true, the kernel shown so far) into the visible area
  // above the play bar: the camera keeps its direction and moves back until all 8 corners of the
  // bounding box are inside both the horizontal and the vertical field of view (the box holds
  // the shape, so the shape fits; tall and wide shapes alike).
  fit(kernel = false) {
    let box = this.box;
    if (kernel && this.kernel.pointBuf.count > 0)
      box = boxOf(this.kernel.pointBuf.attr.array.subarray(0, 3 * this.kernel.pointBuf.count), this.radius * 1e-4);
    const center = new THREE.Vector3().fromArray(box.lo).add(new THREE.Vector3().fromArray(box.hi)).multiplyScalar(0.5);
    const dir = this.camera.position.clone().sub(this.controls.target);
    if (!kernel || dir.lengthSq() === 0) dir.set(1.0, -1.35, 0.9);
    dir.normalize();
    const up = Math.abs(dir.z) > 0.999 ? new THREE.Vector3(0, 1, 0) : new THREE.Vector3(0, 0, 1);
    const right = new THREE.Vector3().crossVectors(up, dir).normalize();
    const upv = new THREE.Vector3().crossVectors(dir, right);
    const t = Math.tan(THREE.MathUtils.degToRad(FOV / 2));
    const h = Math.max(1, this.container.clientHeight),
      w = Math.max(1, this.container.clientWidth);
    const tanV = (t * this.visibleHeight()) / h,
      tanH = (t * w) / h;
    let dist = 0,
      extent = 0;
    const p = new THREE.Vector3();
    for (let i = 0; i < 8; i++) {
      p.set(i & 1 ? box.hi[0] : box.lo[0], i & 2 ? box.hi[1] : box.lo[1], i & 4 ? box.hi[2] : box.lo[2]).sub(center);
      const z = p.dot(dir);
      dist = Math.max(dist, z + Math.abs(p.dot(right)) / tanH, z + Math.abs(p.dot(upv)) / tanV);
      extent = Math.max(extent, p.length());
    }
    dist = Math.max(dist * 1.04, extent * 1.05); // a small margin; never inside the box
    this.controls.target.copy(center);
    this.camera.position.copy(center).addScaledVector(dir, dist);
    this.camera.near = Math.max(extent / 100, this.radius * 1e-5);
    this.camera.updateProjectionMatrix();
    this.camera.lookAt(center);
    this.controls.update();
    this.dirty = true;
  }

  // The deepest point (a dot) and the largest inscribed ball (translucent, drawn over the kernel
  // that contains it: it is always inside, and an opaque kernel would hide it).
  makeInsideMarkers() {
    // The ball is drawn over the kernel that contains it (an opaque kernel would hide it), faint
    // with green meridians and parallels: a small kernel stays visible through it.
    const sphere = new THREE.SphereGeometry(1, 24, 12);
    this.ball = new THREE.Mesh(
      sphere,
      new THREE.MeshLambertMaterial({
        color: BALL_GREEN,
        transparent: true,
        opacity: 0.25,
        depthTest: false,
        depthWrite: false,
      }),
    );
    this.ball.add(
      new THREE.LineSegments(
        new THREE.WireframeGeometry(new THREE.SphereGeometry(1, 16, 8)),
        new THREE.LineBasicMaterial({ color: BALL_GREEN, depthTest: false, transparent: true, opacity: 0.9 }),
      ),
    );
    this.ball.children[0].renderOrder = 20;
    this.ball.renderOrder = 20;
    const dotGeo = new THREE.BufferGeometry();
    dotGeo.setAttribute('position', new THREE.BufferAttribute(new Float32Array(3), 3));
    this.deepestDot = new THREE.Points(
      dotGeo,
      new THREE.PointsMaterial({ color: 0x0b5a28, size: 9, sizeAttenuation: false, depthTest: false }),
    );
    this.deepestDot.renderOrder = 21;
    this.insideGroup = new THREE.Group();
    this.insideGroup.add(this.ball, this.deepestDot);
    for (const o of [this.ball, this.deepestDot]) o.frustumCulled = false;
    this.insideGroup.visible = false;
    this.ballVisible = true;
    this.scene.add(this.insideGroup);
    // Overlays in the input's frame: open edges, the witness faces of an empty kernel, the box
    // facets of an unbounded one. Drawn over everything: they are what the message is about.
    const overlay = (color, opacity) => ({
      color,
      transparent: true,
      opacity,
      depthTest: false,
      depthWrite: false,
      side: THREE.DoubleSide,
    });
    this.openEdges = new THREE.LineSegments(
      new THREE.BufferGeometry(),
      new THREE.LineBasicMaterial(overlay(OPEN_EDGE_RED, 1)),
    );
    this.witnessFill = new THREE.Mesh(
      new THREE.BufferGeometry(),
      new THREE.MeshBasicMaterial(overlay(WITNESS_MAGENTA, 0.55)),
    );
    this.witnessLines = new THREE.LineSegments(
      new THREE.BufferGeometry(),
      new THREE.LineBasicMaterial(overlay(WITNESS_MAGENTA, 1)),
    );
    this.witnessDots = new THREE.Points(
      new THREE.BufferGeometry(),
      new THREE.PointsMaterial({
        color: WITNESS_MAGENTA,
        size: 12,
        sizeAttenuation: false,
        depthTest: false,
        depthWrite: false,
        transparent: true,
      }),
    );
    this.boxFacets = new THREE.Mesh(
      new THREE.BufferGeometry(),
      new THREE.MeshBasicMaterial({
        color: BOX_FACET_GREY,
        side: THREE.DoubleSide,
        polygonOffset: true,
        polygonOffsetFactor: -1,
        polygonOffsetUnits: -4,
      }),
    );
    for (const o of [this.openEdges, this.witnessFill, this.witnessLines, this.witnessDots, this.boxFacets]) {
      o.frustumCulled = false;
      o.visible = false;
      o.renderOrder = o === this.boxFacets ? 1 : 15;
      this.scene.add(o);
    }
  }

  /** The deepest point and the inscribed ball's radius (null: none). */
  setBall(center, radius = 0) {
    this.insideGroup.visible = !!center && this.ballVisible;
    this.hasBall = !!center;
    if (center) {
      const o = this.kernel.offset;
      const c = [center[0] - o.x, center[1] - o.y, center[2] - o.z];
      this.ball.position.fromArray(c);
      this.ball.scale.setScalar(Math.max(radius, 1e-12));
      this.ball.visible = radius > 0;
      const pos = this.deepestDot.geometry.getAttribute('position');
      pos.array.set([0, 0, 0]);
      pos.needsUpdate = true;
      this.deepestDot.position.fromArray(c);
    }
    this.dirty = true;
  }

  setBallVisible(on) {
    this.ballVisible = on;
    this.insideGroup.visible = on && !!this.hasBall;
    this.dirty = true;
  }

  static setLines(object, positions) {
    object.geometry.dispose();
    object.geometry = new THREE.BufferGeometry();
    if (positions?.length) object.geometry.setAttribute('position', new THREE.BufferAttribute(positions, 3));
    object.visible = !!positions?.length;
  }

  /** The input's open edges (float32 segment ends in the drawn frame; null: none). */
  setOpenEdges(lines) {
    Viewer.setLines(this.openEdges, lines);
    // Caps need a closed surface (section.js).
    this.section.capsAllowed = !lines?.length;
    this.section.updateVisibility(this.inputVisible, this.kernelClosed);
    this.dirty = true;
  }

  /** Input faces to highlight ({ triangles, lines, centers } from draw-prep faceHighlight; null: none). */
  setWitnessFaces(faces) {
    Viewer.setLines(this.witnessFill, faces?.triangles);
    Viewer.setLines(this.witnessLines, faces?.lines);
    Viewer.setLines(this.witnessDots, faces?.centers);
    this.dirty = true;
  }

  /** Kernel facets that are the clip box's (vertex-id loops of `result`; null: none). */
  setBoxFacets(result, facetIds = []) {
    const out = [];
    const o = this.kernel.offset,
      v = result?.vertices;
    for (const f of facetIds) {
      const loop = result.faces[f];
      for (let k = 1; k + 1 < loop.length; k++) {
        for (const id of [loop[0], loop[k], loop[k + 1]])
          out.push(v[3 * id] - o.x, v[3 * id + 1] - o.y, v[3 * id + 2] - o.z);
      }
    }
    Viewer.setLines(this.boxFacets, out.length ? Float32Array.from(out) : null);
    this.dirty = true;
  }

  /**
   * The section plane: `on`, normal `axis` (0, 1, 2), position `at` from 0 (the input box's low
   * side) to 1 (its high side), `clipKernel` whether the kernel is cut too. The part of the
   * scene below the plane is kept.
   */
  setSection({ on, axis, at, clipKernel }) {
    const s = this.section;
    s.enabled = on;
    s.clipKernel = clipKernel;
    const lo = this.box.lo[axis],
      hi = this.box.hi[axis];
    // A hair beyond the box at either end: 0 and 1 cut nothing and everything.
    const span = hi - lo || this.radius;
    s.set(axis, lo - 1e-3 * span + at * (1 + 2e-3) * span, this.radius * 1.5);
    // Materials change (and three.js looks their programs up again) only when what is clipped
    // changes; moving the plane moves the shared THREE.Plane.
    const clipKey = `${on}/${clipKernel}`;
    if (clipKey === this.clipKey) {
      s.updateVisibility(this.inputVisible, this.kernelClosed);
      this.dirty = true;
      return;
    }
    this.clipKey = clipKey;
    this.inputMaterial.clippingPlanes = this.wireMaterial.clippingPlanes = s.planesFor(false);
    // What lies inside the kernel (ball, deepest point, kernel point) is cut with it.
    const kernelMaterials = [
      this.kernel.faces.material,
      this.kernel.lines.material,
      this.kernel.points.material,
      this.boxFacets.material,
      this.ball.material,
      this.ball.children[0].material,
      this.deepestDot.material,
      this.kernelPoint.material,
    ];
    for (const m of kernelMaterials) {
      m.clippingPlanes = s.planesFor(true);
      m.needsUpdate = true;
    }
    this.inputMaterial.needsUpdate = this.wireMaterial.needsUpdate = true;
    s.updateVisibility(this.inputVisible, this.kernelClosed);
    this.dirty = true;
  }

  /** Whether the kernel drawn is a closed solid (its section can be capped). */
  setKernelClosed(closed) {
    this.kernelClosed = closed;
    this.section.kernelCap.setGeometry(closed ? this.kernel.facesGeo : null);
    this.section.updateVisibility(this.inputVisible, this.kernelClosed);
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
