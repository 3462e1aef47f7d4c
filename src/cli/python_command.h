// Sub-commands written in Python (`cadmedial thickness`): the program hands its arguments to
// `/usr/bin/python3 -m MODULE` and returns its exit status.
#pragma once

namespace cadmedial::cli {

/// Replaces this process by `/usr/bin/python3 -m module argv[2..argc)` (FreeCAD's interpreter,
/// for which the module is built). From a build tree (build/cadmedial beside build/python/
/// cadmedial and the sources' python/), PYTHONPATH and CADMEDIAL_CORE_DIR are pointed there first
/// unless already set. Returns only on failure: 1 with a message.
int run_python_module(const char* module, int argc, char** argv);

}  // namespace cadmedial::cli
