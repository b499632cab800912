// three.js scene: the input mesh (semi-transparent, with its faces' edges when asked), the
// kernel (kernel-view.js: drawn from the stream of step events so any prefix of the stream can be
// shown), the inscribed ball and overlays (overlays.js), the section plane (section.js) and the
// camera (camera-fit.js). The input arrives prepared (draw-prep.js: float32, centred,
// triangulated), so showing a million-triangle mesh costs this thread only the GPU upload.

import * as THREE from 'three';
import { OrbitControls } from 'three/examples/jsm/controls/OrbitControls.js';
import { prepareDrawing } from './draw-prep.js';
import { SectionPlane } from './section.js';
import { KernelView } from './kernel-view.js';
import { Overlays } from './overlays.js';
import { FOV, boxOf, fitBox } from './camera-fit.js';
import { warmUpPipelines } from './warm-up.js';

export { KERNEL_BLUE } from './kernel-view.js';

function cssColor(name, fallback) {
  const v = getComputedStyle(document.documentElement).getPropertyValue(name).trim();
  return v || fallback;
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
    this.overlays = new Overlays(this.scene, this.kernel.offset);
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

  // Draws one frame with every material at page load: compiling a shader and, with software
  // The pipelines of every material and vertex layout, built before the first mesh (warm-up.js).
  warmUp() {
    warmUpPipelines(this);
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
    // A simplified copy of a big input (draw-prep.js simplify) is shaded smoothly, with normals
    // from the original surface: facet shading of its irregular triangles looked like shards.
    this.smoothInputMaterial = this.inputMaterial.clone();
    this.smoothInputMaterial.flatShading = false;
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
    this.setWitnessEdges(null);
    this.setSourceFace(null);
  }

  /** The input shape's opacity, 0 (hidden) to 1 (opaque). */
  setOpacity(x) {
    this.opacity = x;
    for (const m of [this.inputMaterial, this.smoothInputMaterial]) {
      m.opacity = x;
      // Opaque: write depth so the shape hides what is behind it, as a solid does.
      m.transparent = x < 1;
      m.depthWrite = x >= 1;
      m.needsUpdate = true;
    }
    this.updateInputVisibility();
  }

  /** Shows or hides the input (its faces, face edges and section cap) whatever its opacity. */
  setInputVisible(on) {
    this.inputVisible = on;
    this.updateInputVisibility();
  }

  updateInputVisibility() {
    if (this.inputMesh) this.inputMesh.visible = this.inputVisible && this.opacity > 0;
    // Opacity 0 hides the shape: its face edges too.
    if (this.inputWire) this.inputWire.visible = this.inputVisible && this.edgesVisible && this.opacity > 0;
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
      if (d.normals) geo.setAttribute('normal', new THREE.BufferAttribute(d.normals, 3));
      this.inputMesh = new THREE.Mesh(geo, d.normals ? this.smoothInputMaterial : this.inputMaterial);
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
    fitBox(this.camera, this.controls, box, {
      width: Math.max(1, this.container.clientWidth),
      height: Math.max(1, this.container.clientHeight),
      visibleHeight: this.visibleHeight(),
      keepDirection: kernel,
      radius: this.radius,
    });
    this.dirty = true;
  }

  /** The deepest point and the inscribed ball's radius (null: none); see Overlays.setBall. */
  setBall(center, radius = 0, kernelVolume = 0) {
    this.overlays.setBall(center, radius, kernelVolume);
    this.dirty = true;
  }

  /** The ball is drawn once the kernel is complete on screen (not while it grows). */
  setBallComplete(on) {
    if (this.overlays.setBallComplete(on)) this.dirty = true;
  }

  /** See Overlays.setWitnessEdges. */
  setWitnessEdges(lines, mids = null) {
    this.overlays.setWitnessEdges(lines, mids);
    this.dirty = true;
  }

  /** See Overlays.setSourceFace. */
  setSourceFace(faces, outline = null) {
    this.overlays.setSourceFace(faces, outline);
    this.dirty = true;
  }

  setBallVisible(on) {
    this.overlays.setBallVisible(on);
    this.dirty = true;
  }

  /** The input's open edges (float32 segment ends in the drawn frame; null: none). */
  setOpenEdges(lines) {
    this.overlays.setOpenEdges(lines);
    // Caps need a closed surface (section.js).
    this.section.capsAllowed = !lines?.length;
    this.section.updateVisibility(this.inputVisible, this.kernelClosed);
    this.dirty = true;
  }

  /** Input faces to highlight ({ triangles, lines, centers } from draw-prep faceHighlight; null: none). */
  setWitnessFaces(faces) {
    this.overlays.setWitnessFaces(faces);
    this.dirty = true;
  }

  /** Kernel facets that are the clip box's (vertex-id loops of `result`; null: none). */
  setBoxFacets(result, facetIds = []) {
    this.overlays.setBoxFacets(result, facetIds);
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
    this.inputMaterial.clippingPlanes = this.smoothInputMaterial.clippingPlanes = s.planesFor(false);
    this.wireMaterial.clippingPlanes = s.planesFor(false);
    // What lies inside the kernel (ball, deepest point, kernel point) is cut with it.
    const kernelMaterials = [
      this.kernel.faces.material,
      this.kernel.lines.material,
      this.kernel.points.material,
      ...this.overlays.kernelMaterials(),
      this.kernelPoint.material,
    ];
    for (const m of kernelMaterials) {
      m.clippingPlanes = s.planesFor(true);
      m.needsUpdate = true;
    }
    this.inputMaterial.needsUpdate = this.smoothInputMaterial.needsUpdate = this.wireMaterial.needsUpdate = true;
    s.updateVisibility(this.inputVisible, this.kernelClosed);
    this.dirty = true;
  }

  /** Whether the kernel drawn is a closed solid (its section can be capped). */
  setKernelClosed(closed) {
    this.kernelClosed = closed;
    this.section.kernelCap.setGeometry(closed ? this.kernel.surfaceGeometry : null);
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
    this.overlays.updateRing(this.camera);
    this.renderer.render(this.scene, this.camera);
    const t = performance.now();
    this.renderMs = this.renderMs ? 0.8 * this.renderMs + 0.2 * (t - now) : t - now;
    this.lastRender = t;
    this.dirty = this.kernel.dirty = false;
  }
}
