"""The sheets of each polygon edge, as CSR slices of sorted (edge, sheet) keys."""

import numpy as np


class EdgeSheets:
    """Which sheets hold each edge of an EdgeTable, once faces carry sheet labels (-1: none)."""

    def __init__(self, table, face_sheet, n_sheets):
        self.base = n_sheets + 1
        edge_of = np.repeat(np.arange(len(table)), table.count)
        s = face_sheet[table.faces]
        keyed = s >= 0
        self.keys = np.unique(edge_of[keyed] * self.base + s[keyed])
        self.start = np.searchsorted(self.keys // self.base, np.arange(len(table) + 1))

    def first(self, edges):
        """(k,) the first (smallest) sheet of each of the edges (each must have one)."""
        return self.keys[self.start[edges]] % self.base

    def tally(self, edges):
        """(sheet ids, how many of the edges each holds): most edges first, then by id."""
        n = self.start[edges + 1] - self.start[edges]
        at = np.repeat(self.start[edges] - np.cumsum(n) + n, n) + np.arange(n.sum())
        ids, times = np.unique(self.keys[at] % self.base, return_counts=True)
        order = np.lexsort((ids, -times))
        return ids[order].tolist(), times[order].tolist()
