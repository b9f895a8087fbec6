// Build step of the live cells (`make live`): a memory snapshot of Pyodide with SymPy and pgsym imported.
// The page's worker restores it instead of starting Python and importing SymPy and pgsym, which is
// most of the wait before the first result. Made here in Node from the same pyodide.asm.wasm the page
// loads (the snapshot carries its build id, and the worker falls back to a full start on a mismatch).
//
//   node snapshot.mjs LIVE_DIR      writes LIVE_DIR/pyodide/snapshot.bin and snapshot.json
import { readFileSync, writeFileSync } from "node:fs";
import { join, resolve } from "node:path";
import { pathToFileURL } from "node:url";

const live = resolve(process.argv[2] ?? "_live/_static/live");
const { loadPyodide } = await import(pathToFileURL(join(live, "pyodide", "pyodide.mjs")).href);
const pyodide = await loadPyodide({ indexURL: `${join(live, "pyodide")}/`, _makeSnapshot: true });
// The wheels are imported as zip files from /lib/wheels, as in the page (worker.js), which writes the
// same files at the same place: Python reads them only for modules the snapshot did not import.
const { wheels } = JSON.parse(readFileSync(join(live, "wheels", "manifest.json"), "utf8"));
pyodide.FS.mkdirTree("/lib/wheels");
for (const name of wheels) pyodide.FS.writeFile(`/lib/wheels/${name}`, readFileSync(join(live, "wheels", name)));
pyodide.runPython(`import sys\nsys.path += ["/lib/wheels/" + name for name in ${JSON.stringify(wheels)}]`);
const site = pyodide.runPython("import site; site.getsitepackages()[0]");
pyodide.FS.writeFile(`${site}/live_kernel.py`, readFileSync(join(live, "live_kernel.py"), "utf8"));
// What the worker would import before the first cell, and every public name of pgsym that loads in
// the page (the NumPy parts do not), so that no chapter's cells wait for an import. A throwaway cell
// then runs what a first cell does (a meet, its display as LaTeX, a determinant), so that SymPy's own
// first-use work (printers, caches) is done as well.
pyodide.runPython(`
import live_kernel, sympy
live_kernel.install_ipython_shim()
import pgsym
for name in pgsym.__all__:
    try:
        getattr(pgsym, name)
    except ImportError:
        pass
outputs = live_kernel.Kernel().run("""
from fractions import Fraction
import sympy as sp
from IPython.display import display
from pgsym import Line, Point, join, meet
a, b = sp.symbols("a b")
X = meet(Line(a, 0, -1), Line(0, b, Fraction(-1, 2)))
display(X, join(Point(1, 2), X), sp.Matrix([[a, 1], [2, b]]).det())
print(X.dehomogenize(), X == Point(1, 1))
""")
failed = [o for o in outputs if o["type"] == "error"]
if failed:
    raise RuntimeError(f"the warm-up cell failed: {failed}")
del name, outputs, failed
`);
const snapshot = pyodide.makeMemorySnapshot();
// A quarter of the memory is pages of zeros (free space): only the other pages are stored, in order,
// in snapshot.bin; snapshot.json says where each run of them goes (worker.js puts them back).
const PAGE = 65536;
const runs = [];
for (let start = 0; start < snapshot.length; start += PAGE) {
  const page = snapshot.subarray(start, start + PAGE);
  if (page.every((byte) => byte === 0)) continue;
  const last = runs.at(-1);
  if (last && last[0] + last[1] === start) last[1] += page.length;
  else runs.push([start, page.length]);
}
const stored = Buffer.concat(runs.map(([start, length]) => snapshot.subarray(start, start + length)));
writeFileSync(join(live, "pyodide", "snapshot.bin"), stored);
writeFileSync(join(live, "pyodide", "snapshot.json"), JSON.stringify({ bytes: snapshot.length, runs }));
const mb = (n) => `${(n / 1e6).toFixed(1)} MB`;
console.log(`Pyodide snapshot with SymPy and pgsym: ${mb(stored.length)} (${mb(snapshot.length)} in memory)`);
