// The page's state in its URL: what is open (?sample=<id> or ?url=<http(s) URL>), how it was
// computed (allowOpen=1, open=perpendicular, repair=1, weld=1, flipFaces=1) and the view options that differ from the defaults, so that a
// copied link reopens the same view.

export const VIEW_DEFAULTS = Object.freeze({
  opacity: 0.22,
  shape: true,
  edges: null,
  ball: true,
  section: false,
  axis: 'z',
  pos: 0.5,
  clipKernel: true,
});

const AXES = ['x', 'y', 'z'];
const clamp01 = (x, fallback) => (Number.isFinite(x) ? Math.min(1, Math.max(0, x)) : fallback);
const flag = (params, key, fallback) => (params.has(key) ? params.get(key) !== '0' : fallback);

/** View options read from URL parameters (defaults for what is absent or malformed). */
export function viewFromParams(params) {
  const d = VIEW_DEFAULTS;
  const section = params.get('section'); // "<axis>:<position 0..1>", e.g. "z:0.4"
  const [axis, pos] = section ? section.split(':') : [];
  return {
    opacity: params.has('opacity') ? clamp01(Number(params.get('opacity')), d.opacity) : d.opacity,
    shape: flag(params, 'shape', d.shape),
    edges: params.has('edges') ? params.get('edges') !== '0' : d.edges,
    ball: flag(params, 'ball', d.ball),
    section: !!section && AXES.includes(axis),
    axis: AXES.includes(axis) ? axis : d.axis,
    pos: clamp01(Number(pos), d.pos),
    clipKernel: flag(params, 'clipKernel', d.clipKernel),
  };
}

/**
 * The URL that reopens `source` ({ kind: 'sample', id } or { kind: 'url', url }; anything else
 * cannot be reopened by a link: null) with `options` ({ allowOpen, walls, repair, weld, flipFaces }) and `view`.
 */
export function shareUrl(base, source, options, view) {
  if (source?.kind !== 'sample' && source?.kind !== 'url') return null;
  const url = new URL(base);
  url.search = '';
  url.hash = '';
  const p = url.searchParams;
  if (source.kind === 'sample') p.set('sample', source.id);
  else p.set('url', source.url);
  if (options.allowOpen) p.set('allowOpen', '1');
  if (options.repair) p.set('repair', '1');
  if (options.walls) p.set('open', 'perpendicular');
  if (options.weld) p.set('weld', '1');
  if (options.flipFaces) p.set('flipFaces', '1');
  const d = VIEW_DEFAULTS;
  if (view.opacity !== d.opacity) p.set('opacity', String(view.opacity));
  if (view.shape !== d.shape) p.set('shape', view.shape ? '1' : '0');
  if (view.edges !== d.edges && view.edges !== null) p.set('edges', view.edges ? '1' : '0');
  if (view.ball !== d.ball) p.set('ball', view.ball ? '1' : '0');
  if (view.section) p.set('section', `${view.axis}:${view.pos}`);
  if (view.section && view.clipKernel !== d.clipKernel) p.set('clipKernel', view.clipKernel ? '1' : '0');
  return url.href;
}
