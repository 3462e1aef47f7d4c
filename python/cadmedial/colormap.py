"""Colours for the medial radius: a perceptually uniform map (viridis), no FreeCAD needed."""

import numpy as np

# Viridis sampled at 9 evenly spaced stops (matplotlib's table); linear in between.
STOPS = np.array([
    [0.267004, 0.004874, 0.329415],
    [0.282623, 0.140926, 0.457517],
    [0.253935, 0.265254, 0.529983],
    [0.206756, 0.371758, 0.553117],
    [0.163625, 0.471133, 0.558148],
    [0.127568, 0.566949, 0.550556],
    [0.134692, 0.658636, 0.517649],
    [0.266941, 0.748751, 0.440573],
    [0.477504, 0.821444, 0.318195],
    [0.741388, 0.873449, 0.149561],
    [0.993248, 0.906157, 0.143936],
])


def colors_of(values, low, high):
    """(N, 3) float32 RGB in [0, 1] for (N,) values: low maps to dark violet, high to yellow.

    With high <= low every value gets the middle colour.
    """
    values = np.asarray(values, dtype=np.float64)
    if high > low:
        t = np.clip((values - low) / (high - low), 0.0, 1.0)
    else:
        t = np.full(values.shape, 0.5)
    position = t * (len(STOPS) - 1)
    index = np.minimum(position.astype(np.int64), len(STOPS) - 2)
    weight = (position - index)[:, None]
    return ((1.0 - weight) * STOPS[index] + weight * STOPS[index + 1]).astype(np.float32)
