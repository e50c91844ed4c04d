"""Test settings shared by every part: hypothesis profiles.

``HYPOTHESIS_PROFILE=long`` runs the property tests ten times longer; the fuzz
tests scale with ``MINT_FUZZ_SCALE`` (see ``tests/fuzzing.py``).
"""

from __future__ import annotations

import os

from hypothesis import HealthCheck, settings

settings.register_profile("ci", max_examples=300, deadline=None, suppress_health_check=[HealthCheck.too_slow])
settings.register_profile("long", max_examples=3000, deadline=None, suppress_health_check=[HealthCheck.too_slow])
settings.load_profile(os.environ.get("HYPOTHESIS_PROFILE", "ci"))
