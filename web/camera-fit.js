// The camera's framing: a bounding box fitted into the part of the canvas above the play bar.

import * as THREE from 'three';

// Vertical field of view of the whole canvas (the visible area above the play bar gets its share).
export const FOV = 40;

// The bounding box of float xyz positions ({ lo, hi }), at least `minSize` across.
export function boxOf(positions, minSize) {
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

/**
 * Moves `camera` (and the orbit `controls`' target) so that `box` fits the view: all 8 corners
 * inside both the horizontal and the vertical field of view of the `visibleHeight` top pixels of
 * a `width` × `height` canvas. The camera keeps its direction when `keepDirection` (else the
 * default one). `radius`: the input's size, a floor for the near plane.
 */
export function fitBox(camera, controls, box, { width, height, visibleHeight, keepDirection, radius }) {
  const center = new THREE.Vector3().fromArray(box.lo).add(new THREE.Vector3().fromArray(box.hi)).multiplyScalar(0.5);
  const dir = camera.position.clone().sub(controls.target);
  if (!keepDirection || dir.lengthSq() === 0) dir.set(1.0, -1.35, 0.9);
  dir.normalize();
  const up = Math.abs(dir.z) > 0.999 ? new THREE.Vector3(0, 1, 0) : new THREE.Vector3(0, 0, 1);
  const right = new THREE.Vector3().crossVectors(up, dir).normalize();
  const upv = new THREE.Vector3().crossVectors(dir, right);
  const t = Math.tan(THREE.MathUtils.degToRad(FOV / 2));
  const tanV = (t * visibleHeight) / height,
    tanH = (t * width) / height;
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
  controls.target.copy(center);
  camera.position.copy(center).addScaledVector(dir, dist);
  camera.near = Math.max(extent / 100, radius * 1e-5);
  camera.updateProjectionMatrix();
  camera.lookAt(center);
  controls.update();
}
