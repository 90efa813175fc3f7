"""Settings shared by the whole suite.

Hypothesis draws the same examples on every machine and every run (``derandomize``), keeps
no example database between runs (``database=None``: a failure found once on one machine is
not replayed only there) and sets no deadline (timings belong in ``benchmarks/``). A test
that needs other settings states them with ``@settings(...)``, which inherit the rest from
this profile. A failing example is then a property of the code and of the machine's floating
point alone, and the README's rule holds: no test compares two code paths bit for bit
(README, "Same answers on every machine").

The Lennard-Jones solver keeps the last curve and pull-off it found at a ``mu`` (speed only);
each test starts without them, so that no test depends on which ran before it in the same
process (a test that makes the solver fail must reach the solver).
"""

from __future__ import annotations

from hypothesis import settings

settings.register_profile("linecontact", derandomize=True, database=None, deadline=None)
settings.load_profile("linecontact")
