// The Python of the book's live cells: Pyodide in a module Web Worker, so the page stays responsive.
// Every file comes from the book's own folder (_static/live/), never from the network.
import { loadPyodide } from "./pyodide/pyodide.mjs";

const here = new URL(".", import.meta.url);
let kernel = null;

function progress(text) {
  postMessage({ type: "progress", text });
}

async function fetchOk(path) {
  const response = await fetch(new URL(path, here));
  if (!response.ok) throw new Error(`could not load ${path} (HTTP ${response.status})`);
  return response;
}

async function boot() {
  progress("Loading Python …");
  // the wheels and the kernel download while Pyodide starts
  const downloads = fetchOk("wheels/manifest.json")
    .then((response) => response.json())
    .then(({ wheels }) => Promise.all(wheels.map(async (name) => (await fetchOk(`wheels/${name}`)).arrayBuffer())));
  const kernelSource = fetchOk("live_kernel.py").then((response) => response.text());
  // the book's own pure modules (_show.py), importable from every cell
  const modules = fetchOk("modules/manifest.json")
    .then((response) => response.json())
    .then(({ modules: names }) => Promise.all(names.map(async (name) => [name, await (await fetchOk(`modules/${name}`)).text()])));
  // awaited below; observed now so that a failed download is reported once, by the Run that waits
  downloads.catch(() => {});
  kernelSource.catch(() => {});
  modules.catch(() => {});
  const pyodide = await loadPyodide({ indexURL: new URL("pyodide/", here).href });
  progress("Loading SymPy …");
  for (const bytes of await downloads) pyodide.unpackArchive(new Uint8Array(bytes), "wheel");
  const site = pyodide.runPython("import site; site.getsitepackages()[0]");
  pyodide.FS.writeFile(`${site}/live_kernel.py`, await kernelSource);
  for (const [name, text] of await modules) pyodide.FS.writeFile(`${site}/${name}`, text);
  // SymPy is imported here, once, so that the reader sees what the wait is for.
  pyodide.runPython("import live_kernel, sympy\nlive_kernel.install_ipython_shim()");
  kernel = pyodide.runPython("live_kernel.Kernel()");
  postMessage({ type: "ready" });
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
      postMessage({ type: "result", id, outputs: JSON.parse(kernel.run_json(code, JSON.stringify(stubs))) });
    } catch (error) {
      postMessage({ type: "failed", id, message: String(error?.message ?? error) });
    }
  });
};
