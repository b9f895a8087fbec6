"""Test configuration: the hypothesis profile and the browser fixtures (strategies: tests/strategies.py)."""

from __future__ import annotations

from _browser import browser, server  # noqa: F401  (fixtures of the browser tests)
from hypothesis import settings

# Exact symbolic examples vary widely in cost, and the machine may be shared: a per-example time
# limit would only make runs flaky, so the suite checks results, not speed (speed lives in bench/).
settings.register_profile("pgsym", deadline=None, print_blob=True)
settings.load_profile("pgsym")
