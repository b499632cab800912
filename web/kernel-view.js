// The kernel as a timeline of step events (KernelView): any prefix of the stream can be drawn
// (the scrubber) by setting draw ranges over growable typed arrays.

import * as THREE from 'three';

export const KERNEL_BLUE = 0x1e6fff;
const KERNEL_EDGE = 0x0a2f80;
const FRONT_COLOR = 0xffb000;

// A growable Float32 attribute (xyz) shared by several geometries, whose draw ranges are set
// separately. Only the items added since the last frame are uploaded (upload()): re-sending a
// kernel of a million elements every frame would cost more than drawing it.
class GrowableBuffer {
  constructor(geometries, name = 'position', itemSize = 3) {
    this.geometries = geometries;
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
    for (const g of this.geometries) g.setAttribute(this.name, this.attr);
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

// A growable index (Uint32) of one geometry, uploaded as GrowableBuffer is: edges and faces index
// the kernel's vertices, so each vertex is stored, uploaded and transformed once (a triangle soup
// repeated every vertex ~6 times).
class GrowableIndex {
  constructor(geometry) {
    this.geometry = geometry;
    this.count = 0;
    this.alloc(1024);
  }
  alloc(n) {
    const array = new Uint32Array(n);
    if (this.attr) array.set(this.attr.array.subarray(0, this.count));
    this.attr = new THREE.BufferAttribute(array, 1);
    this.attr.setUsage(THREE.DynamicDrawUsage);
    this.geometry.setIndex(this.attr);
    this.uploaded = this.count;
  }
  push(i) {
    if (this.count === this.attr.array.length) this.alloc(2 * this.count);
    this.attr.array[this.count++] = i;
  }
  upload() {
    if (this.count === this.uploaded) return;
    this.attr.addUpdateRange(this.uploaded, this.count - this.uploaded);
    this.attr.needsUpdate = true;
    this.uploaded = this.count;
  }
  reset() {
    this.count = 0;
    this.alloc(1024);
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
    this.pointBuf = new GrowableBuffer([this.pointsGeo, this.linesGeo, this.facesGeo]);
    this.lineIndex = new GrowableIndex(this.linesGeo);
    this.faceIndex = new GrowableIndex(this.facesGeo);
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
    // A big complete kernel is drawn from a simplified copy (setSimplified): software WebGL pays
    // per triangle, and 600k triangles took ~280 ms a frame where most cover less than a pixel.
    this.simpleGeo = new THREE.BufferGeometry();
    this.simple = new THREE.Mesh(this.simpleGeo, this.faces.material);
    this.simple.visible = false;
    for (const o of [this.faces, this.simple, this.lines, this.points, this.front, this.frontPoint]) {
      o.frustumCulled = false;
      this.group.add(o);
    }
    this.offset = new THREE.Vector3();
    this.dirty = true;
    this.reset();
  }

  reset() {
    this.kinds = new GrowableArray(Uint8Array);
    // After k events: points, line indices, face-triangle indices, faces (4 numbers per k).
    this.prefix = new GrowableArray(Uint32Array);
    for (let i = 0; i < 4; i++) this.prefix.push(0);
    this.slot = []; // vertex id → its point index
    this.triFace = new GrowableArray(Uint32Array); // drawn triangle → its kernel face id (picking)
    this.nFaces = 0;
    this.pointBuf.reset();
    this.lineIndex.reset();
    this.faceIndex.reset();
    this.setSimplified(null);
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
      this.lineIndex.push(a);
      this.lineIndex.push(b);
    } else if (kind === KIND.face) {
      const loop = ev.loop,
        slot = this.slot;
      if (loop.length < 3) return false;
      for (let k = 0; k < loop.length; k++) if (slot[loop[k]] === undefined) return false;
      // A fan: the kernel's faces are convex polygons.
      for (let k = 1; k + 1 < loop.length; k++) {
        this.triFace.push(ev.id);
        this.faceIndex.push(slot[loop[0]]);
        this.faceIndex.push(slot[loop[k]]);
        this.faceIndex.push(slot[loop[k + 1]]);
      }
      this.nFaces++;
    } else {
      return false;
    }
    this.kinds.push(kind);
    this.prefix.push(this.pointBuf.count);
    this.prefix.push(this.lineIndex.count);
    this.prefix.push(this.faceIndex.count);
    this.prefix.push(this.nFaces);
    return true;
  }

  /** The kernel face id of drawn triangle `t` (a raycast's faceIndex on `faces`). */
  faceOfTriangle(t) {
    return t < this.triFace.length ? this.triFace.array[t] : -1;
  }

  /**
   * A simplified copy of the complete kernel's faces (float32 positions in the kernel's frame,
   * triangles), drawn instead of them once every event is shown; null: none.
   */
  setSimplified(positions, triangles) {
    this.simpleGeo.dispose();
    this.simpleGeo = new THREE.BufferGeometry();
    if (positions) {
      this.simpleGeo.setAttribute('position', new THREE.BufferAttribute(positions, 3));
      this.simpleGeo.setIndex(new THREE.BufferAttribute(triangles, 1));
    }
    this.simple.geometry = this.simpleGeo;
    this.hasSimplified = !!positions;
    this.shown = -1; // show() picks the copy or the faces again
    this.dirty = true;
  }

  /** The geometry the complete kernel's faces are drawn with (the section cap counts it). */
  get surfaceGeometry() {
    return this.hasSimplified ? this.simpleGeo : this.facesGeo;
  }

  countsAt(k) {
    const p = this.prefix.array;
    return { vertices: p[4 * k], edges: p[4 * k + 1] / 2, faces: p[4 * k + 3] };
  }

  // Draws the state after the first k events; returns the partial counts.
  show(k) {
    k = Math.max(0, Math.min(this.length, Math.floor(k)));
    for (const b of [this.pointBuf, this.lineIndex, this.faceIndex]) b.upload();
    if (k !== this.shown) {
      const p = this.prefix.array;
      // Big kernels: vertex dots and edge lines only while there are few enough to read (and
      // to draw: software WebGL pays for every primitive); the faces show the shape.
      this.points.visible = p[4 * k] <= BIG_KERNEL_VERTICES;
      this.lines.visible = p[4 * k + 1] / 2 <= BIG_KERNEL_EDGES;
      this.pointsGeo.setDrawRange(0, p[4 * k]);
      this.linesGeo.setDrawRange(0, p[4 * k + 1]);
      this.facesGeo.setDrawRange(0, p[4 * k + 2]);
      const whole = this.hasSimplified && k === this.length;
      this.faces.visible = !whole;
      this.simple.visible = whole;
      // Highlight the newest element: the last edge, or the last vertex.
      const pos = this.frontGeo.getAttribute('position');
      const kind = k > 0 ? this.kinds.array[k - 1] : 0;
      let n = 0;
      if (kind === KIND.edge) {
        const e = p[4 * k + 1] - 2;
        pos.array.set(this.pointAt(this.lineIndex.attr.array[e]), 0);
        pos.array.set(this.pointAt(this.lineIndex.attr.array[e + 1]), 3);
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
