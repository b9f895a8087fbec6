"""The kernel of the book's live cells: runs a cell in one namespace per page, returns Jupyter-like outputs.

It runs in Pyodide inside the page's Web Worker and uses the standard library only. Outputs are what a
notebook stores: streams, rich displays (``display(...)`` and the value of a final expression) as
MIME bundles, and errors as the exception's class name, its message and the folded traceback.

>>> kernel = Kernel()
>>> kernel.run("x = 6 * 7\\nprint('x is', x)\\nx + 1")
[{'type': 'stream', 'name': 'stdout', 'text': 'x is 42\\n'}, {'type': 'result', 'data': {'text/plain': '43'}}]
>>> kernel.run("1 / 0")[0]["ename"]
'ZeroDivisionError'

Modules the page cannot load (the build lists them) import as placeholders that fail only when used:

>>> kernel.run("import no_such_package.sub as nsp\\nfrom no_such_package.sub import ones", ["no_such_package.sub"])
[]
>>> kernel.run("ones(3)")[0]["evalue"]
'no_such_package.sub does not run in the page; run this chapter locally'
"""

from __future__ import annotations

import ast
import builtins
import html
import importlib.util
import json
import linecache
import re
import sys
import traceback
import types
from typing import Any

_MIME_METHODS = (("text/html", "_repr_html_"), ("text/markdown", "_repr_markdown_"), ("text/latex", "_repr_latex_"))


def mime_bundle(obj: object) -> dict[str, str]:
    """``text/plain`` plus every rich representation ``obj`` offers, as IPython collects them."""
    data = {"text/plain": repr(obj)}
    for mime, method in _MIME_METHODS:
        fn = getattr(obj, method, None)
        if callable(fn) and not isinstance(obj, type):
            try:
                value = fn()
            except Exception:  # a broken _repr_ falls back to text, as in Jupyter
                continue
            if isinstance(value, str):
                data[mime] = value
    if "text/markdown" in data and "text/html" not in data:  # the page has no Markdown renderer
        data["text/html"] = markdown_to_html(data["text/markdown"])
    return data


class _Stream:
    def __init__(self, kernel: Kernel, name: str) -> None:
        self.kernel, self.name = kernel, name

    def write(self, text: str) -> int:
        self.kernel.stream(self.name, text)
        return len(text)

    def flush(self) -> None:
        pass

    def isatty(self) -> bool:
        return False


class Kernel:
    """One page's Python state: cells run in order in one namespace, as in a notebook kernel."""

    def __init__(self) -> None:
        # The cells' own __import__ hands out placeholders for modules the page cannot load; libraries
        # keep the real one, so that their `try: import numpy / except ImportError` still works.
        cell_builtins = dict(vars(builtins), __import__=self._import)
        self.namespace: dict[str, Any] = {"__name__": "__main__", "__builtins__": cell_builtins}
        self.stubs: dict[str, _Placeholder] = {}
        self.outputs: list[dict[str, Any]] = []
        self.count = 0

    def stream(self, name: str, text: str) -> None:
        last = self.outputs[-1] if self.outputs else None
        if last and last["type"] == "stream" and last["name"] == name:
            last["text"] += text
        else:
            self.outputs.append({"type": "stream", "name": name, "text": text})

    def display(self, *objs: object) -> None:
        for obj in objs:
            self.outputs.append({"type": "display", "data": mime_bundle(obj)})

    def run(self, code: str, stubs: list[str] = ()) -> list[dict[str, Any]]:
        """Run one cell; the value of a final expression becomes its result, as in Jupyter.

        ``stubs`` are the modules the cell imports that the page cannot load (decided when the book
        was built); they are bound to placeholders, so that only using them fails.
        """
        for name, placeholder in placeholders(list(stubs)).items():
            self.stubs.setdefault(name, placeholder)
        self.count += 1
        self.outputs = []
        filename = f"<cell {self.count}>"
        linecache.cache[filename] = (len(code), None, code.splitlines(keepends=True), filename)
        saved = sys.stdout, sys.stderr
        sys.stdout, sys.stderr = _Stream(self, "stdout"), _Stream(self, "stderr")
        global _current
        _current = self
        try:
            tree = ast.parse(code, filename)
            last = tree.body.pop() if tree.body and isinstance(tree.body[-1], ast.Expr) else None
            exec(compile(tree, filename, "exec"), self.namespace)
            if last is not None:
                value = eval(compile(ast.Expression(last.value), filename, "eval"), self.namespace)
                if value is not None:
                    self.namespace["_"] = value
                    self.outputs.append({"type": "result", "data": mime_bundle(value)})
        except BaseException as exc:  # the reader's code may raise anything, SystemExit included
            self.outputs.append(error_output(exc))
        finally:
            sys.stdout, sys.stderr = saved
        return self.outputs

    def _import(self, name: str, globals: Any = None, locals: Any = None, fromlist: Any = (), level: int = 0) -> Any:
        if level == 0 and name in self.stubs:
            if fromlist:
                return self.stubs[name]
            top = name.split(".")[0]
            return self.stubs[top] if top in self.stubs else builtins.__import__(top, globals, locals, (), 0)
        return builtins.__import__(name, globals, locals, fromlist, level)

    def run_json(self, code: str, stubs: str = "[]") -> str:
        """``run`` for the worker: JSON strings cross between JavaScript and Python."""
        return json.dumps(self.run(code, json.loads(stubs)))


def error_output(exc: BaseException) -> dict[str, Any]:
    """The exception's class name and message, and the traceback without the kernel's own frames."""
    frames = traceback.extract_tb(exc.__traceback__)
    frames = [f for f in frames if f.filename != __file__]
    lines = [*traceback.format_list(frames), *traceback.format_exception_only(type(exc), exc)]
    return {"type": "error", "ename": type(exc).__name__, "evalue": str(exc),
            "traceback": "Traceback (most recent call last):\n" + "".join(lines)}


_current: Kernel | None = None


class NotInBrowserError(ModuleNotFoundError):
    """A module the page cannot load was used (the chapter runs in full with a local install)."""


def _not_in_browser(module: str) -> NotInBrowserError:
    return NotInBrowserError(f"{module} does not run in the page; run this chapter locally", name=module)


class _Missing:
    """What a placeholder module hands out for any name: using it raises NotInBrowserError."""

    def __init__(self, module: str) -> None:
        self._module = module

    def __getattr__(self, name: str) -> Any:
        if name.startswith("__"):
            raise AttributeError(name)
        raise _not_in_browser(self._module)

    def __call__(self, *args: object, **kwargs: object) -> Any:
        raise _not_in_browser(self._module)


class _Placeholder(types.ModuleType):
    def __getattr__(self, name: str) -> Any:
        if name.startswith("__"):
            raise AttributeError(name)
        return _Missing(self.__name__)


def placeholders(modules: list[str]) -> dict[str, _Placeholder]:
    """Placeholders for modules the page cannot load, chained as attributes (``a.b`` on ``a``)."""
    made: dict[str, _Placeholder] = {}
    for module in modules:
        parts = module.split(".")
        try:
            top_exists = importlib.util.find_spec(parts[0]) is not None
        except (ImportError, ValueError):
            top_exists = False
        # below a package that exists (pgsym.linalg) only the module itself is replaced
        first = len(parts) if top_exists else 1
        for i in range(first, len(parts) + 1):
            name = ".".join(parts[:i])
            made.setdefault(name, _Placeholder(name))
            if i > first:
                setattr(made[".".join(parts[: i - 1])], parts[i - 1], made[name])
    return made


def _display(*objs: object, **_: object) -> None:
    if _current is not None:
        _current.display(*objs)


class _TextDisplay:
    def __init__(self, data: str = "") -> None:
        self.data = data

    def __repr__(self) -> str:
        return f"<{type(self).__name__} object>"


class Math(_TextDisplay):
    def _repr_latex_(self) -> str:
        return "$\\displaystyle " + self.data.strip().strip("$") + "$"


class Latex(_TextDisplay):
    def _repr_latex_(self) -> str:
        return self.data


class Markdown(_TextDisplay):
    def _repr_markdown_(self) -> str:
        return self.data


class HTML(_TextDisplay):
    def _repr_html_(self) -> str:
        return self.data


def ipython_display_module() -> types.ModuleType:
    """A stand-in for ``IPython.display`` (IPython does not run in Pyodide) that displays in the page."""
    module = types.ModuleType("IPython.display")
    module.display = _display
    module.Math, module.Latex, module.Markdown, module.HTML = Math, Latex, Markdown, HTML
    return module


def install_ipython_shim() -> None:
    """Register the stand-in as ``IPython.display`` when IPython itself is absent."""
    try:
        import IPython  # noqa: F401
    except ImportError:
        package = types.ModuleType("IPython")
        package.__path__ = []
        package.display = ipython_display_module()
        sys.modules["IPython"], sys.modules["IPython.display"] = package, package.display


def _inline(text: str) -> str:
    """Inline Markdown of the book's tables: code spans, bold and $math$ (for MathJax)."""
    parts = re.split(r"(`[^`]*`)", text)
    out = []
    for part in parts:
        if part.startswith("`") and part.endswith("`") and len(part) >= 2:
            out.append(f"<code>{html.escape(part[1:-1])}</code>")
        else:
            escaped = re.sub(r"\*\*(.+?)\*\*", r"<strong>\1</strong>", html.escape(part, quote=False))
            out.append(re.sub(r"\$([^$]+)\$", r"\\(\1\\)", escaped))  # the page's MathJax reads \( \)
    return "".join(out)


_BULLET = re.compile(r"^\s*[-*]\s+")


def markdown_to_html(text: str) -> str:
    """The small part of Markdown that cells display (paragraphs, pipe tables, headings, lists) as HTML.

    >>> markdown_to_html("| a | b |\\n|---|---|\\n| `x` | **1** |")
    '<table><thead><tr><th>a</th><th>b</th></tr></thead><tbody><tr><td><code>x</code></td><td><strong>1</strong></td></tr></tbody></table>'
    """
    blocks = re.split(r"\n\s*\n", text.strip())
    out = []
    for block in blocks:
        lines = block.splitlines()
        if len(lines) >= 2 and lines[0].lstrip().startswith("|") and re.fullmatch(r"\s*\|?[\s:|-]+\|?\s*", lines[1]):
            def cells(line: str) -> list[str]:
                return [c.strip() for c in line.strip().strip("|").split("|")]

            head = "".join(f"<th>{_inline(c)}</th>" for c in cells(lines[0]))
            rows = "".join("<tr>" + "".join(f"<td>{_inline(c)}</td>" for c in cells(r)) + "</tr>" for r in lines[2:])
            out.append(f"<table><thead><tr>{head}</tr></thead><tbody>{rows}</tbody></table>")
        elif m := re.match(r"(#{1,6})\s+(.*)", block):
            level = len(m.group(1))
            out.append(f"<h{level}>{_inline(m.group(2))}</h{level}>")
        elif all(re.match(r"\s*[-*]\s+", line) for line in lines):
            items = "".join(f"<li>{_inline(_BULLET.sub('', line))}</li>" for line in lines)
            out.append(f"<ul>{items}</ul>")
        else:
            out.append(f"<p>{_inline(' '.join(lines))}</p>")
    return "".join(out)
