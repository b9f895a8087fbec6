"""Sphinx extension: drop repeated inline scripts from each page.

Jupyter Book 1.x registers sphinx-thebe's inline configuration script twice, so
every page declared ``const THEBE_JS_URL`` twice and the browser reported a
SyntaxError in the console. Keeping the first copy of each inline script fixes
it without touching the installed packages.
"""

from __future__ import annotations

from typing import Any


def _dedupe(app: Any, pagename: str, templatename: str, context: dict[str, Any], doctree: Any) -> None:
    scripts = context.get("script_files")
    if not scripts:
        return
    seen: set[tuple[str, str]] = set()
    kept = []
    for script in scripts:
        # an inline script has filename None or "" depending on how it was added
        key = (str(getattr(script, "filename", script) or ""), str(getattr(script, "attributes", {}).get("body", "")))
        if key in seen:
            continue
        seen.add(key)
        kept.append(script)
    context["script_files"] = kept


def setup(app: Any) -> dict[str, Any]:
    app.connect("html-page-context", _dedupe, priority=900)
    return {"parallel_read_safe": True, "parallel_write_safe": True}
