"""Area-weighted statistics of a thickness field."""

import numpy as np

HISTOGRAM_BINS = 10


def thickness_statistics(values, area, counted, minimum=None, maximum=None, bins=HISTOGRAM_BINS):
    """Dict over the counted points: min, max, mean (area-weighted), area (counted), area_total,
    share_below_min / share_above_max (fractions of the counted area, None without the limit),
    histogram {"edges": [B+1], "area": [B]} (area per thickness range; ``bins`` an int for equal
    ranges from min to max, or the edges)."""
    v, a = values[counted], area[counted]
    out = {"area": float(a.sum()), "area_total": float(area.sum()), "points": int(counted.sum())}
    if len(v) == 0:
        out.update(min=None, max=None, mean=None, share_below_min=None, share_above_max=None,
                   histogram={"edges": [], "area": []})
        return out
    total = float(a.sum())
    out["min"], out["max"] = float(v.min()), float(v.max())
    out["mean"] = float((v * a).sum() / total) if total > 0 else float(v.mean())
    out["share_below_min"] = None if minimum is None else float(a[v < minimum].sum() / total)
    out["share_above_max"] = None if maximum is None else float(a[v > maximum].sum() / total)
    if np.isscalar(bins):
        hi = out["max"] if out["max"] > out["min"] else out["min"] + 1.0
        edges = np.linspace(out["min"], hi, int(bins) + 1)
    else:
        edges = np.asarray(bins, dtype=np.float64)
    hist, edges = np.histogram(v, bins=edges, weights=a)
    out["histogram"] = {"edges": edges.tolist(), "area": hist.tolist()}
    return out
