// The 3D view of the volume-mesh page: the cells coloured by a per-cell value, cut by a plane
// (the cells whose centre lies beyond it are hidden) or reduced to the non-star-shaped ones, and
// one selected cell with its kernel, witness faces and inscribed ball.
//
// Only the faces on the boundary of the shown cells are drawn (a face between two shown cells is
// hidden by them): faces are paired across cells by their vertices once per mesh, so a 100k-cell
// mesh draws its outer skin and the cut, not its million inner faces. Polygons are drawn as
// triangle fans (the computation never sees these triangles).
import * as THREE from 'three';
import { OrbitControls } from 'three/examples/jsm/controls/OrbitControls.js';
import { NON_STAR_COLOR } from './cells-colors.js';
import { cellTopology, boundaryFaces } from './cells-geometry.js';

const PENDING_COLOR = [0.8, 0.81, 0.84]; // a cell without a result yet
const KERNEL_BLUE = 0x1e6fff;
const CELL_AMBER = 0xf0a020;
const BALL_GREEN = 0x20b060;

function isSoftwareGL(renderer) {
  const gl = renderer.getContext();
  const info = gl.getExtension('WEBGL_debug_renderer_info');
  const name = String(gl.getParameter(info ? info.UNMASKED_RENDERER_WEBGL : gl.RENDERER));
  return /swiftshader|llvmpipe|softpipe|software/i.test(name);
}

export class CellsView {
  constructor(container) {
    this.container = container;
    this.renderer = new THREE.WebGLRenderer({ antialias: true });
    this.renderer.setPixelRatio(isSoftwareGL(this.renderer) ? 1 : Math.min(window.devicePixelRatio, 2));
    container.appendChild(this.renderer.domElement);
    this.scene = new THREE.Scene();
    // The page's scene colour (style.css --scene-bg), light or dark as the system is.
    const background = () => {
      const css = getComputedStyle(document.documentElement).getPropertyValue('--scene-bg').trim();
      this.scene.background = new THREE.Color(css || '#f3f4f7');
      this.requestRender();
    };
    background();
    window.matchMedia('(prefers-color-scheme: dark)').addEventListener('change', background);
    this.camera = new THREE.PerspectiveCamera(40, 1, 0.01, 100);
    this.camera.up.set(0, 0, 1);
    this.scene.add(this.camera);
    this.scene.add(new THREE.HemisphereLight(0xffffff, 0x667080, 1.7));
    const key = new THREE.DirectionalLight(0xffffff, 1.6);
    key.position.set(0.5, 1, 1.5);
    this.camera.add(key);
    this.controls = new OrbitControls(this.camera, this.renderer.domElement);
    this.controls.addEventListener('change', () => this.requestRender());
    this.cellsMaterial = new THREE.MeshLambertMaterial({ vertexColors: true, side: THREE.DoubleSide });
    this.cells = new THREE.Mesh(new THREE.BufferGeometry(), this.cellsMaterial);
    this.edges = new THREE.LineSegments(
      new THREE.BufferGeometry(),
      new THREE.LineBasicMaterial({ color: 0x202430, transparent: true, opacity: 0.35 }),
    );
    this.selection = new THREE.Group();
    this.scene.add(this.cells, this.edges, this.selection);
    this.mesh = null;
    this.colors = null;
    this.filter = { axis: 2, cut: 1, onlyNonStar: false };
    this.raycaster = new THREE.Raycaster();
    new ResizeObserver(() => this.resize()).observe(container);
    this.resize();
  }

  resize() {
    const w = Math.max(1, this.container.clientWidth),
      h = Math.max(1, this.container.clientHeight);
    this.renderer.setSize(w, h, false);
    this.camera.aspect = w / h;
    this.camera.updateProjectionMatrix();
    this.requestRender();
  }

  requestRender() {
    if (this.frame) return;
    this.frame = requestAnimationFrame(() => {
      this.frame = 0;
      const t0 = performance.now();
      this.renderer.render(this.scene, this.camera);
      this.renderMs = performance.now() - t0; // the last frame's submit time (for the benchmark)
    });
  }

  /**
   * A new mesh (readVolumeMesh's arrays) with its cellTopology (computed here when not given):
   * every cell pending until setColors.
   */
  setMesh(mesh, topology = cellTopology(mesh)) {
    this.clearCell();
    this.mesh = mesh;
    this.topology = topology;
    this.numCells = this.topology.numCells;
    this.centres = this.topology.centres;
    this.box = new THREE.Box3().setFromArray(mesh.positions);
    this.origin = this.box.getCenter(new THREE.Vector3()); // drawn in float32 around the centre
    this.colors = new Float32Array(3 * this.numCells);
    for (let c = 0; c < this.numCells; c++) this.colors.set(PENDING_COLOR, 3 * c);
    this.isNonStar = null;
    this.rebuild();
    this.fit();
  }

  /** The cells' colours ([r, g, b] per cell from colorOf(c)) and which are not star-shaped. */
  setColors(colorOf, isNonStar) {
    for (let c = 0; c < this.numCells; c++) this.colors.set(colorOf(c), 3 * c);
    this.isNonStar = isNonStar;
    this.rebuild();
  }

  /** Which cells are shown: centre ≤ cut along axis (0..2; cut in 0..1 of the box), or only non-star cells. */
  setFilter(filter) {
    this.filter = { ...this.filter, ...filter };
    this.rebuild();
  }

  shownCells() {
    const { axis, cut, onlyNonStar } = this.filter;
    const lo = this.box.min.getComponent(axis),
      hi = this.box.max.getComponent(axis);
    const limit = lo + cut * (hi - lo) + 1e-9 * (hi - lo);
    const shown = new Uint8Array(this.numCells);
    for (let c = 0; c < this.numCells; c++) {
      if (onlyNonStar) shown[c] = this.isNonStar && this.isNonStar(c) ? 1 : 0;
      else shown[c] = this.centres[3 * c + axis] <= limit ? 1 : 0;
    }
    return shown;
  }

  // The geometry of the faces between a shown cell and a hidden one (or the outside).
  rebuild() {
    if (!this.mesh) return;
    const t0 = performance.now();
    const o = this.origin;
    const { positions, colors, triCell, lines } = boundaryFaces(
      this.mesh,
      this.topology,
      this.shownCells(),
      this.colors,
      [o.x, o.y, o.z],
    );
    const g = new THREE.BufferGeometry();
    g.setAttribute('position', new THREE.BufferAttribute(positions, 3));
    g.setAttribute('color', new THREE.BufferAttribute(colors, 3));
    g.computeVertexNormals();
    this.cells.geometry.dispose();
    this.cells.geometry = g;
    this.triCell = triCell;
    const e = new THREE.BufferGeometry();
    e.setAttribute('position', new THREE.BufferAttribute(lines, 3));
    this.edges.geometry.dispose();
    this.edges.geometry = e;
    this.drawnTriangles = triCell.length;
    this.rebuildMs = performance.now() - t0; // (for the benchmark)
    this.requestRender();
  }

  fit() {
    const sphere = this.box.getBoundingSphere(new THREE.Sphere());
    const r = Math.max(sphere.radius, 1e-9);
    const d = r / Math.sin(((this.camera.fov / 2) * Math.PI) / 180);
    this.camera.position
      .set(0.9 * d, -1.3 * d, 0.8 * d)
      .normalize()
      .multiplyScalar(d * 1.05);
    this.camera.near = d / 100;
    this.camera.far = d * 10;
    this.camera.updateProjectionMatrix();
    this.controls.target.set(0, 0, 0);
    this.controls.update();
    this.requestRender();
  }

  /** The cell drawn at the canvas point (clientX, clientY), or -1. */
  pick(clientX, clientY) {
    const rect = this.renderer.domElement.getBoundingClientRect();
    const ndc = new THREE.Vector2(
      ((clientX - rect.left) / rect.width) * 2 - 1,
      -((clientY - rect.top) / rect.height) * 2 + 1,
    );
    this.raycaster.setFromCamera(ndc, this.camera);
    const hit = this.raycaster.intersectObject(this.cells, false)[0];
    return hit ? this.triCell[hit.faceIndex] : -1;
  }

  /** The canvas point where cell `c` is drawn (its first drawn triangle's centre), or null. */
  screenPointOf(c) {
    const t = this.triCell ? this.triCell.indexOf(c) : -1;
    if (t < 0) return null;
    const p = this.cells.geometry.getAttribute('position');
    const v = new THREE.Vector3();
    for (let k = 0; k < 3; k++) v.add(new THREE.Vector3().fromBufferAttribute(p, 3 * t + k));
    v.multiplyScalar(1 / 3).project(this.camera);
    const rect = this.renderer.domElement.getBoundingClientRect();
    return { x: rect.left + ((v.x + 1) / 2) * rect.width, y: rect.top + ((1 - v.y) / 2) * rect.height };
  }

  /**
   * Shows one cell: its surface (cellSurface's arrays: translucent), its kernel (computeKernel's
   * result: blue), the witness faces (indices into the surface's faces: magenta) and the
   * inscribed ball; the other cells are dimmed.
   */
  showCell(surface, kernel) {
    this.clearCell();
    const o = this.origin;
    const shift = (arr) => {
      const out = new Float32Array(arr.length);
      for (let i = 0; i < arr.length; i += 3) {
        out[i] = arr[i] - o.x;
        out[i + 1] = arr[i + 1] - o.y;
        out[i + 2] = arr[i + 2] - o.z;
      }
      return out;
    };
    const loops = [];
    for (let f = 0, at = 0; f < surface.faceSizes.length; at += surface.faceSizes[f++])
      loops.push(surface.indices.subarray(at, at + surface.faceSizes[f]));
    const fan = (faces) => {
      const idx = [];
      for (const l of faces) for (let k = 1; k + 1 < l.length; k++) idx.push(l[0], l[k], l[k + 1]);
      return idx;
    };
    const cellPos = new THREE.Float32BufferAttribute(shift(surface.positions), 3);
    const part = (indices, material) => {
      const g = new THREE.BufferGeometry();
      g.setAttribute('position', cellPos);
      g.setIndex(indices);
      g.computeVertexNormals();
      return new THREE.Mesh(g, material);
    };
    const cell = part(
      fan(loops),
      new THREE.MeshLambertMaterial({
        color: CELL_AMBER,
        transparent: true,
        opacity: 0.28,
        side: THREE.DoubleSide,
        depthWrite: false,
      }),
    );
    const edgeIdx = [];
    for (const l of loops) for (let k = 0; k < l.length; k++) edgeIdx.push(l[k], l[(k + 1) % l.length]);
    const g = new THREE.BufferGeometry();
    g.setAttribute('position', cellPos);
    g.setIndex(edgeIdx);
    const cellEdges = new THREE.LineSegments(g, new THREE.LineBasicMaterial({ color: 0x8a5a00 }));
    this.selection.add(cell, cellEdges);
    const witness = [...kernel.witnessFaces].map((f) => loops[f]);
    if (witness.length) {
      this.selection.add(
        part(
          fan(witness),
          new THREE.MeshLambertMaterial({ color: new THREE.Color(...NON_STAR_COLOR), side: THREE.DoubleSide }),
        ),
      );
    }
    if (kernel.triangles.length) {
      const kg = new THREE.BufferGeometry();
      kg.setAttribute('position', new THREE.Float32BufferAttribute(shift(kernel.vertices), 3));
      kg.setIndex(new THREE.Uint32BufferAttribute(kernel.triangles, 1));
      kg.computeVertexNormals();
      // Translucent, so that the inscribed ball inside it shows through.
      const material = new THREE.MeshLambertMaterial({
        color: KERNEL_BLUE,
        side: THREE.DoubleSide,
        transparent: true,
        opacity: 0.6,
        depthWrite: false,
      });
      this.selection.add(new THREE.Mesh(kg, material));
    }
    if (kernel.deepestPoint && kernel.inscribedRadius > 0) {
      const ball = new THREE.Mesh(
        new THREE.SphereGeometry(kernel.inscribedRadius, 24, 16),
        new THREE.MeshLambertMaterial({ color: BALL_GREEN }),
      );
      ball.position.set(kernel.deepestPoint[0] - o.x, kernel.deepestPoint[1] - o.y, kernel.deepestPoint[2] - o.z);
      this.selection.add(ball);
    }
    this.cellsMaterial.transparent = true;
    this.cellsMaterial.opacity = 0.12;
    this.cellsMaterial.depthWrite = false;
    this.edges.material.opacity = 0.08;
    this.cellsMaterial.needsUpdate = true;
    this.requestRender();
  }

  clearCell() {
    for (const child of [...this.selection.children]) {
      this.selection.remove(child);
      child.geometry.dispose();
      child.material.dispose();
    }
    this.cellsMaterial.transparent = false;
    this.cellsMaterial.opacity = 1;
    this.cellsMaterial.depthWrite = true;
    this.cellsMaterial.needsUpdate = true;
    this.edges.material.opacity = 0.35;
    this.requestRender();
  }
}
