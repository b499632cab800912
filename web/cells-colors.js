// Colours of the volume-mesh page: a perceptually uniform colour map (viridis) for a cell's
// kernel ratio or ρ/h, and the fixed colours of the cells that have no value (not star-shaped,
// or an error), shared by the 3D view and the legend.

// Viridis at 9 evenly spaced stops (matplotlib's table), linearly interpolated between them.
const VIRIDIS = [
  [0.267, 0.005, 0.329],
  [0.283, 0.141, 0.458],
  [0.254, 0.265, 0.53],
  [0.207, 0.372, 0.553],
  [0.164, 0.471, 0.558],
  [0.128, 0.567, 0.551],
  [0.135, 0.659, 0.518],
  [0.267, 0.749, 0.441],
  [0.478, 0.821, 0.318],
  [0.741, 0.873, 0.15],
  [0.993, 0.906, 0.144],
];

export const NON_STAR_COLOR = [0.88, 0.15, 0.62]; // magenta, as the main page's witness faces
export const ERROR_COLOR = [0.55, 0.55, 0.58];

/** The colour map at t in [0, 1] (clamped) as [r, g, b] in 0..1. */
export function colorAt(t) {
  const x = Math.min(1, Math.max(0, Number.isFinite(t) ? t : 0)) * (VIRIDIS.length - 1);
  const i = Math.min(VIRIDIS.length - 2, Math.floor(x));
  const f = x - i;
  const a = VIRIDIS[i],
    b = VIRIDIS[i + 1];
  return [a[0] + f * (b[0] - a[0]), a[1] + f * (b[1] - a[1]), a[2] + f * (b[2] - a[2])];
}

export const cssColor = ([r, g, b]) => `rgb(${Math.round(255 * r)}, ${Math.round(255 * g)}, ${Math.round(255 * b)})`;

/** A CSS linear-gradient of the colour map, left (0) to right (1). */
export function gradientCss() {
  const stops = [];
  for (let i = 0; i <= 10; i++) stops.push(`${cssColor(colorAt(i / 10))} ${i * 10}%`);
  return `linear-gradient(to right, ${stops.join(', ')})`;
}

/**
 * What the cells are coloured by: the quantity's values, its range, and its label.
 * `result` is computeCellKernels' result; `by` 'ratio' or 'rho'.
 */
export function coloring(result, by) {
  if (by === 'rho' && result.summary.hasRhoOverH) {
    return {
      by,
      values: result.rhoOverH,
      min: 0,
      max: Math.max(result.summary.maxRhoOverH, 1e-12),
      label: 'ρ / h: inscribed-ball radius of the kernel over the cell diameter',
    };
  }
  return { by: 'ratio', values: result.kernelRatio, min: 0, max: 1, label: 'kernel volume / cell volume' };
}

/** The status code of a cell that is not star-shaped (the EMPTY kernel's, from the result). */
export const emptyCode = (result) =>
  Number(Object.keys(result.statusNames).find((k) => result.statusNames[k] === 'EMPTY'));

/** The colour of cell `c`: the map for a star-shaped cell, else the marks (errors: negative codes). */
export function cellColor(result, col, c, empty = emptyCode(result)) {
  const status = result.status[c];
  if (status < 0) return ERROR_COLOR;
  if (status === empty) return NON_STAR_COLOR;
  return colorAt((col.values[c] - col.min) / (col.max - col.min));
}
