"""Seeds of exercise variants: (master seed, student id, slot key) → an independent random stream.

The slot key names the exercise by its topic and its occurrence (``"join#0"``, ``"join#1"``), not by
its position on the sheet, so reordering the topics or adding new ones leaves every existing
variant unchanged. The hash is BLAKE2b (stable across Python versions and machines); the stream is a
:class:`random.Random` seeded with the resulting integer.

>>> variant_seed(2026, "alice", "join#0") == variant_seed(2026, "alice", "join#0")
True
>>> variant_seed(2026, "alice", "join#0") != variant_seed(2026, "bob", "join#0")
True
>>> form_id(2026, "alice", ["join#0", "meet#0"])
'F-...'
"""

from __future__ import annotations

import hashlib
import random
from collections.abc import Iterable


def _digest(*parts: str, size: int = 8) -> bytes:
    h = hashlib.blake2b(digest_size=size, person=b"pgsym-exercises")
    for part in parts:
        data = part.encode("utf-8")
        h.update(len(data).to_bytes(4, "big"))
        h.update(data)
    return h.digest()


def variant_seed(master_seed: int, student_id: str, slot_key: str) -> int:
    """The 64-bit seed of one variant.

    >>> 0 <= variant_seed(1, "s1", "meet#0") < 2**64
    True
    """
    return int.from_bytes(_digest(str(int(master_seed)), str(student_id), str(slot_key)), "big")


def variant_rng(seed: int) -> random.Random:
    """The random stream of a variant seed.

    >>> variant_rng(5).randint(1, 10) == variant_rng(5).randint(1, 10)
    True
    """
    return random.Random(seed)


def slot_keys(topics: Iterable[str]) -> list[str]:
    """Slot keys for a list of topics: ``topic#k`` for the k-th occurrence of the topic.

    >>> slot_keys(["join", "meet", "join"])
    ['join#0', 'meet#0', 'join#1']
    """
    seen: dict[str, int] = {}
    keys = []
    for topic in topics:
        k = seen.get(topic, 0)
        seen[topic] = k + 1
        keys.append(f"{topic}#{k}")
    return keys


def form_id(master_seed: int, student_id: str, keys: Iterable[str]) -> str:
    """A short form id printed on the sheet: it identifies the exact set of variants.

    >>> form_id(7, "s1", ["a#0"]) == form_id(7, "s1", ["a#0"])
    True
    """
    digest = _digest(str(int(master_seed)), str(student_id), *keys, size=5)
    return "F-" + digest.hex().upper()
