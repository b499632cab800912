// The names of the compute options, by kind: checks.js validates each kind, and the page side of
// KernelWorker forwards exactly these to the worker (callbacks and mesh arrays travel apart).
export const COUNT_OPTIONS = ['maxFaces', 'maxVertices', 'seed'];
export const BOOLEAN_OPTIONS = ['allowOpen', 'deepestPoint', 'cullFaces', 'repair', 'flipFaces'];
export const OPTION_NAMES = ['from', 'maxSteps', ...COUNT_OPTIONS, ...BOOLEAN_OPTIONS, 'weld', 'open'];
