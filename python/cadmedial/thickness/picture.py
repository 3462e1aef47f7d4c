"""A picture of the part coloured by thickness (PNG bytes), for the HTML report: the surface mesh
seen from an isometric direction, triangles painted back to front (matplotlib, no display)."""

import io

import numpy as np

from ..colormap import colors_of

THIN_RGB = (0.85, 0.1, 0.1)
THICK_RGB = (0.9, 0.3, 0.9)


def render_png(result, low, high, size_px=900, view=(1.0, -1.0, 0.8)):
    """PNG bytes: the mesh from ``view`` (a direction towards the eye), thin regions red, thick
    magenta, the rest viridis from low to high, with a colour bar in model units."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.collections import PolyCollection
    from matplotlib.colors import ListedColormap, Normalize

    eye = np.asarray(view, dtype=np.float64)
    eye /= np.linalg.norm(eye)
    right = np.cross([0.0, 0.0, 1.0], eye)
    right /= np.linalg.norm(right)
    up = np.cross(eye, right)
    p = result.points
    xy = np.column_stack([p @ right, p @ up])
    depth = (p @ eye)[result.triangles].mean(axis=1)
    rgb = colors_of(result.values, low, high).astype(np.float64)
    for regions, colour in ((result.thin_regions, THIN_RGB), (result.thick_regions, THICK_RGB)):
        for g in regions:
            rgb[g["point_indices"]] = colour
    tri_rgb = rgb[result.triangles].mean(axis=1)
    # A little shading by the facet's angle to the eye shows the shape.
    normals = np.cross(p[result.triangles[:, 1]] - p[result.triangles[:, 0]],
                       p[result.triangles[:, 2]] - p[result.triangles[:, 0]])
    normals /= np.maximum(np.linalg.norm(normals, axis=1), 1e-300)[:, None]
    facing = normals @ eye
    shade = 0.55 + 0.45 * np.clip(facing, 0.0, 1.0)
    tri_rgb *= shade[:, None]
    keep = facing > -1e-9
    order = np.argsort(depth[keep])
    polys = xy[result.triangles[keep][order]]
    fig = plt.figure(figsize=(size_px / 100.0, size_px * 0.75 / 100.0), dpi=100)
    ax = fig.add_axes([0.02, 0.02, 0.8, 0.96])
    ax.add_collection(PolyCollection(polys, facecolors=tri_rgb[keep][order], edgecolors="none",
                                     antialiased=False))
    ax.set_xlim(xy[:, 0].min(), xy[:, 0].max())
    ax.set_ylim(xy[:, 1].min(), xy[:, 1].max())
    ax.set_aspect("equal")
    ax.axis("off")
    cax = fig.add_axes([0.86, 0.1, 0.03, 0.8])
    bar = plt.cm.ScalarMappable(norm=Normalize(low, high), cmap=ListedColormap(
        colors_of(np.linspace(low, high, 256), low, high)))
    fig.colorbar(bar, cax=cax, label="thickness")
    buf = io.BytesIO()
    fig.savefig(buf, format="png")
    plt.close(fig)
    return buf.getvalue()
