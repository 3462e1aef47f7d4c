"""The batch summary as a Qt table: one row per part (the records of summary.json), sortable by
any column, numbers sorted as numbers."""

from PySide2 import QtCore, QtGui

# (header, record key, how the cell reads)
COLUMNS = (
    ("Part", "part", str),
    ("Solids", "solids", str),
    ("Status", "status", str),
    ("Message", "message", str),
    ("Samples", "samples", str),
    ("Faces", "faces", str),
    ("Topology right", "topology_right", lambda v: "yes" if v else "no"),
    ("Thinnest wall", "thinnest_wall", lambda v: "%.4g" % v),
    ("Where", "thinnest_wall_at", lambda v: "(%s)" % ", ".join("%.4g" % x for x in v)),
    ("Time s", "time_s", lambda v: "%.2f" % v),
    ("Peak memory MB", "peak_memory_mb", lambda v: "%.0f" % v),
)
_FAILED = QtGui.QColor(200, 40, 40)
_STOPPED = QtGui.QColor(140, 140, 140)


def _cell(record, key, show):
    value = record.get(key)
    if value is None or value == "":
        return ""
    try:
        return show(value)
    except (TypeError, ValueError):
        return str(value)


def _sort_key(value):
    # Numbers before text before nothing, each in its own order; a tuple keeps types apart.
    if isinstance(value, bool):
        return (0, float(value), "")
    if isinstance(value, (int, float)):
        return (0, float(value), "")
    if isinstance(value, (list, tuple)):
        return (1, 0.0, " ".join(map(str, value)))
    if value is None or value == "":
        return (2, 0.0, "")
    return (1, 0.0, str(value))


class SummaryModel(QtCore.QAbstractTableModel):
    """set_records(records) replaces the rows; add_record(record) appends or updates one part."""

    def __init__(self, parent=None):
        super().__init__(parent)
        self.records = []

    def set_records(self, records):
        self.beginResetModel()
        self.records = list(records)
        self.endResetModel()

    def add_record(self, record):
        for row, old in enumerate(self.records):
            if old["part"] == record["part"]:
                self.records[row] = record
                self.dataChanged.emit(self.index(row, 0), self.index(row, len(COLUMNS) - 1))
                return
        self.beginInsertRows(QtCore.QModelIndex(), len(self.records), len(self.records))
        self.records.append(record)
        self.endInsertRows()

    def record(self, row):
        return self.records[row]

    def rowCount(self, parent=QtCore.QModelIndex()):
        return 0 if parent.isValid() else len(self.records)

    def columnCount(self, parent=QtCore.QModelIndex()):
        return 0 if parent.isValid() else len(COLUMNS)

    def headerData(self, section, orientation, role=QtCore.Qt.DisplayRole):
        if role == QtCore.Qt.DisplayRole and orientation == QtCore.Qt.Horizontal:
            return COLUMNS[section][0]
        return None

    def data(self, index, role=QtCore.Qt.DisplayRole):
        if not index.isValid():
            return None
        record = self.records[index.row()]
        _header, key, show = COLUMNS[index.column()]
        if role == QtCore.Qt.DisplayRole:
            return _cell(record, key, show)
        if role == QtCore.Qt.ToolTipRole and key in ("message", "part"):
            return record.get("input") if key == "part" else record.get("message") or None
        if role == QtCore.Qt.ForegroundRole and key == "status":
            status = record.get("status")
            return None if status == "ok" else _STOPPED if status == "stopped" else _FAILED
        return None


class SortProxy(QtCore.QSortFilterProxyModel):
    """Sorts on the records' raw values (10 after 9), not on the text shown."""

    def lessThan(self, left, right):
        model = self.sourceModel()
        key = COLUMNS[left.column()][1]
        return (_sort_key(model.record(left.row()).get(key)) <
                _sort_key(model.record(right.row()).get(key)))


def rows_shown(view):
    """The table's cells as the user sees them, in the view's order: [[cell, ...], ...]."""
    model = view.model()
    return [[model.index(r, c).data() for c in range(model.columnCount())] for r in range(model.rowCount())]
