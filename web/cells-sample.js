// A polyhedral volume mesh generated here: a box grid agglomerated into L-shaped, U-shaped and
// single-box cells, as agglomeration-based VEM meshes are made. Its kernels are known by hand:
//   - a single box is convex: its kernel is itself (ratio 1, ρ = half its shortest side);
//   - an L of three boxes (an elbow and two arms) is star-shaped: every arm's inner side face
//     bounds the kernel to the elbow's slab, so the kernel is the elbow box;
//   - a U of five boxes (a base of three and two arms) is not star-shaped: the two arms' inner
//     side faces face each other across the gap, x ≤ x1 and x ≥ x2 with x1 < x2 (those two faces
//     are its witness).
// The grid's spacings vary from column to column (every face stays planar), so the ratios and ρ/h
// vary from cell to cell. Used by the demo (its volume-mesh sample, written as .vtu text and read
// by the package's reader), by scripts/gen-volume-mesh.mjs (big meshes for benchmarks) and by the
// tests, which compare every cell's computed kernel with `expected` below.

// Block patterns along x for each pair of y rows, repeated: [kind, width in boxes].
const PATTERN = [
  ['U', 3],
  ['L', 2],
  ['S', 1],
  ['L', 2],
  ['S', 1],
];

// Grid coordinates 0..n with spacings that vary smoothly between 0.6 and 1.4 (seeded by `phase`).
function coordinates(n, phase) {
  const out = new Float64Array(n + 1);
  for (let i = 0; i < n; i++) out[i + 1] = out[i] + 1 + 0.4 * Math.sin(1.7 * i + phase);
  return out;
}

// The boxes [i, j] of one block of `kind` at column i0, rows j0, j0 + 1, as cells (lists of
// boxes; the elbow box first for an L). `turn` (0..3) varies the orientation from block to block.
function blockCells(kind, i0, j0, turn) {
  const box = (di, dj) => [i0 + di, j0 + dj];
  if (kind === 'S') return [[box(0, 0)], [box(0, 1)]];
  if (kind === 'L') {
    // The elbow at one corner of the 2×2 block, the arms along x and y, the opposite box alone.
    const ei = turn & 1,
      ej = (turn >> 1) & 1;
    return [[box(ei, ej), box(1 - ei, ej), box(ei, 1 - ej)], [box(1 - ei, 1 - ej)]];
  }
  // U: the base along row jb, arms at both ends of the other row, the gap box alone.
  const jb = turn & 1;
  const ja = 1 - jb;
  return [[box(0, jb), box(1, jb), box(2, jb), box(0, ja), box(2, ja)], [box(1, ja)]];
}

// The cells of layer k as lists of [i, j] boxes: PATTERN repeated along x in each pair of rows;
// columns left at a row's end and an odd last row are single boxes.
function layerCells(nx, ny, k) {
  const cells = [];
  const singles = (i0, i1, j0, j1) => {
    for (let j = j0; j < j1; j++) for (let i = i0; i < i1; i++) cells.push([[i, j]]);
  };
  for (let j0 = 0; j0 + 1 < ny; j0 += 2) {
    let i0 = 0;
    for (let p = (j0 / 2 + k) % PATTERN.length; ; p = (p + 1) % PATTERN.length) {
      const [kind, width] = PATTERN[p];
      if (i0 + width > nx) break;
      cells.push(...blockCells(kind, i0, j0, (i0 + j0 + k) & 3));
      i0 += width;
    }
    singles(i0, nx, j0, j0 + 2);
  }
  if (ny % 2 === 1) singles(0, nx, ny - 1, ny);
  return cells;
}

// The six faces of box (i, j, k) as [corner ids counter-clockwise seen from outside, the
// neighbouring box's offset]; id(di, dj, dk) is the id of the box's corner (i + di, ...).
const BOX_FACES = [
  [[0, 0, 0], [0, 0, 1], [0, 1, 1], [0, 1, 0], -1, 0, 0],
  [[1, 0, 0], [1, 1, 0], [1, 1, 1], [1, 0, 1], 1, 0, 0],
  [[0, 0, 0], [1, 0, 0], [1, 0, 1], [0, 0, 1], 0, -1, 0],
  [[0, 1, 0], [0, 1, 1], [1, 1, 1], [1, 1, 0], 0, 1, 0],
  [[0, 0, 0], [0, 1, 0], [1, 1, 0], [1, 0, 0], 0, 0, -1],
  [[0, 0, 1], [1, 0, 1], [1, 1, 1], [0, 1, 1], 0, 0, 1],
];

/**
 * The agglomerated grid of nx × ny × nz boxes: { positions (Float64Array, flat xyz), cells: each
 * a list of faces (lists of point ids, counter-clockwise seen from outside the cell), kinds: 'S',
 * 'L' or 'U' per cell, expected: per cell { kernelVolume, cellVolume, ratio, diameter,
 * inscribedRadius, starShaped } }.
 */
export function agglomeratedGrid(nx, ny, nz) {
  const xs = coordinates(nx, 0.3),
    ys = coordinates(ny, 1.1),
    zs = coordinates(nz, 2.0);
  const positions = new Float64Array(3 * (nx + 1) * (ny + 1) * (nz + 1));
  const pid = (i, j, k) => i + (nx + 1) * (j + (ny + 1) * k);
  for (let k = 0; k <= nz; k++)
    for (let j = 0; j <= ny; j++) for (let i = 0; i <= nx; i++) positions.set([xs[i], ys[j], zs[k]], 3 * pid(i, j, k));
  const cells = [];
  const kinds = [];
  const expected = [];
  for (let k = 0; k < nz; k++) {
    for (const boxes of layerCells(nx, ny, k)) {
      const inCell = new Set(boxes.map(([i, j]) => `${i},${j}`));
      const faces = [];
      for (const [i, j] of boxes) {
        for (const [a, b, c, d, di, dj, dk] of BOX_FACES) {
          if (dk === 0 && inCell.has(`${i + di},${j + dj}`)) continue; // inner face of the cell
          faces.push([a, b, c, d].map(([x, y, z]) => pid(i + x, j + y, k + z)));
        }
      }
      const kind = boxes.length === 1 ? 'S' : boxes.length === 3 ? 'L' : 'U';
      cells.push(faces);
      kinds.push(kind);
      expected.push(expectedCell(kind, boxes, k, xs, ys, zs, faces, positions));
    }
  }
  return { positions, cells, kinds, expected };
}

const boxVolume = ([i, j], k, xs, ys, zs) => (xs[i + 1] - xs[i]) * (ys[j + 1] - ys[j]) * (zs[k + 1] - zs[k]);

// The analytic kernel of a cell (see the file's head) and its diameter, the largest distance
// between two of its vertices.
function expectedCell(kind, boxes, k, xs, ys, zs, faces, positions) {
  const cellVolume = boxes.reduce((s, b) => s + boxVolume(b, k, xs, ys, zs), 0);
  const ids = [...new Set(faces.flat())];
  let d2 = 0;
  for (let a = 0; a < ids.length; a++) {
    for (let b = a + 1; b < ids.length; b++) {
      const p = 3 * ids[a],
        q = 3 * ids[b];
      const dx = positions[p] - positions[q],
        dy = positions[p + 1] - positions[q + 1],
        dz = positions[p + 2] - positions[q + 2];
      d2 = Math.max(d2, dx * dx + dy * dy + dz * dz);
    }
  }
  const diameter = Math.sqrt(d2);
  if (kind === 'U') {
    return { kernelVolume: 0, cellVolume, ratio: 0, diameter, inscribedRadius: 0, starShaped: false };
  }
  const [i, j] = boxes[0]; // the cell itself, or an L's elbow
  const sides = [xs[i + 1] - xs[i], ys[j + 1] - ys[j], zs[k + 1] - zs[k]];
  const kernelVolume = sides[0] * sides[1] * sides[2];
  return {
    kernelVolume,
    cellVolume,
    ratio: kernelVolume / cellVolume,
    diameter,
    inscribedRadius: Math.min(...sides) / 2,
    starShaped: true,
  };
}

/** Grid dimensions whose agglomerated grid has about `cells` cells (nz layers of nx × ny). */
export function gridForCells(cells) {
  // PATTERN turns 9 columns × 2 rows (18 boxes) into 10 cells: 5/9 of a cell per box.
  const boxes = Math.max(1, Math.round((cells * 9) / 5));
  const n = Math.max(1, Math.round(Math.cbrt(boxes)));
  const nz = Math.max(1, Math.round(boxes / (n * n)));
  return [n, n, nz];
}

/**
 * VTK XML UnstructuredGrid text of a volume mesh { positions, cells } with every cell a
 * VTK_POLYHEDRON (type 42): points, per cell its point ids (`connectivity`, `offsets`), and the
 * face stream (`faces`: per cell its face count, then per face its size and point ids;
 * `faceoffsets`: where each cell's stream ends). ASCII, the format ParaView writes.
 */
export function volumeMeshToVtu({ positions, cells }) {
  const numPoints = positions.length / 3;
  const connectivity = [];
  const offsets = [];
  const faces = [];
  const faceOffsets = [];
  for (const cell of cells) {
    connectivity.push(...new Set(cell.flat()));
    offsets.push(connectivity.length);
    faces.push(cell.length);
    for (const f of cell) faces.push(f.length, ...f);
    faceOffsets.push(faces.length);
  }
  const ints = (name, values) =>
    `        <DataArray type="Int64" Name="${name}" format="ascii">\n${lines(values)}\n        </DataArray>\n`;
  return (
    '<?xml version="1.0"?>\n' +
    '<VTKFile type="UnstructuredGrid" version="1.0" byte_order="LittleEndian" header_type="UInt64">\n' +
    '  <UnstructuredGrid>\n' +
    `    <Piece NumberOfPoints="${numPoints}" NumberOfCells="${cells.length}">\n` +
    '      <Points>\n' +
    `        <DataArray type="Float64" NumberOfComponents="3" format="ascii">\n${lines(positions, 3)}\n        </DataArray>\n` +
    '      </Points>\n' +
    '      <Cells>\n' +
    ints('connectivity', connectivity) +
    ints('offsets', offsets) +
    `        <DataArray type="UInt8" Name="types" format="ascii">\n${lines(new Array(cells.length).fill(42))}\n        </DataArray>\n` +
    ints('faces', faces) +
    ints('faceoffsets', faceOffsets) +
    '      </Cells>\n' +
    '    </Piece>\n' +
    '  </UnstructuredGrid>\n' +
    '</VTKFile>\n'
  );
}

// Values as text, `perLine` to a line (at most 24 for long integer lists).
function lines(values, perLine = 24) {
  const out = [];
  for (let i = 0; i < values.length; i += perLine) {
    out.push('          ' + Array.prototype.slice.call(values, i, i + perLine).join(' '));
  }
  return out.join('\n');
}

/** The demo's volume-mesh sample: 9 × 4 × 2 boxes agglomerated (L, U and single cells). */
export function sampleVolumeMesh() {
  return agglomeratedGrid(9, 4, 2);
}
