// Test-only OFF reader (OFF / COFF / NOFF headers, '#' comments, counts on the header line,
// polygon faces, optional colours after a face's indices). Not shipped with the package.
import fs from 'node:fs';

export function parseOff(text) {
  const tokens = [];
  for (const line of text.split(/\r?\n/)) {
    const body = line.replace(/#.*/, '').trim();
    if (body) tokens.push(body.split(/\s+/));
  }
  let row = 0;
  const head = tokens[row++];
  if (!/^[CNST]*OFF$/.test(head[0])) throw new Error(`not an OFF file (header ${head[0]})`);
  const perVertexExtra = head[0].includes('N') ? 3 : 0;
  let counts = head.slice(1);
  if (counts.length < 2) counts = tokens[row++];
  const nv = Number(counts[0]);
  const nf = Number(counts[1]);
  const positions = new Float64Array(3 * nv);
  for (let v = 0; v < nv; v++) {
    const t = tokens[row++];
    for (let k = 0; k < 3; k++) positions[3 * v + k] = Number(t[k]);
    void perVertexExtra;
  }
  const indices = [];
  const faceSizes = [];
  for (let f = 0; f < nf; f++) {
    const t = tokens[row++];
    const n = Number(t[0]);
    for (let k = 1; k <= n; k++) indices.push(Number(t[k]));
    faceSizes.push(n);
  }
  const allTriangles = faceSizes.every((n) => n === 3);
  return {
    positions,
    indices: Uint32Array.from(indices),
    faceSizes: allTriangles ? null : Uint32Array.from(faceSizes),
  };
}

export function readOff(path) {
  return parseOff(fs.readFileSync(path, 'utf8'));
}
