// A refused mesh: what its refusal proposes (repair, merging close vertices, walls at the open
// edges, computing it as an open surface), tried in the kernel worker before anything is offered,
// so that the page offers first what gets an answer and says why in its own words. Pure functions
// (no DOM): the page runs the trials (runs.js) and shows the texts (page-text.js).

const plural = (n, one, many = `${one}s`) => `${n} ${n === 1 ? one : many}`;
const fmt = (x) => Number(Number(x).toPrecision(6)).toString();

/**
 * The computations a refusal can lead to, in the order they are preferred when several give the
 * same kind of kernel: `options` are the page's run options (sources.js kernelOptions), `button`
 * the retry button that runs it.
 */
export const ALTERNATIVES = {
  repair: { options: { repair: true }, button: 'retryRepair', label: 'Repair and compute' },
  weldRepair: {
    options: { repair: true, weld: true },
    button: 'retryRepair',
    label: 'Merge close vertices, repair and compute',
  },
  weld: { options: { weld: true }, button: 'retryWeld', label: 'Merge close vertices and compute' },
  walls: {
    options: { walls: true, allowOpen: false },
    button: 'retryWalls',
    label: 'Compute with walls at the open edges',
  },
  allowOpen: {
    options: { allowOpen: true, walls: false },
    button: 'retryOpen',
    label: 'Compute as an open surface',
  },
  // Tried only when the surface's faces point inward (warning FACES_POINT_INWARD of another
  // trial): offered first when it has a kernel, by its status (rankTrials), after the others else.
  flipWalls: {
    options: { flipFaces: true, walls: true, allowOpen: false },
    button: 'retryFlip',
    label: 'Turn the faces outward and compute with walls',
  },
};

/** Whether a computation's warnings say that an open surface's faces point inward. */
export const facesPointInward = (warnings) => (warnings ?? []).some((w) => w.kind === 'FACES_POINT_INWARD');

/**
 * The package's options for the page's run options ({ allowOpen, walls, repair, weld, flipFaces }). Walls at
 * the boundary edges (open: 'perpendicular') bound an open surface's kernel where allowOpen clips
 * it to a box; walls win when both were asked for.
 */
export function packageOptions(run) {
  return {
    ...(run.walls ? { open: 'perpendicular' } : run.allowOpen ? { allowOpen: true } : {}),
    ...(run.repair ? { repair: true } : {}),
    ...(run.weld ? { weld: true } : {}),
    ...(run.flipFaces ? { flipFaces: true } : {}),
  };
}

/**
 * The options of the page's kernel runs for run options `run`: the package's, and the inscribed
 * ball (it costs little next to the kernel: always on). A refusal's trials use them too, so that
 * a tried alternative's result is the one its run would compute (sources.js shows it as is).
 */
export function kernelOptions(run) {
  return { deepestPoint: true, ...packageOptions(run) };
}

/**
 * The alternatives worth trying for a refusal `code`, given the options the refused run used:
 * each names what the package's message proposes for that code. `weldRepair` is tried only when
 * `repair` alone is refused (runs.js).
 */
export function candidatesFor(code, runOptions) {
  const out = [];
  if (code === 'OPEN_MESH' || code === 'NON_MANIFOLD_EDGE') {
    if (!runOptions.repair) out.push('repair');
    if (!runOptions.weld) out.push('weldRepair');
  }
  // Separate pieces: a triangle soup's corners, merged at equal positions by repair, else when close.
  if (code === 'MULTIPLE_COMPONENTS') {
    if (!runOptions.repair) out.push('repair');
    if (!runOptions.weld) out.push('weld');
  }
  if (code === 'OPEN_MESH') {
    if (!runOptions.walls) out.push('walls');
    if (!runOptions.allowOpen) out.push('allowOpen');
  }
  return out;
}

// A kernel of some volume first, then a flat one, then an unbounded one, then an empty one.
const STATUS_RANK = { POLYHEDRON: 0, POLYGON: 1, SEGMENT: 1, POINT: 1, UNBOUNDED: 2, EMPTY: 3 };

/**
 * The trials that got a kernel, best first: `trials` maps an alternative's id to { status,
 * volume, warnings } or { error, message }. Ties keep the ALTERNATIVES order.
 */
export function rankTrials(trials) {
  const order = Object.keys(ALTERNATIVES);
  return Object.entries(trials)
    .filter(([, t]) => t && !t.error)
    .sort(([a, ta], [b, tb]) => STATUS_RANK[ta.status] - STATUS_RANK[tb.status] || order.indexOf(a) - order.indexOf(b))
    .map(([id]) => id);
}

/** What a kernel status is, in words ("a polyhedron (volume 1000)", "empty", ...). */
export function kernelInWords(t) {
  switch (t.status) {
    case 'POLYHEDRON':
      return `a polyhedron${t.volume > 0 ? ` (volume ${fmt(t.volume)})` : ''}`;
    case 'POLYGON':
      return 'a flat polygon';
    case 'SEGMENT':
      return 'a line segment';
    case 'POINT':
      return 'a single point';
    case 'UNBOUNDED':
      return 'unbounded (it goes on without end; shown clipped to a box)';
    case 'EMPTY':
      return 'empty';
    default:
      return String(t.status);
  }
}

// The tolerance a VERTICES_WELDED warning names ("... merged into others within 1e-09"); 0 means
// only vertices at exactly one position were merged.
function weldTolerance(message) {
  const m = /within ([-+0-9.eE]+)/.exec(message ?? '');
  return m ? Number(m[1]) : null;
}

/**
 * A repair warning ({ kind, count, message }) in the page's words: what was found and what was
 * done about it. Other warnings: the package's message.
 */
export function warningInWords(w) {
  const n = w.count;
  switch (w.kind) {
    case 'T_JUNCTIONS_SPLIT':
      return `${plural(n, 'vertex', 'vertices')} ${n === 1 ? 'lies' : 'lie'} inside another face's edge (T-junctions): the faces there do not meet edge to edge, so those edges look open; repair splits the edges at ${n === 1 ? 'it' : 'them'}.`;
    case 'VERTICES_WELDED': {
      const tol = weldTolerance(w.message);
      const where = tol ? `closer than ${fmt(tol)} to another vertex` : 'at the same position as another vertex';
      const dropped = /(\d+) faces? that collapsed/.exec(w.message ?? '');
      const also = dropped
        ? `; ${plural(Number(dropped[1]), 'face')} that collapsed ${dropped[1] === '1' ? 'was' : 'were'} dropped`
        : '';
      return `${plural(n, 'vertex', 'vertices')} ${where} ${n === 1 ? 'was' : 'were'} merged with it${also}.`;
    }
    case 'DUPLICATE_FACES_REMOVED':
      return `${plural(n, 'face')} repeating another face ${n === 1 ? 'was' : 'were'} removed.`;
    case 'FACES_POINT_INWARD': {
      const volume = /volume of ([-+0-9.eE]+)/.exec(w.message ?? '');
      const holes = /closed over its holes/.test(w.message ?? '') ? 'holes' : 'hole';
      return `The surface is open and its faces point inward: closed over its ${holes}, it encloses a negative volume${volume ? ` (${fmt(Number(volume[1]))})` : ''}. An open surface is taken as given, never turned over by itself.`;
    }
    case 'CANCELLING_FACES_REMOVED':
      return `${plural(n, 'face')} in pairs of opposite orientation on the same corners ${n === 1 ? 'was' : 'were'} removed.`;
    default:
      return null;
  }
}

/**
 * Why an alternative that worked works, and what it gives, as one paragraph (`trials`: every
 * alternative tried, for what one says about another).
 */
export function trialInWords(id, t, trials = {}) {
  const kernel = kernelInWords(t);
  const repairs = (t.warnings ?? []).map(warningInWords).filter(Boolean).join(' ');
  switch (id) {
    case 'repair':
    case 'weldRepair':
    case 'weld':
      return `${repairs || 'Repair changes nothing that shows here.'} Then the kernel is ${kernel}.`;
    case 'walls':
      if (t.status !== 'EMPTY')
        return `With a wall at each open edge (perpendicular to its face), the kernel is ${kernel}.`;
      return trials.allowOpen?.status === 'EMPTY'
        ? 'With a wall at each open edge (perpendicular to its face), the kernel is empty: no point is behind every face, walls or not.'
        : 'With a wall at each open edge (perpendicular to its face), no point is behind every face and inside every wall: the walls make the kernel empty.';
    case 'flipWalls':
      return `With every face turned over (they then point outward) and a wall at each open edge, the kernel is ${kernel}.`;
    case 'allowOpen':
      return `As an open surface (only its faces bound the kernel, no walls), the kernel is ${kernel}.`;
    default:
      return `The kernel is ${kernel}.`;
  }
}

/** What an alternative that was tried and refused leads to, in a short clause. */
export function failureInWords(id, t) {
  const what = {
    repair: 'Repair',
    weldRepair: 'Merging close vertices and repair',
    weld: 'Merging close vertices',
    walls: 'Walls at the open edges',
    allowOpen: 'Computing it as an open surface',
    flipWalls: 'Turning the faces outward, with walls',
  }[id];
  return `${what} was tried: refused too (${t.error}).`;
}

/**
 * A package message in the page's words: the package's option names (`weld: true`,
 * `allowOpen: true`, `open: 'perpendicular'`, `Options::…`), which this page offers as buttons, are
 * cut out with the clause that names them; "edge(s)" reads as "edges".
 */
export function messageInWords(message) {
  let text = String(message ?? '');
  // A parenthesis that names options: "(weld: true merges …; allowOpen: true accepts open meshes)".
  text = text.replace(/\s*\([^()]*(?:weld: |repair: |allowOpen: |flipFaces: |open: '|Options::)[^()]*\)/g, '');
  // A trailing clause that names one: "; open: 'perpendicular' bounds such a surface's kernel …".
  // (Cut from the end, one clause after another.)
  const trailing = /;\s*(?:[^;]*?)(?:weld: |repair: |allowOpen: |flipFaces: |open: '|Options::)[^;]*$/;
  for (let before = ''; before !== text;) {
    before = text;
    text = text.replace(trailing, '');
  }
  return text.replace(/\b(\d+) (edge|face|vertex)\(s\)/g, (_, n, w) =>
    `${n} ${n === '1' ? w : `${w}s`}`.replace('vertexs', 'vertices'),
  );
}
