// After a refusal: the alternatives its message proposes (alternatives.js) are computed in the
// kernel worker, one after another, and then offered best first, each with what it gives and why
// (the repairs it made, in the page's words). Meshes too big to keep for this (state.input null)
// get the same buttons untried, in the default order.

import {
  ALTERNATIVES,
  candidatesFor,
  rankTrials,
  trialInWords,
  failureInWords,
  kernelOptions,
  facesPointInward,
  warningInWords,
} from './alternatives.js';
import { state, ui } from './page-state.js';
import { addParagraph, revealVerdict, setBusy } from './page-text.js';
import { worker } from './workers.js';

const BUTTONS = ['retryFlip', 'retryRepair', 'retryWeld', 'retryWalls', 'retryOpen'];

/** Hides every retry button (a new run, or nothing to offer). */
export function hideAlternatives() {
  for (const id of BUTTONS) ui[id].hidden = true;
  ui.actions.hidden = true;
  ui.actions.dataset.state = ''; // 'trying' while the alternatives are computed, then 'ready' or 'none'
}

// Computes each alternative of `ids` on the kept input; null when a newer run took over.
async function runTrials(ids, token) {
  const { mesh, options } = state.input;
  const trials = {};
  const results = {};
  state.trying = true;
  ui.cancel.disabled = false; // trials can take a while on a big mesh
  const tryOne = async (id) => {
    setBusy(`Trying first: ${ALTERNATIVES[id].label.toLowerCase()}…`);
    const run = { ...state.runOptions, ...ALTERNATIVES[id].options };
    try {
      const r = await worker().compute(mesh.positions, mesh.indices, {
        faceSizes: mesh.faceSizes,
        ...options,
        ...kernelOptions(run),
      });
      trials[id] = { status: r.status, volume: r.volume, warnings: r.warnings };
      results[id] = r;
    } catch (err) {
      if (token !== state.token) return null;
      if (err?.code === 'CANCELLED') return 'cancelled'; // the Cancel button: offer them untried
      trials[id] = { error: err?.code ?? 'ERROR', message: err?.message ?? String(err) };
    }
    return token === state.token ? 'tried' : null;
  };
  try {
    for (const id of ids) {
      // Merging close vertices is tried only when repair alone (equal positions) is refused.
      if ((id === 'weldRepair' || id === 'weld') && trials.repair && !trials.repair.error) continue;
      const outcome = await tryOne(id);
      if (outcome !== 'tried') return outcome;
    }
    // An open surface given inside out (the core says so in the accepted trials' warnings): the
    // same with its faces turned over, never done without asking.
    const inward = Object.values(trials).some((t) => facesPointInward(t.warnings));
    if (inward && !state.runOptions.flipFaces) {
      const outcome = await tryOne('flipWalls');
      if (outcome !== 'tried') return outcome;
    }
  } finally {
    state.trying = false;
    ui.cancel.disabled = true;
    setBusy('');
  }
  return { trials, results };
}

/**
 * Offers what can get an answer from a mesh refused with `code`: tried first when the input is
 * kept, then the buttons that worked in order (best first) with a paragraph each; what was tried
 * and refused is said in one line each. `token`: the refused run's.
 */
export async function offerAlternatives(code, token) {
  hideAlternatives();
  const reopenable = !!state.source && state.inputShown;
  const ids = reopenable ? candidatesFor(code, state.runOptions) : [];
  if (!ids.length) {
    ui.actions.dataset.state = 'none';
    return;
  }
  let ranked, trials, tried;
  ui.actions.dataset.state = 'trying';
  if (state.input) {
    tried = await runTrials(ids, token);
    if (!tried) return;
  }
  const cancelled = tried === 'cancelled';
  if (tried && !cancelled) {
    trials = tried.trials;
    ranked = rankTrials(trials);
    state.trials = { source: state.source, trials, ranked, results: tried.results };
  } else {
    ranked = ids.filter((id) => id !== 'weldRepair');
    trials = null;
  }
  // One button per alternative: the first that worked of those sharing it (repair, or merge + repair).
  const shown = new Set();
  const order = [];
  for (const id of ranked) {
    const button = ALTERNATIVES[id].button;
    if (shown.has(button)) continue;
    shown.add(button);
    order.push(id);
    const el = ui[button];
    el.dataset.alt = id;
    el.dataset.outcome = trials ? trials[id].status : '';
    el.textContent = ALTERNATIVES[id].label;
    el.hidden = false;
  }
  ui.actions.replaceChildren(
    ...order.map((id) => ui[ALTERNATIVES[id].button]),
    ...BUTTONS.filter((b) => !shown.has(b)).map((b) => ui[b]),
  );
  ui.actions.hidden = order.length === 0;
  if (trials) {
    const inward = Object.values(trials).find((t) => facesPointInward(t.warnings));
    if (inward) addParagraph(warningInWords(inward.warnings.find((w) => w.kind === 'FACES_POINT_INWARD')));
    if (order.length) addParagraph('Each way offered above was computed first; the first gives the best answer.');
    for (const id of order) addParagraph(trialInWords(id, trials[id], trials));
    for (const [id, t] of Object.entries(trials)) if (t.error) addParagraph(failureInWords(id, t));
  } else {
    addParagraph(
      cancelled
        ? 'Trying these first was cancelled: they are offered untried.'
        : 'The mesh is too large to try these first: they are offered untried.',
    );
  }
  ui.actions.dataset.state = order.length ? 'ready' : 'none';
  revealVerdict();
}
