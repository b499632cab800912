// Test-only: runs inside a worker_thread and gives the worker script a Web Worker global scope
// (self, self.onmessage, self.postMessage), then imports it.
import { parentPort, workerData } from 'node:worker_threads';

globalThis.self = globalThis;
globalThis.postMessage = (data, transfer) => parentPort.postMessage(data, transfer);
let loaded = false;
const early = [];
parentPort.on('message', (data) => {
  if (!loaded) early.push(data);
  else if (typeof globalThis.onmessage === 'function') globalThis.onmessage({ data });
});
await import(workerData.url);
loaded = true;
for (const data of early) if (typeof globalThis.onmessage === 'function') globalThis.onmessage({ data });
