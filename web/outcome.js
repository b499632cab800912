// What the page says about a finished run: the status line, the message box and which rows of
// the stats table apply, for each outcome (a kernel of each shape, or an error). Kept apart from
// the page's code so that every state's text is written in one place.

import { messageInWords, kernelInWords } from './alternatives.js';

const fmt = (x, digits = 6) => (Number.isFinite(x) ? Number(x.toPrecision(digits)).toString() : String(x));
const plural = (n, one, many = `${one}s`) => `${n} ${n === 1 ? one : many}`;

/** A package message as a sentence of its own: capital first letter, closing full stop. */
export function sentence(text) {
  const t = String(text ?? '').trim();
  if (!t) return '';
  // A plain first word is capitalized; a file name ("bad.off:16: ...") is kept as it is.
  const capital = /^[a-z]+[ ,]/.test(t) ? t[0].toUpperCase() + t.slice(1) : t;
  return /[.!?]$/.test(capital) ? capital : `${capital}.`;
}

export const ERROR_TITLES = {
  PARSE_ERROR: 'Could not read the file',
  URL_ERROR: 'Could not open the link',
  OPEN_MESH: 'The mesh is open',
  NON_MANIFOLD_EDGE: 'The mesh is not manifold',
  INCONSISTENT_ORIENTATION: 'Inconsistent face orientation',
  MULTIPLE_COMPONENTS: 'The mesh has several separate pieces',
  SELF_INTERSECTION: 'The surface crosses itself',
  DEGENERATE_INPUT: 'The mesh encloses no volume',
  NON_FINITE_COORDINATE: 'Invalid coordinates',
  INDEX_OUT_OF_RANGE: 'A face refers to a vertex that does not exist',
  EMPTY_INPUT: 'The mesh is empty',
  FACE_TOO_SMALL: 'A face has fewer than 3 vertices',
  TOO_LARGE: 'The mesh is too large',
  COORDINATE_RANGE: 'Coordinates span too many orders of magnitude',
};

const ERROR_HINTS = {
  OPEN_MESH: 'The kernel is defined for closed (watertight) meshes: every edge must belong to exactly two faces.',
  NON_MANIFOLD_EDGE: 'Every edge must belong to exactly two faces.',
  INCONSISTENT_ORIENTATION: 'Neighbouring faces must traverse their shared edge in opposite directions.',
  MULTIPLE_COMPONENTS: 'Load one closed piece at a time.',
};

// Rows of the stats table (ids row-<name>), in table order.
export const ROWS = [
  'name',
  'input-faces',
  'open-edges',
  'planes',
  'status',
  'counts',
  'volume',
  'area',
  'ratio',
  'kernel-point',
  'deepest',
  'time',
  'wall',
];

/** The error state: { title, paragraphs, rows }. `openEdges`: their count when known. */
export function describeError(err, { openEdges = null } = {}) {
  const code = err?.code || 'ERROR';
  const title = `${ERROR_TITLES[code] ?? 'Error'} (${code})`;
  // The package's message without its option names: the page offers those as buttons.
  const paragraphs = [sentence(messageInWords(err?.message ?? err))];
  if (ERROR_HINTS[code]) paragraphs.push(ERROR_HINTS[code]);
  if (openEdges)
    paragraphs.push(
      `${plural(openEdges, 'open edge')} (used by one face only) ${openEdges === 1 ? 'is' : 'are'} drawn in red.`,
    );
  const rows = ['name', 'input-faces', 'status'];
  if (openEdges) rows.push('open-edges');
  return { code, title, paragraphs, rows, status: `${ERROR_TITLES[code] ?? 'Error'}.` };
}

// An empty kernel with walls at the open edges: the walls may be what empties it (the shape as
// an open surface can still have a kernel), so the page does not say the shape is not star-shaped.
// `extra`: { witness (faces), witnessEdges (boundary edges), openSurface (the kernel without walls,
// when it was tried: { status, volume }) }.
function emptyWithWalls(extra, rows) {
  const w = extra.witness ?? 0,
    e = extra.witnessEdges ?? 0;
  const paragraphs = [];
  if (e > 0)
    paragraphs.push(
      `The walls at the ${plural(e, 'boundary edge')} and the ${plural(w, 'face')} drawn in magenta have no common point: no point is behind every face and inside every wall.`,
    );
  else if (w > 0)
    paragraphs.push(
      `The ${plural(w, 'face')} drawn in magenta have no common point behind them: no point is behind every face.`,
    );
  else
    paragraphs.push(
      'No point is behind every face and inside every wall at the open edges: the walls make the kernel empty.',
    );
  if (extra.openEdges > 0)
    paragraphs.push(
      `The ${plural(extra.openEdges, 'open edge')}, where the walls stand, ${extra.openEdges === 1 ? 'is' : 'are'} drawn in red.`,
    );
  const o = extra.openSurface;
  if (o && !o.error && o.status !== 'EMPTY')
    paragraphs.push(
      `Without the walls (as an open surface) the kernel is ${kernelInWords(o)}: the walls empty it, not the shape.`,
    );
  return {
    outcome: 'empty',
    status: 'Empty with walls at the open edges.',
    kind: 'empty',
    title: 'The walls at the open edges make the kernel empty.',
    paragraphs,
    rows: extra.openEdges > 0 ? [...rows, 'open-edges'] : rows,
  };
}

/**
 * A finished kernel: { outcome ('star' | 'empty' | 'flat' | 'open'), status, kind, title,
 * paragraphs, rows }. `extra`: { boxFacets (count), openEdges (count), witness (face count), walls (computed
 * with walls), witnessEdges, openSurface (see emptyWithWalls) }.
 */
export function describeResult(result, V, E, F, extra = {}) {
  const s = result.stats ?? {};
  const timing = ['time', 'wall'];
  const planes = s.distinctPlanes > 0 ? ['planes'] : [];
  const head = ['name', 'input-faces', ...planes, 'status'];
  const deepest = result.deepestPoint ? ['deepest'] : [];
  const ratio = result.volumeRatio > 0 ? ['ratio'] : [];
  switch (result.status) {
    case 'POLYHEDRON':
      return {
        outcome: 'star',
        status: `Star-shaped: the kernel is a polyhedron (${V} vertices, ${E} edges, ${F} faces).`,
        kind: null,
        // (An open surface's kernel has no ratio: it may reach beyond the caps of its holes.)
        rows: [...head, 'counts', 'volume', 'area', ...ratio, 'kernel-point', ...deepest, ...timing],
      };
    case 'EMPTY': {
      if (extra.walls) return emptyWithWalls(extra, [...head, ...timing]);
      const w = extra.witness ?? 0;
      const paragraphs =
        w > 0
          ? [
              `No point sees all of the ${plural(w, 'face')} drawn in magenta from their inner side: the half-spaces behind ${w === 1 ? 'it have' : 'them have'} no point in common, so no point sees the whole shape.`,
            ]
          : [
              'No point inside this shape sees all of it: the inner half-spaces of its face planes have no common point.',
            ];
      return {
        outcome: 'empty',
        status: 'Not star-shaped: the kernel is empty.',
        kind: 'empty',
        title: 'Not star-shaped — the kernel is empty.',
        paragraphs,
        rows: [...head, ...timing],
      };
    }
    case 'POINT':
      return {
        outcome: 'flat',
        status: 'Star-shaped, but only from a single point.',
        kind: 'flat',
        title: 'Flat kernel: a single point.',
        paragraphs: [
          `Only one point, (${result.kernelPoint?.map((x) => fmt(x)).join(', ')}), sees the whole shape; the kernel has no volume.`,
        ],
        rows: [...head, 'counts', 'kernel-point', ...timing],
      };
    case 'SEGMENT':
      return {
        outcome: 'flat',
        status: 'Star-shaped, but only from the points of a line segment.',
        kind: 'flat',
        title: 'Flat kernel: a line segment.',
        paragraphs: ['Only the points of one segment see the whole shape; the kernel has no volume.'],
        rows: [...head, 'counts', 'kernel-point', ...timing],
      };
    case 'POLYGON':
      return {
        outcome: 'flat',
        status: `Star-shaped, but only from the points of a flat polygon (${V} vertices, area ${fmt(result.area)}).`,
        kind: 'flat',
        title: 'Flat kernel: a polygon.',
        paragraphs: [
          `The kernel is a flat convex polygon with ${V} vertices and area ${fmt(result.area)}: its points see the whole shape, and it has no volume.`,
        ],
        rows: [...head, 'counts', 'area', 'kernel-point', ...timing],
      };
    case 'UNBOUNDED': {
      const b = extra.boxFacets ?? 0,
        o = extra.openEdges ?? 0;
      const paragraphs = [
        "The open mesh's face planes do not enclose a bounded region: the kernel goes on without end. It is shown clipped to a box around the mesh.",
      ];
      if (b > 0)
        paragraphs.push(
          `${plural(b, 'facet')} of ${F} ${b === 1 ? 'is' : 'are'} the clip box's (grey), not the mesh's: the kernel continues beyond ${b === 1 ? 'it' : 'them'}.`,
        );
      if (o > 0) paragraphs.push(`${plural(o, 'open edge')} ${o === 1 ? 'is' : 'are'} drawn in red.`);
      return {
        outcome: 'open',
        status: 'Open mesh: the kernel is unbounded (shown clipped to a box).',
        kind: 'warning',
        title: 'Unbounded kernel.',
        paragraphs,
        rows: [...head, ...(o > 0 ? ['open-edges'] : []), 'counts', 'kernel-point', ...timing],
      };
    }
    default:
      return { outcome: 'star', status: String(result.status), kind: null, rows: [...head, ...timing] };
  }
}
