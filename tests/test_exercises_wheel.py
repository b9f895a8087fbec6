"""The HTML sheets work after `pip install`: a wheel installed in a fresh virtual environment, run away
from the repository, writes pages whose math Chromium renders with every network request blocked."""

from __future__ import annotations

import json
import subprocess
import sys
import sysconfig
import venv
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]


def _run(cmd: list[str], cwd: Path, timeout: float = 300) -> str:
    done = subprocess.run(cmd, cwd=cwd, capture_output=True, text=True, timeout=timeout)
    assert done.returncode == 0, f"{cmd[:4]} failed:\n{done.stdout[-2000:]}\n{done.stderr[-2000:]}"
    return done.stdout


@pytest.fixture(scope="module")
def installed(tmp_path_factory) -> Path:
    """A fresh venv with the pgsym wheel (no repository, no node); the dependencies come from the
    project's venv through a .pth file, so nothing is downloaded."""
    base = tmp_path_factory.mktemp("wheel")
    # setuptools of the project's venv builds the wheel (no build isolation: no download)
    _run([sys.executable, "-m", "pip", "wheel", "--no-deps", "--no-build-isolation", "-q", "-w", str(base / "dist"),
          str(ROOT)], cwd=base)
    wheel = next((base / "dist").glob("pgsym-*.whl"))
    env = base / "env"
    venv.create(env, with_pip=False)
    python = env / "bin" / "python"
    _run([sys.executable, "-m", "pip", "--python", str(python), "install", "--no-deps", "-q", str(wheel)], cwd=base)
    purelib = "import sysconfig; print(sysconfig.get_paths()['purelib'])"
    site = Path(_run([str(python), "-c", purelib], cwd=base).strip())
    # a plain directory line: Python adds the folder to sys.path but does not run the .pth files inside it,
    # so the project's editable install of pgsym stays inactive in the new venv
    (site / "project-deps.pth").write_text(sysconfig.get_paths()["purelib"] + "\n")
    return env


def test_the_installed_pgsym_is_the_wheel(installed, tmp_path):
    where = _run([str(installed / "bin" / "python"), "-c", "import pgsym, latex2mathml; print(pgsym.__file__)"],
                 cwd=tmp_path).strip()
    assert Path(where).is_relative_to(installed) and not Path(where).is_relative_to(ROOT)


def test_html_sheets_of_the_wheel_render_math_offline(installed, tmp_path, browser):
    out = tmp_path / "out"
    _run([str(installed / "bin" / "pgsym"), "sheet", "--topics", "join,decompose:3,cross-ratio:3", "--count", "2",
          "--seed", "3", "--format", "html", "--out", str(out)], cwd=tmp_path)
    pages = sorted((out / "html").glob("*.html")) + sorted((out / "key" / "html").glob("*.html"))
    assert len(pages) == 4 and not list(out.rglob("*.js"))
    context = browser.new_context()
    requests: list[str] = []

    def route(r):  # type: ignore[no-untyped-def]
        requests.append(r.request.url)
        return r.continue_() if r.request.url.startswith("file://") else r.abort()

    context.route("**/*", route)
    try:
        for path in (pages[0], pages[2]):  # a student sheet and a key page (solutions open)
            page = context.new_page()
            errors: list[str] = []
            page.on("pageerror", lambda exc, errors=errors: errors.append(str(exc)))
            page.goto(path.as_uri(), wait_until="load")
            # Chromium lays MathML out natively: a fraction and a matrix get real boxes
            page.wait_for_function("""() => {
                const box = (sel) => { const e = document.querySelector(sel); if (!e) return null;
                                       const r = e.getBoundingClientRect(); return r.width > 0 && r.height > 0; };
                return box('math') && box('mfrac') && box('mtable');
            }""", timeout=15000)
            sizes = json.loads(page.evaluate("""() => JSON.stringify([...document.querySelectorAll('mfrac')].map(
                f => { const [n, d] = f.children; return [n.getBoundingClientRect().bottom,
                                                            d.getBoundingClientRect().top]; }))"""))
            # numerator above denominator: the fraction is typeset, not shown as inline text
            assert sizes and all(top_of_denominator >= bottom - 1 for bottom, top_of_denominator in sizes)
            assert errors == [] and page.evaluate("() => document.scripts.length") == 0
            page.close()
    finally:
        context.close()
    assert requests and all(url.startswith("file://") for url in requests)  # nothing asked the network
