"""Stress test of a template over many seeds.

Seed ``i`` runs at level ``levels[i % len(levels)]``, so ``seeds`` seeds give ``seeds`` instances
spread evenly over the levels. For every seed: the instance builds (no degenerate configuration slips through), the
template's independent :meth:`~pgsym.exercises.template.Template.verify` accepts it (it re-checks the
answer with the pgsym core objects, not with the template's own solver), every answer round-trips
through the answer parser and grades as right, every number in an answer stays within
``max_entry``, and multiple-choice keys are spread (no letter gets more than twice its fair share, and
every letter appears when there are enough seeds), and the answers vary across seeds.

Variation: for each level and part, the *top share* is the fraction of instances whose answer is the
most common one (answers compared as displayed, so equal up to the answer's own normal form). A
student guessing that answer is right with that probability, and a class would share it: a part whose
top share is at least :data:`MAX_TOP_SHARE` over at least :data:`MIN_VARIATION_INSTANCES` instances
fails ("barely varies"). A fair coin over 20 instances reaches 0.8 with probability 2 · P(≥ 16 of 20)
≈ 1.2 %, over 100 instances practically never.

>>> from pgsym.exercises.registry import get_template
>>> report = stress(get_template("join"), seeds=60)
>>> report.ok, report.instances
(True, 60)
"""

from __future__ import annotations

from collections import Counter
from collections.abc import Callable
from dataclasses import dataclass, field

from ..errors import PgsymError
from .answers import grade
from .seeds import variant_seed
from .template_base import Template

#: Largest share of instances (of one level and part) that may have the same answer.
MAX_TOP_SHARE = 0.8

#: Instances of one level and part needed before the variation is judged.
MIN_VARIATION_INSTANCES = 20


@dataclass
class StressReport:
    """The outcome of :func:`stress`: counts, the largest answer entry, key spread and failures."""

    template: str
    instances: int = 0
    failures: list[str] = field(default_factory=list)
    largest: int = 0
    keys: dict[str, Counter] = field(default_factory=dict)
    top_shares: dict[str, tuple[float, int]] = field(default_factory=dict)

    @property
    def ok(self) -> bool:
        """True when no check failed."""
        return not self.failures

    def lines(self) -> list[str]:
        """A human-readable summary."""
        out = [f"{self.template}: {self.instances} instances, largest answer entry {self.largest}, "
               + ("OK" if self.ok else f"{len(self.failures)} failure(s)")]
        for part, counter in sorted(self.keys.items()):
            out.append(f"  choice keys of part {part}: " + ", ".join(f"{k}={v}" for k, v in sorted(counter.items())))
        out += [f"  FAIL {f}" for f in self.failures[:20]]
        return out


def stress(template: Template, seeds: int = 10_000, master_seed: int = 0,
           progress: Callable[[int], None] | None = None) -> StressReport:
    """Run ``seeds`` seeds, cycling through the levels of ``template`` (``progress(1)`` after each seed)."""
    report = StressReport(template.name)
    choice_counts: dict[str, Counter] = {}
    n_choices: dict[str, int] = {}
    answers: dict[str, Counter] = {}
    for i in range(seeds):
        for level in (template.levels[i % len(template.levels)],):
            seed = variant_seed(master_seed, f"stress-{i}", f"{template.name}@{level}")
            where = f"seed {i}, level {level}"
            try:
                ex = template.generate(seed, level, 1)
                template.verify(ex)
            except (PgsymError, AssertionError, ArithmeticError, ValueError) as err:
                report.failures.append(f"{where}: {type(err).__name__}: {err}")
                continue
            report.instances += 1
            for idx, part in enumerate(ex.parts):
                ans = part.answer
                size = max((max(abs(x.numerator), x.denominator) for x in ans.flat()), default=0)
                report.largest = max(report.largest, size)
                if size > template.max_entry:
                    report.failures.append(f"{where}: answer entry {size} exceeds max_entry {template.max_entry}")
                try:
                    right = grade(ans, ans.display())
                except PgsymError as err:
                    right = False
                    report.failures.append(f"{where}: the key {ans.display()!r} cannot be read back: {err}")
                if not right:
                    report.failures.append(f"{where}: the key {ans.display()!r} does not grade as right")
                answers.setdefault(f"{part.label[len(str(ex.slot)):] or '-'}@level{level}", Counter())[
                    ans.display()] += 1
                if ans.kind == "choice":
                    key = f"{idx}@level{level}"
                    choice_counts.setdefault(key, Counter())[ans.value] += 1
                    n_choices[key] = len(part.choices)
        if progress is not None:
            progress(1)
    for key, counter in choice_counts.items():
        n, total = n_choices[key], sum(counter.values())
        report.keys[key] = counter
        if total >= 20 * n:
            for letter in "ABCDEFGH"[:n]:
                share = counter.get(letter, 0)
                if share == 0 or share > 2 * total / n:
                    report.failures.append(f"keys of part {key} are not spread: {dict(counter)}")
                    break
    for key, counter in sorted(answers.items()):
        total = sum(counter.values())
        top = counter.most_common(1)[0][1] / total
        report.top_shares[key] = (top, len(counter))
        if total >= MIN_VARIATION_INSTANCES and top >= MAX_TOP_SHARE:
            part, _, level = key.partition("@")
            report.failures.append(
                f"part {part} at {level} barely varies: {len(counter)} distinct answer(s), the most common "
                f"({counter.most_common(1)[0][0][:40]}) in {top:.0%} of {total} instances (at most "
                f"{MAX_TOP_SHARE:.0%} allowed)")
    return report
