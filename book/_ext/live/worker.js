// The Python of the book's live cells: Pyodide in a module Web Worker, so the page stays responsive.
// Every file comes from the book's own folder (_static/live/), never from the network.
//
// Python starts from a memory snapshot made when the book was built (snapshot.mjs): Pyodide with SymPy
// and pgsym already imported, so the page skips most of the start-up. Without it (not built, or made
// by another Pyodide) Python starts in full and imports SymPy here.
import { loadPyodide } from "./pyodide/pyodide.mjs";

const here = new URL(".", import.meta.url);
const pyodideURL = new URL("pyodide/", here);
let kernel = null;

function progress(text) {
  postMessage({ type: "progress", text });
}

// Moments of the start-up, on the page's clock (the page records them with performance.mark).
function mark(name) {
  postMessage({ type: "mark", name, time: performance.timeOrigin + performance.now() });
}

mark("worker");

async function fetchOk(path, options) {
  const response = await fetch(new URL(path, here), options);
  if (!response.ok) throw new Error(`could not load ${path} (HTTP ${response.status})`);
  return response;
}

// After a restore the wheels are imported as zip files from /lib/wheels (the snapshot was made with the
// same files at the same place): writing them is a copy, and Python reads only the modules it imports.
const WHEELS = "/lib/wheels";

// The snapshot's bytes as they download (its pages of zeros are not stored: snapshot.json says where
// the stored runs go), or null when the book has none.
async function snapshotBytes() {
  let layout, response;
  try {
    [layout, response] = await Promise.all([
      fetchOk("pyodide/snapshot.json").then((r) => r.json()),
      fetchOk("pyodide/snapshot.bin", { priority: "high" }),
    ]);
  } catch {
    return null;
  }
  return response.arrayBuffer().then((buffer) => {
    const stored = new Uint8Array(buffer);
    const snapshot = new Uint8Array(layout.bytes);
    let at = 0;
    for (const [start, length] of layout.runs) {
      snapshot.set(stored.subarray(at, at + length), start);
      at += length;
    }
    mark("snapshot-fetched");
    return snapshot;
  });
}

// Pyodide from the snapshot. Its memory is made as large as the snapshot's before the bytes are
// copied in (Pyodide 314 leaves it at its initial size, too small for SymPy).
async function restore(bytes) {
  const { default: createModule } = await import(new URL("pyodide.asm.mjs", pyodideURL).href);
  const createPyodideModule = async (settings) => {
    const module = await createModule(settings);
    const snapshot = await bytes;
    const size = snapshot.length - new DataView(snapshot.buffer).getUint32(4, true);
    if (module.HEAP8.length < size && !module._emscripten_resize_heap(size)) throw new Error("out of memory");
    return module;
  };
  const pyodide = await loadPyodide({ indexURL: pyodideURL.href, _loadSnapshot: bytes, createPyodideModule });
  // the snapshot fixed the state of `random` for every reader: seed it afresh
  pyodide.runPython("import random\nrandom.seed()");
  return pyodide;
}

async function boot() {
  progress("Loading Python …");
  const snapshot = snapshotBytes();
  // the wheels and the kernel download while Pyodide starts
  const downloads = fetchOk("wheels/manifest.json")
    .then((response) => response.json())
    .then(({ wheels }) => Promise.all(wheels.map(async (name) => [name, await (await fetchOk(`wheels/${name}`)).arrayBuffer()])));
  const kernelSource = fetchOk("live_kernel.py").then((response) => response.text());
  // the book's own pure modules (_show.py), importable from every cell
  const modules = fetchOk("modules/manifest.json")
    .then((response) => response.json())
    .then(({ modules: names }) => Promise.all(names.map(async (name) => [name, await (await fetchOk(`modules/${name}`)).text()])));
  // awaited below; observed now so that a failed download is reported once, by the Run that waits
  downloads.catch(() => {});
  kernelSource.catch(() => {});
  modules.catch(() => {});
  let pyodide = null;
  const bytes = await snapshot;
  if (bytes) {
    try {
      pyodide = await restore(bytes);
    } catch (error) {
      console.warn(`live cells: the Python snapshot did not load (${error?.message ?? error}); starting Python in full`);
    }
  }
  const restored = pyodide !== null;
  pyodide ??= await loadPyodide({ indexURL: pyodideURL.href });
  mark(restored ? "python-restored" : "python-started");
  if (!restored) progress("Loading SymPy …");
  if (restored) {
    // where the snapshot expects them (it imported SymPy and pgsym from there)
    pyodide.FS.mkdirTree(WHEELS);
    for (const [name, bytes] of await downloads) pyodide.FS.writeFile(`${WHEELS}/${name}`, new Uint8Array(bytes));
  } else {
    // unpacked: a full import of SymPy from files is faster than from the zip files
    for (const [, bytes] of await downloads) pyodide.unpackArchive(new Uint8Array(bytes), "wheel");
  }
  const site = pyodide.runPython("import site; site.getsitepackages()[0]");
  pyodide.FS.writeFile(`${site}/live_kernel.py`, await kernelSource);
  for (const [name, text] of await modules) pyodide.FS.writeFile(`${site}/${name}`, text);
  mark("wheels-installed");
  if (!restored) {
    // SymPy is imported here, once, so that the reader sees what the wait is for.
    pyodide.runPython("import live_kernel, sympy\nlive_kernel.install_ipython_shim()");
    mark("sympy-imported");
  }
  kernel = pyodide.runPython("live_kernel.Kernel()");
  mark("ready");
  postMessage({ type: "ready", snapshot: restored });
}

let booting = null;
let chain = Promise.resolve();

// Cells run one after another, in the order the page sends them, like a notebook kernel's queue.
onmessage = (event) => {
  const { id, code, stubs, boot: bootOnly } = event.data;
  if (bootOnly) {
    // a failure is reported to the Run that follows, which awaits the same promise
    chain = chain.then(() => (booting ??= boot()).catch(() => {}));
    return;
  }
  chain = chain.then(async () => {
    try {
      await (booting ??= boot());
      postMessage({ type: "started", id });
      const outputs = JSON.parse(kernel.run_json(code, JSON.stringify(stubs)));
      mark(`cell-${id}`);
      postMessage({ type: "result", id, outputs });
    } catch (error) {
      postMessage({ type: "failed", id, message: String(error?.message ?? error) });
    }
  });
};
