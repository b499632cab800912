// What the view draws besides the input and the kernel: the deepest point and the inscribed
// ball, and the overlays in the input's frame (open edges, the witness faces of an empty kernel,
// the box facets of an unbounded one). Positions are relative to `offset` (the drawn input's
// centre, shared with the kernel view).

import * as THREE from 'three';

const BALL_GREEN = 0x17a34a;
const OPEN_EDGE_RED = 0xe8141c;
const WITNESS_MAGENTA = 0xd4168f;
const BOX_FACET_GREY = 0xa9adb8;

// Replaces `object`'s geometry by float32 xyz `positions` (hidden when there are none).
function setPositions(object, positions) {
  object.geometry.dispose();
  object.geometry = new THREE.BufferGeometry();
  if (positions?.length) object.geometry.setAttribute('position', new THREE.BufferAttribute(positions, 3));
  object.visible = !!positions?.length;
}

export class Overlays {
  constructor(scene, offset) {
    this.offset = offset;
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
    scene.add(this.insideGroup);
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
      scene.add(o);
    }
  }

  /** The materials of what lies inside the kernel: cut with it by the section plane. */
  kernelMaterials() {
    return [this.boxFacets.material, this.ball.material, this.ball.children[0].material, this.deepestDot.material];
  }

  /** The deepest point and the inscribed ball's radius (null: none). */
  setBall(center, radius = 0) {
    this.insideGroup.visible = !!center && this.ballVisible;
    this.hasBall = !!center;
    if (center) {
      const o = this.offset;
      const c = [center[0] - o.x, center[1] - o.y, center[2] - o.z];
      this.ball.position.fromArray(c);
      this.ball.scale.setScalar(Math.max(radius, 1e-12));
      this.ball.visible = radius > 0;
      const pos = this.deepestDot.geometry.getAttribute('position');
      pos.array.set([0, 0, 0]);
      pos.needsUpdate = true;
      this.deepestDot.position.fromArray(c);
    }
  }

  setBallVisible(on) {
    this.ballVisible = on;
    this.insideGroup.visible = on && !!this.hasBall;
  }

  /** The input's open edges (float32 segment ends in the drawn frame; null: none). */
  setOpenEdges(lines) {
    setPositions(this.openEdges, lines);
  }

  /** Input faces to highlight ({ triangles, lines, centers } from draw-prep faceHighlight; null: none). */
  setWitnessFaces(faces) {
    setPositions(this.witnessFill, faces?.triangles);
    setPositions(this.witnessLines, faces?.lines);
    setPositions(this.witnessDots, faces?.centers);
  }

  /** Kernel facets that are the clip box's (vertex-id loops of `result`; null: none). */
  setBoxFacets(result, facetIds = []) {
    const out = [];
    const o = this.offset,
      v = result?.vertices;
    for (const f of facetIds) {
      const loop = result.faces[f];
      for (let k = 1; k + 1 < loop.length; k++) {
        for (const id of [loop[0], loop[k], loop[k + 1]])
          out.push(v[3 * id] - o.x, v[3 * id + 1] - o.y, v[3 * id + 2] - o.z);
      }
    }
    setPositions(this.boxFacets, out.length ? Float32Array.from(out) : null);
  }
}
