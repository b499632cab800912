// KergenError lives in its own tiny module so that the worker helper (worker.js) can use it on the
// main thread without loading the WebAssembly glue there.

/** Error thrown by every function of this package; `code` says what went wrong. */
export class KergenError extends Error {
  constructor(code, message, options) {
    super(message, options);
    this.name = 'KergenError';
    this.code = code;
  }
}
