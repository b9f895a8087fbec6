// Live cells: Edit / Run / Reset controls on the book's code cells. Python runs in a Web Worker
// (worker.js, Pyodide). It starts loading as soon as this script has loaded (when the browser asks to
// save data, only once the reader points at or focuses a live cell, or clicks Edit or Run), so that a
// Run right after the page loads waits as little as possible; the editor (editor.js, CodeMirror)
// loads on the first Edit. Which cells can run was decided when the book was built
// (book/_ext/live_cells.py).
performance.mark("live:script");
const here = new URL(".", import.meta.url);

let worker = null;
let nextId = 1;
const pending = new Map(); // request id -> {resolve, onStart}
let statusCell = null; // the cell whose status line shows the worker's progress
let lastProgress = null; // what the worker is doing while Python starts; null once it has run a cell

function startWorker() {
  worker = new Worker(new URL("worker.js", here), { type: "module" });
  worker.onmessage = ({ data: message }) => {
    if (message.type === "mark") {
      // the worker's start-up on the page's timeline (performance.getEntriesByType("mark"))
      performance.mark(`live:${message.name}`, { startTime: message.time - performance.timeOrigin });
      return;
    }
    if (message.type === "ready") {
      document.documentElement.dataset.livePython = "ready";
      // how Python started: from the book's snapshot, or in full when the page could not use it
      document.documentElement.dataset.livePythonStart = message.snapshot ? "snapshot" : "full";
      lastProgress = null;
      return;
    }
    if (message.type === "progress") {
      if (message.text === "Running …") return;
      lastProgress = message.text;
      if (statusCell) statusCell.status(message.text);
      return;
    }
    lastProgress = null;
    const request = pending.get(message.id);
    if (!request) return;
    if (message.type === "started") {
      request.onStart();
      return;
    }
    pending.delete(message.id);
    request.resolve(
      message.type === "result"
        ? message.outputs
        : [{ type: "error", ename: "LoadError", evalue: `Python could not start in this page: ${message.message}`, traceback: "" }],
    );
  };
  worker.onerror = (event) => {
    event.preventDefault();
    for (const [id, request] of pending) {
      pending.delete(id);
      request.resolve([{ type: "error", ename: "LoadError", evalue: `Python could not start in this page: ${event.message}`, traceback: "" }]);
    }
  };
}

// A page with live cells, pointing at a cell or Edit announce a Run: Python starts loading then.
function warmUp() {
  if (worker) return;
  startWorker();
  document.documentElement.dataset.livePython = "loading";
  lastProgress = "Loading Python …";
  worker.postMessage({ boot: true });
}

function execute(code, stubs, onStart) {
  if (!worker) startWorker();
  const id = nextId++;
  return new Promise((resolve) => {
    pending.set(id, { resolve, onStart });
    worker.postMessage({ id, code, stubs });
  });
}

function element(tag, attributes = {}, text = "") {
  const node = document.createElement(tag);
  for (const [key, value] of Object.entries(attributes)) node.setAttribute(key, value);
  if (text) node.textContent = text;
  return node;
}

async function typeset(node) {
  const mathjax = window.MathJax;
  if (!mathjax?.startup?.promise) return;
  await mathjax.startup.promise;
  await mathjax.typesetPromise([node]);
}

// Jupyter's order of preference, as the book's stored outputs were rendered.
function renderBundle(bundle) {
  if ("text/html" in bundle) {
    const node = element("div", { class: "live-html output_area" });
    node.innerHTML = bundle["text/html"];
    return node;
  }
  if ("text/latex" in bundle) {
    const latex = bundle["text/latex"].replace(/^\$+|\$+$/g, "");
    return element("div", { class: "live-latex math notranslate nohighlight" }, `\\[${latex}\\]`);
  }
  return element("pre", { class: "live-text" }, bundle["text/plain"] ?? "");
}

function renderOutput(output) {
  if (output.type === "stream") return element("pre", { class: `live-stream live-${output.name}` }, output.text);
  if (output.type === "error") {
    const box = element("div", { class: "live-error", role: "alert" });
    const line = element("p", { class: "live-error-message" });
    line.append(element("strong", { class: "live-error-name" }, output.ename), `: ${output.evalue}`);
    box.append(line);
    if (output.traceback) {
      const details = element("details", { class: "live-traceback" });
      details.append(element("summary", {}, "Traceback"), element("pre", {}, output.traceback));
      box.append(details);
    }
    return box;
  }
  return renderBundle(output.data);
}

class LiveCell {
  constructor(index, info, node) {
    Object.assign(this, { index, node, source: info.source, live: info.live, reason: info.reason, stubs: info.stubs });
    // a cell that cannot run still runs its statements that can (its imports, its SymPy), silently
    this.quiet = info.quiet ?? "";
    this.ran = false;
    this.editor = null;
    this.input = node.querySelector(".cell_input");
    this.stored = node.querySelector(".cell_output");
    node.classList.add("live-cell");
    this.output = element("div", { class: "live-output", "aria-live": "polite", hidden: "" });
    node.append(this.output);
    if (info.hidden) {
      // code the reader does not see (the chapter's imports) runs before the cells below, without controls
      node.dataset.liveState = this.live ? "idle" : "disabled";
      node.dataset.liveHidden = "";
      return;
    }
    this.toolbar = element("div", { class: "live-toolbar", role: "toolbar", "aria-label": `Live cell ${index + 1}` });
    node.prepend(this.toolbar);
    if (!this.live) {
      this.disable(data.local);
      return;
    }
    this.buttons = {
      edit: this.button("Edit", "Edit this cell", () => this.edit()),
      run: this.button("Run", "Run this cell (Shift+Enter)", () => this.run()),
      reset: this.button("Reset", "Reset this cell to the book's code and output", () => this.reset()),
    };
    node.addEventListener("pointerenter", warmUp, { once: true });
    node.addEventListener("focusin", warmUp, { once: true });
    if (this.input) {
      this.input.setAttribute("tabindex", "0");
      this.input.setAttribute("aria-label", `Code of cell ${index + 1}; Shift+Enter runs it`);
    }
    // Capture phase: Shift+Enter runs the cell before the editor would insert a line break.
    node.addEventListener("keydown", (event) => {
      if (event.key === "Enter" && event.shiftKey && !event.altKey && !event.ctrlKey && !event.metaKey) {
        event.preventDefault();
        event.stopPropagation();
        this.run();
      }
    }, true);
    node.dataset.liveState = "idle";
  }

  button(text, label, action) {
    const button = element("button", { type: "button", class: "live-button", "aria-label": label, title: label }, text);
    button.addEventListener("click", action);
    this.toolbar.append(button);
    return button;
  }

  disable(local) {
    const reasonId = `live-reason-${this.index}`;
    for (const [text, label] of [["Edit", "Edit this cell"], ["Run", "Run this cell"], ["Reset", "Reset this cell"]]) {
      const button = element("button", { type: "button", class: "live-button", "aria-label": `${label} (not available in the page)`, "aria-describedby": reasonId, disabled: "" }, text);
      this.toolbar.append(button);
    }
    const note = element("p", { class: "live-reason", id: reasonId }, `${this.reason}. Run it locally: `);
    note.append(element("code", {}, local));
    this.toolbar.append(note);
    this.node.dataset.liveState = "disabled";
  }

  code() {
    return this.editor ? this.editor.getCode() : this.source;
  }

  status(text) {
    this.output.hidden = false;
    this.output.replaceChildren(element("p", { class: "live-status", role: "status" }, text));
  }

  async edit() {
    if (this.editor) {
      this.editor.focus();
      return;
    }
    warmUp();
    const { createEditor } = await import(new URL("editor.js", here).href);
    const host = element("div", { class: "live-editor" });
    this.input.after(host);
    this.editor = createEditor(host, this.source, `Code of cell ${this.index + 1}; Shift+Enter runs it`);
    this.input.hidden = true;
    this.editor.focus();
  }

  async run() {
    if (this.node.dataset.liveState === "running") return;
    performance.mark("live:run");
    // The first time, the earlier cells run in order, so that their imports and names exist.
    const batch = cells.filter((c) => (c.live || c.quiet) && c.index < this.index && !c.ran);
    batch.push(this);
    for (const cell of batch) {
      cell.ran = true;
      cell.node.dataset.liveState = "running";
    }
    statusCell = this;
    this.status(worker ? lastProgress ?? "Running …" : "Loading Python …");
    const results = batch.map((cell, k) =>
      execute(cell.live ? cell.code() : cell.quiet, cell.stubs, () => {
        if (cell !== this) this.status(`Running the cells above (${k + 1} of ${batch.length - 1}) …`);
        else this.status("Running …");
      }),
    );
    for (const [k, cell] of batch.entries()) {
      const outputs = await results[k];
      // Earlier cells stay quiet unless they fail: the reader asked for this cell's result.
      if (!cell.live) cell.node.dataset.liveState = "disabled";
      else if (cell === this || outputs.some((o) => o.type === "error")) await cell.show(outputs);
      else cell.node.dataset.liveState = "idle";
    }
  }

  async show(outputs) {
    const nodes = outputs.map(renderOutput);
    this.output.replaceChildren(...nodes);
    this.output.hidden = false;
    if (this.stored) this.stored.hidden = true;
    await Promise.all(nodes.filter((n) => n.matches(".live-latex, .live-html")).map(typeset));
    this.node.dataset.liveState = outputs.some((o) => o.type === "error") ? "error" : "done";
    this.node.dataset.liveRuns = String(Number(this.node.dataset.liveRuns ?? 0) + 1);
    performance.mark("live:shown");
  }

  reset() {
    if (this.editor) this.editor.setCode(this.source);
    this.output.replaceChildren();
    this.output.hidden = true;
    if (this.stored) this.stored.hidden = false;
    if (this.node.dataset.liveState !== "running") this.node.dataset.liveState = "idle";
  }
}

// Python takes a while to start: begin at once (this module runs as soon as it has loaded, usually
// before the page is parsed; the worker runs beside the page) when the page has a live cell (the
// build marks it in the head), unless the reader asked to save data.
if (document.querySelector('meta[name="live-cells-python"]') && !navigator.connection?.saveData) warmUp();

// The controls need the cells and their description, at the end of the page.
if (document.readyState === "loading") {
  await new Promise((resolve) => document.addEventListener("DOMContentLoaded", resolve, { once: true }));
}
const data = JSON.parse(document.getElementById("live-cells-data").textContent);
const cells = [];
for (const [index, info] of data.cells.entries()) {
  const node = document.querySelector(`.live-cell-${index}`);
  if (node) cells.push(new LiveCell(index, info, node));
}

