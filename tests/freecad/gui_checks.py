"""Checks the GUI scripts under Xvfb share (run inside FreeCAD)."""
from PySide2 import QtCore, QtWidgets


def cut_off(form):
    """What of the panel `form` is cut off at its present width: a visible widget reaching past
    its right edge, a one-line label, check box, button or list shorter than its text, a spin
    box whose line shows less than its text, a wrapped label lower than its text needs."""
    found = []
    for widget in form.findChildren(QtWidgets.QWidget):
        if not widget.isVisibleTo(form) or widget.width() == 0:
            continue
        name = widget.metaObject().className()
        text = getattr(widget, "text", lambda: "")() if not isinstance(widget, QtWidgets.QAbstractSpinBox) else widget.text()
        what = "%s %r" % (name, text)
        right = widget.mapTo(form, QtCore.QPoint(widget.width(), 0)).x()
        if right > form.width():
            found.append("%s reaches x %d of %d" % (what, right, form.width()))
        if isinstance(widget, QtWidgets.QLabel):
            if widget.wordWrap():
                if widget.heightForWidth(widget.width()) > widget.height():
                    found.append("%s: %d px high, needs %d" % (what, widget.height(), widget.heightForWidth(widget.width())))
            elif widget.width() < widget.sizeHint().width():
                found.append("%s: %d px wide, needs %d" % (what, widget.width(), widget.sizeHint().width()))
        elif isinstance(widget, (QtWidgets.QAbstractButton, QtWidgets.QComboBox)):
            if widget.width() < widget.sizeHint().width():
                found.append("%s: %d px wide, needs %d" % (what, widget.width(), widget.sizeHint().width()))
        elif isinstance(widget, QtWidgets.QAbstractSpinBox):
            line = widget.findChild(QtWidgets.QLineEdit)
            needed = line.fontMetrics().horizontalAdvance(line.text())
            if line.width() < needed:
                found.append("%s: its line %d px wide, the text %d" % (what, line.width(), needed))
    return found
