// The live cells' editor: CodeMirror 6 with Python highlighting, bundled by esbuild at build time.
import { python } from "@codemirror/lang-python";
import { EditorView, basicSetup } from "codemirror";

export function createEditor(parent, doc, label) {
  const view = new EditorView({
    doc,
    parent,
    extensions: [basicSetup, python(), EditorView.contentAttributes.of({ "aria-label": label })],
  });
  return {
    getCode: () => view.state.doc.toString(),
    setCode: (code) => view.dispatch({ changes: { from: 0, to: view.state.doc.length, insert: code } }),
    focus: () => view.focus(),
  };
}
