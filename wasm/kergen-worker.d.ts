// The worker script spawned by KernelWorker; it exports nothing.
export {};
