// Polyhedral volume meshes: the core's readers (.vtu, legacy .vtk, the .node + .ele pair) and the
// kernel of every cell (kergen/volume.h), through wasm/cells_bindings.cpp.
//
// A computation opens a *volume* in the heap (the mesh, read there from a file's bytes or copied
// there once from the caller's arrays), computes its cells range by range (so progress is
// reported, and the async variant yields to the event loop, between ranges) and closes it in a
// `finally`: nothing of the heap outlives the call. Results are copied out as typed arrays.
import { KergenError } from './errors.js';
import { init, requireModule, callWasm } from './load.js';
import { invalid, checkNotDetached } from './checks.js';
import { bytesView } from './files.js';
import { OUT_OF_MEMORY, readStrings } from './wire.js';

const textEncoder = new TextEncoder();
const DEFAULT_RANGE = 1000;
const DEFAULT_WORST = 10;

// ---- the layout (cells_bindings.cpp cellWireFormat(), read once per module instance) ---------

const layouts = new WeakMap();
// The array names this file reads; a module without one of them is from another build.
const WIRE_NAMES = {
  f64: [
    ...['positions', 'kernelVolume', 'cellVolume', 'kernelRatio', 'diameter', 'inscribedRadius', 'rhoOverH'],
    ...['deepestPoints', 'warningCounts', 'summary'],
  ],
  u32: [
    ...['faceIndices', 'faceOffsets', 'cellFaces', 'cellOffsets', 'status', 'reoriented', 'witnessOffsets'],
    ...[
      'witnessFaces',
      'witnessGlobalFaces',
      'errorCells',
      'faceSizes',
      'globalVertices',
      'summaryErrors',
      'worstCells',
    ],
  ],
};

function layout(m) {
  let L = layouts.get(m);
  if (L) return L;
  if (typeof m.cellWireFormat !== 'function') {
    throw new KergenError('UNSUPPORTED', 'this build of kergen.wasm has no volume meshes (rebuild it)');
  }
  L = m.cellWireFormat();
  const missing = [];
  for (const group of ['f64', 'u32'])
    for (const n of WIRE_NAMES[group]) if (!L[group].includes(n)) missing.push(`${group}.${n}`);
  for (const n of ['ok', 'volume', 'textBytes', 'numWarnings', 'words', 'arrays'])
    if (typeof L.head[n] !== 'number') missing.push(`head.${n}`);
  if (missing.length) {
    throw new KergenError(
      'WASM_LOAD_FAILED',
      `kergen.wasm does not match this cells.js (rebuild both): its cell wire format lacks ${missing.join(', ')}`,
    );
  }
  // Status codes (cell_status_code): a kernel type's value, or minus an error's value.
  L.statusNames = {};
  L.kernelTypes.forEach((name, code) => (L.statusNames[code] = name));
  L.errors.forEach((name, code) => code > 0 && (L.statusNames[-code] = name));
  layouts.set(m, L);
  return L;
}

// Copies a result block out of the heap (each array into a buffer of its own, so any of them can
// be transferred alone) and frees it. Throws the block's error.
function readBlock(m, L, ptr) {
  if (!ptr) throw new KergenError('OUT_OF_MEMORY', OUT_OF_MEMORY);
  try {
    const u32 = m.HEAPU32;
    const h = ptr / 4;
    const lengths = (i) => u32[h + L.head.arrays + i];
    let at = ptr + 4 * L.head.words;
    const f64 = {};
    L.f64.forEach((name, i) => {
      const n = lengths(i);
      f64[name] = new Float64Array(m.HEAPU8.slice(at, at + 8 * n).buffer);
      at += 8 * n;
    });
    const ints = {};
    L.u32.forEach((name, i) => {
      const n = lengths(L.f64.length + i);
      ints[name] = new Uint32Array(m.HEAPU8.slice(at, at + 4 * n).buffer);
      at += 4 * n;
    });
    const strings = readStrings(m.HEAPU8, at, at + u32[h + L.head.textBytes]);
    if (u32[h + L.head.ok] === 0) throw new KergenError(strings[0], strings[1] || strings[0]);
    const numWarnings = u32[h + L.head.numWarnings];
    const rest = strings.slice(2);
    const warnings = [];
    for (let i = 0; i < numWarnings; i++) {
      const s = rest.length - 2 * numWarnings + 2 * i;
      warnings.push({ kind: rest[s], count: f64.warningCounts[i], message: rest[s + 1] });
    }
    return {
      volume: u32[h + L.head.volume],
      f64,
      u32: ints,
      messages: rest.slice(0, rest.length - 2 * numWarnings),
      warnings,
    };
  } finally {
    m._free(ptr);
  }
}

// A request block of the given byte arrays back to back; returns its address (the caller frees it).
function writeBytes(m, parts) {
  const size = parts.reduce((s, p) => s + p.length, 0);
  const ptr = size < 2 ** 32 ? m._malloc(Math.max(size, 1)) : 0;
  if (!ptr) throw new KergenError('OUT_OF_MEMORY', OUT_OF_MEMORY);
  let at = ptr;
  for (const p of parts) {
    m.HEAPU8.set(p, at);
    at += p.length;
  }
  return ptr;
}

// ---- reading -----------------------------------------------------------------------------------

// The files of `input` (one file's bytes, or { node, ele }) and the format code to read them with.
function readRequest(fn, input, options, L) {
  if (options != null && typeof options !== 'object') throw invalid(fn, 'options must be an object');
  const { format, name, eleName } = options ?? {};
  if (format != null && (typeof format !== 'string' || !L.formats.includes(format) || format === '')) {
    throw invalid(
      fn,
      `options.format must be ${L.formats
        .slice(1)
        .map((f) => `'${f}'`)
        .join(', ')} (got ${String(format)})`,
    );
  }
  if (name != null && typeof name !== 'string') throw invalid(fn, 'options.name must be a string');
  if (eleName != null && typeof eleName !== 'string') throw invalid(fn, 'options.eleName must be a string');
  const pair = input !== null && typeof input === 'object' && !ArrayBuffer.isView(input) && 'node' in input;
  if (pair || format === 'node-ele') {
    if (!pair || input.ele == null)
      throw invalid(fn, "the .node + .ele pair is given as { node, ele }: the two files' bytes");
    return {
      format: L.formats.indexOf('node-ele'),
      parts: [bytesView(fn, input.node), textEncoder.encode(name ?? '<node>')],
      ele: [bytesView(fn, input.ele), textEncoder.encode(eleName ?? '<ele>')],
    };
  }
  return {
    format: L.formats.indexOf(format ?? ''),
    parts: [bytesView(fn, input), textEncoder.encode(name ?? '<memory>')],
    ele: [new Uint8Array(0), new Uint8Array(0)],
  };
}

// Reads a file into a heap volume (keep) and/or copies its arrays out (wantArrays).
function readVolume(fn, m, L, input, options, keep, wantArrays) {
  const r = readRequest(fn, input, options, L);
  return callWasm(fn, () => {
    const request = writeBytes(m, [...r.parts, ...r.ele]);
    try {
      const [bytes, name] = r.parts;
      const [ele, eleName] = r.ele;
      return readBlock(
        m,
        L,
        m.volumeRead(request, bytes.length, name.length, r.format, ele.length, eleName.length, keep, wantArrays),
      );
    } finally {
      m._free(request);
    }
  });
}

const meshOf = (block) => ({
  positions: block.f64.positions,
  faceIndices: block.u32.faceIndices,
  faceOffsets: block.u32.faceOffsets,
  cellFaces: block.u32.cellFaces,
  cellOffsets: block.u32.cellOffsets,
});

/**
 * Reads a volume mesh with the core's readers: a .vtu or legacy .vtk file's bytes, or the pair
 * { node, ele }. Synchronous (init() must have finished). See index.d.ts.
 */
export function readVolumeMeshSync(input, options = {}) {
  const fn = 'readVolumeMesh';
  const m = requireModule(fn);
  return meshOf(readVolume(fn, m, layout(m), input, options, false, true));
}

/** Async variant of readVolumeMeshSync (loads the module on first use). */
export async function readVolumeMesh(input, options = {}) {
  await init();
  return readVolumeMeshSync(input, options);
}

// ---- a mesh from the caller's arrays -----------------------------------------------------------

const MESH_ARRAYS = ['faceIndices', 'faceOffsets', 'cellFaces', 'cellOffsets'];

function checkVolumeMesh(fn, mesh) {
  if (mesh === null || typeof mesh !== 'object')
    throw invalid(fn, 'the mesh must be { positions, faceIndices, faceOffsets, cellFaces, cellOffsets }');
  const { positions } = mesh;
  if (!(positions instanceof Float64Array || positions instanceof Float32Array || Array.isArray(positions)))
    throw invalid(fn, 'mesh.positions must be a Float64Array, a Float32Array or an array of numbers');
  if (positions.length % 3 !== 0)
    throw invalid(fn, `mesh.positions has ${positions.length} values, not a multiple of 3`);
  checkNotDetached(fn, 'mesh.positions', positions);
  for (const key of MESH_ARRAYS) {
    const a = mesh[key];
    if (!(a instanceof Uint32Array || Array.isArray(a)))
      throw invalid(fn, `mesh.${key} must be a Uint32Array or an array`);
    checkNotDetached(fn, `mesh.${key}`, a);
    if (Array.isArray(a)) {
      for (let i = 0; i < a.length; i++)
        if (!Number.isInteger(a[i]) || a[i] < 0 || a[i] > 0xffffffff)
          throw invalid(fn, `mesh.${key}[${i}] = ${String(a[i])} is not an integer in 0 .. 2^32-1`);
    }
  }
}

// Copies the caller's mesh into a heap volume; returns its address.
function volumeFromMesh(fn, m, L, mesh) {
  checkVolumeMesh(fn, mesh);
  return callWasm(fn, () => {
    const arrays = MESH_ARRAYS.map((k) => mesh[k]);
    const bytes = 8 * mesh.positions.length + 4 * arrays.reduce((s, a) => s + a.length, 0);
    const ptr = bytes < 2 ** 32 ? m._malloc(Math.max(bytes, 1)) : 0;
    if (!ptr) throw new KergenError('OUT_OF_MEMORY', OUT_OF_MEMORY);
    try {
      m.HEAPF64.set(mesh.positions, ptr / 8);
      let at = ptr / 4 + 2 * mesh.positions.length;
      for (const a of arrays) {
        m.HEAPU32.set(a, at);
        at += a.length;
      }
      const [fi, fo, cf, co] = arrays.map((a) => a.length);
      return readBlock(m, L, m.volumeFromArrays(ptr, mesh.positions.length, fi, fo, cf, co)).volume;
    } finally {
      m._free(ptr);
    }
  });
}

/**
 * One cell as a surface mesh (the core's cell_surface: the cell's vertices and faces, turned
 * outward), for computeKernel. Synchronous. See index.d.ts.
 */
export function cellSurfaceSync(mesh, cell) {
  const fn = 'cellSurface';
  const m = requireModule(fn);
  const L = layout(m);
  if (!Number.isSafeInteger(cell) || cell < 0)
    throw invalid(fn, `cell must be a non-negative integer (got ${String(cell)})`);
  const volume = volumeFromMesh(fn, m, L, mesh);
  try {
    const b = callWasm(fn, () => readBlock(m, L, m.volumeCellSurface(volume, cell)));
    return {
      positions: b.f64.positions,
      indices: b.u32.faceIndices,
      faceSizes: b.u32.faceSizes,
      globalVertices: b.u32.globalVertices,
      reoriented: b.u32.reoriented[0] === 1,
    };
  } finally {
    closeVolume(m, volume);
  }
}

/** Async variant of cellSurfaceSync (loads the module on first use). */
export async function cellSurface(mesh, cell) {
  await init();
  return cellSurfaceSync(mesh, cell);
}

function closeVolume(m, volume) {
  try {
    m.volumeClose(volume);
  } catch {
    // the module failed meanwhile (callWasm dropped it): its heap is gone with it
  }
}

// ---- the kernels of the cells ------------------------------------------------------------------

const isBytes = (x) =>
  x instanceof ArrayBuffer ||
  ArrayBuffer.isView(x) ||
  (typeof SharedArrayBuffer === 'function' && x instanceof SharedArrayBuffer) ||
  (x !== null && typeof x === 'object' && 'node' in x && 'ele' in x);

function checkCellOptions(fn, options) {
  if (options == null) return { rangeSize: DEFAULT_RANGE, worst: DEFAULT_WORST, firstCell: 0, count: Infinity };
  if (typeof options !== 'object') throw invalid(fn, 'options must be an object');
  const count = (key, fallback, min = 0) => {
    const v = options[key];
    if (v == null) return fallback;
    if (!Number.isSafeInteger(v) || v < min) throw invalid(fn, `options.${key} must be an integer >= ${min}`);
    return v;
  };
  if (options.deepestPoint != null && typeof options.deepestPoint !== 'boolean')
    throw invalid(fn, 'options.deepestPoint must be a boolean');
  if (options.onProgress != null && typeof options.onProgress !== 'function')
    throw invalid(fn, 'options.onProgress must be a function');
  return {
    deepestPoint: options.deepestPoint === true,
    firstCell: count('firstCell', 0),
    count: count('count', Infinity),
    rangeSize: count('rangeSize', DEFAULT_RANGE, 1),
    worst: count('worst', DEFAULT_WORST),
    onProgress: options.onProgress ?? null,
  };
}

const F64_OUT = [
  'kernelVolume',
  'cellVolume',
  'kernelRatio',
  'diameter',
  'inscribedRadius',
  'rhoOverH',
  'deepestPoints',
];

// Concatenates the ranges' arrays into the result's.
function joinRanges(ranges, first, total) {
  const cat = (Type, pick) => {
    const out = new Type(ranges.reduce((s, r) => s + pick(r).length, 0));
    let at = 0;
    for (const r of ranges) {
      out.set(pick(r), at);
      at += pick(r).length;
    }
    return out;
  };
  const result = { firstCell: first, numCells: total };
  result.status = new Int32Array(cat(Uint32Array, (r) => r.u32.status).buffer);
  for (const key of F64_OUT) result[key] = cat(Float64Array, (r) => r.f64[key]);
  result.reoriented = Uint8Array.from(cat(Uint32Array, (r) => r.u32.reoriented));
  result.witnessFaces = cat(Uint32Array, (r) => r.u32.witnessFaces);
  result.witnessGlobalFaces = cat(Uint32Array, (r) => r.u32.witnessGlobalFaces);
  // Each range's offsets start at 0: shifted by the faces of the ranges before it.
  const offsets = new Uint32Array(total + 1);
  let cell = 0,
    base = 0;
  for (const r of ranges) {
    const o = r.u32.witnessOffsets;
    for (let i = 1; i < o.length; i++) offsets[++cell] = base + o[i];
    base += r.u32.witnessFaces.length;
  }
  result.witnessOffsets = offsets;
  result.errors = [];
  for (const r of ranges) {
    r.u32.errorCells.forEach((c, i) => {
      const message = r.messages[i];
      result.errors.push({ cell: c, code: null, message });
    });
  }
  return result;
}

// The ranges' warnings by kind: counts added (the message of a kind seen in one range only is the core's).
function joinWarnings(ranges) {
  const byKind = new Map();
  for (const r of ranges) {
    for (const w of r.warnings) {
      const seen = byKind.get(w.kind);
      if (!seen) byKind.set(w.kind, { ...w });
      else {
        seen.count += w.count;
        seen.message = `${seen.message}; ${w.message}`;
      }
    }
  }
  return [...byKind.values()];
}

function readSummary(m, L, block) {
  const b = readBlock(m, L, block);
  const v = b.f64.summary;
  const S = L.summary;
  const byType = {};
  L.kernelTypes.forEach((name, t) => (byType[name] = v[S.byType + t]));
  const byError = {};
  const e = b.u32.summaryErrors;
  for (let i = 0; i < e.length; i += 2) byError[L.errors[e[i]]] = e[i + 1];
  const hasRhoOverH = v[S.hasRhoOverH] === 1;
  return {
    cells: v[S.cells],
    okCells: v[S.okCells],
    byType,
    byError,
    reorientedCells: v[S.reorientedCells],
    minRatio: v[S.minRatio],
    medianRatio: v[S.medianRatio],
    maxRatio: v[S.maxRatio],
    hasRhoOverH,
    minRhoOverH: hasRhoOverH ? v[S.minRhoOverH] : null,
    medianRhoOverH: hasRhoOverH ? v[S.medianRhoOverH] : null,
    maxRhoOverH: hasRhoOverH ? v[S.maxRhoOverH] : null,
    worstCells: b.u32.worstCells,
  };
}

// The computation as a generator: it yields after every range (the sync variant runs it through,
// the async one awaits between ranges) and returns the result.
function* cellRun(fn, meshOrBytes, options) {
  const m = requireModule(fn);
  const L = layout(m);
  const opts = checkCellOptions(fn, options);
  let mesh = null;
  let volume;
  if (isBytes(meshOrBytes)) {
    const b = readVolume(fn, m, L, meshOrBytes, readOptionsOf(options), true, true);
    mesh = meshOf(b);
    volume = b.volume;
  } else volume = volumeFromMesh(fn, m, L, meshOrBytes);
  try {
    const offsets = (mesh ?? meshOrBytes).cellOffsets;
    const numCells = offsets.length ? offsets.length - 1 : 0;
    const first = Math.min(opts.firstCell, numCells);
    const total = Math.min(opts.count, numCells - first);
    const ranges = [];
    const report = (done) => {
      if (opts.onProgress) opts.onProgress({ phase: 'cells', count: done, total });
    };
    report(0);
    for (let done = 0; done < total;) {
      const n = Math.min(opts.rangeSize, total - done);
      ranges.push(callWasm(fn, () => readBlock(m, L, m.volumeCells(volume, first + done, n, opts.deepestPoint))));
      done += n;
      report(done);
      if (done < total) yield;
    }
    const result = joinRanges(ranges, first, total);
    for (const e of result.errors) e.code = L.statusNames[result.status[e.cell - first]];
    result.warnings = joinWarnings(ranges);
    result.summary = callWasm(fn, () => readSummary(m, L, m.volumeSummary(volume, opts.worst)));
    result.statusNames = { ...L.statusNames };
    if (mesh) result.mesh = mesh;
    return result;
  } finally {
    closeVolume(m, volume);
  }
}

const readOptionsOf = (options) =>
  options == null ? {} : { format: options.format, name: options.name, eleName: options.eleName };

/**
 * The kernel of every cell of a volume mesh (or of the cells firstCell .. firstCell + count - 1),
 * synchronously: `meshOrBytes` is a mesh from readVolumeMesh, a file's bytes or { node, ele }.
 * onProgress({ phase: 'cells', count, total }) after every range of `rangeSize` cells. See index.d.ts.
 */
export function computeCellKernelsSync(meshOrBytes, options = {}) {
  return runThrough(cellRun('computeCellKernels', meshOrBytes, options));
}

// A run (a generator that yields between ranges) run to its end; returns its value.
export function runThrough(run) {
  for (;;) {
    const step = run.next();
    if (step.done) return step.value;
  }
}

// Lets the event loop run (a message round trip: no timer clamping), then resumes.
function yieldToEventLoop() {
  if (typeof MessageChannel === 'function') {
    return new Promise((resolve) => {
      const channel = new MessageChannel();
      channel.port1.onmessage = () => {
        channel.port1.close();
        resolve();
      };
      channel.port2.postMessage(null);
    });
  }
  return new Promise((resolve) => setTimeout(resolve, 0));
}

/**
 * Async variant of computeCellKernelsSync (loads the module on first use): yields to the event
 * loop between ranges; options.signal (an AbortSignal) cancels between ranges (code 'CANCELLED').
 */
export async function computeCellKernels(meshOrBytes, options = {}) {
  await init();
  return runYielding('computeCellKernels', options, () => cellRun('computeCellKernels', meshOrBytes, options));
}

/**
 * Runs the generator makeRun() returns to its end, yielding to the event loop between its steps;
 * options.signal (an AbortSignal) cancels between them (code 'CANCELLED'; the generator's
 * `finally` frees what it holds in the heap).
 */
export async function runYielding(fn, options, makeRun) {
  const signal = options && options.signal;
  if (signal != null && typeof signal.aborted !== 'boolean') throw invalid(fn, 'options.signal must be an AbortSignal');
  const cancelled = () => new KergenError('CANCELLED', `${fn}: cancelled by options.signal`);
  if (signal && signal.aborted) throw cancelled();
  const run = makeRun();
  for (;;) {
    const step = run.next();
    if (step.done) return step.value;
    await yieldToEventLoop();
    if (signal && signal.aborted) {
      run.return();
      throw cancelled();
    }
  }
}

// ---- joining parts ---------------------------------------------------------------------------

/**
 * One result of results computed in parts (consecutive cell ranges, by several workers, say):
 * the arrays concatenated, the witness offsets shifted, and the summary of all the cells computed
 * again by the core (summarize_cells). Synchronous (init() must have finished). See index.d.ts.
 */
export function joinCellKernelsSync(parts, options = {}) {
  const fn = 'joinCellKernels';
  const m = requireModule(fn);
  const L = layout(m);
  if (!Array.isArray(parts) || parts.length === 0) throw invalid(fn, 'parts must be a non-empty array of results');
  const sorted = [...parts].sort((a, b) => a.firstCell - b.firstCell);
  for (let i = 1; i < sorted.length; i++) {
    if (sorted[i].firstCell !== sorted[i - 1].firstCell + sorted[i - 1].numCells)
      throw invalid(
        fn,
        `the parts are not consecutive: cells from ${sorted[i].firstCell} follow a part ending at ${sorted[i - 1].firstCell + sorted[i - 1].numCells}`,
      );
  }
  const worst = options && options.worst != null ? options.worst : DEFAULT_WORST;
  if (!Number.isSafeInteger(worst) || worst < 0) throw invalid(fn, 'options.worst must be a non-negative integer');
  const cat = (Type, key) => {
    const out = new Type(sorted.reduce((s, p) => s + p[key].length, 0));
    let at = 0;
    for (const p of sorted) {
      out.set(p[key], at);
      at += p[key].length;
    }
    return out;
  };
  const result = { firstCell: sorted[0].firstCell, numCells: sorted.reduce((s, p) => s + p.numCells, 0) };
  result.status = cat(Int32Array, 'status');
  for (const key of F64_OUT) result[key] = cat(Float64Array, key);
  result.reoriented = cat(Uint8Array, 'reoriented');
  result.witnessFaces = cat(Uint32Array, 'witnessFaces');
  result.witnessGlobalFaces = cat(Uint32Array, 'witnessGlobalFaces');
  result.witnessOffsets = new Uint32Array(result.numCells + 1);
  let cell = 0,
    base = 0;
  for (const p of sorted) {
    for (let i = 1; i <= p.numCells; i++) result.witnessOffsets[++cell] = base + p.witnessOffsets[i];
    base += p.witnessFaces.length;
  }
  result.errors = sorted.flatMap((p) => p.errors);
  result.warnings = joinWarnings(sorted);
  result.statusNames = { ...L.statusNames };
  const n = result.numCells;
  result.summary = callWasm(fn, () => {
    const ptr = m._malloc(Math.max(1, 32 * n));
    if (!ptr) throw new KergenError('OUT_OF_MEMORY', OUT_OF_MEMORY);
    try {
      const f64 = ptr / 8;
      m.HEAPF64.set(result.kernelRatio, f64);
      m.HEAPF64.set(result.rhoOverH, f64 + n);
      for (let i = 0; i < n; i++) m.HEAPF64[f64 + 2 * n + i] = result.deepestPoints[3 * i];
      new Int32Array(m.HEAPU8.buffer, ptr + 24 * n, n).set(result.status);
      m.HEAPU32.set(result.reoriented, ptr / 4 + 7 * n);
      return readSummary(m, L, m.cellSummaryOf(ptr, n, result.firstCell, worst));
    } finally {
      m._free(ptr);
    }
  });
  return result;
}

/** Async variant of joinCellKernelsSync (loads the module on first use). */
export async function joinCellKernels(parts, options = {}) {
  await init();
  return joinCellKernelsSync(parts, options);
}
