// Hovering (or tapping) a kernel face says what bounds it: the input face whose plane it lies on
// (highlighted in cyan, the kernel face outlined), the clipping box of an unbounded kernel, or a
// wall at a boundary edge (result.faceSources; face-sources.js). Nothing happens with a result
// that has no faceSources (an older package).

import * as THREE from 'three';
import { faceHighlight } from './draw-prep.js';
import { faceSourceInWords } from './face-sources.js';
import { state, ui, viewer } from './page-state.js';
import { drawRequest } from './workers.js';

const raycaster = new THREE.Raycaster();
let shownFace = -1;
let pending = null; // the latest pointer position, picked at the next animation frame

/** The kernel face under client point (x, y), or -1. */
export function kernelFaceAt(x, y) {
  const canvas = viewer.renderer.domElement;
  const rect = canvas.getBoundingClientRect();
  const ndc = new THREE.Vector2(((x - rect.left) / rect.width) * 2 - 1, -((y - rect.top) / rect.height) * 2 + 1);
  raycaster.setFromCamera(ndc, viewer.camera);
  // The raycast first tests the geometry's bounding sphere, which three.js computes once: the
  // kernel's arrays grow and are replaced, so it is recomputed when the faces changed.
  const geo = viewer.kernel.facesGeo;
  const attr = geo.getAttribute('position'),
    count = viewer.kernel.faceIndex.count;
  if (geo.userData.sphereOf !== attr || geo.userData.sphereCount !== count) {
    geo.computeBoundingSphere();
    Object.assign(geo.userData, { sphereOf: attr, sphereCount: count });
  }
  const hit = raycaster.intersectObject(viewer.kernel.faces, false)[0];
  return hit ? viewer.kernel.faceOfTriangle(hit.faceIndex) : -1;
}

// The kernel face's outline (float32 segments in the drawn frame).
function faceOutline(result, f) {
  const loop = result.faces[f],
    v = result.vertices,
    o = viewer.kernel.offset;
  const out = new Float32Array(6 * loop.length);
  for (let i = 0; i < loop.length; i++) {
    const a = loop[i],
      b = loop[(i + 1) % loop.length];
    out.set([v[3 * a] - o.x, v[3 * a + 1] - o.y, v[3 * a + 2] - o.z], 6 * i);
    out.set([v[3 * b] - o.x, v[3 * b + 1] - o.y, v[3 * b + 2] - o.z], 6 * i + 3);
  }
  return out;
}

/** Shows what bounds kernel face `f` of the current result (-1: nothing). */
export async function showFaceSource(f) {
  const result = state.result;
  const info = f >= 0 && result ? faceSourceInWords(result, f) : null;
  if (f === shownFace && info) return;
  shownFace = info ? f : -1;
  ui.faceInfo.hidden = !info;
  ui.faceInfo.textContent = info?.text ?? '';
  ui.faceInfo.dataset.face = info ? String(f) : '';
  ui.faceInfo.dataset.source = info ? String(result.faceSources[f]) : '';
  if (!info) {
    viewer.setSourceFace(null);
    return;
  }
  const token = state.token;
  let faces = null;
  if (info.input >= 0) {
    const center = state.drawing?.center ?? [0, 0, 0];
    faces = state.mesh
      ? faceHighlight(state.mesh, [info.input], center)
      : await drawRequest({ type: 'faces', faces: [info.input] });
  }
  if (token !== state.token || shownFace !== f) return;
  viewer.setSourceFace(faces?.triangles ? faces : null, faceOutline(result, f));
}

/** Hover and tap on the view; cleared with each new run (state.token changes). */
export function installFaceInfo() {
  const canvas = viewer.renderer.domElement;
  const pick = () => {
    const p = pending;
    pending = null;
    if (!p || !state.result?.faceSources) return;
    showFaceSource(kernelFaceAt(p.x, p.y));
  };
  canvas.addEventListener('pointermove', (e) => {
    // Not while orbiting (a button held), nor for touch (a tap picks: click below).
    if (e.buttons || e.pointerType === 'touch' || !state.result?.faceSources) return;
    if (!pending) requestAnimationFrame(pick);
    pending = { x: e.clientX, y: e.clientY };
  });
  canvas.addEventListener('click', (e) => {
    if (!state.result?.faceSources) return;
    pending = { x: e.clientX, y: e.clientY };
    pick();
  });
  canvas.addEventListener('pointerleave', (e) => {
    if (e.pointerType !== 'touch' && shownFace >= 0) showFaceSource(-1);
  });
}

/** Forgets the shown face (a new run). */
export function clearFaceInfo() {
  shownFace = -1;
  ui.faceInfo.hidden = true;
  ui.faceInfo.textContent = '';
  viewer.setSourceFace(null);
}
