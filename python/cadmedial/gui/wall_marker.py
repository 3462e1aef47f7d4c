"""The mark "Go to the thinnest wall" leaves in the 3D view: a red dot at ThinnestWallAt, the same
size on screen at any zoom, and a translucent red ball as thick as the wall around it, so that
the place shows even when the view is turned away from it. One mark at a time."""

NODE_NAME = "cadmedial_thinnest_wall"
RGB = (0.9, 0.1, 0.1)


class WallMarker:
    """The mark in one view's scene graph (an SoAnnotation: drawn after the scene without the
    depth test, so it shows through the source's faces and the medial surface)."""

    def __init__(self):
        self.root = None
        self.graph = None
        self.point = None
        self.owner = None  # the MedialAxis whose wall is marked

    def show(self, view, point, thickness, owner=None):
        """Puts the mark at point (x, y, z) with a ball of diameter thickness, in view."""
        from pivy import coin  # here: the workbench loads even where pivy is missing
        self.clear()
        self.owner = owner
        root = coin.SoAnnotation()
        root.setName(NODE_NAME)
        colour = coin.SoBaseColor()
        colour.rgb = RGB
        place = coin.SoTranslation()
        place.translation = tuple(point)
        dot = coin.SoMarkerSet()  # screen-sized: seen at any zoom
        dot.markerIndex = coin.SoMarkerSet.CIRCLE_FILLED_9_9
        origin = coin.SoCoordinate3()
        origin.point.setValue(0.0, 0.0, 0.0)
        ball = coin.SoSeparator()
        material = coin.SoMaterial()
        material.diffuseColor = RGB
        material.transparency = 0.6
        sphere = coin.SoSphere()
        sphere.radius = 0.5 * thickness
        for node in (material, sphere):
            ball.addChild(node)
        for node in (colour, place, ball, origin, dot):
            root.addChild(node)
        self.graph = view.getSceneGraph()
        self.graph.addChild(root)
        self.root = root
        self.point = tuple(point)

    def clear(self):
        if self.root is not None and self.graph is not None:
            try:
                self.graph.removeChild(self.root)
            except Exception:  # the view was closed: the mark went with it
                pass
        self.root = self.graph = self.point = self.owner = None


marker = WallMarker()
