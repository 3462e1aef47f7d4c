"""The radius legend: a small panel over each 3D view of a document that shows the colour map
and the colour range of every visible MedialAxis object in it (its radii's, or the one set in
its ColorRangeMin / ColorRangeMax)."""

import FreeCADGui as Gui
from PySide2 import QtCore, QtGui, QtWidgets

from cadmedial.app import is_medial_axis
from cadmedial.app.color_range import color_range, set_range
from cadmedial.colormap import STOPS

OBJECT_NAME = "cadmedial_radius_legend"


class RadiusLegend(QtWidgets.QFrame):
    """A vertical viridis bar, small value at the bottom, with TICKS ticks in mm beside it
    (one object) and one line per object: "<label>: <min> – <max> mm". Keeps itself in the
    bottom-left corner of its parent (or the top-left: ``top=True``), clear of FreeCAD's axis
    triad (bottom right) and navigation cube (top right). The wall thickness legend is this
    widget with its own title and object name (thickness_legend.py)."""

    BAR_WIDTH, BAR_HEIGHT, MARGIN, TICKS = 16, 120, 12, 5

    def __init__(self, parent, title="Medial radius", name=OBJECT_NAME, top=False):
        super().__init__(parent)
        self.top = top
        self.setObjectName(name)
        self.setAttribute(QtCore.Qt.WA_TransparentForMouseEvents)
        self.setStyleSheet("#%s { background: rgba(255, 255, 255, 215); border-radius: 6px; }"
                           " QLabel { color: #202020; }" % name)
        self.bar = QtWidgets.QLabel(self)
        self.bar.setFixedSize(self.BAR_WIDTH, self.BAR_HEIGHT)
        self.bar.setPixmap(self._bar_pixmap())
        self.title = QtWidgets.QLabel("<b>%s</b>" % title, self)
        self.scale = QtWidgets.QWidget(self)  # tick labels, top = high, placed by hand
        self.scale.setFixedHeight(self.BAR_HEIGHT)
        self.ticks = [QtWidgets.QLabel(self.scale) for _ in range(self.TICKS)]
        self.lines = QtWidgets.QLabel(self)
        column = QtWidgets.QHBoxLayout()
        column.addWidget(self.bar)
        column.addWidget(self.scale)
        layout = QtWidgets.QVBoxLayout(self)
        layout.setContentsMargins(8, 8, 8, 8)
        layout.addWidget(self.title)
        layout.addLayout(column)
        layout.addWidget(self.lines)
        # Kept for tests and callers: the top and bottom ticks.
        self.high, self.low = self.ticks[0], self.ticks[-1]
        parent.installEventFilter(self)

    def _bar_pixmap(self):
        gradient = QtGui.QLinearGradient(0, self.BAR_HEIGHT, 0, 0)
        for i, (r, g, b) in enumerate(STOPS):
            gradient.setColorAt(i / (len(STOPS) - 1), QtGui.QColor.fromRgbF(r, g, b))
        pixmap = QtGui.QPixmap(self.BAR_WIDTH, self.BAR_HEIGHT)
        painter = QtGui.QPainter(pixmap)
        painter.fillRect(pixmap.rect(), QtGui.QBrush(gradient))
        painter.end()
        return pixmap

    def set_entries(self, entries, notes=""):
        """entries: list of (label, low, high) or (label, low, high, more): the bar spans each
        object's own colour range low..high, the ticks show it (one object); `more` is text
        after the object's line. notes: rich text shown under the lines (the thickness legend's
        colour key)."""
        if not entries:
            self.hide()
            return
        low, high = (entries[0][1], entries[0][2]) if len(entries) == 1 else (None, None)
        width = 0
        for i, tick in enumerate(self.ticks):
            share = 1.0 - i / (self.TICKS - 1)
            if low is None:
                tick.setText("max" if i == 0 else "min" if i == self.TICKS - 1 else "")
            else:
                tick.setText("– %.3g mm" % (low + share * (high - low)))
            tick.adjustSize()
            y = int((1.0 - share) * (self.BAR_HEIGHT - 1) - tick.height() / 2)
            tick.move(0, max(0, min(self.BAR_HEIGHT - tick.height(), y)))
            width = max(width, tick.width())
        self.scale.setFixedWidth(width)
        self.lines.setText("<br>".join(["%s: %.4g – %.4g mm%s" % (tuple(entry[:3]) + (
            entry[3] if len(entry) > 3 else "",)) for entry in entries] + ([notes] if notes else [])))
        self.adjustSize()
        self._place()
        self.show()
        self.raise_()

    def text(self):
        """What the legend says, for tests."""
        return " ".join(label.text() for label in [self.title] + self.ticks + [self.lines])

    def _place(self):
        parent = self.parentWidget()
        y = self.MARGIN if self.top else parent.height() - self.height() - self.MARGIN
        self.move(self.MARGIN, y)

    def eventFilter(self, watched, event):
        if event.type() == QtCore.QEvent.Resize:
            self._place()
        return False


def _view_widgets(doc):
    gui_doc = Gui.getDocument(doc.Name) if doc is not None else None
    if gui_doc is None:
        return []
    widgets = []
    for view in gui_doc.mdiViewsOfType("Gui::View3DInventor"):
        try:
            widget = view.graphicsView()
            widget.objectName()  # raises on a wrapper PySide kept of a deleted widget
            widgets.append(widget)
        except Exception:  # a view that is being closed, or a stale wrapper
            continue
    if not widgets and gui_doc.mdiViewsOfType("Gui::View3DInventor"):
        # After a document was closed, PySide can hand back its deleted view's wrapper for the
        # new one: find the new view's widget through the main window instead.
        for window in Gui.getMainWindow().findChildren(QtWidgets.QMdiSubWindow):
            if window.windowTitle().split(" : ")[0] == doc.Label:
                widgets.extend(window.findChildren(QtWidgets.QGraphicsView))
    return widgets


def legend_of(widget, name=OBJECT_NAME):
    """The legend (by object name) on a 3D view's graphics widget, or None (also when PySide's
    wrapper outlived the widget, as it can while a document closes and another opens)."""
    try:
        return widget.findChild(QtWidgets.QFrame, name)
    except RuntimeError:
        return None


def first_legend(doc, name=OBJECT_NAME):
    """The legend named ``name`` over doc's first 3D view that has one (a visible view's first),
    or None."""
    found = [f for f in (legend_of(w, name) for w in _view_widgets(doc)) if f is not None]
    visible = [f for f in found if _visible(f)]
    return (visible or found or [None])[0]


def _visible(widget):
    try:
        return widget.isVisible()
    except RuntimeError:
        return False


def refresh(doc, leaving=None):
    """Shows the ranges of the visible MedialAxis objects of doc (but `leaving`, being deleted)
    in a legend over each of its 3D views; hides the legend when there is none. Returns whether
    it showed one (False also when the document has no 3D view yet)."""
    entries = []
    for obj in doc.Objects if doc is not None else []:
        if obj is leaving or not is_medial_axis(obj) or not obj.VertexCount:
            continue
        if obj.ViewObject is None or not obj.ViewObject.Visibility:
            continue
        entries.append(entry_of(obj))
    return show_on_views(doc, entries, RadiusLegend)


def entry_of(obj):
    """A MedialAxis object's legend entry: its colour range, and its radii when that was set
    by hand (the colours then clamp outside it)."""
    low, high = color_range(obj)
    if set_range(obj) is None:
        return (obj.Label, low, high)
    return (obj.Label, low, high, "<br>&nbsp;&nbsp;radii %.4g – %.4g mm" % (
        obj.RadiusMin.Value, obj.RadiusMax.Value))


def show_on_views(doc, entries, make, name=OBJECT_NAME, notes=""):
    """Puts entries (see RadiusLegend.set_entries) in the legend named ``name`` over each 3D view
    of doc, made by make(widget) where there is none yet; hides it when entries is empty.
    Returns whether a legend shows on a view the user sees: while a document closes and another
    opens, the closing one's view can still be listed (its wrapper alive, its window hidden), and
    a legend put only there is lost with it, so the callers try again."""
    shown = False
    for widget in _view_widgets(doc):
        legend = legend_of(widget, name)
        try:
            if legend is None:
                if not entries:
                    continue
                legend = make(widget)
            legend.set_entries(entries, notes)
            shown = shown or widget.isVisible()
        except RuntimeError:  # the widget was deleted under its PySide wrapper
            continue
    return shown and bool(entries)
