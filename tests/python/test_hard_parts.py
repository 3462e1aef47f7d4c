"""bench/hard_parts.py: deterministic, valid, and each solid's Euler characteristic by construction
equals half the boundary's V - E + F (measures.solid_euler), on 2 seeds per family."""
import os
import sys

import pytest

sys.path.append("/usr/lib/freecad/lib")
pytest.importorskip("FreeCAD")
pytest.importorskip("Part")
sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "..", "bench"))
import hard_parts  # noqa: E402
import measures  # noqa: E402

SEEDS = list(range(2 * len(hard_parts.FAMILIES)))


@pytest.mark.parametrize("seed", SEEDS)
def test_part(seed):
    shape, meta = hard_parts.generate(seed)
    again, meta2 = hard_parts.generate(seed)
    assert meta == meta2
    assert abs(shape.Volume - again.Volume) <= 1e-12 * max(shape.Volume, 1)
    assert shape.isValid()
    assert meta["family"] == hard_parts.FAMILIES[seed % len(hard_parts.FAMILIES)][0]
    assert len(shape.Solids) == len(meta["solids"])
    for solid, m in zip(shape.Solids, meta["solids"]):
        assert solid.isValid() and solid.Volume > 0
        assert all(sh.isClosed() for sh in solid.Shells)
        assert measures.solid_euler(solid) == m["euler"]
