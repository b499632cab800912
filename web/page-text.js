// What the page says: the status line, the stats table, the message box, the busy line, each
// outcome's and error's text (written in outcome.js) put on the page.

import { warningInWords, messageInWords } from './alternatives.js';
import { ROWS, describeError, describeResult, sentence } from './outcome.js';
import { $, state, ui, viewer } from './page-state.js';

export const fmt = (x, digits = 6) => (Number.isFinite(x) ? Number(x.toPrecision(digits)).toString() : String(x));
// A count and its noun ("1 face", "2,048 faces").
const counted = (n, one, many = `${one}s`) => `${fmtCount(n)} ${n === 1 ? one : many}`;

// Durations: "850 ms", "1.3 s".
const fmtMs = (ms) => (ms < 1000 ? `${ms.toFixed(0)} ms` : `${(ms / 1000).toFixed(ms < 10000 ? 1 : 0)} s`);
export const fmtBytes = (n) => (n < 1e6 ? `${(n / 1e3).toFixed(0)} kB` : `${(n / 1e6).toFixed(1)} MB`);
export const fmtCount = (n) => Number(n).toLocaleString('en-US');

export function setStat(id, text, value = text) {
  const el = $(id);
  el.textContent = text;
  el.dataset.value = value === null || value === undefined ? '' : String(value);
}

export function clearStats() {
  for (const id of [
    'stat-input-faces',
    'stat-open-edges',
    'stat-planes',
    'stat-status',
    'stat-vertices',
    'stat-edges',
    'stat-faces',
    'stat-volume',
    'stat-area',
    'stat-ratio',
    'stat-kernel-point',
    'stat-deepest',
    'stat-time',
    'stat-wall',
  ])
    setStat(id, '—', '');
}

// Shows the rows of the stats table that apply (the others are hidden, not shown as 0).
export function showRows(rows) {
  for (const id of ROWS) $(`row-${id}`).hidden = !rows.includes(id);
}

// `stateName`: idle, reading, computing, cancelled, error, done; `outcome` (done only): star,
// empty, flat, open. The canvas's label says the same in words.
export function setStatus(stateName, text, value = '', outcome = '') {
  ui.status.dataset.state = stateName;
  ui.status.dataset.value = value;
  ui.status.dataset.outcome = outcome;
  ui.status.textContent = text;
  viewer.renderer.domElement.setAttribute('aria-label', `3D view${state.name ? ` of ${state.name}` : ''}: ${text}`);
  if (stateName !== 'idle') revealVerdict();
}

/**
 * Brings the verdict (the status line) and the first action offered under it into view. A load
 * starts from wherever the panel (and, on a phone, the page around it) was scrolled to reach
 * Choose…, a sample or an action, which leaves the verdict above the screen. Both scrolled back
 * to the top when that shows the verdict and the action (on a phone, under the 3D view), else
 * the verdict to the top.
 */
export function revealVerdict() {
  const panel = ui.status.closest('#panel');
  const inView = () => {
    const first = ui.actions.hidden ? null : [...ui.actions.children].find((b) => !b.hidden);
    const top = ui.status.getBoundingClientRect().top;
    const bottom = (first ?? ui.status).getBoundingClientRect().bottom;
    const box = panel.getBoundingClientRect();
    return top >= Math.max(0, box.top) && bottom <= Math.min(window.innerHeight, box.bottom);
  };
  if (inView()) return;
  document.scrollingElement.scrollTop = 0;
  panel.scrollTop = 0;
  if (!inView()) ui.status.scrollIntoView({ block: 'start' });
}

// The message box: a title and paragraphs, each its own sentence(s).
function showMessage(kind, title, paragraphs = [], code = '') {
  ui.message.hidden = false;
  ui.message.dataset.kind = kind;
  ui.message.dataset.code = code;
  ui.message.replaceChildren();
  const b = document.createElement('b');
  b.textContent = title;
  ui.message.append(b);
  for (const text of [paragraphs].flat().filter(Boolean)) addParagraph(text);
}

export function addParagraph(text) {
  const p = document.createElement('p');
  p.textContent = text;
  ui.message.append(p);
}

export function hideMessage() {
  ui.message.hidden = true;
  ui.message.dataset.kind = '';
  ui.message.dataset.code = '';
  ui.message.replaceChildren();
}

export function setBusy(text) {
  ui.busy.hidden = !text;
  if (text) ui.busyText.textContent = text;
}

// The error state (what can get an answer from the same mesh is offered by trials.js).
export function showError(err) {
  const d = describeError(err, { openEdges: state.openEdges });
  showMessage('error', d.title, d.paragraphs, d.code);
  setStatus('error', d.status, 'ERROR');
  setStat('stat-status', d.code, 'ERROR');
  showRows(d.rows);
}

const PHASE_TEXT = {
  loading: () => 'Loading the kernel module…',
  reading: (p) => `Reading ${state.name} (${fmtBytes(p.bytes ?? 0)})…`,
  computing: () => 'Computing…',
  validating: (p) => `Validating ${counted(p.count ?? 0, 'face')}…`,
  planes: (p) => `Merging planes of ${counted(p.count ?? 0, 'face')}…`,
  lp: (p) => `Finding a kernel point (LP over ${counted(p.count ?? 0, 'plane')})…`,
  tracing: (p) => `Tracing the kernel · ${fmtCount(p.steps)} steps…`,
  assembling: (p) => `Assembling the kernel (${fmtCount(p.count ?? 0)})…`,
  done: () => 'Drawing…',
};

export function onProgress(p) {
  if (!state.phases.includes(p.phase)) {
    state.phases.push(p.phase);
    ui.busy.dataset.phases = state.phases.join(',');
  }
  setBusy((PHASE_TEXT[p.phase] ?? (() => `${p.phase}…`))(p));
}

export function showCancelled() {
  const steps = viewer.kernel.length;
  showMessage(
    'info',
    'Cancelled.',
    steps > 0
      ? `The computation was stopped; the ${fmtCount(steps)} steps that had arrived (part of the kernel's boundary) are still shown.`
      : 'The computation was stopped before any part of the kernel had arrived; nothing of it is shown.',
    'CANCELLED',
  );
  setStatus('cancelled', 'Cancelled.', 'CANCELLED');
  showRows(['name', 'input-faces']);
}

export function showStats(result, wall, V, E, F) {
  const s = result.stats ?? {};
  setStat(
    'stat-input-faces',
    `${s.inputFaces != null ? fmtCount(s.inputFaces) : '—'}${s.droppedFaces ? ` (${s.droppedFaces} zero-area dropped)` : ''}`,
    s.inputFaces,
  );
  const planesNote = [
    s.activePlanes != null ? `${s.activePlanes} active` : null,
    s.culledFaces ? `${counted(s.culledFaces, 'face')} culled first` : null,
  ]
    .filter(Boolean)
    .join(', ');
  setStat(
    'stat-planes',
    `${s.distinctPlanes != null ? fmtCount(s.distinctPlanes) : '—'}${planesNote ? ` (${planesNote})` : ''}`,
    s.distinctPlanes,
  );
  setStat('stat-status', result.status + (result.complete === false ? ' (partial)' : ''), result.status);
  setStat('stat-vertices', String(V), V);
  setStat('stat-edges', String(E), E);
  setStat('stat-faces', String(F), F);
  setStat('stat-volume', fmt(result.volume, 10), result.volume);
  setStat('stat-ratio', `${fmt(100 * result.volumeRatio, 4)} %`, result.volumeRatio);
  setStat('stat-area', fmt(result.area, 10), result.area);
  const kp = result.kernelPoint;
  setStat('stat-kernel-point', kp ? `(${kp.map((x) => fmt(x, 7)).join(', ')})` : 'none', kp ? kp.join(',') : '');
  const dp = result.deepestPoint;
  setStat(
    'stat-deepest',
    dp ? `(${dp.map((x) => fmt(x, 7)).join(', ')}), inscribed ball radius ${fmt(result.inscribedRadius, 6)}` : '—',
    dp ? [...dp, result.inscribedRadius].join(',') : '',
  );
  setStat(
    'stat-time',
    s.msTotal != null ? `${fmtMs(s.msTotal)} (LP ${fmtMs(s.msLp ?? 0)}, trace ${fmtMs(s.msTrace ?? 0)})` : '—',
    s.msTotal,
  );
  const tm = state.timing;
  const parts = [
    tm.read != null && `read ${fmtMs(tm.read)}`,
    tm.tried ? 'computed while trying the ways offered' : `worker round trip ${fmtMs(tm.worker)}`,
    tm.view != null && `view ${fmtMs(tm.view)}`,
  ].filter(Boolean);
  setStat('stat-wall', `${fmtMs(wall)} (${parts.join(', ')})`, wall);
  viewer.setKernelPoint(kp);
  viewer.setBall(dp, result.inscribedRadius, result.volume);
  viewer.setKernelClosed(result.status === 'POLYHEDRON' || result.status === 'UNBOUNDED');
}

export function showOutcome(result, V, E, F, extra) {
  const d = describeResult(result, V, E, F, extra);
  setStatus('done', d.status, result.status, d.outcome);
  showRows(d.rows);
  if (d.kind) showMessage(d.kind, d.title, d.paragraphs, result.status);
  if (result.warnings?.length) {
    const text = result.warnings
      .map((w) => warningInWords(w) ?? sentence(messageInWords(w.message) || `${w.kind} (${w.count})`))
      .join(' ');
    if (ui.message.hidden) showMessage('info', 'Note', [text], 'WARNINGS');
    else addParagraph(`Note: ${text}`);
  }
  setExportEnabled(result.triangles?.length > 0);
  ui.faceHint.hidden = !(result.faceSources?.length > 0);
}

export function setExportEnabled(on) {
  ui.exportObj.disabled = ui.exportStl.disabled = ui.exportOff.disabled = !on;
}
