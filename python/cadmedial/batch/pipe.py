"""batch() driven through pipes, for a program that must not host Dask itself (the FreeCAD
dialog: the scheduler, the imports and their garbage would share FreeCAD's process and stall its
GUI, and local workers would be spawned with the freecad program):

    /usr/bin/python3 -m cadmedial.batch.pipe < options.json

stdin   first line: {"inputs": [...], "out_dir": "...", "options": {batch() keywords}}; then a
        line "stop" (or the end of stdin: the caller is gone) stops the batch
stdout  one JSON object a line: {"update": [done, failed, total, record, message]} per
        progress.Update, then {"result": {"records", "counts", "seconds", "text"}} or
        {"error": "message"} (bad arguments or inputs: InvalidInput and its kin)
stderr  Dask's own messages
"""

import json
import sys
import threading


def _watch_stdin(stop):
    for line in sys.stdin:
        if line.strip() == "stop":
            break
    stop.set()


def main():
    from .. import Error
    from .run import batch
    request = json.loads(sys.stdin.readline())
    stop = threading.Event()
    threading.Thread(target=_watch_stdin, args=(stop,), daemon=True).start()
    lock = threading.Lock()

    def say(obj):
        with lock:
            sys.stdout.write(json.dumps(obj) + "\n")
            sys.stdout.flush()

    try:
        result = batch(request["inputs"], request["out_dir"], progress=False,
                       on_progress=lambda u: say({"update": list(u)}), stop=stop, **request.get("options", {}))
    except Error as e:
        say({"error": str(e)})
        return 2
    say({"result": result._asdict()})
    return 0


if __name__ == "__main__":
    sys.exit(main())
