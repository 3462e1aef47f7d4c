"""Where a part's outputs go, and writing them so that a kill never leaves a partial file.

    OUTDIR/parts/<name>.<format>      the medial mesh (ply, obj or ma)
    OUTDIR/parts/<name>.stats.json    the engine's statistics (cadmedial compute --stats)
    OUTDIR/parts/<name>.log           the part's messages (warnings, or the error)
    OUTDIR/parts/<name>.record.json   the batch's record of the part, written last
    OUTDIR/summary.csv, summary.json  one row per part
    OUTDIR/.work/                     a folder per running part, removed when it ends

<name> is the part's name (discover.Part), a relative path: a folder's layout is kept.
"""

import json
import os
import shutil
import tempfile

PARTS = "parts"
WORK = ".work"


def part_stem(out_dir, name):
    return os.path.join(out_dir, PARTS, name)


def mesh_path(out_dir, name, fmt):
    return part_stem(out_dir, name) + "." + fmt


def stats_path(out_dir, name):
    return part_stem(out_dir, name) + ".stats.json"


def log_path(out_dir, name):
    return part_stem(out_dir, name) + ".log"


def record_path(out_dir, name):
    return part_stem(out_dir, name) + ".record.json"


def make_work_dir(out_dir):
    """A fresh folder on the same file system as the outputs, so that rename() moves files in
    one step."""
    root = os.path.join(out_dir, WORK)
    os.makedirs(root, exist_ok=True)
    return tempfile.mkdtemp(dir=root)


def remove_work_dir(path):
    shutil.rmtree(path, ignore_errors=True)


def promote(src, dst):
    """Moves a finished file into place in one rename (same file system: see make_work_dir)."""
    os.makedirs(os.path.dirname(dst), exist_ok=True)
    os.replace(src, dst)


def write_text_atomically(path, text):
    os.makedirs(os.path.dirname(path) or ".", exist_ok=True)
    fd, tmp = tempfile.mkstemp(dir=os.path.dirname(path) or ".", prefix=".tmp-")
    try:
        with os.fdopen(fd, "w", encoding="utf-8") as f:
            f.write(text)
            f.flush()
            os.fsync(f.fileno())
        os.replace(tmp, path)
    except BaseException:
        try:
            os.unlink(tmp)
        except OSError:
            pass
        raise


def write_json_atomically(path, data):
    write_text_atomically(path, json.dumps(data, indent=1, sort_keys=True) + "\n")


def remove_outputs(out_dir, name, fmt):
    """A part redone and failed must not leave the previous run's mesh beside a failed record."""
    for path in (record_path(out_dir, name), mesh_path(out_dir, name, fmt), stats_path(out_dir, name)):
        try:
            os.unlink(path)
        except FileNotFoundError:
            pass
