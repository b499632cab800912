// The viewer's first frame, drawn before any mesh: every material of the scene with every vertex
// layout the page draws it with, so that WebGL builds its pipelines now (viewer.js).

import * as THREE from 'three';

// WebGL, generating its pipeline on first use cost a few hundred ms, which would otherwise fall
// in the middle of a file's computation. A pipeline is built per material *and* vertex layout
// (attributes, index type), so each material is drawn with the layouts the page draws it with:
// position only (the kernel's indexed faces and edges, the flat-shaded input, overlays without
// an index), position + normal (the smoothly shaded simplified input), and the ball's own
// sphere (16-bit index).
export function warmUpPipelines(viewer) {
  // A 100 × 100 grid (20k triangles) filling the view in front of the camera (at the origin,
  // looking down -z until the first fit()): software rasterizers build their pixel stage and
  // start their threads only when fragments are drawn, and a drawing of this size is what a
  // big input costs.
  const grid = new THREE.PlaneGeometry(2, 2, 100, 100);
  grid.translate(0, 0, -1);
  grid.setIndex(new THREE.BufferAttribute(Uint32Array.from(grid.index.array), 1));
  // The other layouts on a coarse grid covering the same pixels (what builds a pipeline is
  // drawing fragments, not the triangle count).
  const coarse = new THREE.PlaneGeometry(2, 2, 4, 4);
  coarse.translate(0, 0, -1);
  const index = new THREE.BufferAttribute(Uint32Array.from(coarse.index.array), 1);
  const layout = (names, indexed) => {
    const g = new THREE.BufferGeometry();
    for (const n of names) g.setAttribute(n, coarse.getAttribute(n));
    if (indexed) g.setIndex(index);
    return g;
  };
  const layouts = [grid, layout(['position'], true), layout(['position'], false), layout(['position', 'normal'], true)];
  const dummies = [];
  const add = (o) => {
    const Kind = o.isMesh ? THREE.Mesh : o.isLineSegments ? THREE.LineSegments : o.isPoints ? THREE.Points : null;
    if (!Kind) return;
    for (const geo of layouts) {
      const dummy = new Kind(geo, o.material);
      dummy.renderOrder = o.renderOrder;
      dummies.push(dummy);
    }
  };
  add(new THREE.Mesh(grid, viewer.inputMaterial));
  add(new THREE.Mesh(grid, viewer.smoothInputMaterial));
  add(new THREE.LineSegments(grid, viewer.wireMaterial));
  viewer.scene.traverse((o) => add(o));
  viewer.inputGroup.add(...dummies);
  // Hidden objects (the ball, overlays) are drawn once too, with their own geometry.
  const hidden = [];
  viewer.scene.traverse((o) => {
    if (!o.visible) hidden.push(o);
  });
  for (const o of hidden) o.visible = true;
  viewer.renderer.render(viewer.scene, viewer.camera);
  for (const o of hidden) o.visible = false;
  viewer.inputGroup.remove(...dummies);
  for (const g of [...layouts, coarse]) g.dispose();
  viewer.dirty = true;
}
