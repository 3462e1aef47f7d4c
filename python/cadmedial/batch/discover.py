"""The parts of a batch from its INPUTS: CAD files, folders searched for them, and list files."""

import os
from typing import List, NamedTuple, Sequence

from .._core import InvalidInput

# What a folder is searched for. FCStd documents are read through FreeCAD (fcstd.py).
CAD_SUFFIXES = (".step", ".stp", ".iges", ".igs", ".brep", ".brp", ".fcstd")
# A list file: one path a line, relative to the list file's folder; '#' starts a comment.
LIST_SUFFIXES = (".txt", ".lst", ".list")


class Part(NamedTuple):
    name: str  # unique within the batch; its outputs are named after it (a relative path)
    path: str  # absolute path of the input file


def is_cad_file(path):
    return path.lower().endswith(CAD_SUFFIXES)


def _folder_parts(folder):
    """(name, path) of every CAD file under folder, names relative to folder's parent so that
    the folder's own name is kept (two folders with an a.step each give two names)."""
    base = os.path.dirname(os.path.abspath(folder).rstrip(os.sep))
    found = []
    for root, dirs, files in os.walk(folder):
        dirs[:] = sorted(d for d in dirs if not d.startswith("."))
        for f in sorted(files):
            if is_cad_file(f):
                path = os.path.abspath(os.path.join(root, f))
                found.append((os.path.relpath(path, base), path))
    return found


def _list_parts(list_file):
    here = os.path.dirname(os.path.abspath(list_file))
    found = []
    with open(list_file, encoding="utf-8") as f:
        for number, line in enumerate(f, 1):
            entry = line.split("#", 1)[0].strip()
            if not entry:
                continue
            path = os.path.normpath(os.path.join(here, os.path.expanduser(entry)))
            if os.path.isdir(path):
                found.extend(_folder_parts(path))
            elif os.path.isfile(path):
                found.append((os.path.basename(path), path))
            else:
                raise InvalidInput("%s, line %d: %s does not exist" % (list_file, number, entry))
    return found


def discover(inputs: Sequence[str]) -> List[Part]:
    """The parts named by ``inputs`` (files, folders, list files), in the order given, each file
    once. A file with another suffix is taken as given (the engine will say if it cannot read
    it); a missing input, or a folder with no CAD file, is InvalidInput. Names that would clash
    get '~2', '~3', ... in order."""
    if isinstance(inputs, (str, os.PathLike)):
        inputs = [inputs]
    found = []
    for item in inputs:
        item = os.fspath(item)
        if os.path.isdir(item):
            parts = _folder_parts(item)
            if not parts:
                raise InvalidInput("%s: no STEP, IGES, BREP or FCStd file in this folder" % item)
            found.extend(parts)
        elif os.path.isfile(item):
            if item.lower().endswith(LIST_SUFFIXES):
                found.extend(_list_parts(item))
            else:
                found.append((os.path.basename(item), os.path.abspath(item)))
        else:
            raise InvalidInput("%s: no such file or folder" % item)
    if not found:
        raise InvalidInput("no input parts given")
    parts, seen_paths, seen_names = [], set(), set()
    for name, path in found:
        real = os.path.realpath(path)
        if real in seen_paths:
            continue
        seen_paths.add(real)
        unique, n = name, 1
        while unique in seen_names:
            n += 1
            unique = "%s~%d" % (name, n)
        seen_names.add(unique)
        parts.append(Part(unique, path))
    return parts
