// A section plane: clips the input (and, when asked, the kernel) with three.js clipping planes
// and closes each cut solid with a cap drawn through the stencil buffer (as in three.js's
// webgl_clipping_stencil example). For each solid, its back faces add one and its front faces
// subtract one in the stencil buffer, clipped by the plane and without depth test: where a view
// ray enters the cut solid's inside the count is non-zero, and a quad in the plane is coloured
// there (and resets the count to zero for the next solid). This needs a closed surface: an open
// mesh would leave stray caps, so the page turns caps off for open meshes.
import * as THREE from 'three';

// Materials of the two counting passes (one per solid: they share nothing but the plane).
function stencilPassMaterials(plane) {
  const base = {
    depthWrite: false,
    depthTest: false,
    colorWrite: false,
    stencilWrite: true,
    stencilFunc: THREE.AlwaysStencilFunc,
    clippingPlanes: [plane],
  };
  const back = new THREE.MeshBasicMaterial({
    ...base,
    side: THREE.BackSide,
    stencilFail: THREE.IncrementWrapStencilOp,
    stencilZFail: THREE.IncrementWrapStencilOp,
    stencilZPass: THREE.IncrementWrapStencilOp,
  });
  const front = new THREE.MeshBasicMaterial({
    ...base,
    side: THREE.FrontSide,
    stencilFail: THREE.DecrementWrapStencilOp,
    stencilZFail: THREE.DecrementWrapStencilOp,
    stencilZPass: THREE.DecrementWrapStencilOp,
  });
  return [back, front];
}

function capMaterial(color) {
  return new THREE.MeshLambertMaterial({
    color,
    side: THREE.DoubleSide,
    stencilWrite: true,
    stencilRef: 0,
    stencilFunc: THREE.NotEqualStencilFunc,
    stencilFail: THREE.ReplaceStencilOp,
    stencilZFail: THREE.ReplaceStencilOp,
    stencilZPass: THREE.ReplaceStencilOp,
  });
}

/** One solid's cap: its two counting passes (sharing `geometry`) and the quad that fills the cut. */
class Cap {
  constructor(plane, color, renderOrder) {
    const [back, front] = stencilPassMaterials(plane);
    this.back = new THREE.Mesh(new THREE.BufferGeometry(), back);
    this.front = new THREE.Mesh(new THREE.BufferGeometry(), front);
    this.quad = new THREE.Mesh(new THREE.PlaneGeometry(2, 2), capMaterial(color));
    // The counting passes run before the quad; later solids' caps are drawn over earlier ones in
    // the same plane (same quad, same depth, LessEqual depth test).
    this.back.renderOrder = this.front.renderOrder = renderOrder;
    this.quad.renderOrder = renderOrder + 0.5;
    this.group = new THREE.Group();
    for (const o of [this.back, this.front, this.quad]) {
      o.frustumCulled = false;
      this.group.add(o);
    }
    this.group.visible = false;
  }
  setGeometry(geometry) {
    this.back.geometry = this.front.geometry = geometry ?? new THREE.BufferGeometry();
  }
}

export const CAP_INPUT = 0xb0793a;
export const CAP_KERNEL = 0x1e6fff;

export class SectionPlane {
  constructor(scene) {
    this.plane = new THREE.Plane(new THREE.Vector3(0, 0, -1), 0);
    this.inputCap = new Cap(this.plane, CAP_INPUT, 10);
    this.kernelCap = new Cap(this.plane, CAP_KERNEL, 12);
    scene.add(this.inputCap.group, this.kernelCap.group);
    this.enabled = false;
    this.clipKernel = true;
    this.capsAllowed = true; // false for open meshes (see above)
  }

  /**
   * Keeps the part of the scene with coordinate `axis` (0, 1, 2) at most `at` (in the drawn,
   * centred frame); `size` is the input's radius (the caps' quads must cover its cut).
   */
  set(axis, at, size) {
    const n = new THREE.Vector3();
    n.setComponent(axis, -1);
    this.plane.set(n, at);
    const centre = new THREE.Vector3().setComponent(axis, at);
    for (const cap of [this.inputCap, this.kernelCap]) {
      cap.quad.position.copy(centre);
      cap.quad.lookAt(centre.clone().add(n));
      cap.quad.scale.setScalar(2 * size);
      cap.quad.updateMatrixWorld();
    }
  }

  /** Clipping planes for a material of the input (`kernel` false) or of the kernel. */
  planesFor(kernel) {
    return this.enabled && (!kernel || this.clipKernel) ? [this.plane] : null;
  }

  updateVisibility(inputVisible) {
    this.inputCap.group.visible = this.enabled && this.capsAllowed && inputVisible;
    this.kernelCap.group.visible = this.enabled && this.clipKernel && this.capsAllowed;
  }
}
