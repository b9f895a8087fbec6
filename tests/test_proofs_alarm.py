"""The alarm that ends a proof's time limit (pgsym.proofs.budget.alarm) cannot be lost: an exception raised in a
finaliser is dropped by Python, so the alarm fires again until the computation has stopped."""

from __future__ import annotations

import gc
import time

import pytest

from pgsym.proofs.budget import ALARM_REPEAT, Timeout, alarm


class _SlowFinaliser:
    """An object whose finaliser outlasts the alarm: the alarm's Timeout is raised inside it, where Python drops it."""

    dropped = 0

    def __del__(self) -> None:
        end = time.perf_counter() + 0.5
        try:
            while time.perf_counter() < end:
                pass
        except Timeout:
            type(self).dropped += 1
            raise  # dropped by Python ("Exception ignored in ...")


@pytest.mark.filterwarnings("ignore::pytest.PytestUnraisableExceptionWarning")
def test_an_alarm_dropped_in_a_finaliser_fires_again():
    start = time.perf_counter()
    with pytest.raises(Timeout), alarm(0.1):
        _SlowFinaliser()  # no name: finalised at once, while the alarm comes
        gc.collect()
        while time.perf_counter() - start < 5:  # a loop that would run on once the first alarm is lost
            pass
    assert _SlowFinaliser.dropped == 1  # the first alarm was raised in the finaliser and lost there
    # the finaliser's 0.5 s, then a repeat within ALARM_REPEAT s ended the loop (without it, the loop's 5 s); the rest
    # is a margin for a loaded machine
    assert time.perf_counter() - start < 0.5 + ALARM_REPEAT + 2


def test_no_alarm_fires_once_its_block_is_left():
    with alarm(0.05):
        pass
    end = time.perf_counter() + 3 * ALARM_REPEAT + 0.1
    while time.perf_counter() < end:  # a repeat armed by the block would raise Timeout here
        pass
