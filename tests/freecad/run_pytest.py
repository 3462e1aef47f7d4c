# Runs pytest inside FreeCAD's own interpreter:
#   CADMEDIAL_PYTEST_ARGS='["tests/freecad/test_app.py"]' freecadcmd tests/freecad/run_pytest.py
# freecadcmd passes no arguments to scripts, hence the JSON list in the environment.
# Exits with pytest's status (sys.exit would be caught by freecadcmd and give status 0).
import json
import os
import sys

import pytest

args = json.loads(os.environ.get("CADMEDIAL_PYTEST_ARGS", "[]"))
if not args:
    print("run_pytest.py: set CADMEDIAL_PYTEST_ARGS to a JSON list of pytest arguments", file=sys.stderr)
    code = 2
else:
    code = int(pytest.main(["-q", "-p", "no:cacheprovider"] + args))
sys.stdout.flush()
sys.stderr.flush()
os._exit(code)
