// What the cells page draws of a volume mesh, as typed arrays (no three.js here, so Node tests
// and benchmarks run it too): which cell lies across each face, each cell's centre, and the
// faces on the boundary of a set of shown cells, fan-triangulated, with their colours, their
// cells and their edges. A 100k-cell mesh has about a million face incidences: every loop below
// is over flat arrays, without an object per face.

/**
 * The topology the view needs: cellOf[i] is the cell of face incidence i (an entry of
 * cellFaces), other[i] the cell across that face (-1 on the mesh's boundary), centres the mean of
 * each cell's face corners (3 per cell). Faces are matched by their three smallest vertex ids.
 */
export function cellTopology(mesh) {
  const { positions, faceIndices, faceOffsets, cellFaces, cellOffsets } = mesh;
  const numCells = cellOffsets.length ? cellOffsets.length - 1 : 0;
  const n = cellFaces.length;
  const cellOf = new Int32Array(n);
  const centres = new Float64Array(3 * numCells);
  for (let c = 0; c < numCells; c++) {
    let corners = 0,
      x = 0,
      y = 0,
      z = 0;
    for (let i = cellOffsets[c]; i < cellOffsets[c + 1]; i++) {
      cellOf[i] = c;
      const f = cellFaces[i];
      for (let k = faceOffsets[f]; k < faceOffsets[f + 1]; k++) {
        const v = 3 * faceIndices[k];
        x += positions[v];
        y += positions[v + 1];
        z += positions[v + 2];
        corners++;
      }
    }
    const d = Math.max(corners, 1);
    centres[3 * c] = x / d;
    centres[3 * c + 1] = y / d;
    centres[3 * c + 2] = z / d;
  }
  // Incidences with the same two smallest ids are chained (next); a match also needs the same
  // third id and another cell.
  const other = new Int32Array(n).fill(-1);
  const third = new Float64Array(n);
  const next = new Int32Array(n).fill(-1);
  const heads = new Map();
  const wide = positions.length / 3 >= 2 ** 26; // ids too large to pack two into a double
  for (let i = 0; i < n; i++) {
    const f = cellFaces[i];
    let a = Infinity,
      b = Infinity,
      c = Infinity;
    for (let k = faceOffsets[f]; k < faceOffsets[f + 1]; k++) {
      const v = faceIndices[k];
      if (v < a) {
        c = b;
        b = a;
        a = v;
      } else if (v < b) {
        c = b;
        b = v;
      } else if (v < c) c = v;
    }
    third[i] = c;
    const key = wide ? `${a},${b}` : a * 2 ** 26 + b;
    const head = heads.get(key);
    let j = head === undefined ? -1 : head;
    for (; j >= 0; j = next[j]) if (third[j] === c && other[j] === -1 && cellOf[j] !== cellOf[i]) break;
    if (j >= 0) {
      other[j] = cellOf[i];
      other[i] = cellOf[j];
    } else {
      next[i] = head === undefined ? -1 : head;
      heads.set(key, i);
    }
  }
  return { numCells, cellOf, other, centres };
}

/**
 * The faces between a shown cell (shown[c] = 1) and a hidden one or the outside, relative to
 * `origin`: positions (float32, 3 per corner), colors (3 per corner, from cellColors: 3 per
 * cell), triCell (the cell of each triangle) and lines (the faces' edges, 2 corners each).
 */
export function boundaryFaces(mesh, topology, shown, cellColors, origin) {
  const { positions: p, faceIndices, faceOffsets, cellFaces } = mesh;
  const { cellOf, other } = topology;
  const drawn = (i) => shown[cellOf[i]] === 1 && (other[i] < 0 || shown[other[i]] !== 1);
  let triangles = 0,
    edges = 0;
  for (let i = 0; i < cellFaces.length; i++) {
    if (!drawn(i)) continue;
    const size = faceOffsets[cellFaces[i] + 1] - faceOffsets[cellFaces[i]];
    triangles += Math.max(size - 2, 0);
    edges += size;
  }
  const positions = new Float32Array(9 * triangles);
  const colors = new Float32Array(9 * triangles);
  const triCell = new Int32Array(triangles);
  const lines = new Float32Array(6 * edges);
  const [ox, oy, oz] = origin;
  let t = 0,
    e = 0;
  const put = (out, at, v) => {
    out[at] = p[3 * v] - ox;
    out[at + 1] = p[3 * v + 1] - oy;
    out[at + 2] = p[3 * v + 2] - oz;
  };
  for (let i = 0; i < cellFaces.length; i++) {
    if (!drawn(i)) continue;
    const c = cellOf[i];
    const first = faceOffsets[cellFaces[i]],
      end = faceOffsets[cellFaces[i] + 1];
    for (let k = first + 1; k + 1 < end; k++) {
      put(positions, 9 * t, faceIndices[first]);
      put(positions, 9 * t + 3, faceIndices[k]);
      put(positions, 9 * t + 6, faceIndices[k + 1]);
      for (let corner = 0; corner < 3; corner++) {
        colors[9 * t + 3 * corner] = cellColors[3 * c];
        colors[9 * t + 3 * corner + 1] = cellColors[3 * c + 1];
        colors[9 * t + 3 * corner + 2] = cellColors[3 * c + 2];
      }
      triCell[t++] = c;
    }
    for (let k = first; k < end; k++) {
      put(lines, 6 * e, faceIndices[k]);
      put(lines, 6 * e + 3, faceIndices[k + 1 < end ? k + 1 : first]);
      e++;
    }
  }
  return { positions, colors, triCell, lines };
}
